"""One finding per cause: repeats of a rule's finding about one datum, routine or flow.

A rule that finds the same thing at many places (a PERS used unchecked as an index in
every line of a routine, one socket read reaching forty move targets) would bury the
rest of a report under copies.  Findings of one code and severity with the same cause
become one: the first place (in file and line order) carries it, the others are its
``places``, which every report shows (a note in text, related locations in SARIF and
the language server, a list in JSON).  The cause is the finding's ``subject`` where the
rule sets one (a flow: its source and the kind of use), else its message.

    >>> from rapidmc.ast import Span
    >>> from rapidmc.diagnostics import SHARED_INDEX, Diagnostic
    >>> found = [Diagnostic(SHARED_INDEX, "PERS 'n' ...", Span("m.mod", line, 5), "warning")
    ...          for line in (3, 9, 12)]
    >>> [(f.span.line, [p.line for p in f.places]) for f in one_per_cause(found)]
    [(3, [9, 12])]

May import: ``diagnostics``.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Iterable

from ..diagnostics import Diagnostic


def cause(finding: Diagnostic) -> tuple:
    """What makes two findings the same finding."""
    return finding.code.code, finding.severity, finding.subject or finding.message


def one_per_cause(findings: Iterable[Diagnostic]) -> list[Diagnostic]:
    """``findings`` (in report order) with each cause once, at its first place."""
    first: dict[tuple, Diagnostic] = {}
    others: dict[tuple, list] = {}
    for finding in findings:
        key = cause(finding)
        if key not in first:
            first[key] = finding
            others[key] = list(finding.places)
        elif finding.span is not None:
            others[key].append(finding.span)
            others[key].extend(finding.places)
    return [replace(finding, places=tuple(others[key])) if others[key] else finding
            for key, finding in first.items()]
