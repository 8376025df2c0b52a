"""Math, bit and numeric-instruction builtins, differentially against Python."""
from __future__ import annotations

import math
from decimal import ROUND_DOWN, ROUND_HALF_UP, Decimal

import pytest
from hypothesis import given, strategies as st

from rapidmc.semantics.library import lookup_function, lookup_procedure
from rapidmc.semantics.errors import RapidError
from rapidmc.semantics.values import to_num

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def call(name, *args):
    return lookup_function(name.upper()).impl(*args)


def run(name, *args, numeric="num"):
    return lookup_procedure(name.upper()).implementation(numeric)(*args)


def raises(name, fn, *args):
    with pytest.raises(RapidError) as caught:
        fn(*args)
    assert caught.value.name == name


angles = st.floats(min_value=-720, max_value=720, allow_nan=False)
units = st.floats(min_value=-1, max_value=1, allow_nan=False)
bytes_ = st.integers(0, 255)
words = st.integers(0, 2 ** 32 - 1)


# --- trigonometry in degrees ----------------------------------------------------------


@given(angles)
def test_sin_cos_are_degree_versions_of_math(angle):
    assert call("Sin", angle) == pytest.approx(to_num(math.sin(math.radians(angle))), abs=1e-6)
    assert call("CosDnum", angle) == pytest.approx(math.cos(math.radians(angle)), abs=1e-12)


@pytest.mark.parametrize("name, angle, value", [
    ("Sin", 180, 0.0), ("Sin", -90, -1.0), ("Cos", 90, 0.0), ("Cos", 540, -1.0), ("Tan", 180, 0.0),
    ("Sin", 30, 0.5), ("ATan2", 1, 180.0 - 45.0),
])
def test_exact_values_at_quadrants(name, angle, value):
    if name == "ATan2":
        assert call(name, 1.0, -1.0) == value
    else:
        assert call(name, float(angle)) == value


def test_tan_of_90_degrees_is_an_argument_error():
    raises("ERR_ARGVALERR", call, "Tan", 90.0)


@given(units)
def test_inverse_trig_in_degrees(value):
    assert call("ASinDnum", value) == pytest.approx(math.degrees(math.asin(value)))
    assert call("ACos", value) == to_num(math.degrees(math.acos(value)))
    assert -90 <= call("ATan", value * 1e6) <= 90


@pytest.mark.parametrize("name, value", [("ASin", 1.5), ("ACos", -1.01), ("Sqrt", -1.0),
                                         ("SqrtDnum", -4.0)])
def test_domain_errors(name, value):
    raises("ERR_ARGVALERR", call, name, value)


@pytest.mark.parametrize("base, exponent, error", [(-8.0, 1 / 3, "ERR_ARGVALERR"),
                                                   (0.0, 0.0, "ERR_ARGVALERR"),
                                                   (0.0, -1.0, "ERR_ARGVALERR"),
                                                   (10.0, 40.0, "ERR_NUM_LIMIT")])
def test_pow_errors(base, exponent, error):
    raises(error, call, "Pow", base, exponent)


def test_pow_exp_sqrt_abs_values():
    assert call("Pow", -2.0, 3.0) == -8.0
    assert call("PowDnum", 2.0, 0.5) == math.sqrt(2)
    assert call("Exp", 1.0) == to_num(math.e)
    raises("ERR_NUM_LIMIT", call, "Exp", 1000.0)
    assert call("Sqrt", 2.0) == to_num(math.sqrt(2))
    assert call("Abs", -3.5) == 3.5 and call("AbsDnum", -1e300) == 1e300


# --- Round / Trunc vs decimal -----------------------------------------------------------


