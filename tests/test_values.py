"""num/dnum arithmetic and the text formats of rapidmc.semantics.values.

Each decided open question of docs/semantics.md ("Numbers, rounding and
formatting") is pinned by a row in one of the tables below.
"""
from __future__ import annotations

import math
import struct
from decimal import Decimal

import pytest
from hypothesis import given, strategies as st

from rapidmc.semantics.errors import RapidError
from rapidmc.semantics.values import (
    DNUM_EXACT_INTEGER, checked_string, concat, divide, dnum_to_str, format_dnum, format_num,
    format_value, int_div, int_mod, num_to_str, round_decimal, shortest_decimal, to_dnum, to_num,
)

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

FLOAT32_MAX = struct.unpack("f", struct.pack("I", 0x7F7FFFFF))[0]
finite_doubles = st.floats(allow_nan=False, allow_infinity=False)
num_values = st.floats(width=32, allow_nan=False, allow_infinity=False)
small_integers = st.integers(min_value=-100000, max_value=100000)


def raises(name, fn, *args):
    with pytest.raises(RapidError) as caught:
        fn(*args)
    assert caught.value.name == name


# --- to_num / to_dnum ---------------------------------------------------------------


@given(st.floats(min_value=-FLOAT32_MAX, max_value=FLOAT32_MAX))
def test_to_num_is_the_nearest_float32_and_idempotent(x):
    expected = struct.unpack("f", struct.pack("f", x))[0]
    assert to_num(x) == expected
    assert to_num(to_num(x)) == to_num(x)


@given(st.integers(min_value=-2**24, max_value=2**24))
def test_integers_up_to_2_pow_24_are_exact_in_num(n):
    assert to_num(n) == n and type(to_num(n)) is float


@pytest.mark.parametrize("x", [1e39, -1e39, 2 ** 200, math.inf, -math.inf, math.nan])
def test_values_beyond_float32_raise_num_limit(x):
    raises("ERR_NUM_LIMIT", to_num, x)


@pytest.mark.parametrize("x", [math.inf, math.nan, 10 ** 400])
def test_dnum_rejects_what_a_double_cannot_hold(x):
    raises("ERR_NUM_LIMIT", to_dnum, x)


@pytest.mark.parametrize("convert, x", [
    (to_num, -0.0), (to_dnum, -0.0),
    (to_num, 0.0 * -1),
    (to_num, -1e-50),       # underflows to -0.0 in single precision
])
def test_no_value_holds_negative_zero(convert, x):
    # a checked state holds -0.0 and 0.0 as one value, so no computed value may keep the sign
    assert math.copysign(1.0, convert(x)) == 1.0


def test_dnum_keeps_double_precision():
    assert to_dnum(0.1) == 0.1 and to_num(0.1) != 0.1


# --- division, DIV, MOD ---------------------------------------------------------------


@pytest.mark.parametrize("a, b, quotient, remainder", [
    (14, 4, 3, 2),          # the manual's example
    (-7, 2, -3, -1),        # truncation toward zero; remainder takes the dividend's sign
    (7, -2, -3, 1),
    (-7, -2, 3, -1),
    (0, 5, 0, 0),
])
def test_div_truncates_and_mod_follows_the_dividend(a, b, quotient, remainder):
    assert int_div(float(a), float(b)) == quotient
    assert int_mod(float(a), float(b)) == remainder


@given(small_integers, small_integers.filter(lambda b: b != 0))
def test_div_mod_identity(a, b):
    q, r = int_div(float(a), float(b)), int_mod(float(a), float(b))
    assert q * b + r == a
    assert abs(r) < abs(b)
    assert r == 0 or (r < 0) == (a < 0)


@pytest.mark.parametrize("fn", [int_div, int_mod])
def test_div_mod_by_zero_and_non_integers(fn):
    raises("ERR_DIVZERO", fn, 5.0, 0.0)
    raises("ERR_NOTINTVAL", fn, 5.5, 2.0)
    raises("ERR_NOTINTVAL", fn, 5.0, 0.5)


def test_divide_by_zero():
    raises("ERR_DIVZERO", divide, 1.0, 0.0)
    assert divide(1.0, 4.0) == 0.25


# --- strings --------------------------------------------------------------------------


def test_concatenation_is_limited_to_80_characters():
    assert concat("a" * 40, "b" * 40) == "a" * 40 + "b" * 40
    raises("ERR_STRTOOLNG", concat, "a" * 40, "b" * 41)
    raises("ERR_STRTOOLNG", checked_string, "x" * 81)


# --- rounding -------------------------------------------------------------------------


