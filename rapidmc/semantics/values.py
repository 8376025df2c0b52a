"""RAPID values in Python: num/dnum arithmetic and the controller's text formats.

``num`` is a Python float that always holds an IEEE single-precision value
(``to_num`` rounds), ``dnum`` a Python float (double).  Neither holds -0.0:
the conversions and negation turn it into 0.0, so that a value stored in a
state (where -0.0 and 0.0 are one value) reads back as it was computed.  Arithmetic helpers
here apply RAPID's rules (ERR_DIVZERO, ERR_NOTINTVAL, ERR_STRTOOLNG,
ERR_NUM_LIMIT); formatting helpers produce the text of ``ValToStr``,
``TPWrite \\Num`` and ``NumToStr``.  Every decision not fixed by ABB's
manuals is written down, with its evidence, in docs/semantics.md
("Numbers, rounding and formatting").

Example::

    >>> to_num(0.1)
    0.10000000149011612
    >>> format_num(to_num(1.234567))
    '1.23457'
    >>> int_div(-7.0, 2.0), int_mod(-7.0, 2.0)
    (-3.0, -1.0)
"""
from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from decimal import ROUND_DOWN, ROUND_HALF_UP, Context, Decimal
from typing import Callable

from .errors import RapidError

STRING_MAX = 80                       # characters in a RAPID string value
NUM_EXACT_INTEGER = 8388608           # 2**23: integers up to this are exact in num
DNUM_EXACT_INTEGER = 4503599627370496  # 2**52: the same for dnum
NUM_SIGNIFICANT = 6                   # digits ValToStr / TPWrite show for num
DNUM_SIGNIFICANT = 15                 # ... and for dnum
NUM_MAX_DECIMALS = 6                  # largest Dec of Round/Trunc/NumToStr
DNUM_MAX_DECIMALS = 15                # ... of RoundDnum/TruncDnum/DnumToStr

_FLOAT32 = struct.Struct("f")
_pack, _unpack = _FLOAT32.pack, _FLOAT32.unpack
_INFINITY = math.inf
# Wide enough for every double written out in full plus 15 decimals.
_DECIMAL_CONTEXT = Context(prec=400)


# --------------------------------------------------------------------------
# Conversion to num and dnum
# --------------------------------------------------------------------------


def to_num(x: float | int) -> float:
    """``x`` rounded to the nearest IEEE single-precision value.

    Exact small integers skip the conversion (the interpreter's hot path).
    A result outside the float32 range, or a NaN, raises ERR_NUM_LIMIT.
    """
    if type(x) is float and x.is_integer() and -NUM_EXACT_INTEGER <= x <= NUM_EXACT_INTEGER:
        return x + 0.0              # exact in single precision; + 0.0 turns -0.0 into 0.0
    if type(x) is int and -NUM_EXACT_INTEGER <= x <= NUM_EXACT_INTEGER:
        return float(x)
    try:
        result = _unpack(_pack(x))[0]
    except OverflowError:           # ints beyond the double range
        raise RapidError("ERR_NUM_LIMIT", f"{x} is outside the range of num") from None
    if result == _INFINITY or result == -_INFINITY or result != result:
        raise RapidError("ERR_NUM_LIMIT", f"{x} is outside the range of num")
    return result + 0.0


def signal_value(kind: str, value: float) -> float:
    """A value given for a signal of ``kind`` (an input domain, ``--io``) as the signal holds
    it: analog values are nums (single precision, as AInput returns them), others as given."""
    if kind in ("AI", "AO"):
        try:
            return to_num(float(value))
        except RapidError:
            return float(value)          # (beyond num: reported where it is read)
    return float(value)


def to_dnum(x: float | int) -> float:
    """``x`` as a dnum (double); infinities and NaN raise ERR_NUM_LIMIT."""
    try:
        result = float(x)
    except OverflowError:
        raise RapidError("ERR_NUM_LIMIT", f"{x} is outside the range of dnum") from None
    if result == _INFINITY or result == -_INFINITY or result != result:
        raise RapidError("ERR_NUM_LIMIT", f"{x} is outside the range of dnum")
    return result + 0.0


def is_integer(x: float) -> bool:
    """True if ``x`` has no fractional part (and is finite)."""
    return x == x and x not in (_INFINITY, -_INFINITY) and x == int(x)


@dataclass(frozen=True)
class NumericKind:
    """What distinguishes num from dnum for a routine that accepts both."""

    name: str                       # "num" or "dnum"
    convert: Callable[[float], float]   # to_num or to_dnum
    exact_integer: int              # largest integer held exactly
    max_decimals: int               # largest Dec of Round/Trunc/...ToStr
    single: bool                    # True for float32


