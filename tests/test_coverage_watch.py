"""The statement watch records every line a transition executes, remembering spans seen.

Spans met again are skipped by identity; what it remembers must never hide a
line: not after ``clear`` (a second search watched from scratch), not beyond
the number of spans it keeps, not for a merged step's tuple of spans.
"""
from __future__ import annotations

import pytest

from rapidmc.findings import coverage
from rapidmc.ast import Span
from rapidmc.findings.coverage import StatementWatch

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def step(span):
    """One successor as a search hands it over: (label (choices, span, output), state)."""
    return (((), span, ""), "state")


def test_every_line_of_single_and_merged_steps_is_recorded():
    watch = StatementWatch()
    first, second, third = (Span("a.mod", line, 1) for line in (3, 4, 9))
    watch("s", [step(first), step((second, None, third)), step(None)])
    watch("s", [step(first)])
    assert watch.executed == {("a.mod", 3), ("a.mod", 4), ("a.mod", 9)}


def test_a_cleared_watch_records_the_same_spans_again():
    watch = StatementWatch()
    span = Span("a.mod", 5, 1)
    watch("s", [step(span)])
    watch.clear()
    assert watch.executed == set()
    watch("s", [step(span)])
    assert watch.executed == {("a.mod", 5)}


def test_lines_beyond_the_spans_kept_are_recorded(monkeypatch):
    monkeypatch.setattr(coverage, "SPANS_KEPT", 2)
    watch = StatementWatch()
    spans = [Span("a.mod", line, 1) for line in range(1, 8)]
    for span in spans + spans:
        watch("s", [step(span)])
    assert watch.executed == {("a.mod", line) for line in range(1, 8)}
