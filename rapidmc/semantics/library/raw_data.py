"""rawbytes instructions: ClearRawBytes, RawBytesLen, PackRawBytes, UnpackRawBytes, CopyRawBytes.

The byte layouts live in ``rapidmc.semantics.rawbytes``; this module binds
the arguments and reads and writes the variables.

PackRawBytes may start past the bytes held (StartIndex 1..1024): the
bytes skipped are zeros. This is our reading, not verified on a controller; ABB YuMi's ROS
driver packs a message's last joints past such a gap. UnpackRawBytes and CopyRawBytes past
the bytes held raise ERR_OUTOFBND.
"""
from __future__ import annotations

from ...diagnostics import ARGUMENT, error
from .. import rawbytes
from ..expressions import Compiled
from ..instructions import Action
from ..machine import ABSENT
from ..types import NUM, STRING
from .arguments import Arguments, argument_expression
from .registry import compiled
from .signature_parts import FORMATS


def _encoding(call, arguments, value_type):
    """fn(m) -> the byte layout chosen by the format switch (checked at link time)."""
    names = {arg.name.key for arg in call.args if arg.name is not None}
    given = [key for key in ("Hex1", "IntX", "Float4", "ASCII") if key.upper() in names]
    if not given:
        if value_type is STRING and call.name.key == "PACKRAWBYTES":
            return lambda m: ("ascii",)
        raise error(ARGUMENT, f"{call.name.text} needs one of \\Hex1, \\IntX, \\Float4 or "
                    "\\ASCII to know the byte layout", call.span)
    key = given[0]
    if key == "Hex1":
        return lambda m: rawbytes.HEX1
    if key == "Float4":
        return lambda m: rawbytes.FLOAT4
    size = arguments.value(key)
    if key == "ASCII":
        if call.name.key == "PACKRAWBYTES":
            return lambda m: ("ascii",)
        return lambda m: ("ascii", size(m))
    return lambda m: ("int", size(m))


def _value_type(compiler, call, key: str, position: int, by_reference: bool):
    expr = argument_expression(call, key, position)
    if expr is None:
        return None
    if by_reference:
        return compiler.reference(expr, "unpacked into")[1]
    return compiler.value(expr).type


@compiled("ClearRawBytes(VAR rawbytes RawData \\num FromIndex)")
def _clear_raw_bytes(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    ref, start = arguments.fn("RawData"), arguments.value("FromIndex")

    def clear(m):
        index = start(m)
        target = ref(m)
        m.write_ref(target, rawbytes.clear(m.read_ref(target), None if index is ABSENT else index))
    return Action(call.span, clear)


@compiled("num RawBytesLen(VAR rawbytes RawData)")
def _raw_bytes_len(calls, compiler, call, entry) -> Compiled:
    ref = Arguments(calls, compiler, call, entry).fn("RawData")
    return Compiled(lambda m: float(len(rawbytes.as_bytes(m.read_ref(ref(m))))), NUM)


@compiled(f"PackRawBytes(anytype Value, VAR rawbytes RawData \\switch Network, num StartIndex "
              f"{FORMATS} | switch ASCII)")
def _pack_raw_bytes(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    encoding = _encoding(call, arguments, _value_type(compiler, call, "Value", 0, False))
    value, ref = arguments.value("Value"), arguments.fn("RawData")
    network, start = arguments.value("Network"), arguments.value("StartIndex")

    def pack(m):
        target = ref(m)
        m.write_ref(target, rawbytes.pack(m.read_ref(target), start(m), value(m), encoding(m),
                                          network(m) is True))
    return Action(call.span, pack)


@compiled(f"UnpackRawBytes(VAR rawbytes RawData \\switch Network, num StartIndex, INOUT anytype Value "
              f"{FORMATS} | num ASCII)")
def _unpack_raw_bytes(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    value_type = _value_type(compiler, call, "Value", 2, True)
    encoding = _encoding(call, arguments, value_type)
    ref, target = arguments.fn("RawData"), arguments.fn("Value")
    network, start = arguments.value("Network"), arguments.value("StartIndex")

    def unpack(m):
        found = rawbytes.unpack(m.read_ref(ref(m)), start(m), encoding(m), network(m) is True)
        m.write_ref(target(m), found)
    return Action(call.span, unpack)


@compiled("CopyRawBytes(VAR rawbytes FromRawData, num FromIndex, VAR rawbytes ToRawData, "
              "num ToIndex \\num NoOfBytes)")
def _copy_raw_bytes(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    source, from_index = arguments.fn("FromRawData"), arguments.value("FromIndex")
    target, to_index = arguments.fn("ToRawData"), arguments.value("ToIndex")
    count = arguments.value("NoOfBytes")

    def copy(m):
        n = count(m)
        ref = target(m)
        m.write_ref(ref, rawbytes.copy(m.read_ref(source(m)), from_index(m), m.read_ref(ref),
                                       to_index(m), None if n is ABSENT else n))
    return Action(call.span, copy)