NUM = NumericKind("num", to_num, NUM_EXACT_INTEGER, NUM_MAX_DECIMALS, True)
DNUM = NumericKind("dnum", to_dnum, DNUM_EXACT_INTEGER, DNUM_MAX_DECIMALS, False)


# --------------------------------------------------------------------------
# Arithmetic with RAPID's error rules (results are NOT rounded to num here;
# the caller applies to_num or to_dnum according to the operand type)
# --------------------------------------------------------------------------


def divide(a: float, b: float) -> float:
    """``a / b``; division by zero raises ERR_DIVZERO."""
    if b == 0:
        raise RapidError("ERR_DIVZERO", "division by zero")
    return a / b


def _integer_operands(a: float, b: float, operator: str) -> tuple[int, int]:
    if not (is_integer(a) and is_integer(b)):
        raise RapidError("ERR_NOTINTVAL", f"{operator} needs integer operands")
    if b == 0:
        raise RapidError("ERR_DIVZERO", f"{operator} by zero")
    return int(a), int(b)


def int_div(a: float, b: float) -> float:
    """``a DIV b``: integer quotient truncated toward zero (``-7 DIV 2 = -3``)."""
    if type(a) is float and type(b) is float and a.is_integer() and b.is_integer() and b:
        dividend, divisor = int(a), int(b)      # the common case, checked as below
    else:
        dividend, divisor = _integer_operands(a, b, "DIV")
    quotient = abs(dividend) // abs(divisor)
    return float(quotient if (dividend < 0) == (divisor < 0) else -quotient)


def int_mod(a: float, b: float) -> float:
    """``a MOD b``: remainder with the dividend's sign (``-7 MOD 2 = -1``)."""
    if type(a) is float and type(b) is float and a.is_integer() and b.is_integer() and b:
        dividend, divisor = int(a), int(b)      # the common case, checked as below
    else:
        dividend, divisor = _integer_operands(a, b, "MOD")
    remainder = abs(dividend) % abs(divisor)
    return float(remainder if dividend >= 0 else -remainder)


def checked_string(text: str) -> str:
    """``text`` if it fits a RAPID string (80 characters), else ERR_STRTOOLNG."""
    if len(text) > STRING_MAX:
        raise RapidError("ERR_STRTOOLNG", f"string of {len(text)} characters (max {STRING_MAX})")
    return text


def concat(a: str, b: str) -> str:
    """String ``+``; a result longer than 80 characters raises ERR_STRTOOLNG."""
    return checked_string(a + b)


def values_equal(a: object, b: object) -> bool:
    """RAPID ``=``: exact, component-wise for records (tuples)."""
    return a == b


# --------------------------------------------------------------------------
# Decimal rounding (Round, Trunc, NumToStr)
# --------------------------------------------------------------------------


def shortest_decimal(x: float, single: bool) -> Decimal:
    """The shortest decimal that reads back as ``x`` (in float32 when ``single``).

    Rounding works on this decimal, i.e. on the number as the programmer
    wrote it: Trunc(0.7 \\Dec:=1) is 0.7 although float32(0.7) < 0.7.
    """
    if not single:
        return Decimal(repr(x))
    for digits in range(NUM_SIGNIFICANT, 10):
        text = f"{x:.{digits}g}"
        if _unpack(_pack(float(text)))[0] == x:
            return Decimal(text)
    return Decimal(x)  # unreachable: 9 digits always round-trip a float32


def round_decimal(x: float, decimals: int, single: bool, truncate: bool = False) -> float:
    """``x`` rounded (ties away from zero) or truncated to ``decimals`` places.

    The result is a double; callers convert it with ``to_num``/``to_dnum``.
    """
    if x != x or x in (_INFINITY, -_INFINITY):
        return x
    mode = ROUND_DOWN if truncate else ROUND_HALF_UP
    quantum = Decimal(1).scaleb(-decimals)
    result = float(shortest_decimal(x, single).quantize(quantum, mode, _DECIMAL_CONTEXT))
    return result + 0.0 if result else 0.0   # never return -0.0


# --------------------------------------------------------------------------
# Text formats
# --------------------------------------------------------------------------


def _general(x: float, significant: int) -> str:
    """C's ``%.<n>G``: integers without decimals, exponent as ``E+07``."""
    if x == 0:
        return "0"
    return f"{x:.{significant}G}"


