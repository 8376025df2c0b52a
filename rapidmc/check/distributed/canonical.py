"""Canonical bytes of a state, and the partition that owns it.

A distributed search splits the states among workers by a hash of the state.  Python's
``hash`` will not do: it is salted per process (strings) and, for ``None`` and plain
objects, taken from memory addresses, so two workers would disagree about the owner of one
state.  ``canonical_bytes`` writes a state as bytes that depend only on its value: every
part tagged with its kind, containers in their own order (tuples, named tuples, vectors)
or sorted by their members' bytes (sets, maps), so insertion history and hash seeds play no
part.  ``owner`` hashes those bytes with BLAKE2b, the same in every process and on every
machine.

Equal states give equal bytes, which is all the partition needs: numbers that Python
holds equal (``True``, ``1``, ``1.0``) are written alike.  Distinct states give distinct bytes
but for such numbers (the encoding is prefix-free), which keeps the partitions balanced.  A part of a kind the codec does not know
is a programming error, reported with the kind's name, never hashed by address.
"""
from __future__ import annotations

import hashlib
import struct
from typing import Hashable

from pyrsistent import PMap, PSet, PVector

_DOUBLE = struct.Struct("<d")


def canonical_bytes(value: Hashable) -> bytes:
    """The value as bytes that equal values share in every process (module docstring)."""
    out = bytearray()
    _write(value, out)
    return bytes(out)


def owner(value: Hashable, partitions: int) -> int:
    """The partition (0 .. partitions-1) that owns ``value``: the same in every process."""
    return owner_of_bytes(state_bytes(value), partitions)


def owner_of_bytes(encoded: bytes, partitions: int) -> int:
    digest = hashlib.blake2b(encoded, digest_size=8).digest()
    return int.from_bytes(digest, "little") % partitions


_PARTS: dict = {}          # a state's part -> its canonical bytes (see state_bytes)
MAX_PARTS = 1 << 17


def state_bytes(value) -> bytes:
    """``canonical_bytes`` of a tuple-shaped state, each of its parts encoded once per
    process: successive states share most parts (a model changes a few per step), and
    writing them afresh in Python dominated the cost of a distributed search.  The cache is
    keyed by the part itself, so a part equal to a cached one (hence written alike) reuses
    its bytes; it is emptied when it grows past ``MAX_PARTS``."""
    if not isinstance(value, tuple):
        return canonical_bytes(value)
    out = bytearray(b"L")
    _length(len(value), out)
    parts = _PARTS
    for part in value:
        try:
            encoded = parts.get(part)
        except TypeError:                     # (an unhashable part: written each time)
            encoded = canonical_bytes(part)
        else:
            if encoded is None:
                if len(parts) >= MAX_PARTS:
                    parts.clear()
                encoded = parts[part] = canonical_bytes(part)
        out += encoded
    return bytes(out)


def _length(count: int, out: bytearray) -> None:
    out += count.to_bytes(4, "little")


def _write(value, out: bytearray) -> None:
    kind = type(value)
    if value is None:
        out += b"N"
    elif isinstance(value, int):                  # (bools too: True == 1 in a state)
        _integer(int(value), out)
    elif isinstance(value, float):
        if value.is_integer():                    # 2.0 == 2 (and -0.0 == 0): one encoding
            _integer(int(value), out)
        else:
            out += b"D"
            out += _DOUBLE.pack(value)
    elif isinstance(value, str):
        data = value.encode("utf-8", "surrogatepass")
        out += b"S"
        _length(len(data), out)
        out += data
    elif isinstance(value, (bytes, bytearray)):
        out += b"B"
        _length(len(value), out)
        out += value
    elif isinstance(value, (tuple, list, PVector)):
        out += b"L"
        _length(len(value), out)
        for item in value:
            _write(item, out)
    elif isinstance(value, (frozenset, set, PSet)):
        _sorted(b"E", (canonical_bytes(item) for item in value), len(value), out)
    elif isinstance(value, (dict, PMap)):
        _sorted(b"M", (canonical_bytes(key) + canonical_bytes(item)
                       for key, item in value.items()), len(value), out)
    else:
        raise TypeError(f"no canonical encoding for a state part of type "
                        f"{kind.__module__}.{kind.__qualname__}")


def _integer(number: int, out: bytearray) -> None:
    text = str(number).encode()
    out += b"I"
    _length(len(text), out)
    out += text


def _sorted(tag: bytes, members, count: int, out: bytearray) -> None:
    out += tag
    _length(count, out)
    for member in sorted(members):
        _length(len(member), out)
        out += member
