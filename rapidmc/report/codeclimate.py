"""The Code Quality report (``--format codeclimate``) that GitLab shows in merge requests.

A JSON array of issues in the Code Climate format, each with ``description``,
``check_name`` (a diagnostic code, or a property's name), ``fingerprint`` (stable across runs
and unrelated edits: ``ci_findings.fingerprints``), ``severity`` (info, minor, major,
critical, blocker) and ``location`` (``path`` relative to the working folder, ``lines.begin``).
"""
from __future__ import annotations

import json
from typing import Sequence

from .ci_findings import Finding, fingerprints


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
    return json.dumps(issues, indent=1, ensure_ascii=False) + "\n"
