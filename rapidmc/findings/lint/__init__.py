"""``rapidmc lint``: mistakes visible without a search, and unchecked input flows.

Each rule is a registered object (``registry.Rule``: code RMC801-RMC840, severity,
summary, a bad and a good example) in one module per rule or small family; they
read the program's syntax tree through a ``LintContext`` built once per program
(``context``).  ``flows`` follows data read from sockets, files, serial channels,
the FlexPendant and analog or group inputs to the arguments where unchecked input
does harm (RMC820).  ``config`` chooses the rules and reads suppression comments;
docs/lint.md is generated from the registry (``documentation``).

One entry point, used by ``rapidmc lint`` and the language server::

    >>> from rapidmc.syntax import parse_text
    >>> program = ast.Program(parse_text(
    ...     "MODULE M\\nPROC main()\\nVAR bool b;\\nb := TRUE AND NOT b AND b;\\nENDPROC\\nENDMODULE",
    ...     "m.mod"))
    >>> [(d.code.code, d.span.line) for d in lint_program(program)]
    [('RMC801', 4)]

May import: everything below ``findings`` (``ast``, ``diagnostics``, ``syntax``,
``semantics``, ``load``).
"""
from __future__ import annotations

import contextlib
import gc
from typing import Optional

from ... import ast
from ...diagnostics import Diagnostic
from ..grouping import one_per_cause
from . import (blocking, call_rules, flexpendant, flows, precedence,  # noqa: F401
               shared_index, unreachable, unused)                     # (they register rules)
from .config import LintConfig, suppressed
from .context import LintContext
from .registry import RULES, Rule, severity_rank
from .shared_index import changed_data


def lint_program(program: ast.Program, config: Optional[LintConfig] = None,
                 files: Optional[set] = None,
                 other_tasks_change: frozenset = frozenset()) -> list[Diagnostic]:
    """The findings of every enabled rule on ``program``, suppressed ones left out, sorted
    by file, line and column, each cause once (``grouping``: the repeats are its
    ``places``); with ``files``, only findings in those files.  ``other_tasks_change``:
    the PERS data other tasks of the controller change (``lint_tasks`` finds them)."""
    config = config or LintConfig()
    context = LintContext(program, other_tasks_change)
    findings = []
    with _collector_paused():
        for code, entry in sorted(RULES.items()):
            findings.extend(_findings(code, entry, context, config, files))
    findings.sort(key=_order)
    return one_per_cause(findings)


@contextlib.contextmanager
def _collector_paused():
    """The indexes hold a tuple per expression: the cycle collector's passes over them
    (none of them is garbage) would take as long as the rules themselves."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def lint_tasks(programs: list[ast.Program],
               config: Optional[LintConfig] = None) -> list[list[Diagnostic]]:
    """The findings of each task of one controller: each linted as a program of its own,
    knowing which PERS data the others change."""
    changes = [changed_data(LintContext(program)) for program in programs]
    return [lint_program(program, config, other_tasks_change=frozenset().union(
                *(other for number, other in enumerate(changes) if number != own)))
            for own, program in enumerate(programs)]


def _findings(code, entry, context, config, files):
    if not config.enabled(code):
        return
    severity = config.severity_of(code)
    for finding in entry.check(context):
        if files is not None and (finding.span is None or finding.span.file not in files):
            continue
        if suppressed(finding):
            continue
        if finding.severity != severity:
            finding = _with_severity(finding, severity)
        yield finding


def _with_severity(finding: Diagnostic, severity: str) -> Diagnostic:
    from dataclasses import replace
    return replace(finding, severity=severity)


def _order(finding: Diagnostic):
    span = finding.span
    return (span.file, span.line, span.column, finding.code.code) if span is not None \
        else ("", 0, 0, finding.code.code)


def failing(findings: list[Diagnostic], threshold: str) -> bool:
    """Is any finding at or above ``threshold``?"""
    limit = severity_rank(threshold)
    return any(severity_rank(f.severity) >= limit for f in findings)


__all__ = ["lint_program", "lint_tasks", "failing", "LintConfig", "RULES", "Rule"]
