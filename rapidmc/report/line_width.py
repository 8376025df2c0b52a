"""Text reports keep every line within ``LONGEST_LINE`` characters, losing nothing.

A longer line (a value printed whole by ``--full-trace``, a deep file path, a long
formula) is broken into pieces: after a comma, a space or a ``/`` where one falls in
the second half of the width, else at the width; each further piece is indented four
spaces more than the line.

    >>> wrapped("  x = [" + "1," * 5 + "1]", 12)
    '  x = [1,1,\\n      1,1,1,\\n      1]'
"""
from __future__ import annotations

LONGEST_LINE = 300
BREAKS = ", /"                  # a line is broken after one of these where it can be
CONTINUED = "    "              # further pieces of a line are indented this much more


def wrapped(text: str, width: int = LONGEST_LINE) -> str:
    """``text`` with each line longer than ``width`` broken into pieces of at most ``width``."""
    return "\n".join(piece for line in text.split("\n") for piece in line_pieces(line, width))


def line_pieces(line: str, width: int = LONGEST_LINE) -> list[str]:
    """One line as pieces of at most ``width`` characters (the line itself when it fits)."""
    if len(line) <= width:
        return [line]
    indent = line[:len(line) - len(line.lstrip(" "))] + CONTINUED
    if len(indent) > width // 2:               # a deeply indented line: no more indent
        indent = CONTINUED
    pieces, rest, prefix = [], line, ""
    while len(prefix) + len(rest) > width:
        room = width - len(prefix)
        cut = max(rest.rfind(char, room // 2, room) for char in BREAKS) + 1
        if cut <= 0:
            cut = room
        pieces.append(prefix + rest[:cut])       # a space it ends with stays: nothing lost
        rest, prefix = rest[cut:], indent
    pieces.append(prefix + rest)
    return pieces
