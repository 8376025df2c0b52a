"""Instructions that update a num or dnum variable: Add, Incr, Decr, Clear, TryInt.

Each returns the new value of its INOUT parameter (see the registry's calling
convention), rounded to the variable's type; the dnum variant is chosen by
the interpreter from the argument's static type.
"""
from __future__ import annotations

from ..errors import RapidError
from ..values import NumericKind, is_integer
from .registry import numeric


@numeric("Add(INOUT anynum Name, anynum AddValue)")
def add(kind: NumericKind):
    return lambda name, add_value: {"Name": kind.convert(name + add_value)}


@numeric("Incr(INOUT anynum Name)")
def incr(kind: NumericKind):
    return lambda name: {"Name": kind.convert(name + 1)}


@numeric("Decr(INOUT anynum Name)")
def decr(kind: NumericKind):
    return lambda name: {"Name": kind.convert(name - 1)}


@numeric("Clear(INOUT anynum Name)")
def clear(kind: NumericKind):
    return lambda name: {"Name": 0.0}


@numeric("TryInt(INOUT anynum DataObj)")
def try_int(kind: NumericKind):
    """ERR_INT_NOTVAL for a fraction, ERR_INT_MAXVAL beyond the exact-integer range."""
    def check(data_obj: float) -> None:
        if not is_integer(data_obj):
            raise RapidError("ERR_INT_NOTVAL", f"{data_obj} is not an integer")
        if abs(data_obj) > kind.exact_integer:
            raise RapidError("ERR_INT_MAXVAL", f"{data_obj} is beyond the exact {kind.name} integers")
        return None
    return check
