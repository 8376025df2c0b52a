"""The robot's position left out of states where nothing but moves reads it.

Differential: generated programs that move relative to where the robot is
(tests/robot_programs.py), and the cases of tests/robot_tracking/, are checked with the
position left out (the default, which each must take) and with ``--track-robot``; the
verdicts of the built-in checks and of the LTL properties must be the same wherever the
tracked search ends.  The ``kept_*`` cases read the position where it matters (a
condition, the program's own function, ``GetDataVal``, ``CalcJointT``, a property's atom, a
PERS, a product that may leave the range of num): the analysis keeps the robot there, and
a test shows that each of their verdicts would change if it did not.  A counterexample of a
check without the position replays.
"""
from __future__ import annotations

import json
import os
import shlex
from pathlib import Path

import pytest

import rapidmc.api
from rapidmc.cli import main
from rapidmc.findings.assumptions import UNTRACKED_ROBOT

from robot_programs import properties, random_program
from test_assumptions import check_in_folder, text_lines
from test_replay_command import replay_every_violation

CASES = Path(__file__).resolve().parent / "robot_tracking"
CASE_NAMES = sorted(p.name for p in CASES.iterdir() if p.is_dir())
ROBOT_LINE = f"  assumes: {UNTRACKED_ROBOT.text}"
BOUND = ["--max-states", "3000"]
UNKNOWN = "UNKNOWN"


def json_run(folder: Path, argv: list[str]) -> dict:
    """Property -> (verdict, assumptions) of ``rapidmc check ARGV --format json``."""
    _, out = check_in_folder(folder, *argv, "--format", "json")
    return {p["name"]: (p["verdict"], p["assumes"]) for p in json.loads(out)["properties"]}


def assert_tracking_keeps_verdicts(folder: Path, argv: list[str]) -> dict:
    """The verdicts without the position, checked against the tracked ones; returns them."""
    untracked = json_run(folder, argv + BOUND)
    tracked = json_run(folder, argv + BOUND + ["--track-robot"])
    assert untracked.keys() == tracked.keys()
    for name, (verdict, _) in untracked.items():
        assert verdict != UNKNOWN, name          # every search of these programs ends
        if tracked[name][0] != UNKNOWN:
            assert tracked[name][0] == verdict, name
        assert UNTRACKED_ROBOT.text not in tracked[name][1]
    return untracked


@pytest.mark.parametrize("seed", range(24))
def test_generated_programs_keep_their_verdicts(tmp_path, seed):
    (tmp_path / "prog.mod").write_text(random_program(seed))
    argv = ["prog.mod"] + [word for text in properties(seed) for word in ("--formula", text)]
    untracked = assert_tracking_keeps_verdicts(tmp_path, argv)
    # each of them reads the position only to move again: the check leaves it out
    assert all(UNTRACKED_ROBOT.text in assumes for verdict, assumes in untracked.values()
               if verdict != "VIOLATED")
    assert any(UNTRACKED_ROBOT.text in assumes for _, assumes in untracked.values())


@pytest.mark.parametrize("name", CASE_NAMES)
def test_cases_show_their_verdicts_and_assumptions(name):
    folder = CASES / name
    _, out = check_in_folder(folder, *shlex.split((folder / "args").read_text()))
    wanted = [line for line in (folder / "expected").read_text().splitlines()
              if line.strip() and not line.startswith("#")]
    assert text_lines(out) == wanted, out
    assert (ROBOT_LINE in wanted) == name.startswith("untracked_")


@pytest.mark.parametrize("name", CASE_NAMES)
def test_cases_keep_their_verdicts_with_the_robot_tracked(name):
    folder = CASES / name
    assert_tracking_keeps_verdicts(folder, shlex.split((folder / "args").read_text()))


@pytest.mark.parametrize("name", [n for n in CASE_NAMES if n.startswith("kept_")])
def test_kept_cases_would_get_a_wrong_verdict_without_the_position(name, monkeypatch):
    """The analysis keeps the robot where a verdict depends on it: forced off, the robot
    left at its start changes a verdict of each ``kept_`` case."""
    folder = CASES / name
    argv = shlex.split((folder / "args").read_text())
    kept = json_run(folder, argv + BOUND)
    monkeypatch.setattr(rapidmc.api, "robot_untracked", lambda program, atoms: True)
    forced = json_run(folder, argv + BOUND)
    assert {n: v for n, (v, _) in kept.items()} != {n: v for n, (v, _) in forced.items()}


def test_a_program_that_drifts_ends_only_without_the_position():
    """untracked_error: the height and a joint drift each cycle (as in a public backup whose
    joints turned 90 degrees a cycle, UNKNOWN at 300,000 states): tracked, no search
    ends."""
    folder = CASES / "untracked_error"
    argv = shlex.split((folder / "args").read_text())
    tracked = json_run(folder, argv + BOUND + ["--track-robot"])
    assert tracked["no_deadlock"][0] == tracked["Cycles"][0] == UNKNOWN
    assert json_run(folder, argv)["no_deadlock"][0] == "HOLDS"


def test_a_violation_names_the_assumption_only_when_its_run_moves(tmp_path):
    (tmp_path / "prog.mod").write_text(
        "MODULE Prog\n  VAR num tab{2} := [1, 2];\n  VAR num i := 3;\n  PROC main()\n"
        "    tab{i} := 0;\n    MoveL Offs(CRobT(), 0, 0, 10), v100, fine, tool0;\n"
        "  ENDPROC\nENDMODULE\n")
    found = json_run(tmp_path, ["prog.mod"])
    assert found["no_runtime_error"] == ("VIOLATED", [])
    assert found["no_deadlock"] == ("HOLDS", [UNTRACKED_ROBOT.text])


@pytest.mark.parametrize("name", ["untracked_error", "untracked_deadlock"])
def test_counterexamples_without_the_position_replay(name, capsys, tmp_path):
    folder = CASES / name
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        main(["check", *shlex.split((folder / "args").read_text()), "--format", "json"])
        path = tmp_path / "trace.json"
        path.write_text(capsys.readouterr().out)
        assert replay_every_violation(capsys, json.loads(path.read_text()), path)
    finally:
        os.chdir(cwd)