@given(st.decimals(min_value=-999, max_value=999, places=3), st.integers(0, 3))
def test_round_and_trunc_match_decimal_on_the_written_number(value, places):
    x = to_num(float(value))        # at most 6 digits: float32 reads back as written
    quantum = Decimal(1).scaleb(-places)
    assert call("Round", x, float(places)) == to_num(float(value.quantize(quantum, ROUND_HALF_UP)))
    assert call("Trunc", x, float(places)) == to_num(float(value.quantize(quantum, ROUND_DOWN)))


def test_round_default_and_dec_limits():
    assert call("Round", to_num(0.38521), None) == 0.0
    assert call("Round", to_num(0.38521), 3.0) == to_num(0.385)
    assert call("RoundDnum", 1 / 3, 15.0) == 0.333333333333333
    raises("ERR_ARGVALERR", call, "Round", 1.0, 7.0)
    raises("ERR_ARGVALERR", call, "TruncDnum", 1.0, 16.0)


# --- bits vs Python ints -------------------------------------------------------------------


@given(bytes_, bytes_)
def test_byte_bit_operations(a, b):
    assert call("BitAnd", float(a), float(b)) == a & b
    assert call("BitOr", float(a), float(b)) == a | b
    assert call("BitXOr", float(a), float(b)) == a ^ b
    assert call("BitNeg", float(a)) == 255 - a


@given(bytes_, st.integers(1, 8))
def test_byte_shifts_and_checks(a, steps):
    assert call("BitLSh", float(a), float(steps)) == (a << steps) & 0xFF
    assert call("BitRSh", float(a), float(steps)) == a >> steps
    assert call("BitCheck", float(a), float(steps)) == bool(a & (1 << (steps - 1)))
    assert run("BitSet", float(a), float(steps)) == {"BitData": a | (1 << (steps - 1))}
    assert run("BitClear", float(a), float(steps)) == {"BitData": a & ~(1 << (steps - 1))}


@given(words, words, st.integers(1, 32))
def test_dnum_bit_operations(a, b, steps):
    assert call("BitAndDnum", float(a), float(b)) == a & b
    assert call("BitNegDnum", float(a)) == 0xFFFFFFFF ^ a
    assert call("BitLShDnum", float(a), float(steps)) == (a << steps) & 0xFFFFFFFF
    assert call("BitCheckDnum", float(a), float(steps)) == bool(a >> (steps - 1) & 1)
    assert run("BitSet", float(a), float(steps), numeric="dnum") == {"BitData": a | 1 << (steps - 1)}


@pytest.mark.parametrize("name, args", [("BitAnd", (256.0, 1.0)), ("BitNeg", (-1.0,)),
                                        ("BitAnd", (1.5, 1.0)), ("BitLSh", (1.0, 9.0)),
                                        ("BitCheck", (1.0, 0.0)), ("BitCheckDnum", (1.0, 33.0)),
                                        ("BitOrDnum", (2.0 ** 32, 0.0))])
def test_bit_arguments_out_of_range(name, args):
    raises("ERR_ARGVALERR", call, name, *args)


# --- Add, Incr, Decr, Clear, TryInt ----------------------------------------------------------


def test_numeric_instructions():
    assert run("Add", 1.0, 0.1) == {"Name": to_num(1.1)}
    assert run("Add", 1.0, 0.1, numeric="dnum") == {"Name": 1.1}
    assert run("Decr", 0.0) == {"Name": -1.0}
    assert run("Clear", 42.0) == {"Name": 0.0}
    raises("ERR_NUM_LIMIT", run, "Add", 3e38, 3e38)


@pytest.mark.parametrize("value, numeric, error", [
    (5.0, "num", None), (5.5, "num", "ERR_INT_NOTVAL"), (16777216.0, "num", "ERR_INT_MAXVAL"),
    (16777216.0, "dnum", None), (2.0 ** 53, "dnum", "ERR_INT_MAXVAL"), (-8388608.0, "num", None),
])
def test_try_int(value, numeric, error):
    impl = lookup_procedure("TRYINT").implementation(numeric)
    if error is None:
        assert impl(value) is None
    else:
        raises(error, impl, value)
