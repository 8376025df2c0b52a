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

try:                                    # the compiled LALR loop (``accelerated``), if installed
    from lark_cython.lark_cython import Token as CompiledToken
except ImportError:                     # pragma: no cover - lark_cython is a dependency
    CompiledToken = None

# The classes a token on the parser's value stack can be: Lark's, and lark_cython's
# (which is not a ``str``: its text is ``.value``, as for Lark's).
TOKEN_TYPES: tuple[type, ...] = (Token,) if CompiledToken is None else (Token, CompiledToken)

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
