"""Findings as CI gates see them: one rule, one place, one message, one severity each.

``lint`` findings and input errors are diagnostics; ``check`` findings are the properties
that are not HOLDS (VIOLATED, UNKNOWN) and the warnings beside the verdicts.  The Code
Quality report (``codeclimate``) and baselines (``baseline``) both need to know when two
findings are "the same" across runs: by rule (or property), the file of a diagnostic and what
the message says, never by line, so that an unrelated edit above a finding leaves it the same
finding.  Line references inside
a message ("the RETURN on line 8") are blanked for the same reason.
"""
from __future__ import annotations

import hashlib
import os
import re
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Optional, Sequence

from ..check.result import UNKNOWN, VIOLATED
from ..check.trace import Trace, TraceDescriber, TraceStep, build_trace
from ..diagnostics import Diagnostic
from .results import PropertyResult, described_formula

# Code Quality severities, lowest first (GitLab shows them in merge requests).
SEVERITIES = ("info", "minor", "major", "critical", "blocker")
DIAGNOSTIC_SEVERITY = {"note": "info", "warning": "minor", "error": "major"}

_LINE_REFERENCE = re.compile(r"\b(lines?) \d+(?:-\d+)?")
_FILE_POSITION = re.compile(r"(\.\w+):\d+(?::\d+)?")


@dataclass(frozen=True)
class Finding:
    """One thing a CI gate reports: ``rule`` is a diagnostic code or a property's name."""

    rule: str
    path: str                  # the file, relative to the working folder where it can be
    line: int
    message: str
    severity: str              # one of SEVERITIES
    # the file the finding belongs to: its own for a diagnostic, none ("") for a property,
    # which is about the whole program wherever its counterexample ends
    owner: str = ""
    end_line: int = 0          # the last line of a finding over several (0: ``line`` alone)
    # a finding given once per cause: its other places, (path, first line, last line) each
    places: tuple = ()

    def key(self) -> tuple[str, str, str]:
        """What makes two findings of two runs the same one (no line number)."""
        return self.rule, self.owner, without_positions(self.message)


def without_positions(message: str) -> str:
    """``message`` with its line numbers blanked: 'on line 8' -> 'on line N'."""
    return _FILE_POSITION.sub(r"\1:N", _LINE_REFERENCE.sub(r"\1 N", message))


def relative_path(file: str) -> str:
    """``file`` relative to the working folder (as CI tools root their paths), posix style."""
    try:
        relative = os.path.relpath(file)
    except ValueError:                  # another drive (Windows)
        relative = file
    return Path(file if relative.startswith("..") else relative).as_posix()


def from_diagnostics(diagnostics: Sequence[Diagnostic], default_path: str,
                     severity_of=DIAGNOSTIC_SEVERITY.get) -> list[Finding]:
    """A finding per diagnostic; one without a source position sits on ``default_path``:1."""
    found = []
    for diagnostic in diagnostics:
        span = diagnostic.span
        located = span is not None and span.line > 0
        path = relative_path(span.file if located else default_path)
        found.append(Finding(rule=diagnostic.code.code, path=path,
                             line=span.line if located else 1, message=diagnostic.message,
                             severity=severity_of(diagnostic.severity), owner=path,
                             end_line=_last_line(span) if located else 0,
                             places=tuple((relative_path(place.file), place.line,
                                           _last_line(place))
                                          for place in diagnostic.places if place.line > 0)))
    return found


def _last_line(span) -> int:
    """The last line of ``span`` when it covers several, else 0."""
    return span.end_line if span.end_line > span.line else 0


def from_results(results: Sequence[PropertyResult], describer: TraceDescriber,
                 warnings: Sequence[Diagnostic], default_path: str,
                 fail_on_vacuous: bool = False) -> list[tuple[Finding, object]]:
    """(finding, its source) for each property that is not HOLDS (and, with
    ``fail_on_vacuous``, each vacuous one), then for each warning beside the verdicts."""
    found: list[tuple[Finding, object]] = []
    for checked in results:
        finding = property_finding(checked, describer, default_path, fail_on_vacuous)
        if finding is not None:
            found.append((finding, checked))
    found.extend(zip(from_diagnostics(warnings, default_path), warnings))
    return found


def property_finding(checked: PropertyResult, describer: TraceDescriber, default_path: str,
                     fail_on_vacuous: bool = False) -> Optional[Finding]:
    """A VIOLATED property at the statement its counterexample points at, an UNKNOWN one (or
    a vacuous one, when that fails the check) at the program's first file; else None."""
    result = checked.result
    path, line = default_path, 1
    if result.verdict == VIOLATED:
        anchor = violation_anchor(build_trace(result, describer))
        if anchor is not None:
            path, line = anchor.transition.file, anchor.transition.line or 1
        message = f"{checked.name} is violated: {described_formula(checked)}"
        severity = "critical"
    elif result.verdict == UNKNOWN:
        message = f"{checked.name} is UNKNOWN: no violation found, but the search was " \
                  f"bounded ({without_numbers(result.reason)})"
        severity = "major"
    elif fail_on_vacuous and checked.vacuous:
        message = f"{checked.name} holds vacuously: {checked.vacuous}"
        severity = "major"
    else:
        return None
    return Finding(checked.name, relative_path(path), line, message, severity)


def without_numbers(reason: Optional[str]) -> str:
    """A bound's reason without its figures ('state limit 1000 reached; 1,000 states' ->
    'state limit reached; states'): the figures move with every edit of the program."""
    text = re.sub(r"\s*\d[\d.,]*(?:\s*s\b)?", "", reason or "bounded")
    return re.sub(r"\s+", " ", text).strip()


def fingerprints(findings: Sequence[Finding]) -> list[str]:
    """A stable fingerprint per finding: its key and how many findings with the same key come
    before it in its file, so that two equal findings in one file differ."""
    seen: Counter = Counter()
    prints = [""] * len(findings)
    for index in sorted(range(len(findings)), key=lambda i: (findings[i].path, findings[i].line)):
        key = findings[index].key()
        text = "\0".join((*key, str(seen[key])))
        prints[index] = hashlib.sha256(text.encode("utf-8")).hexdigest()
        seen[key] += 1
    return prints


def violation_anchor(trace: Trace) -> Optional[TraceStep]:
    """The step a violation points at: the last located step before the loop (or the last
    one); None when no step has a source line."""
    located = [s for s in [*trace.prefix, *trace.cycle]
               if s.transition is not None and s.transition.file]
    if not located:
        return None
    before_loop = [s for s in located if trace.loop_start is None or s.index < trace.loop_start]
    return (before_loop or located)[-1]
