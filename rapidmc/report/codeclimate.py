"""The Code Quality report (``--format codeclimate``) that GitLab shows in merge requests.

A JSON array of issues in the Code Climate format, each with ``description``,
``check_name`` (a diagnostic code, or a property's name), ``fingerprint`` (stable across runs
and unrelated edits: ``ci_findings.fingerprints``), ``severity`` (info, minor, major,
critical, blocker) and ``location`` (``path`` relative to the working folder, ``lines.begin``,
and ``lines.end`` for a stretch of lines); a finding given once per cause (RMC701) carries its
other places as ``other_locations``, as SARIF's ``relatedLocations`` do.
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
        "location": _location(finding.path, finding.line, finding.end_line),
        **({"other_locations": [_location(*place) for place in finding.places]}
           if finding.places else {}),
    } for finding, fingerprint in zip(findings, fingerprints(findings))]
    return indented_json.dumps(issues, 1) + "\n"


def _location(path: str, begin: int, end: int) -> dict:
    """A Code Climate location: the path and its lines (``end`` when more than one)."""
    return {"path": path, "lines": {"begin": begin, **({"end": end} if end > begin else {})}}


def format_codeclimate_errors(diagnostics: Sequence[Diagnostic], first_file: str) -> str:
    """Input errors (exit 2: nothing could be checked) as ``blocker`` issues; one without a
    source position sits on the program's first file."""
    return format_codeclimate(from_diagnostics(diagnostics, first_file,
                                               severity_of=lambda severity: "blocker"))
