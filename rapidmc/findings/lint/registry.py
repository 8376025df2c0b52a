"""The registry of lint rules: each rule is one registered object.

A rule has a diagnostic code (``rapidmc.diagnostics``, RMC80x-RMC84x), a default
severity (``error``, ``warning`` or ``note``), a one-line summary, a bad and a good
example (RAPID source, shown in docs/lint.md and linted by the tests: the bad one
must give the rule's finding, the good one none) and ``check``, a function from a
``LintContext`` to the findings (``Diagnostic`` values)::

    @rule(NOT_CHAIN, "warning", bad=..., good=...)
    def not_chain(context): ...
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Iterable

from ...diagnostics import Diagnostic, ErrorCode

SEVERITIES = ("note", "warning", "error")        # lowest first


@dataclass(frozen=True)
class Rule:
    code: ErrorCode
    severity: str
    bad: str
    good: str
    check: Callable[[object], Iterable[Diagnostic]]
    why: str = ""
    default: bool = True          # on unless selected away; False: opt-in (``select``)

    @property
    def summary(self) -> str:
        return self.code.summary


RULES: dict[str, Rule] = {}


def rule(code: ErrorCode, severity: str, bad: str, good: str, why: str = "",
         default: bool = True):
    """Register the decorated function as the check of the rule ``code``; ``default``
    False: the rule runs only when a ``select`` names it (opt-in)."""
    assert severity in SEVERITIES and code.code not in RULES, code.code

    def register(check: Callable[[object], Iterable[Diagnostic]]):
        RULES[code.code] = Rule(code, severity, _dedent(bad), _dedent(good), check, why,
                                default)
        return check
    return register


def _dedent(text: str) -> str:
    import textwrap
    return textwrap.dedent(text).strip("\n") + "\n"


def severity_rank(severity: str) -> int:
    return SEVERITIES.index(severity)
