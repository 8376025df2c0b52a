"""User text shown inside a diagnostic message, on one line whatever it holds."""
from __future__ import annotations

import re

IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


def one_line(text: str) -> str:
    """``text`` with control characters (newlines too) written as their escapes."""
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in text)


def quoted(text: str) -> str:
    """``text`` in single quotes with control characters escaped.

    A diagnostic's first line must stay one line (``FILE:LINE:COL: error: ... [RMCnnn]``),
    so a newline or other control character the user typed is shown as its escape:
    ``quoted("a\\nb") == "'a\\\\nb'"``.
    """
    return "'" + one_line(text) + "'"


def routine_name(text: str) -> str:
    """An option value that names a routine (argparse ``type``): a RAPID identifier."""
    if not IDENTIFIER.fullmatch(text):
        raise ValueError(text)          # argparse: "invalid routine_name value: '...'"
    return text
