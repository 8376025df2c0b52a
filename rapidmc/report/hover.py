"""Hover text for the editor: what a name is, in Markdown.

A predefined routine shows its signature and how rapidmc models it, from the
registry that docs/predefined.md is generated from
(``semantics.library.documentation``), as do predefined data (``v100``) and
data types (``robtarget``); a name the program declares shows its
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
from ..semantics.library.data import PREDEFINED_DATA
from ..semantics.library.documentation import (HIDDEN_TYPES, components_text, signature_text,
                                               topic_summary)
from ..semantics.types import PREDEFINED_TYPES


def predefined_hover(word: str) -> Optional[str]:
    """What the predefined routines, data object or data type named ``word`` are: a
    routine's signature, kind, topic and modelling; a data object's declaration; a type's
    kind and components."""
    key = word.upper()
    texts = [_routine_text(entry) for entry in (lookup_procedure(key), lookup_function(key))
             if entry]
    data = PREDEFINED_DATA.get(key)
    if data is not None:
        texts.append(f"```rapid\n{data.storage} {data.type_name} {data.name}\n```\n"
                     "predefined data")
    rapid_type = PREDEFINED_TYPES.get(key)
    if rapid_type is not None and key not in HIDDEN_TYPES:
        components = components_text(rapid_type)
        texts.append(f"predefined data type **{rapid_type.name}** ({rapid_type.kind})"
                     + (f": {components}" if components else ""))
    return "\n\n---\n\n".join(texts) if texts else None


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
