"""The reports of ``rapidmc lint``: text (the findings as diagnostics, then a count),
JSON and SARIF (``sarif.format_sarif_diagnostics``: one result per finding, a flow's
steps as its code flow)."""
from __future__ import annotations

from collections import Counter
from typing import Sequence

from ..diagnostics import Diagnostic, render
from .sarif import format_sarif_diagnostics
from . import indented_json


def format_lint_text(findings: Sequence[Diagnostic], lines: int, files: int) -> str:
    parts = [_render_with_flow(finding) for finding in findings]
    parts.append(f"{files} file{'s' if files != 1 else ''}, {lines} lines: {summary(findings)}")
    return "\n".join(parts) + "\n"


def _render_with_flow(finding: Diagnostic) -> str:
    text = render(finding)
    if finding.flow:
        text += "".join(f"\n  {'flow:' if order == 0 else '     '} {span.file}:{span.line}  {step}"
                        for order, (span, step) in enumerate(finding.flow))
    return text


def summary(findings: Sequence[Diagnostic]) -> str:
    if not findings:
        return "no findings"
    counts = Counter(f.severity for f in findings)
    shown = ", ".join(f"{counts[level]} {level}{'s' if counts[level] != 1 else ''}"
                      for level in ("error", "warning", "note") if counts[level])
    return f"{len(findings)} finding{'s' if len(findings) != 1 else ''} ({shown})"


def finding_json(finding: Diagnostic) -> dict:
    span = finding.span
    return {"code": finding.code.code, "rule": finding.code.name, "severity": finding.severity,
            "message": finding.message,
            "location": None if span is None else {
                "file": span.file, "line": span.line, "column": span.column,
                "end_line": span.end_line, "end_column": span.end_column},
            "notes": list(finding.notes),
            "places": [{"file": s.file, "line": s.line, "column": s.column}
                       for s in finding.places],
            "flow": [{"file": s.file, "line": s.line, "column": s.column, "step": text}
                     for s, text in finding.flow]}


def format_lint_json(findings: Sequence[Diagnostic], exit_code: int, lines: int) -> str:
    counts = Counter(f.severity for f in findings)
    document = {"findings": [finding_json(f) for f in findings],
                "summary": {level: counts[level] for level in ("error", "warning", "note")},
                "lines": lines, "exit_code": exit_code}
    return indented_json.dumps(document, 1) + "\n"


def format_lint_sarif(findings: Sequence[Diagnostic], exit_code: int) -> str:
    return format_sarif_diagnostics(findings, exit_code)
