"""ABB configuration files (SYSPAR/*.cfg): instances of a type, each a list of attributes.

A file such as EIO.cfg or SYS.cfg holds sections (``EIO_SIGNAL:``,
``CAB_TASKS:``), each a list of instances, one per logical line (a line
ending in a backslash goes on on the next)::

      -Name "T_ROB1" -Type "NORMAL" -MotionTask

An attribute is ``-Name value`` (the value quoted or not) or a bare flag
(``-MotionTask``, read as the empty string).
"""
from __future__ import annotations

import re
from typing import Iterator

# -Name "T_ROB1", -Type SEMISTATIC, -Default -1, or a flag such as -MotionTask
_ATTRIBUTE = re.compile(r'-(\w+)(?:\s+(?:"([^"]*)"|(?!-[A-Za-z])([^\s"]\S*)))?')


def instances(text: str, sections: tuple[str, ...]) -> Iterator[tuple[int, dict[str, str]]]:
    """(first line number, attributes by upper-case name) of each instance in ``sections``."""
    section = ""
    for number, line in logical_lines(text):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if re.fullmatch(r"[A-Z_]+:", stripped):
            section = stripped[:-1]
            continue
        if section in sections:
            yield number, {m.group(1).upper(): m.group(2) if m.group(2) is not None
                           else (m.group(3) or "") for m in _ATTRIBUTE.finditer(stripped)}


def logical_lines(text: str) -> Iterator[tuple[int, str]]:
    """(first line number, text) with backslash-continued lines joined."""
    pending, start = "", 0
    for number, line in enumerate(text.splitlines(), start=1):
        if not pending:
            start = number
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        yield start, pending + line
        pending = ""
    if pending:
        yield start, pending
