"""Which rules run, at which severity, and which findings a comment suppresses.

Configuration comes from ``[tool.rapidmc.lint]`` of the nearest ``pyproject.toml``
(from the current folder upward), then the command line::

    [tool.rapidmc.lint]
    select = ["RMC80"]            # codes, code prefixes or rule names
    ignore = ["unused-data"]
    severity = "warning"          # lowest severity that makes the exit code 1
    severities = { RMC807 = "warning" }

A finding is suppressed by a comment on its line, or on a comment line right above
it: ``! rapidmc: ignore`` (every rule) or ``! rapidmc: ignore[RMC801, unused-data]``.
"""
from __future__ import annotations

import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from ...diagnostics import LINT_CONFIG, Diagnostic, SourceCache, error
from .registry import RULES, SEVERITIES

_SUPPRESSION = re.compile(r"!\s*rapidmc:\s*ignore(?:\[([^\]]*)\])?", re.IGNORECASE)
_KEYS = {"select", "ignore", "severity", "severities"}


@dataclass(frozen=True)
class LintConfig:
    select: tuple[str, ...] = ()          # empty: every rule
    ignore: tuple[str, ...] = ()
    severity: str = "warning"             # the exit code's threshold
    severities: dict = field(default_factory=dict)    # code -> severity

    def enabled(self, code: str) -> bool:
        """Is the rule on: selected (no ``select``: every rule on by default), not ignored?"""
        rule = RULES[code]
        chosen = any(_matches(rule, s) for s in self.select) if self.select else rule.default
        return chosen and not any(_matches(rule, s) for s in self.ignore)

    def severity_of(self, code: str) -> str:
        return self.severities.get(code, RULES[code].severity)


def _matches(rule, selector: str) -> bool:
    selector = selector.strip()
    return rule.code.code.startswith(selector.upper()) or rule.code.name == selector.lower()


def check_selectors(selectors, origin: str) -> None:
    for selector in selectors:
        if not any(_matches(rule, selector) for rule in RULES.values()):
            raise error(LINT_CONFIG, f"{origin}: '{selector}' names no lint rule (codes "
                        "RMC801-RMC840, or a rule name such as not-chain)")


def read_pyproject(start: Path) -> tuple[dict, Optional[Path]]:
    """``[tool.rapidmc.lint]`` of the nearest pyproject.toml at or above ``start``."""
    for folder in (start, *start.parents):
        candidate = folder / "pyproject.toml"
        if candidate.is_file():
            try:
                document = tomllib.loads(candidate.read_text(encoding="utf-8"))
            except (tomllib.TOMLDecodeError, UnicodeDecodeError, OSError) as failure:
                raise error(LINT_CONFIG, f"{candidate}: cannot be read: {failure}")
            return document.get("tool", {}).get("rapidmc", {}).get("lint", {}), candidate
    return {}, None


def make_config(table: dict, origin: str, select=(), ignore=(), severity=None) -> LintConfig:
    """The configuration: the file's table, then the command line's options over it."""
    unknown = set(table) - _KEYS
    if unknown:
        raise error(LINT_CONFIG, f"{origin}: unknown key(s) {', '.join(sorted(unknown))} in "
                    f"[tool.rapidmc.lint] (known: {', '.join(sorted(_KEYS))})")
    file_select = _strings(table.get("select", []), origin, "select")
    file_ignore = _strings(table.get("ignore", []), origin, "ignore")
    check_selectors(file_select + file_ignore, origin)
    check_selectors(tuple(select) + tuple(ignore), "command line")
    severities = {}
    for selector, level in dict(table.get("severities", {})).items():
        check_selectors([selector], origin)
        _check_severity(level, origin)
        for code, entry in RULES.items():
            if _matches(entry, selector):
                severities[code] = level
    threshold = severity or table.get("severity", "warning")
    _check_severity(threshold, origin if severity is None else "--severity")
    return LintConfig(tuple(select) or file_select, file_ignore + tuple(ignore), threshold,
                      severities)


def _strings(value, origin: str, key: str) -> tuple[str, ...]:
    if isinstance(value, str):
        value = [value]
    if not isinstance(value, list) or not all(isinstance(v, str) for v in value):
        raise error(LINT_CONFIG, f"{origin}: '{key}' must be a list of strings")
    return tuple(value)


def _check_severity(level, origin: str) -> None:
    if level not in SEVERITIES:
        raise error(LINT_CONFIG, f"{origin}: severity '{level}' is not one of "
                    f"{', '.join(SEVERITIES)}")


def suppressed(diagnostic: Diagnostic) -> bool:
    """Does a ``! rapidmc: ignore`` comment on the line, or right above it, cover it?"""
    span = diagnostic.span
    if span is None or span.line <= 0:
        return False
    here = SourceCache.line(span.file, span.line)
    if here is not None and _covers(here, diagnostic):
        return True
    above = SourceCache.line(span.file, span.line - 1) if span.line > 1 else None
    return above is not None and above.lstrip().startswith("!") and _covers(above, diagnostic)


def _covers(line: str, diagnostic: Diagnostic) -> bool:
    if "rapidmc" not in line:
        return False
    match = _SUPPRESSION.search(line)
    if match is None:
        return False
    if match.group(1) is None:
        return True
    rule = RULES.get(diagnostic.code.code)
    wanted = [part.strip() for part in match.group(1).split(",") if part.strip()]
    return rule is not None and any(_matches(rule, selector) for selector in wanted)


__all__ = ["LintConfig", "make_config", "read_pyproject", "suppressed"]