def format_num(x: float) -> str:
    """A num as ValToStr and TPWrite \\Num print it.

    Integers in num's exact range (|x| <= 8388608) print in full; anything
    else with six significant digits.

    >>> format_num(5.0), format_num(to_num(0.1)), format_num(3628800.0), format_num(1e7)
    ('5', '0.1', '3628800', '1E+07')
    """
    if -NUM_EXACT_INTEGER <= x <= NUM_EXACT_INTEGER and x == int(x):
        return str(int(x))
    return _general(x, NUM_SIGNIFICANT)


def format_dnum(x: float) -> str:
    """A dnum as ValToStr and TPWrite \\Dnum print it: fifteen significant digits."""
    return _general(x, DNUM_SIGNIFICANT)


def quote_string(text: str) -> str:
    """``text`` as a RAPID string literal: ``"`` doubled, ``\\`` doubled,
    characters outside printable Latin-1 as ``\\hh``."""
    out = ['"']
    for ch in text:
        code = ord(ch)
        if ch == '"':
            out.append('""')
        elif ch == "\\":
            out.append("\\\\")
        elif code < 32 or 127 <= code < 160 or code > 255:
            out.append(f"\\{code & 0xFF:02X}")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


def format_value(value: object, kind: object = "num") -> str:
    """A value in RAPID literal/aggregate syntax, as ValToStr writes it.

    ``kind`` says how floats print: ``"dnum"`` with 15 significant digits,
    any other name with 6.  For records and arrays ``kind`` may be a tuple
    of kinds, one per component (nested like the value), or one name
    applied to every element.  The result is not length-checked; ValToStr
    passes it through ``checked_string``.

    >>> format_value(((1.0, 2.5, 3.0), (1.0, 0.0, 0.0, 0.0)))
    '[[1,2.5,3],[1,0,0,0]]'
    """
    if value is True:
        return "TRUE"
    if value is False:
        return "FALSE"
    if isinstance(value, str):
        return quote_string(value)
    if isinstance(value, tuple):
        if isinstance(kind, tuple):
            parts = (format_value(v, k) for v, k in zip(value, kind))
        else:
            parts = (format_value(v, kind) for v in value)
        return "[" + ",".join(parts) + "]"
    if kind == "dnum":
        return format_dnum(float(value))  # type: ignore[arg-type]
    return format_num(float(value))  # type: ignore[arg-type]


def decimals_argument(decimals: float, limit: int) -> int:
    if not is_integer(decimals) or not 0 <= decimals <= limit:
        raise RapidError("ERR_ARGVALERR", f"Dec must be an integer 0..{limit}, not {decimals}")
    return int(decimals)


def _fixed(x: float, decimals: int, single: bool) -> str:
    quantum = Decimal(1).scaleb(-decimals)
    rounded = shortest_decimal(x, single).quantize(quantum, ROUND_HALF_UP, _DECIMAL_CONTEXT)
    text = f"{rounded:f}"
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _scientific(x: float, decimals: int, single: bool) -> str:
    """``d.ddE+xx`` with ``decimals`` mantissa decimals, ties away from zero."""
    value = shortest_decimal(x, single)
    quantum = Decimal(1).scaleb(-decimals)
    exponent = value.adjusted() if value else 0
    mantissa = value.scaleb(-exponent).quantize(quantum, ROUND_HALF_UP, _DECIMAL_CONTEXT)
    if abs(mantissa) >= 10:          # 9.99 -> 10.0: renormalise
        exponent += 1
        mantissa = value.scaleb(-exponent).quantize(quantum, ROUND_HALF_UP, _DECIMAL_CONTEXT)
    sign = "-" if exponent < 0 else "+"
    return f"{mantissa:f}E{sign}{abs(exponent):02d}"


def num_to_str(x: float, decimals: float, exp: bool = False) -> str:
    """NumToStr: ``x`` rounded to ``decimals`` places (0..6), trailing zeros dropped;
    with ``exp`` scientific form with exactly ``decimals`` mantissa decimals.

    >>> num_to_str(to_num(0.38521), 3), num_to_str(to_num(0.38521), 2, exp=True)
    ('0.385', '3.85E-01')
    """
    places = decimals_argument(decimals, NUM_MAX_DECIMALS)
    text = _scientific(x, places, True) if exp else _fixed(x, places, True)
    return checked_string(text)


def dnum_to_str(x: float, decimals: float, exp: bool = False) -> str:
    """DnumToStr: as ``num_to_str`` for a dnum, 0..15 decimals."""
    places = decimals_argument(decimals, DNUM_MAX_DECIMALS)
    text = _scientific(x, places, False) if exp else _fixed(x, places, False)
    return checked_string(text)
