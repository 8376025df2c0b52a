"""Baselines: the findings a team accepts today, so that a gate fails only on new ones.

``--write-baseline FILE`` records every finding of a run by its key (rule or property, the
file of a diagnostic, message without line numbers: ``ci_findings.Finding.key``) with how often it occurs; ``--baseline
FILE`` then leaves out as many findings of each key as the file records.  A finding moved by
an edit above it keeps its key; a second finding like a recorded one is new.  The file is
JSON (``SCHEMA``), sorted, to be committed and reviewed like code.
"""
from __future__ import annotations

import json
from collections import Counter
from typing import Sequence, TypeVar

from ..diagnostics import BASELINE_FILE, error
from .ci_findings import Finding
from . import indented_json

SCHEMA = "rapidmc-baseline/1"

T = TypeVar("T")


def format_baseline(command: str, findings: Sequence[Finding]) -> str:
    counts = Counter(finding.key() for finding in findings)
    entries = [{"rule": rule, "file": path, "message": message, "count": count}
               for (rule, path, message), count in sorted(counts.items())]
    document = {"schema": SCHEMA, "command": command, "findings": entries}
    return indented_json.dumps(document, 1) + "\n"


def read_baseline(path: str, command: str) -> Counter:
    """The recorded keys and their counts; RMC509 when the file is not a baseline of
    ``command``."""
    try:
        with open(path, encoding="utf-8") as handle:
            document = json.load(handle)
    except OSError as exc:
        raise error(BASELINE_FILE, f"cannot read the baseline '{path}': "
                    f"{exc.strerror or type(exc).__name__}") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise error(BASELINE_FILE, f"the baseline '{path}' is not JSON: {exc}") from None
    if not isinstance(document, dict) or document.get("schema") != SCHEMA:
        raise error(BASELINE_FILE, f"'{path}' is not a rapidmc baseline (no \"schema\": "
                    f"\"{SCHEMA}\"); write one with --write-baseline")
    if document.get("command") != command:
        raise error(BASELINE_FILE, f"the baseline '{path}' records the findings of "
                    f"'rapidmc {document.get('command')}', not of 'rapidmc {command}'")
    findings = document.get("findings", [])
    if not isinstance(findings, list):
        raise error(BASELINE_FILE, f"the baseline '{path}' is malformed: its findings are not "
                    "a list")
    known: Counter = Counter()
    for entry in findings:
        try:
            key = (entry["rule"], entry["file"], entry["message"])
            count = int(entry.get("count", 1))
        except (TypeError, KeyError, ValueError):
            raise error(BASELINE_FILE, f"the baseline '{path}' has a malformed finding: "
                        f"{json.dumps(entry)[:80]}") from None
        if not all(isinstance(part, str) for part in key) or count < 1:
            raise error(BASELINE_FILE, f"the baseline '{path}' has a malformed finding: "
                        f"{json.dumps(entry)[:80]}")
        known[key] += count
    return known


def split_known(findings: Sequence[Finding], items: Sequence[T],
                known: Counter) -> tuple[list[T], list[T]]:
    """``items`` (one per finding) split into (new, in the baseline); the baseline's count of
    a key covers that many findings with the key, in file order."""
    left = Counter(known)
    in_baseline = set()
    for index in sorted(range(len(findings)), key=lambda i: (findings[i].path, findings[i].line)):
        key = findings[index].key()
        if left[key] > 0:
            left[key] -= 1
            in_baseline.add(index)
    new = [item for index, item in enumerate(items) if index not in in_baseline]
    old = [item for index, item in enumerate(items) if index in in_baseline]
    return new, old
