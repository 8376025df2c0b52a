"""StrDigCmp and StrDigCalc: arithmetic on non-negative integers held as digit strings.

A stringdig holds only decimal digits and a value 0..4294967295.  Other
text raises ERR_INT_NOTVAL, a larger value ERR_INT_MAXVAL; results above
the maximum raise ERR_CALC_OVERFLOW, negative results ERR_CALC_NEG, and
division (OpDiv, OpMod) by zero ERR_CALC_DIVZERO.
"""
from __future__ import annotations

import operator

from ..errors import RapidError
from .data import PREDEFINED_DATA
from .registry import function

STRINGDIG_MAX = 4294967295


def stringdig_value(text: str) -> int:
    """The integer a stringdig holds (errors as in the module docstring)."""
    if not text or not all("0" <= ch <= "9" for ch in text):
        raise RapidError("ERR_INT_NOTVAL", f"{text!r} is not a digit string")
    value = int(text)
    if value > STRINGDIG_MAX:
        raise RapidError("ERR_INT_MAXVAL", f"{text} exceeds {STRINGDIG_MAX}")
    return value


def _constant(name: str) -> float:
    return PREDEFINED_DATA[name.upper()].value  # type: ignore[return-value]


_RELATIONS = {
    _constant("LT"): operator.lt, _constant("LTEQ"): operator.le, _constant("EQ"): operator.eq,
    _constant("NOTEQ"): operator.ne, _constant("GTEQ"): operator.ge, _constant("GT"): operator.gt,
}


def _quotient(a: int, b: int) -> int:
    if b == 0:
        raise RapidError("ERR_CALC_DIVZERO", "StrDigCalc division by zero")
    return a // b


def _remainder(a: int, b: int) -> int:
    if b == 0:
        raise RapidError("ERR_CALC_DIVZERO", "StrDigCalc division by zero")
    return a % b


_OPERATIONS = {
    _constant("OpAdd"): operator.add, _constant("OpSub"): operator.sub,
    _constant("OpMult"): operator.mul, _constant("OpDiv"): _quotient, _constant("OpMod"): _remainder,
}


@function("bool StrDigCmp(stringdig StrDig1, opnum Relation, stringdig StrDig2)")
def str_dig_cmp(first: str, relation: float, second: str) -> bool:
    compare = _RELATIONS.get(relation)
    if compare is None:
        raise RapidError("ERR_ARGVALERR", f"{relation} is not an opnum relation")
    return compare(stringdig_value(first), stringdig_value(second))


@function("stringdig StrDigCalc(stringdig StrDig1, opcalc Operation, stringdig StrDig2)")
def str_dig_calc(first: str, operation: float, second: str) -> str:
    calculate = _OPERATIONS.get(operation)
    if calculate is None:
        raise RapidError("ERR_ARGVALERR", f"{operation} is not an opcalc operator")
    result = calculate(stringdig_value(first), stringdig_value(second))
    if result < 0:
        raise RapidError("ERR_CALC_NEG", "StrDigCalc result is negative")
    if result > STRINGDIG_MAX:
        raise RapidError("ERR_CALC_OVERFLOW", f"StrDigCalc result exceeds {STRINGDIG_MAX}")
    return str(result)