@pytest.mark.parametrize("x, places, rounded, truncated", [
    (0.38521, 3, 0.385, 0.385),     # manual examples
    (0.38521, 1, 0.4, 0.3),
    (0.38521, 0, 0.0, 0.0),
    (2.5, 0, 3.0, 2.0),             # ties away from zero
    (-2.5, 0, -3.0, -2.0),
    (0.385, 2, 0.39, 0.38),         # on the decimal the programmer wrote, not float32's 0.38499...
    (0.7, 1, 0.7, 0.7),             # float32(0.7) < 0.7, still truncates to 0.7
    (-0.04, 1, 0.0, 0.0),           # never -0
])
def test_round_and_trunc_of_num(x, places, rounded, truncated):
    value = to_num(x)
    assert round_decimal(value, places, single=True) == rounded
    assert round_decimal(value, places, single=True, truncate=True) == truncated
    assert math.copysign(1, round_decimal(value, places, single=True)) == math.copysign(1, rounded or 1)


@given(st.decimals(min_value=-10**6, max_value=10**6, places=4), st.integers(0, 3))
def test_dnum_rounding_matches_decimal_half_up(value, places):
    x = float(value)
    expected = Decimal(repr(x)).quantize(Decimal(1).scaleb(-places), rounding="ROUND_HALF_UP")
    assert round_decimal(x, places, single=False) == float(expected)


# --- formatting -----------------------------------------------------------------------


@pytest.mark.parametrize("x, text", [
    (1.234567, "1.23457"),          # the manual's ValToStr example
    (5, "5"),                       # integers without decimals
    (-0.0, "0"),
    (0.1, "0.1"),                   # float32 noise beyond 6 digits is not shown
    (123456, "123456"),
    (1234567, "1234567"),           # exact integers of num print in full
    (8388608, "8388608"),
    (1234567.5, "1.23457E+06"),     # more than 6 digits otherwise: exponent form
    (1e7, "1E+07"),                 # beyond num's exact integers
    (9e9, "9E+09"),                 # extjoint "not used"
    (0.0001, "0.0001"),
    (0.00001, "1E-05"),
])
def test_format_num_six_significant_digits(x, text):
    assert format_num(to_num(x)) == text


def test_format_dnum_fifteen_significant_digits():
    assert format_dnum(0.1) == "0.1"
    assert format_dnum(1 / 3) == "0.333333333333333"
    assert format_dnum(float(DNUM_EXACT_INTEGER)) == "4.5035996273705E+15"


@pytest.mark.parametrize("value, kind, text", [
    (True, "bool", "TRUE"),
    (False, "bool", "FALSE"),
    ("a\"b\\c\x07", "string", '"a""b\\\\c\\07"'),
    ((1817.3, 905.17, 879.11), "num", "[1817.3,905.17,879.11]"),
    (((1.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0)), "num", "[[1,0,0],[1,0,0,0]]"),
    ((True, "x", 1 / 3), ("bool", "string", "dnum"), '[TRUE,"x",0.333333333333333]'),
    ((1 / 3, 1 / 3), "num", "[0.333333,0.333333]"),
])
def test_format_value_uses_rapid_literal_syntax(value, kind, text):
    assert format_value(value, kind) == text


@pytest.mark.parametrize("x, dec, exp, text", [
    (0.38521, 3, False, "0.385"),   # manual examples
    (0.38521, 2, True, "3.85E-01"),
    (2, 2, False, "2"),             # trailing zeros dropped
    (1.5, 3, False, "1.5"),
    (-0.001, 2, False, "0"),
    (2.5, 0, False, "3"),           # ties away from zero
    (9.999, 2, True, "1.00E+01"),   # mantissa carries into the exponent
    (0, 1, True, "0.0E+00"),
    (-123.456, 1, True, "-1.2E+02"),
])
def test_num_to_str(x, dec, exp, text):
    assert num_to_str(to_num(x), dec, exp) == text


def test_num_to_str_decimals_must_be_0_to_6():
    raises("ERR_ARGVALERR", num_to_str, 1.0, 7)
    raises("ERR_ARGVALERR", num_to_str, 1.0, -1)
    raises("ERR_ARGVALERR", num_to_str, 1.0, 1.5)
    assert dnum_to_str(1 / 3, 10) == "0.3333333333"
    raises("ERR_ARGVALERR", dnum_to_str, 1.0, 16)


def test_num_to_str_of_a_huge_value_is_too_long():
    raises("ERR_STRTOOLNG", dnum_to_str, 1e300, 0)


@given(num_values.filter(lambda x: abs(x) < 1e6), st.integers(0, 6))
def test_num_to_str_reads_back_within_half_a_unit_of_the_written_number(x, dec):
    text = num_to_str(x, dec)
    written = shortest_decimal(x, single=True)
    assert abs(Decimal(text) - written) <= Decimal(5).scaleb(-dec - 1)
    assert to_num(float(written)) == x


@pytest.mark.parametrize("x", [1e30, -3e38, 1e300])
def test_rounding_works_for_large_magnitudes(x):
    single = abs(x) < 1e39
    value = to_num(x) if single else x
    convert = to_num if single else to_dnum
    assert convert(round_decimal(value, 6 if single else 15, single)) == value
