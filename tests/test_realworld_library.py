"""A cell in the style of the public programs that used to stop at the first predefined
name rapidmc lacked (issue 8): every name the issue lists now loads, runs and checks."""
from __future__ import annotations

from pathlib import Path

from tests.test_realworld import cli

CELL = str(Path(__file__).resolve().parent / "realworld" / "library_names" / "WeldCell.mod")
ISSUE_TYPES = ("sensor listitem seamdata welddata trapdata speedlimdata cameradev testsignal "
               "datapos itmsrc menudata jointgroup").split()
ISSUE_ROUTINES = ("GripLoad WorldAccLim PathAccLim StorePath RestoPath MoveExtJ GetMotorTorque "
                  "GetDataVal SetDataVal IsFile MaxRobSpeed IError GetTrapData ReadErrData "
                  "ErrRaise WriteCfgData SearchL UIListView RMQFindSlot Hand_MoveTo").split()


def test_the_cell_uses_every_name_the_issue_lists():
    text = Path(CELL).read_text()
    assert all(name in text for name in ISSUE_TYPES + ISSUE_ROUTINES)


def test_the_cell_runs():
    code, out, err = cli(["run", CELL, "--io", "diTouch=1"], stdin="1\n")
    assert code == 0, err
    assert out.splitlines() == ["seam at speed 8", "max speed 5000", "motor torque 0"]


def test_the_cell_checks_with_both_search_outcomes(tmp_path):
    properties = tmp_path / "p.ltl"
    properties.write_text('ends: F "Ended()"\nalways_found: G !"AtLine(63)"\n')
    code, out, err = cli(["check", CELL, "--ltl", str(properties)])
    assert "ends: HOLDS" in out and "always_found: VIOLATED" in out, out + err
