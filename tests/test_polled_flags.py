"""Handshake flags another party sets, read in a task checked alone (issue 28).

A flag polled in an endless loop (``IF newTarget = TRUE THEN newTarget := FALSE; ...``)
that the loaded code only clears is set by a party not loaded
(``load.awaited_from_outside``: a poll); a stub's PERS flag, command or state that no loaded
code writes is written from outside (``load.outside_data``), and a state passed on to a
routine takes the numbers that routine compares it with.  Cases: tests/polled_flags/ (its
README.md).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc import api

CASES = Path(__file__).resolve().parent / "polled_flags"
NAMES = sorted(p.name for p in CASES.iterdir() if p.is_dir())


def _check(folder: Path, fixed: bool = False) -> api.CheckReport:
    files = [str(folder / "prog.mod")] + ([str(folder / "Missing.mod")]
                                          if (folder / "Missing.mod").exists() else [])
    return api.check(api.load_program(files, outside_data=not fixed))


def _expected(folder: Path) -> tuple[list, list]:
    lines = [line for line in (folder / "expected").read_text().splitlines()
             if line.strip() and not line.startswith("#")]
    assumes = [line[len("assumes: "):] for line in lines if line.startswith("assumes: ")]
    return [line for line in lines if not line.startswith("assumes: ")], assumes


def _unreached(report: api.CheckReport) -> list:
    return [w.message for w in report.warnings if w.code.code == "RMC701"]


@pytest.mark.parametrize("name", NAMES)
def test_the_flag_another_party_sets_lets_the_code_run(name):
    folder = CASES / name
    report = _check(folder)
    warnings, assumes = _expected(folder)
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    assert _unreached(report) == warnings
    assert set(assumes) <= set(report.results[0].assumes), report.results[0].assumes


@pytest.mark.parametrize("name", NAMES)
def test_with_fixed_outside_data_the_flag_keeps_its_value(name):
    """``--fixed-outside-data`` (the reading before): the flag stays FALSE and the code it
    guards is reported unreached, naming the data."""
    messages = _unreached(_check(CASES / name, fixed=True))
    assert messages and all("persistent data" in m for m in messages), messages
