"""Hover text for the editor: what a name is, in Markdown.

A predefined routine shows its signature and how rapidmc models it, from the
registry that docs/predefined.md is generated from
(``semantics.library.documentation``); a name the program declares shows its
declaration's source line and where it is.

Example::

    >>> print(predefined_hover("WaitTime"))
    ```rapid
    WaitTime(\\switch InPos, num Time)
    ```
    instruction (waits) · modelled: exact
    <BLANKLINE>
    Waiting: for a time, a signal or a condition.
"""
from __future__ import annotations

from typing import Optional

from ..diagnostics import SourceCache
from ..findings.declarations import Declaration
from ..semantics.library import lookup_function, lookup_procedure
from ..semantics.library.documentation import signature_text, topic_summary


def predefined_hover(word: str) -> Optional[str]:
    """Signature, kind, topic and modelling of the predefined routines named ``word``."""
    key = word.upper()
    entries = [entry for entry in (lookup_procedure(key), lookup_function(key)) if entry]
    if not entries:
        return None
    return "\n\n---\n\n".join(_routine_text(entry) for entry in entries)


def _routine_text(entry) -> str:
    kind = "function" if entry.signature.return_type else "instruction"
    topic = entry.topic.replace("_", " ")
    summary = topic_summary(entry.topic)
    lines = ["```rapid", signature_text(entry.signature), "```",
             f"{kind} ({topic}) · modelled: {entry.modelled}"]
    if summary:
        lines += ["", summary[0]]
    return "\n".join(lines)


def declaration_hover(declaration: Declaration) -> str:
    """The declaring source line and its place (file:line)."""
    span = declaration.name.span
    line = SourceCache.line(span.file, span.line) or declaration.name.text
    return "\n".join(["```rapid", line.strip(), "```",
                      f"{declaration.kind} declared at {span.file}:{span.line}"])
