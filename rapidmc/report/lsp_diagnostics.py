"""Diagnostics as the Language Server Protocol carries them (``textDocument/publishDiagnostics``).

A rapidmc ``Span`` counts lines and columns from 1; an LSP ``Range`` counts
both from 0 and ends after the last character.  A span without an end
covers the word (or the one character) at its start.  Characters count as
UTF-16 code units in LSP; RAPID text is Latin-1, where both counts agree.

The values are plain JSON data, so this module needs no LSP library (the
server structures them into its own types).

Example::

    >>> from rapidmc.ast import Span
    >>> from rapidmc.diagnostics import Diagnostic, SYNTAX
    >>> found = Diagnostic(SYNTAX, "unexpected ';'", Span("a.mod", 3, 8, 3, 9))
    >>> lsp_diagnostic(found, ["", "", "  x := ;"])["range"]
    {'start': {'line': 2, 'character': 7}, 'end': {'line': 2, 'character': 8}}
"""
from __future__ import annotations

import re
from typing import Callable, Optional, Sequence

from ..ast import Span
from ..diagnostics import Diagnostic, SourceCache, places_text

ERROR, WARNING, INFORMATION, HINT = 1, 2, 3, 4
SEVERITIES = {"error": ERROR, "warning": WARNING, "note": INFORMATION, "info": INFORMATION,
              "hint": HINT}
SOURCE = "rapidmc"
_WORD = re.compile(r"[A-Za-z0-9_]+")
_LINE_BREAK = re.compile(r"\r?\n")


def document_lines(text: str) -> list[str]:
    """The lines as the parser counts them, ended by LF or CR LF (``str.splitlines`` also
    breaks at form feeds and Latin-1's NEL, which RAPID text may hold)."""
    return _LINE_BREAK.split(text)


def position(line: int, character: int) -> dict:
    return {"line": max(line, 0), "character": max(character, 0)}


def lsp_range(span: Optional[Span], lines: Sequence[str]) -> dict:
    """The range a span covers; no span (or line 0): the start of the document."""
    if span is None or span.line <= 0:
        return {"start": position(0, 0), "end": position(0, 0)}
    start = position(span.line - 1, span.column - 1)
    if span.end_line > span.line or (span.end_line == span.line and
                                     span.end_column > span.column):
        return {"start": start, "end": position(span.end_line - 1, span.end_column - 1)}
    text = lines[span.line - 1] if span.line <= len(lines) else ""
    word = _WORD.match(text, span.column - 1)
    width = word.end() - word.start() if word else 1
    return {"start": start, "end": position(span.line - 1, span.column - 1 + width)}


def lsp_diagnostic(diagnostic: Diagnostic, lines: Sequence[str],
                   uri_of: Optional[Callable[[str], str]] = None) -> dict:
    """One LSP ``Diagnostic``: range, severity, code, source and message (notes appended).

    A diagnostic that carries a flow (a lint finding's path from an input to where it is
    used: ``(span, what happens there)`` steps) gives each step as related information,
    with ``uri_of(file)`` as its document; so does each other place of a finding given once
    per cause (``findings.grouping``)."""
    places = getattr(diagnostic, "places", ())
    notes = diagnostic.notes + ((places_text(places),) if places else ())
    message = "\n".join((diagnostic.message,) + tuple(f"note: {n}" for n in notes))
    found = {"range": lsp_range(diagnostic.span, lines),
             "severity": SEVERITIES.get(diagnostic.severity, ERROR),
             "code": diagnostic.code.code, "source": SOURCE, "message": message}
    related = [*getattr(diagnostic, "flow", ()),
               *((span, "the same finding") for span in places)]
    if related and uri_of is not None:
        found["relatedInformation"] = [
            {"location": {"uri": uri_of(span.file),
                          "range": lsp_range(span, SourceCache.lines(span.file) or ())},
             "message": what} for span, what in related]
    return found


def lsp_location(uri: str, span: Span, length: int) -> dict:
    """An LSP ``Location``: ``length`` characters from the span's start (a name)."""
    start = position(span.line - 1, span.column - 1)
    return {"uri": uri, "range": {"start": start,
                                  "end": position(span.line - 1, span.column - 1 + length)}}
