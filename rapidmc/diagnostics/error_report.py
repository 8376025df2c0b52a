"""Every error at once: collect diagnostics, merge repeats, sort and cap the report.

Static checking and parsing go on after an error so that one run reports
all of them.  The report is ordered by file, line and column; an unknown
name appears once, at its first use, with the number of its uses and a
pointer to ``rapidmc stubs``; past ``MAX_REPORTED`` diagnostics a last one
counts the rest.

Example::

    >>> from rapidmc.diagnostics import Diagnostic, UNKNOWN_NAME
    >>> from rapidmc.ast import Span
    >>> found = [Diagnostic(UNKNOWN_NAME, "unknown name 'p'", Span("a.mod", line, 5),
    ...                     subject="P") for line in (9, 3)]
    >>> [(d.span.line, d.message) for d in report(found)]
    [(3, "unknown name 'p' (2 uses)")]
"""
from __future__ import annotations

import dataclasses
from typing import Iterable

from . import (MORE_ERRORS, UNKNOWN_NAME, UNKNOWN_ROUTINE, UNKNOWN_TYPE, Diagnostic,
                          UserError)

MAX_REPORTED = 50
UNKNOWN_CODES = (UNKNOWN_NAME, UNKNOWN_ROUTINE, UNKNOWN_TYPE)
STUBS_HINT = ("'rapidmc stubs FILES... -o Missing.mod' writes a module declaring every name "
              "the program uses and no module declares ('check --stubs' declares them in "
              "every task of a backup)")


def position(diagnostic: Diagnostic) -> tuple:
    """Sort key: diagnostics with a place first, by file, line and column."""
    span = diagnostic.span
    if span is None:
        return (1, "", 0, 0)
    return (0, span.file, span.line, span.column)


def merge_unknown_names(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """One diagnostic per unknown name (its first use), counting the uses."""
    ordered = sorted(diagnostics, key=position)
    uses: dict[tuple, int] = {}
    for diagnostic in ordered:
        if diagnostic.subject and diagnostic.code in UNKNOWN_CODES:
            key = (diagnostic.code.code, diagnostic.subject)
            uses[key] = uses.get(key, 0) + 1
    merged, seen = [], set()
    for diagnostic in ordered:
        if not (diagnostic.subject and diagnostic.code in UNKNOWN_CODES):
            merged.append(diagnostic)
            continue
        key = (diagnostic.code.code, diagnostic.subject)
        if key in seen:
            continue
        merged.append(_with_use_count(diagnostic, uses[key], hint=not seen))
        seen.add(key)
    return merged


def _with_use_count(diagnostic: Diagnostic, count: int, hint: bool) -> Diagnostic:
    """The first use's diagnostic, counting the uses; the first unknown name points to stubs."""
    message = diagnostic.message + (f" ({count} uses)" if count > 1 else "")
    notes = diagnostic.notes + (STUBS_HINT,) if hint else diagnostic.notes
    return dataclasses.replace(diagnostic, message=message, notes=notes)


def without_repeats(diagnostics: Iterable[Diagnostic]) -> list[Diagnostic]:
    """Drop exact repeats (one construct checked twice reports once)."""
    seen, kept = set(), []
    for diagnostic in diagnostics:
        key = (diagnostic.code.code, diagnostic.message, diagnostic.span)
        if key not in seen:
            seen.add(key)
            kept.append(diagnostic)
    return kept


def report(diagnostics: Iterable[Diagnostic], limit: int = MAX_REPORTED) -> list[Diagnostic]:
    """The diagnostics as shown: merged, sorted, at most ``limit`` plus a count of the rest."""
    merged = without_repeats(merge_unknown_names(diagnostics))
    if len(merged) <= limit:
        return merged
    rest = len(merged) - limit
    return merged[:limit] + [Diagnostic(MORE_ERRORS, f"{rest} more error{'s' * (rest != 1)} "
                                        f"not shown (the report stops after {limit})", omitted=rest)]


def omitted_count(diagnostics: Iterable[Diagnostic]) -> int:
    """How many errors a capped report leaves out (0 when it shows them all)."""
    return sum(d.omitted for d in diagnostics if d.code == MORE_ERRORS)


class ErrorCollector:
    """Gathers the diagnostics of the ``UserError``s raised while checking goes on."""

    def __init__(self) -> None:
        self.diagnostics: list[Diagnostic] = []

    def add(self, failure: UserError) -> None:
        self.diagnostics.extend(failure.diagnostics)

    def __bool__(self) -> bool:
        return bool(self.diagnostics)

    def raise_if_any(self) -> None:
        if self.diagnostics:
            raise UserError(report(self.diagnostics))
