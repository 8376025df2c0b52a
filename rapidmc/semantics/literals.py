"""Reading RAPID literal text into values of a given type (StrToVal).

Accepts what ValToStr writes: numbers (with exponents), ``TRUE``/``FALSE``,
double-quoted strings with ``""`` and ``\\hh`` escapes, and aggregates
``[a,b,...]`` shaped like the target type.  Anything else gives None.
"""
from __future__ import annotations

import re
from typing import Optional

from . import values
from .types import BOOL, DNUM, RECORD, STRING, ArrayType, RapidType

_NUMBER = re.compile(r"\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)")


class _Reader:
    def __init__(self, text: str):
        self.text = text
        self.pos = 0

    def skip(self) -> None:
        while self.pos < len(self.text) and self.text[self.pos] in " \t":
            self.pos += 1

    def take(self, token: str) -> bool:
        self.skip()
        if self.text.startswith(token, self.pos):
            self.pos += len(token)
            return True
        return False

    def value(self, rapid_type):
        if isinstance(rapid_type, ArrayType):
            inner = ArrayType(rapid_type.element, rapid_type.dims[1:]) if rapid_type.rank > 1 \
                else rapid_type.element
            return self.aggregate([inner] * (rapid_type.dims[0] or 0))
        if rapid_type.kind == RECORD:
            return self.aggregate([c.type for c in rapid_type.components])
        if rapid_type is BOOL:
            if self.take("TRUE"):
                return True
            if self.take("FALSE"):
                return False
            raise ValueError
        if rapid_type is STRING:
            return self.string()
        match = _NUMBER.match(self.text, self.pos)
        if not match:
            raise ValueError
        self.pos = match.end()
        number = float(match.group(1))
        return values.to_dnum(number) if rapid_type is DNUM else values.to_num(number)

    def aggregate(self, item_types):
        if not self.take("["):
            raise ValueError
        items = []
        for i, item_type in enumerate(item_types):
            if i and not self.take(","):
                raise ValueError
            items.append(self.value(item_type))
        if not self.take("]"):
            raise ValueError
        return tuple(items)

    def string(self) -> str:
        if not self.take('"'):
            raise ValueError
        out = []
        text = self.text
        while self.pos < len(text):
            ch = text[self.pos]
            if ch == '"':
                if text.startswith('""', self.pos):
                    out.append('"')
                    self.pos += 2
                    continue
                self.pos += 1
                return "".join(out)
            if ch == "\\":
                if text.startswith("\\\\", self.pos):
                    out.append("\\")
                    self.pos += 2
                    continue
                code = text[self.pos + 1:self.pos + 3]
                out.append(chr(int(code, 16)))
                self.pos += 3
                continue
            out.append(ch)
            self.pos += 1
        raise ValueError


def parse_literal(text: str, rapid_type) -> Optional[object]:
    """The value ``text`` denotes as a ``rapid_type``, or None if it is not such a literal."""
    if rapid_type is None:
        return None
    reader = _Reader(text)
    try:
        value = reader.value(rapid_type)
        reader.skip()
        if reader.pos != len(text):
            return None
        return value
    except (ValueError, IndexError, OverflowError):
        return None
    except Exception:
        return None
