"""Data and system functions: Present, Dim, ValToStr, StrToVal, modes, dates.

The controller's date and time are one fixed moment (FIXED): CDate gives "2026-01-01",
CTime "00:00:00", GetTime \\WDay 4 (that date is a Thursday; weekdays run from 1, Monday,
to 7) and \\Hour, \\Min, \\Sec 0. Elapsed times are measured with clocks (ClkRead).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import ARGUMENT, TYPE_MISMATCH, error
from .. import values
from ..errors import RapidError
from ..expressions import Compiled, constant
from ..machine import ABSENT
from ..scope import LOCAL_DATA
from ..types import (
    BOOL,
    DNUM,
    NON_VALUE,
    NUM,
    RECORD,
    SEMI_VALUE,
    STRING,
    ArrayType,
    RapidType,
)
from .arguments import Arguments, argument_expression
from .probed_readings import probed_reading
from .registry import FIXED, compiled


@compiled("bool Present(REF anytype OptPar)")
def _present(calls, compiler, call, entry) -> Compiled:
    if len(call.args) != 1 or call.args[0].kind != ast.REQUIRED or \
            not isinstance(call.args[0].value, ast.NameRef):
        raise error(ARGUMENT, "Present takes one optional parameter name", call.span)
    name = call.args[0].value.name
    symbol = compiler.scope.lookup(name.key)
    if symbol is None or symbol.kind != LOCAL_DATA or not symbol.optional:
        raise error(ARGUMENT, f"'{name.text}' is not an optional parameter of this routine",
                    call.args[0].span)
    slot = symbol.slot
    return Compiled(lambda m: m.frames[-1].locals[slot] is not ABSENT, BOOL)


@compiled("num Dim(REF anytype ArrPar, num DimNo)")
def _dim(calls, compiler, call, entry) -> Compiled:
    args = [a for a in call.args if a.kind == ast.REQUIRED]
    if len(args) != 2:
        raise error(ARGUMENT, "Dim takes an array and a dimension number", call.span)
    array = compiler.value(args[0].value)
    if array.type is not None and not isinstance(array.type, ArrayType):
        raise error(TYPE_MISMATCH, "the first argument of Dim must be an array", args[0].span)
    number = compiler.value(args[1].value, NUM)
    array_fn, number_fn = array.fn, number.fn

    def dim(m):
        value = array_fn(m)
        n = number_fn(m)
        if n != int(n) or n < 1:
            raise RapidError("ERR_ILLDIM", f"dimension {values.format_num(n)} does not exist")
        for _ in range(int(n) - 1):
            if not value or not isinstance(value[0], tuple):
                raise RapidError("ERR_ILLDIM", f"the array has fewer than {int(n)} dimensions")
            value = value[0]
        return float(len(value))
    return Compiled(dim, NUM)


def value_kind(rapid_type):
    """The ``kind`` argument of ``values.format_value`` for a static type."""
    if isinstance(rapid_type, ArrayType):
        inner = ArrayType(rapid_type.element, rapid_type.dims[1:]) if rapid_type.rank > 1 \
            else rapid_type.element
        return ("array", value_kind(inner))
    if rapid_type is None:
        return "num"
    if rapid_type.kind == RECORD:
        return tuple(value_kind(c.type) for c in rapid_type.components)
    return "dnum" if rapid_type is DNUM else "num"


def format_typed(value, kind) -> str:
    if isinstance(kind, tuple) and kind and kind[0] == "array":
        return "[" + ",".join(format_typed(v, kind[1]) for v in value) + "]"
    return values.format_value(value, kind)


@compiled("string ValToStr(anytype Val)")
def _val_to_str(calls, compiler, call, entry) -> Compiled:
    args = [a for a in call.args if a.kind == ast.REQUIRED]
    if len(args) != 1:
        raise error(ARGUMENT, "ValToStr takes one value", call.span)
    value = compiler.value(args[0].value)
    kind = value_kind(value.type)
    fn = value.fn
    return Compiled(lambda m: values.checked_string(format_typed(fn(m), kind)), STRING)


@compiled("bool StrToVal(string Str, INOUT anytype Val)")
def _str_to_val(calls, compiler, call, entry) -> Compiled:
    from ..literals import parse_literal
    arguments = Arguments(calls, compiler, call, entry)
    text_fn = arguments.fn("Str")
    ref_fn = arguments.fn("Val")
    target = argument_expression(call, "Val", 1)
    _, target_type, _ = compiler.reference(target, "written by StrToVal")
    element = target_type.element if isinstance(target_type, ArrayType) else target_type
    if isinstance(element, RapidType) and element.kind in (SEMI_VALUE, NON_VALUE):
        raise error(TYPE_MISMATCH, f"StrToVal writes value data, not {element.name}",
                    target.span)

    def str_to_val(m):
        parsed = parse_literal(text_fn(m), target_type)
        if parsed is None:
            return False
        m.write_ref(ref_fn(m), parsed)
        return True
    return Compiled(str_to_val, BOOL)


@compiled("bool IsPers(INOUT anytype DatObj)",
          "bool IsVar(INOUT anytype DatObj)")
def _is_pers(calls, compiler, call, entry) -> Compiled:
    target = argument_expression(call, "DatObj", 0)
    _, _, symbol = compiler.reference(target, "inspected")
    storage = symbol.storage
    wanted = "PERS" if call.name.key == "ISPERS" else "VAR"
    return constant(storage == wanted, BOOL)


@compiled("symnum OpMode()",
          modelled=FIXED)
def _op_mode(calls, compiler, call, entry) -> Compiled:
    """OP_AUTO (any mode in the readings probe: probed_readings)."""
    mode = compiler.linker.system_symbol(ast.Name.of("OP_AUTO")).value
    return probed_reading(compiler, call, lambda m: mode, NUM)


@compiled("symnum RunMode(\\switch Main)",
          modelled=FIXED)
def _run_mode(calls, compiler, call, entry) -> Compiled:
    """RUN_CONT_CYCLE (any mode in the readings probe: probed_readings)."""
    Arguments(calls, compiler, call, entry)
    mode = compiler.linker.system_symbol(ast.Name.of("RUN_CONT_CYCLE")).value
    return probed_reading(compiler, call, lambda m: mode, NUM)


@compiled("num RemainingRetries()")
def _remaining_retries(calls, compiler, call, entry) -> Compiled:
    return Compiled(lambda m: float(max(0, m.program.options.get("max_retries", 4)
                                        - m.frames[-1].retries)), NUM)


# The one date and time rapidmc's controller has (FIXED): Thursday 2026-01-01, 00:00:00.
FIXED_DATE, FIXED_TIME, FIXED_WEEKDAY = "2026-01-01", "00:00:00", 4.0


@compiled("string CDate()",
          "string CTime()",
          modelled=FIXED)
def _date(calls, compiler, call, entry) -> Compiled:
    text = FIXED_DATE if call.name.key == "CDATE" else FIXED_TIME
    return constant(text, STRING)


@compiled("num GetTime(\\switch WDay | switch Hour | switch Min | switch Sec)",
          modelled=FIXED)
def _get_time(calls, compiler, call, entry) -> Compiled:
    """The part of the fixed date asked for: \\WDay 1 (Monday) to 7 (Sunday), so 4 (the
    fixed date is a Thursday; 0 is no weekday, and a program indexing an array by it
    must not fail); hour, minute and second 0."""
    Arguments(calls, compiler, call, entry)
    switches = {arg.name.key for arg in call.args if arg.name is not None}
    return constant(FIXED_WEEKDAY if "WDAY" in switches else 0.0, NUM)

