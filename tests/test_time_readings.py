"""Clock and date readings when model checking (docs/predefined.md, clocks and system).

Time is abstracted away when checking, so how long a clock ran is the controller's
decision: ClkRead of a clock that ran is a choice of 0.001 s, 1 s or a day, never the 0 of
the abstract clock (which made a rate ``3600 / ClkRead(c)`` a false division by zero),
while a clock that never ran since its reset still reads 0, a real error when divided by.
GetTime's weekday is one of 1..7."""
from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import run_cli

CYCLE_RATE = Path(__file__).resolve().parent / "realworld" / "survey4" / "cycle_rate.mod"


def cli(*argv) -> tuple[int, str, str]:
    return run_cli(argv)


def verdicts(out: str) -> dict[str, str]:
    return {line.split(":")[0]: line.split(": ")[1].split()[0]
            for line in out.splitlines() if ": " in line and not line.startswith(" ")}


def program(tmp_path, body: str, data: str = "") -> str:
    path = tmp_path / "timing.mod"
    path.write_text(f"MODULE timing\n  VAR clock c;\n  VAR num t := -1;\n{data}"
                    f"  PROC main()\n{body}  ENDPROC\nENDMODULE\n")
    return str(path)


def test_rate_from_a_measured_cycle_is_no_division_by_zero_and_both_branches_are_seen():
    code, out, _ = cli("check", str(CYCLE_RATE), "--quiet",
                       "--formula", 'never_slow: G "slow_cycles = 0"',
                       "--formula", 'never_fast: G !"parts_per_hour > 100"')
    found = verdicts(out)
    assert found["no_runtime_error"] == "HOLDS"
    # a long and a short reading are both explored: each property has a counterexample
    assert found["never_slow"] == "VIOLATED" and found["never_fast"] == "VIOLATED"
    assert code == 1


def test_run_reads_the_virtual_time_exactly():
    code, out, _ = cli("run", str(CYCLE_RATE))
    assert code == 0 and out == "Parts per hour: 7200\n"      # 3600 / 0.5 s of WaitTime


# (body, readings the checked program may store in t)
READINGS = [
    ("    ClkReset c;\n    t := ClkRead(c);\n", {"0"}),                          # never ran
    ("    ClkStart c;\n    t := ClkRead(c);\n", {"0.001", "1", "86400"}),       # running
    ("    ClkStart c;\n    ClkStop c;\n    t := ClkRead(c);\n", {"0.001", "1", "86400"}),
    ("    ClkStart c;\n    ClkStop c;\n    ClkReset c;\n    t := ClkRead(c \\HighRes);\n", {"0"}),
]


@pytest.mark.parametrize("body, expected", READINGS, ids=["reset", "running", "stopped",
                                                          "reset-after-run"])
def test_what_a_clock_may_read_when_checking(body, expected, tmp_path):
    path = program(tmp_path, body)
    seen = set()
    for value in ("0", "0.001", "1", "86400"):
        code, out, _ = cli("check", path, "--quiet", "--formula", f'p: G !"t = {value}"')
        if verdicts(out)["p"] == "VIOLATED":
            seen.add(value)
    assert seen == expected


def test_a_clock_that_never_ran_is_still_a_division_by_zero(tmp_path):
    path = program(tmp_path, "    ClkReset c;\n    t := 60 / ClkRead(c);\n")
    code, out, _ = cli("check", path, "--quiet")
    assert code == 1 and verdicts(out)["no_runtime_error"] == "VIOLATED"
    assert "ERR_DIVZERO" in out or "division" in out.lower()


def test_weekday_indexes_a_table_of_seven_days(tmp_path):
    days = '  CONST string names{7} := ["Mon","Tue","Wed","Thu","Fri","Sat","Sun"];\n'
    path = program(tmp_path, '    TPWrite CDate() + " " + CTime() + " " + '
                             'names{GetTime(\\WDay)};\n    t := GetTime(\\Hour);\n', days)
    code, out, _ = cli("run", path)
    assert code == 0 and out == "2026-01-01 00:00:00 Thu\n"
    code, out, _ = cli("check", path, "--quiet")
    assert code == 0 and verdicts(out)["no_runtime_error"] == "HOLDS"
