"""Arithmetic and trigonometric functions (Abs ... ATan2Dnum), angles in degrees.

Each function exists for num and dnum (``Sqrt`` / ``SqrtDnum``); one factory
per function builds both from a ``NumericKind`` so the two cannot drift.
Domain errors (Sqrt of a negative, ASin of 2, Pow(-8, 1/3)) raise
ERR_ARGVALERR; results beyond the type's range raise ERR_NUM_LIMIT.
"""
from __future__ import annotations

import math

from ..errors import RapidError
from ..values import DNUM, NUM, NumericKind, decimals_argument, round_decimal
from .registry import function


def _both(num_text: str, dnum_text: str):
    """Register ``make(NUM)`` under ``num_text`` and ``make(DNUM)`` under ``dnum_text``."""
    def decorate(make):
        function(num_text)(make(NUM))
        function(dnum_text)(make(DNUM))
        return make
    return decorate


def _domain(condition: bool, message: str) -> None:
    if not condition:
        raise RapidError("ERR_ARGVALERR", message)


def _overflow_safe(compute, *args) -> float:
    try:
        return compute(*args)
    except OverflowError:
        raise RapidError("ERR_NUM_LIMIT", "result out of range") from None


# --------------------------------------------------------------------------
# Absolute value, roots, powers
# --------------------------------------------------------------------------


@_both("num Abs(num Value)", "dnum AbsDnum(dnum Value)")
def _abs(kind: NumericKind):
    return lambda value: abs(value)


@_both("num Sqrt(num Value)", "dnum SqrtDnum(dnum Value)")
def _sqrt(kind: NumericKind):
    def sqrt(value: float) -> float:
        _domain(value >= 0, f"Sqrt of negative value {value}")
        return kind.convert(math.sqrt(value))
    return sqrt


@function("num Exp(num Exponent)")
def exp(exponent: float) -> float:
    return NUM.convert(_overflow_safe(math.exp, exponent))


@_both("num Pow(num Base, num Exponent)", "dnum PowDnum(dnum Base, dnum Exponent)")
def _pow(kind: NumericKind):
    def power(base: float, exponent: float) -> float:
        _domain(not (base < 0 and exponent != int(exponent)),
                f"Pow of negative base {base} with non-integer exponent {exponent}")
        _domain(not (base == 0 and exponent <= 0), "Pow of 0 with exponent <= 0")
        return kind.convert(_overflow_safe(math.pow, base, exponent))
    return power


# --------------------------------------------------------------------------
# Rounding
# --------------------------------------------------------------------------


@_both("num Round(num Val \\num Dec)", "dnum RoundDnum(dnum Val \\num Dec)")
def _round(kind: NumericKind):
    def round_value(val: float, dec: float | None) -> float:
        places = 0 if dec is None else decimals_argument(dec, kind.max_decimals)
        return kind.convert(round_decimal(val, places, kind.single))
    return round_value


@_both("num Trunc(num Val \\num Dec)", "dnum TruncDnum(dnum Val \\num Dec)")
def _trunc(kind: NumericKind):
    def trunc_value(val: float, dec: float | None) -> float:
        places = 0 if dec is None else decimals_argument(dec, kind.max_decimals)
        return kind.convert(round_decimal(val, places, kind.single, truncate=True))
    return trunc_value


# --------------------------------------------------------------------------
# Trigonometry in degrees
# --------------------------------------------------------------------------

# Exact results at multiples of 90 degrees: sin/cos of the quadrant index.
_QUADRANT_SIN = (0.0, 1.0, 0.0, -1.0)


def sin_degrees(angle: float) -> float:
    """sin of ``angle`` degrees; exact 0 / ±1 at multiples of 90."""
    if angle % 90 == 0:
        return _QUADRANT_SIN[int(angle // 90) % 4]
    return math.sin(math.radians(math.fmod(angle, 360.0)))


def cos_degrees(angle: float) -> float:
    """cos of ``angle`` degrees; exact 0 / ±1 at multiples of 90."""
    if angle % 90 == 0:
        return _QUADRANT_SIN[(int(angle // 90) + 1) % 4]
    return math.cos(math.radians(math.fmod(angle, 360.0)))


def tan_degrees(angle: float) -> float:
    """tan of ``angle`` degrees; 0 at multiples of 180, ERR_ARGVALERR at ±90 + k·180."""
    if angle % 180 == 0:
        return 0.0
    _domain(angle % 180 != 90, f"Tan of {angle} degrees is infinite")
    return math.tan(math.radians(math.fmod(angle, 360.0)))


@_both("num Sin(num Angle)", "dnum SinDnum(dnum Angle)")
def _sin(kind: NumericKind):
    return lambda angle: kind.convert(sin_degrees(angle))


@_both("num Cos(num Angle)", "dnum CosDnum(dnum Angle)")
def _cos(kind: NumericKind):
    return lambda angle: kind.convert(cos_degrees(angle))


@_both("num Tan(num Angle)", "dnum TanDnum(dnum Angle)")
def _tan(kind: NumericKind):
    return lambda angle: kind.convert(tan_degrees(angle))


def _arc(inverse, name: str):
    """Factory for ASin/ACos: argument in [-1, 1], result in degrees."""
    def make(kind: NumericKind):
        def arc(value: float) -> float:
            _domain(-1 <= value <= 1, f"{name} of {value} outside [-1, 1]")
            return kind.convert(math.degrees(inverse(value)))
        return arc
    return make


_both("num ASin(num Value)", "dnum ASinDnum(dnum Value)")(_arc(math.asin, "ASin"))
_both("num ACos(num Value)", "dnum ACosDnum(dnum Value)")(_arc(math.acos, "ACos"))


@_both("num ATan(num Value)", "dnum ATanDnum(dnum Value)")
def _atan(kind: NumericKind):
    return lambda value: kind.convert(math.degrees(math.atan(value)))


@_both("num ATan2(num Y, num X)", "dnum ATan2Dnum(dnum Y, dnum X)")
def _atan2(kind: NumericKind):
    return lambda y, x: kind.convert(math.degrees(math.atan2(y, x)))
