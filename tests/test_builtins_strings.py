"""String, stringdig and conversion builtins, differentially against Python."""
from __future__ import annotations

import pytest
from hypothesis import given, strategies as st

from rapidmc.semantics.library import lookup_function
from rapidmc.semantics.library.data import PREDEFINED_DATA
from rapidmc.semantics.errors import RapidError

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def call(name, *args):
    return lookup_function(name.upper()).impl(*args)


def raises(name, *args):
    with pytest.raises(RapidError) as caught:
        call(*args)
    assert caught.value.name == name


def constant(name):
    return PREDEFINED_DATA[name.upper()].value


latin1 = st.text(st.characters(min_codepoint=32, max_codepoint=255), max_size=20)
small = st.text("abc", max_size=12)


@given(latin1, st.data())
def test_str_part_is_a_slice(text, data):
    start = data.draw(st.integers(1, len(text) + 1))
    length = data.draw(st.integers(0, len(text) - start + 1))
    assert call("StrPart", text, float(start), float(length)) == text[start - 1:start - 1 + length]
    assert call("StrLen", text) == len(text)


@pytest.mark.parametrize("start, length", [(0, 1), (2, 3), (5, 0), (1.5, 1)])
def test_str_part_outside_the_string(start, length):
    raises("ERR_ARGVALERR", "StrPart", "abc", float(start), float(length))


@given(small, small, st.data())
def test_str_find_and_match_against_python(text, other, data):
    start = data.draw(st.integers(1, len(text) + 1))
    hits = [i + 1 for i in range(start - 1, len(text)) if text[i] in other]
    misses = [i + 1 for i in range(start - 1, len(text)) if text[i] not in other]
    none = len(text) + 1
    assert call("StrFind", text, float(start), other, False) == (hits[0] if hits else none)
    assert call("StrFind", text, float(start), other, True) == (misses[0] if misses else none)
    found = text.find(other, start - 1)
    assert call("StrMatch", text, float(start), other) == (found + 1 if found >= 0 else none)


def test_str_memb():
    assert call("StrMemb", "Robot", 2.0, "aeiou") is True
    assert call("StrMemb", "Robot", 3.0, "aeiou") is False
    raises("ERR_ARGVALERR", "StrMemb", "Robot", 6.0, "aeiou")


@given(small, small)
def test_str_order_with_a_full_alphabet_is_python_order(a, b):
    assert call("StrOrder", a, b, "abc") == (a < b)
    assert call("StrOrder", a, b, "cba") == ([2 - "abc".index(c) for c in a]
                                             < [2 - "abc".index(c) for c in b])


def test_str_order_puts_unlisted_characters_last():
    assert call("StrOrder", "a", "z", "a") is True
    assert call("StrOrder", "z", "a", "a") is False
    assert call("StrOrder", "ab", "ab", "ab") is False
    assert call("StrOrder", "a", "ab", "ab") is True


@given(st.text(st.characters(min_codepoint=32, max_codepoint=126), max_size=30))
def test_str_map_with_case_tables_is_python_case_mapping_for_ascii(text):
    upper, lower = constant("STR_UPPER"), constant("STR_LOWER")
    assert call("StrMap", text, lower, upper) == text.upper()
    assert call("StrMap", text, upper, lower) == text.lower()


def test_case_tables_pair_latin1_letters():
    upper, lower = constant("STR_UPPER"), constant("STR_LOWER")
    assert len(upper) == len(lower) == 56
    assert [u.lower() for u in upper] == list(lower)


# --- stringdig -------------------------------------------------------------------------------

digits = st.integers(0, 4294967295)


@given(digits, digits)
def test_str_dig_cmp_and_calc_against_int(a, b):
    assert call("StrDigCmp", str(a), constant("LT"), str(b)) == (a < b)
    assert call("StrDigCmp", str(a), constant("GTEQ"), str(b)) == (a >= b)
    total = a + b
    if total <= 4294967295:
        assert call("StrDigCalc", str(a), constant("OpAdd"), str(b)) == str(total)
    else:
        raises("ERR_CALC_OVERFLOW", "StrDigCalc", str(a), constant("OpAdd"), str(b))
    if b:
        assert call("StrDigCalc", str(a), constant("OpMod"), str(b)) == str(a % b)


@pytest.mark.parametrize("a, op, b, error", [
    ("12a", "OpAdd", "1", "ERR_INT_NOTVAL"), ("", "OpAdd", "1", "ERR_INT_NOTVAL"),
    ("4294967296", "OpAdd", "0", "ERR_INT_MAXVAL"), ("1", "OpSub", "2", "ERR_CALC_NEG"),
    ("1", "OpDiv", "0", "ERR_CALC_DIVZERO"), ("65536", "OpMult", "65536", "ERR_CALC_OVERFLOW"),
])
def test_str_dig_calc_errors(a, op, b, error):
    raises(error, "StrDigCalc", a, constant(op), b)


# --- conversions ---------------------------------------------------------------------------------

NOTATIONS = [(False, False, False, False, "{:d}"), (True, False, False, False, "{:02X}"),
             (False, True, False, False, "{:03o}"), (False, False, True, False, "{:08b}")]


@given(st.integers(0, 255), st.sampled_from(NOTATIONS))
def test_byte_to_str_and_back(value, notation):
    *switches, pattern = notation
    text = call("ByteToStr", float(value), *switches)
    assert text == pattern.format(value)
    assert call("StrToByte", text, *switches) == value


def test_byte_char_notation_and_errors():
    assert call("ByteToStr", 65.0, False, False, False, True) == "A"
    assert call("StrToByte", "A", False, False, False, True) == 65
    raises("ERR_ARGVALERR", "StrToByte", "256", False, False, False, False)
    raises("ERR_ARGVALERR", "StrToByte", "G0", True, False, False, False)
    raises("ERR_ARGVALERR", "StrToByte", "AB", False, False, False, True)
    raises("ERR_ARGVALERR", "ByteToStr", 300.0, False, False, False, False)


@given(st.integers(0, 2 ** 63 - 1))
def test_dec_to_hex_and_back(value):
    assert call("DecToHex", str(value)) == f"{value:X}"
    assert call("HexToDec", f"{value:x}") == str(value)


@pytest.mark.parametrize("name, text", [("DecToHex", "9223372036854775808"), ("DecToHex", "-1"),
                                        ("HexToDec", "8000000000000000"), ("HexToDec", "xyz")])
def test_dec_hex_out_of_range(name, text):
    raises("ERR_ARGVALERR", name, text)


def test_dnum_num_conversions():
    assert call("NumToDnum", 0.5) == 0.5
    assert call("DnumToNum", 0.1, False) == pytest.approx(0.1, rel=1e-7)
    assert call("DnumToNum", 8388608.0, True) == 8388608.0
    raises("ERR_ARGVALERR", "DnumToNum", 8388609.0, True)
    raises("ERR_ARGVALERR", "DnumToNum", 0.5, True)
    raises("ERR_NUM_LIMIT", "DnumToNum", 1e39, False)


def test_num_to_str_builtin_uses_the_values_format():
    assert call("NumToStr", 0.38521, 2.0, True) == "3.85E-01"
    assert call("DnumToStr", 1 / 3, 3.0, False) == "0.333"
