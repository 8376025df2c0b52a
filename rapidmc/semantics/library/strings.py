"""String functions: StrLen, StrPart, StrFind, StrMatch, StrMemb, StrOrder, StrMap, StrFormat.

Character positions are 1-based.  A position or length that leaves the
string raises ERR_ARGVALERR; "not found" is StrLen(Str)+1 as in the manual.
"""
from __future__ import annotations

from ..errors import RapidError
from ..values import is_integer
from .registry import function


def _position(value: float, low: int, high: int, what: str) -> int:
    """A 1-based index in low..high, else ERR_ARGVALERR."""
    if not is_integer(value) or not low <= value <= high:
        raise RapidError("ERR_ARGVALERR", f"{what} {value} outside {low}..{high}")
    return int(value)


@function("num StrLen(string Str)")
def str_len(text: str) -> float:
    return float(len(text))


@function("string StrPart(string Str, num ChPos, num Len)")
def str_part(text: str, position: float, length: float) -> str:
    start = _position(position, 1, len(text) + 1, "ChPos")
    count = _position(length, 0, len(text) - start + 1, "Len")
    return text[start - 1:start - 1 + count]


@function("num StrFind(string Str, num ChPos, string Set \\switch NotInSet)")
def str_find(text: str, position: float, charset: str, not_in_set: bool) -> float:
    start = _position(position, 1, len(text) + 1, "ChPos")
    for index in range(start - 1, len(text)):
        if (text[index] in charset) != not_in_set:
            return float(index + 1)
    return float(len(text) + 1)


@function("num StrMatch(string Str, num ChPos, string Pattern)")
def str_match(text: str, position: float, pattern: str) -> float:
    start = _position(position, 1, len(text) + 1, "ChPos")
    found = text.find(pattern, start - 1)
    return float(len(text) + 1 if found < 0 else found + 1)


@function("bool StrMemb(string Str, num ChPos, string Set)")
def str_memb(text: str, position: float, charset: str) -> bool:
    index = _position(position, 1, len(text), "ChPos")
    return text[index - 1] in charset


@function("bool StrOrder(string Str1, string Str2, string Order)")
def str_order(first: str, second: str, order: str) -> bool:
    """TRUE if Str1 sorts strictly before Str2 in the character order ``Order``.

    Characters missing from Order sort after all listed ones (among
    themselves by character code); a proper prefix sorts first.
    """
    rank = {}
    for index, ch in enumerate(order):
        rank.setdefault(ch, index)
    unlisted = len(order)

    def weight(ch: str) -> tuple[int, int]:
        return (rank.get(ch, unlisted), ord(ch))

    return [weight(c) for c in first] < [weight(c) for c in second]


@function("string StrMap(string Str, string FromMap, string ToMap)")
def str_map(text: str, from_map: str, to_map: str) -> str:
    """Replace each character found at position k of FromMap by ToMap's k-th.

    The first occurrence in FromMap counts; a FromMap position with no
    counterpart in ToMap raises ERR_ARGVALERR when used.
    """
    out = []
    for ch in text:
        index = from_map.find(ch)
        if index < 0:
            out.append(ch)
        elif index < len(to_map):
            out.append(to_map[index])
        else:
            raise RapidError("ERR_ARGVALERR", "ToMap is shorter than FromMap")
    return "".join(out)


# StrFormat (RobotWare 7): ``{n}`` in the format stands for the optional argument \\Argn.
# No manual text was found with the search tools; the form is that of a motion-program
# driver that runs on controllers (``StrFormat("motion_program_p{1}.bin"\\Arg1:=NumToStr(n,0))``).
# The number of arguments (ten) is an assumption; a placeholder whose argument is absent stays.
_FORMAT_ARGUMENTS = 10


@function("string StrFormat(string Format "
          + " ".join(f"\\string Arg{i}" for i in range(1, _FORMAT_ARGUMENTS + 1)) + ")")
def str_format(text: str, arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8, arg9, arg10) -> str:
    arguments = (arg1, arg2, arg3, arg4, arg5, arg6, arg7, arg8, arg9, arg10)
    for number, argument in enumerate(arguments, start=1):
        if argument is not None:
            text = text.replace("{%d}" % number, argument)
    return text
