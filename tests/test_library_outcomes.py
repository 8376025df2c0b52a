"""Nondeterministic outcomes of predefined routines (issue 8, C): when model checking, every
outcome the controller, the operator or the world may produce is explored.  Each property
claims that an outcome never happens; VIOLATED shows that it is reachable."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld import cli

PROGRAM = str(Path(__file__).resolve().parent / "library_outcomes" / "Outcomes.mod")
OUTCOMES = [
    ("search hit", '"nSearch = 1"'), ("search miss (ERR_WHLSEARCH)", '"nSearch = 2"'),
    ("button Yes", '"nButton = resYes"'), ("button No", '"nButton = resNo"'),
    ("button Cancel", '"nButton = resCancel"'),
    ("file exists", '"nFile = 1"'), ("no file", '"nFile = 2"'),
    ("no part", '"nParts = 0"'), ("two parts", '"nParts = 2"'),
    ("search on a PERS bool hit", '"nFlagSearch = 1"'),
    ("search on a PERS bool miss", '"nFlagSearch = 2"'),
    ("CalcJointT reached", '"nReach = 1"'),
    ("CalcJointT ERR_ROBLIMIT in \\ErrorNumber", '"nReach = 2"'),
]


@pytest.mark.parametrize("atom", [atom for _, atom in OUTCOMES], ids=[n for n, _ in OUTCOMES])
def test_every_outcome_is_reachable(atom, tmp_path):
    properties = tmp_path / "p.ltl"
    properties.write_text(f"never: G !{atom}\n")
    code, out, err = cli(["check", PROGRAM, "--ltl", str(properties)])
    assert code == 1 and "never: VIOLATED" in out, out + err


def test_buttons_not_shown_are_never_answered(tmp_path):
    properties = tmp_path / "p.ltl"
    properties.write_text('only_shown: G !"nButton = resOK"\nno_third_part: G !"nParts = 3"\n')
    code, out, err = cli(["check", PROGRAM, "--ltl", str(properties)])
    assert "only_shown: HOLDS" in out and "no_third_part: HOLDS" in out, out + err


def test_a_not_modelled_routine_loads_and_stops_the_run_where_it_is_reached():
    program = str(Path(__file__).resolve().parent / "library_outcomes" / "Calibration.mod")
    code, out, err = cli(["run", program])
    assert code == 2 and out == "calibrating\n"
    assert "MToolTCPCalib needs the robot's kinematic model" in err and "[RMC305]" in err
