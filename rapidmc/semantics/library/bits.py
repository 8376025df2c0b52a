"""Bit functions on byte (0..255, bits 1..8) and dnum (0..4294967295, bits 1..32).

Operands outside the range, non-integer operands, and bit positions or
shift counts outside 1..width raise ERR_ARGVALERR.  Bit 1 is the least
significant bit.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..errors import RapidError
from ..values import NumericKind, is_integer
from .registry import function, numeric


@dataclass(frozen=True)
class BitWidth:
    """A bit-vector type: byte (8 bits, num) or the dnum 32-bit form."""

    name: str
    bits: int

    @property
    def mask(self) -> int:
        return (1 << self.bits) - 1

    def operand(self, value: float) -> int:
        """``value`` as an int, or ERR_ARGVALERR if it is no valid bit pattern."""
        if not is_integer(value) or not 0 <= value <= self.mask:
            raise RapidError("ERR_ARGVALERR", f"{value} is not a {self.name} (0..{self.mask})")
        return int(value)

    def position(self, value: float, what: str) -> int:
        """A bit position or shift count in 1..bits, else ERR_ARGVALERR."""
        if not is_integer(value) or not 1 <= value <= self.bits:
            raise RapidError("ERR_ARGVALERR", f"{what} {value} outside 1..{self.bits}")
        return int(value)


BYTE = BitWidth("byte", 8)
DWORD = BitWidth("dnum bit pattern", 32)


def _register_pair(byte_text: str, dnum_text: str, make) -> None:
    function(byte_text)(make(BYTE))
    function(dnum_text)(make(DWORD))


def _binary(operation):
    def make(width: BitWidth):
        return lambda a, b: float(operation(width.operand(a), width.operand(b)))
    return make


_register_pair("byte BitAnd(byte BitData1, byte BitData2)",
               "dnum BitAndDnum(dnum Value1, dnum Value2)", _binary(lambda a, b: a & b))
_register_pair("byte BitOr(byte BitData1, byte BitData2)",
               "dnum BitOrDnum(dnum Value1, dnum Value2)", _binary(lambda a, b: a | b))
_register_pair("byte BitXOr(byte BitData1, byte BitData2)",
               "dnum BitXOrDnum(dnum Value1, dnum Value2)", _binary(lambda a, b: a ^ b))


def _negate(width: BitWidth):
    return lambda a: float(width.mask ^ width.operand(a))


def _shift_left(width: BitWidth):
    return lambda a, steps: float((width.operand(a) << width.position(steps, "ShiftSteps")) & width.mask)


def _shift_right(width: BitWidth):
    return lambda a, steps: float(width.operand(a) >> width.position(steps, "ShiftSteps"))


def _check(width: BitWidth):
    return lambda a, position: bool(width.operand(a) >> (width.position(position, "BitPos") - 1) & 1)


_register_pair("byte BitNeg(byte BitData)", "dnum BitNegDnum(dnum Value)", _negate)
_register_pair("byte BitLSh(byte BitData, num ShiftSteps)",
               "dnum BitLShDnum(dnum Value, num ShiftSteps)", _shift_left)
_register_pair("byte BitRSh(byte BitData, num ShiftSteps)",
               "dnum BitRShDnum(dnum Value, num ShiftSteps)", _shift_right)
_register_pair("bool BitCheck(byte BitData, num BitPos)",
               "bool BitCheckDnum(dnum Value, num BitPos)", _check)


def _width(kind: NumericKind) -> BitWidth:
    return DWORD if kind.name == "dnum" else BYTE


@numeric("BitSet(INOUT anynum BitData, num BitPos)")
def bit_set(kind: NumericKind):
    width = _width(kind)
    return lambda data, position: {
        "BitData": float(width.operand(data) | 1 << (width.position(position, "BitPos") - 1))}


@numeric("BitClear(INOUT anynum BitData, num BitPos)")
def bit_clear(kind: NumericKind):
    width = _width(kind)
    return lambda data, position: {
        "BitData": float(width.operand(data) & ~(1 << (width.position(position, "BitPos") - 1)))}
