"""The Code Quality report (``--format codeclimate``) that GitLab shows in merge requests.

A JSON array of issues in the Code Climate format, each with ``description``,
``check_name`` (a diagnostic code, or a property's name), ``fingerprint`` (stable across runs
and unrelated edits: ``ci_findings.fingerprints``), ``severity`` (info, minor, major,
critical, blocker) and ``location`` (``path`` relative to the working folder, ``lines.begin``).
"""
from __future__ import annotations

from typing import Sequence

from ..diagnostics import Diagnostic
from .ci_findings import Finding, fingerprints, from_diagnostics
from . import indented_json


def format_codeclimate(findings: Sequence[Finding]) -> str:
    issues = [{
        "type": "issue",
        "check_name": finding.rule,
        "description": finding.message,
        "categories": ["Bug Risk"],
        "severity": finding.severity,
        "fingerprint": fingerprint,
        "location": {"path": finding.path, "lines": {"begin": finding.line}},
    } for finding, fingerprint in zip(findings, fingerprints(findings))]
    return indented_json.dumps(issues, 1) + "\n"


def format_codeclimate_errors(diagnostics: Sequence[Diagnostic], first_file: str) -> str:
    """Input errors (exit 2: nothing could be checked) as ``blocker`` issues; one without a
    source position sits on the program's first file."""
    return format_codeclimate(from_diagnostics(diagnostics, first_file,
                                               severity_of=lambda severity: "blocker"))
