"""Readable names for the grammar's terminals, used in syntax error messages.

Lark names terminals ``_IF``, ``SEMICOLON`` or ``NAME``; users should read
``IF``, ``';'`` and ``identifier``.

Example::

    >>> describe_expected({"SEMICOLON", "_ENDIF", "NAME"})
    "';', ENDIF, identifier"
"""
from __future__ import annotations

from typing import Iterable

from lark import Token

# Terminals whose Lark name says nothing to a RAPID programmer.
TERMINAL_NAMES = {
    "NAME": "identifier", "NUMBER": "number", "STRING": "string",
    "PLACEHOLDER": "placeholder", "RELATION": "relational operator",
    "$END": "end of file",
    "SEMICOLON": "';'", "COMMA": "','", "COLON": "':'", "DOT": "'.'",
    "LPAR": "'('", "RPAR": "')'", "LBRACE": "'{'", "RBRACE": "'}'",
    "LSQB": "'['", "RSQB": "']'", "PERCENT": "'%'", "VBAR": "'|'",
    "QMARK": "'?'", "PLUS": "'+'", "MINUS": "'-'", "STAR": "'*'",
    "SLASH": "'/'", "BACKSLASH": "'\\'", "_ASSIGN": "':='",
}


def describe_terminal(name: str) -> str:
    """The readable form of one terminal name: ``_ENDIF`` -> ``ENDIF``."""
    if name in TERMINAL_NAMES:
        return TERMINAL_NAMES[name]
    return name.lstrip("_")


def describe_expected(names: Iterable[str]) -> str:
    """A sorted, de-duplicated list of readable terminal names."""
    readable = sorted({describe_terminal(name) for name in names}, key=_punctuation_first)
    return ", ".join(readable)


def _punctuation_first(text: str) -> tuple[bool, str]:
    return (text[0].isalpha(), text)


def describe_token(token: Token) -> str:
    """How to show the token the parser did not expect: its text, quoted."""
    if token.type == "$END":
        return "end of file"
    text = str(token)
    if len(text) > 30:
        text = text[:27] + "..."
    return repr(text) if "'" in text else f"'{text}'"
