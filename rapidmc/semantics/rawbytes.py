"""rawbytes buffers: packing and unpacking values, as pure functions over ``bytes``.

A RAPID ``rawbytes`` variable holds at most 1024 bytes; rapidmc stores it as
an immutable ``bytes`` value (``None``, the value of a fresh non-value
variable, reads as empty).  Indexes are 1-based as in RAPID.  Integers are
little endian unless ``network`` (big endian) is asked for, as with the
``\\Network`` switch of PackRawBytes/UnpackRawBytes.

The ``\\IntX`` sizes (inttypes constants): USINT 1, UINT 2, UDINT 4,
ULINT 8 (unsigned), SINT -1, INT -2, DINT -4, LINT -8 (signed).

    >>> pack(b"", 1, 258.0, ("int", 2), network=True)
    b'\\x01\\x02'
    >>> unpack(b"\\x01\\x02", 1, ("int", 2), network=False)
    513.0
"""
from __future__ import annotations

import re
import struct
from typing import Optional

from .errors import RapidError
from .values import to_num

MAX_BYTES = 1024
INT_SIZES = {1: "B", 2: "H", 4: "I", 8: "Q", -1: "b", -2: "h", -4: "i", -8: "q"}
INTTYPES = (("USINT", 1), ("UINT", 2), ("UDINT", 4), ("ULINT", 8),
            ("SINT", -1), ("INT", -2), ("DINT", -4), ("LINT", -8))

HEX1 = ("hex1",)
FLOAT4 = ("float4",)


def as_bytes(value) -> bytes:
    """The bytes of a rawbytes value (a fresh variable holds None)."""
    return b"" if value is None else value


def _check_index(index: float, length: int, what: str) -> int:
    if index != int(index) or not 1 <= index <= MAX_BYTES:
        raise RapidError("ERR_OUTOFBND", f"{what} {index:g} is outside 1..{MAX_BYTES}")
    if index > length + 1:
        raise RapidError("ERR_OUTOFBND", f"{what} {int(index)} is beyond the {length} bytes "
                         "held plus one")
    return int(index)


def encode(value, encoding: tuple, network: bool) -> bytes:
    """The bytes of one value in ``encoding`` (HEX1, FLOAT4, ("int", n), ("ascii",))."""
    order = ">" if network else "<"
    kind = encoding[0]
    if kind == "hex1":
        if value != int(value) or not 0 <= value <= 255:
            raise RapidError("ERR_ARGVALERR", f"\\Hex1 needs a byte 0..255, not {value:g}")
        return bytes([int(value)])
    if kind == "float4":
        return struct.pack(order + "f", value)
    if kind == "ascii":
        return value.encode("latin-1")
    size = encoding[1]
    code = INT_SIZES.get(int(size)) if size == int(size) else None
    if code is None:
        raise RapidError("ERR_ARGVALERR", f"\\IntX must be an inttypes size, not {size:g}")
    if value != int(value):
        raise RapidError("ERR_ARGVALERR", f"\\IntX packs integers, not {value:g}")
    try:
        return struct.pack(order + code, int(value))
    except struct.error:
        raise RapidError("ERR_ARGVALERR", f"{value:g} does not fit in \\IntX:={int(size)}") \
            from None


def pack(buffer, start: float, value, encoding: tuple, network: bool = False) -> bytes:
    """``buffer`` with ``value`` written from byte ``start`` on (PackRawBytes).

    ``start`` may lie past the bytes held: the bytes skipped count as zeros and the
    length grows to the end of ``value``; StartIndex stays within 1..1024.  The ROS
    driver of ABB's YuMi packs a message's last joints past a gap (``PackRawBytes 0,
    raw_message.data, 33+i*4`` after 32 bytes) in the backups of controllers that ran
    it, so packing past the end is taken as no error (not verified on a controller)."""
    data = as_bytes(buffer)
    index = _check_index(start, MAX_BYTES - 1, "StartIndex")
    chunk = encode(value, encoding, network)
    data = data + bytes(max(0, index - 1 - len(data)))
    result = data[:index - 1] + chunk + data[index - 1 + len(chunk):]
    if len(result) > MAX_BYTES:
        raise RapidError("ERR_OUTOFBND", f"rawbytes hold at most {MAX_BYTES} bytes")
    return result


def unpack(buffer, start: float, encoding: tuple, network: bool = False):
    """The value held from byte ``start`` on (UnpackRawBytes)."""
    data = as_bytes(buffer)
    index = _check_index(start, len(data), "StartIndex")
    kind = encoding[0]
    if kind == "ascii":
        size = encoding[1]
        if size != int(size) or not 1 <= size <= 80:
            raise RapidError("ERR_ARGVALERR", f"\\ASCII takes 1..80 characters, not {size:g}")
        size = int(size)
    elif kind == "int":
        size = abs(int(encoding[1]))
    else:
        size = 1 if kind == "hex1" else 4
    chunk = data[index - 1:index - 1 + size]
    if len(chunk) < size:
        raise RapidError("ERR_OUTOFBND", f"reading {size} bytes from byte {index} passes the "
                         f"end of the {len(data)} bytes held")
    order = ">" if network else "<"
    if kind == "hex1":
        return float(chunk[0])
    if kind == "float4":
        return to_num(struct.unpack(order + "f", chunk)[0])
    if kind == "ascii":
        return chunk.decode("latin-1")
    if encoding[1] not in INT_SIZES:
        raise RapidError("ERR_ARGVALERR", f"\\IntX must be an inttypes size, not {encoding[1]:g}")
    return float(struct.unpack(order + INT_SIZES[int(encoding[1])], chunk)[0])


def copy(source, from_index: float, target, to_index: float,
         count: Optional[float] = None) -> bytes:
    """``target`` with bytes of ``source`` copied in (CopyRawBytes)."""
    data = as_bytes(source)
    start = _check_index(from_index, len(data), "FromIndex")
    chunk = data[start - 1:]
    if count is not None:
        if count != int(count) or count < 0 or count > len(chunk):
            raise RapidError("ERR_OUTOFBND", f"NoOfBytes {count:g} is more than the "
                             f"{len(chunk)} bytes from FromIndex on")
        chunk = chunk[:int(count)]
    out = as_bytes(target)
    index = _check_index(to_index, len(out), "ToIndex")
    result = out[:index - 1] + chunk + out[index - 1 + len(chunk):]
    if len(result) > MAX_BYTES:
        raise RapidError("ERR_OUTOFBND", f"rawbytes hold at most {MAX_BYTES} bytes")
    return result


def clear(buffer, from_index: Optional[float] = None) -> bytes:
    """ClearRawBytes: empty, or cut from ``from_index`` on."""
    if from_index is None:
        return b""
    data = as_bytes(buffer)
    index = _check_index(from_index, len(data), "FromIndex")
    return data[:index - 1]


_HEX = re.compile(r"^(?:\s*[0-9A-Fa-f]{2})*\s*$")


def from_text(text: str) -> bytes:
    """Bytes a text message stands for: hex pairs (``"0a 1F"``) if it is only that, else Latin-1."""
    if text.strip() and _HEX.match(text):
        return bytes.fromhex("".join(text.split()))
    return text.encode("latin-1", errors="replace")


def to_text(data: bytes) -> str:
    """Bytes shown as lower-case hex pairs separated by spaces."""
    return " ".join(f"{b:02x}" for b in data)
