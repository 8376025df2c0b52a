"""Conversions: NumToStr, DnumToStr, NumToDnum, DnumToNum, StrToByte, ByteToStr,
DecToHex, HexToDec.

Malformed digit strings and values outside a conversion's range raise
ERR_ARGVALERR (the manuals name no error code for them).
"""
from __future__ import annotations

import re

from ..errors import RapidError
from ..values import NUM_EXACT_INTEGER, dnum_to_str, is_integer, num_to_str, to_num
from .registry import function

INT64_MAX = 9223372036854775807


@function("string NumToStr(num Val, num Dec \\switch Exp)")
def num_to_string(val: float, dec: float, exp: bool) -> str:
    return num_to_str(val, dec, exp)


@function("string DnumToStr(dnum Val, num Dec \\switch Exp)")
def dnum_to_string(val: float, dec: float, exp: bool) -> str:
    return dnum_to_str(val, dec, exp)


@function("dnum NumToDnum(num Value)")
def num_to_dnum(value: float) -> float:
    return value


@function("num DnumToNum(dnum Value \\switch Integer)")
def dnum_to_num(value: float, integer: bool) -> float:
    """Narrow to num; with \\Integer the value must be an exact num integer."""
    if integer and not (is_integer(value) and abs(value) <= NUM_EXACT_INTEGER):
        raise RapidError("ERR_ARGVALERR", f"{value} is not an integer within num's exact range")
    return to_num(value)


# --------------------------------------------------------------------------
# byte <-> string: (switch position, pattern, base, format) per notation
# --------------------------------------------------------------------------

_DECIMAL = (re.compile(r"[0-9]{1,3}"), 10, "{:d}")
_NOTATIONS = (
    (re.compile(r"[0-9A-Fa-f]{1,2}"), 16, "{:02X}"),   # \Hex
    (re.compile(r"[0-7]{1,3}"), 8, "{:03o}"),          # \Okt
    (re.compile(r"[01]{1,8}"), 2, "{:08b}"),           # \Bin
)


def _notation(hex_: bool, okt: bool, binary: bool):
    for chosen, notation in zip((hex_, okt, binary), _NOTATIONS):
        if chosen:
            return notation
    return _DECIMAL


@function("byte StrToByte(string ConStr \\switch Hex | switch Okt | switch Bin | switch Char)")
def str_to_byte(text: str, hex_: bool, okt: bool, binary: bool, char: bool) -> float:
    if char:
        if len(text) != 1:
            raise RapidError("ERR_ARGVALERR", "StrToByte \\Char needs exactly one character")
        return float(ord(text))
    pattern, base, _ = _notation(hex_, okt, binary)
    if not pattern.fullmatch(text) or int(text, base) > 255:
        raise RapidError("ERR_ARGVALERR", f"{text!r} is not a byte in base {base}")
    return float(int(text, base))


@function("string ByteToStr(byte BitData \\switch Hex | switch Okt | switch Bin | switch Char)")
def byte_to_str(data: float, hex_: bool, okt: bool, binary: bool, char: bool) -> str:
    if not is_integer(data) or not 0 <= data <= 255:
        raise RapidError("ERR_ARGVALERR", f"{data} is not a byte (0..255)")
    if char:
        return chr(int(data))
    return _notation(hex_, okt, binary)[2].format(int(data))


# --------------------------------------------------------------------------
# Decimal <-> hexadecimal digit strings (0 .. 2**63-1)
# --------------------------------------------------------------------------

_DECIMAL_DIGITS = re.compile(r"[0-9]+")
_HEX_DIGITS = re.compile(r"[0-9A-Fa-f]+")


def _digit_string(text: str, pattern: re.Pattern[str], base: int) -> int:
    if not pattern.fullmatch(text) or int(text, base) > INT64_MAX:
        raise RapidError("ERR_ARGVALERR", f"{text!r} is not a base-{base} number 0..{INT64_MAX}")
    return int(text, base)


@function("string DecToHex(string Str)")
def dec_to_hex(text: str) -> str:
    return f"{_digit_string(text, _DECIMAL_DIGITS, 10):X}"


@function("string HexToDec(string Str)")
def hex_to_dec(text: str) -> str:
    return str(_digit_string(text, _HEX_DIGITS, 16))
