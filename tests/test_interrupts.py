"""A check interrupted (SIGTERM from a CI job's time limit, Ctrl-C) reports what it reached.

The first signal stops the running search and the later ones (UNKNOWN, "interrupted by
SIGTERM") and the report is written as usual, with the verdicts reached before; a second
signal ends the command at once (``rapidmc: interrupted``, exit 130).  The signals are
real ones, sent to this process from inside the search once it has stored enough states,
so the test does not depend on timing.
"""
from __future__ import annotations

import json
import os
import signal
from pathlib import Path

import pytest

from rapidmc.check import budget
from rapidmc.commands.interrupts import stop_on_interrupt
from cli_capture import run_cli

COUNTING = Path(__file__).resolve().parent / "interrupts" / "counting.mod"


def run_interrupted(monkeypatch, signals: list, after: int = 20_000) -> tuple[int, str, str]:
    """``rapidmc check`` on the counting program, sending ``signals`` to this process, one
    after the other, at the first checkpoint past ``after`` stored states."""
    checkpoint = budget.SearchBudget.checkpoint
    pending = list(signals)

    def interrupting(self, stored, transitions, depth):
        while stored > after and pending:
            os.kill(os.getpid(), pending.pop(0))
        return checkpoint(self, stored, transitions, depth)

    monkeypatch.setattr(budget.SearchBudget, "checkpoint", interrupting)
    return run_cli(["check", COUNTING, "--max-states", "100000000", "--format", "json",
                    "--quiet"])


@pytest.mark.parametrize("sent, name", [(signal.SIGTERM, "SIGTERM"), (signal.SIGINT, "SIGINT"),
                                        (signal.SIGXCPU, "SIGXCPU")])
def test_a_first_interrupt_keeps_the_verdicts_reached_and_stops_the_rest(monkeypatch, sent,
                                                                         name):
    before = signal.getsignal(signal.SIGTERM)     # (a test run's own, or Ray's, or none)
    code, out, err = run_interrupted(monkeypatch, [sent])
    found = {p["name"]: p for p in json.loads(out)["properties"]}
    assert found["no_runtime_error"]["verdict"] == "VIOLATED"
    assert found["no_deadlock"]["verdict"] == "UNKNOWN"
    assert found["no_deadlock"]["reason"] == f"interrupted by {name}"
    assert code == 1, err                      # the violation found decides the exit code
    assert budget.stop_requested is None       # the next command in this process runs whole
    assert signal.getsignal(signal.SIGTERM) is before


def test_a_second_interrupt_ends_the_command_at_once(monkeypatch):
    code, out, err = run_interrupted(monkeypatch, [signal.SIGTERM, signal.SIGTERM])
    assert code == 130 and "rapidmc: interrupted" in err and out == ""


def test_a_cpu_limit_repeating_its_signal_still_gets_the_report(monkeypatch):
    # the kernel sends SIGXCPU again each second past the soft limit (ulimit -t): only the
    # hard limit may end the command, so the report of the verdicts reached is written
    code, out, err = run_interrupted(monkeypatch, [signal.SIGXCPU, signal.SIGXCPU])
    found = {p["name"]: p for p in json.loads(out)["properties"]}
    assert found["no_deadlock"]["reason"] == "interrupted by SIGXCPU"
    assert code == 1, err


def test_outside_a_command_the_handlers_are_the_callers():
    before = signal.getsignal(signal.SIGINT)
    with stop_on_interrupt():
        assert signal.getsignal(signal.SIGINT) is not before
    assert signal.getsignal(signal.SIGINT) is before
