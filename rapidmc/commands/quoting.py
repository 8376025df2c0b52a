"""User text shown inside a diagnostic message, on one line whatever it holds."""
from __future__ import annotations


def quoted(text: str) -> str:
    """``text`` in single quotes with control characters escaped.

    A diagnostic's first line must stay one line (``FILE:LINE:COL: error: ... [RMCnnn]``),
    so a newline or other control character the user typed is shown as its escape:
    ``quoted("a\\nb") == "'a\\\\nb'"``.
    """
    return "'" + "".join(c if c.isprintable() else repr(c)[1:-1] for c in text) + "'"
