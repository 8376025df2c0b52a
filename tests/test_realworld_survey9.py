"""Survey round 9, loading what controllers load (issue 19, docs/realworld-survey.md): a
controller backup of ours in the style of the public backups surveyed, whose modules a real
controller loads but rapidmc refused before.

``survey9/service_cell`` is a backup folder (RAPID/T_ROB1/SYSMOD, PROGMOD): Production
Manager's ``TASK PERS menudata`` entries called by late binding, ``tool0``/``wobj0`` given to
PERS and INOUT parameters, a ``PERS wzstationary`` declared with a value, UIMsgBox
``\\Result`` into a PERS, CalcJointT with ``\\ErrorNumber``, SearchL on a PERS bool,
``pos / num`` and a routine left unfinished with ``<SMT>``. It loads as it is and every
outcome stays reachable (no verdict becomes HOLDS by hiding one).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld_survey4 import cli, verdicts

BACKUP = Path(__file__).resolve().parent / "realworld" / "survey9" / "service_cell"


def check(tmp_path: Path, properties: str) -> tuple[int, dict, str]:
    path = tmp_path / "p.ltl"
    path.write_text(properties)
    code, out, err = cli("check", BACKUP, "--task", "T_ROB1", "--ltl", path)
    return code, verdicts(out), err


def test_the_backup_loads_and_reaches_verdicts_directly(tmp_path):
    code, found, err = check(tmp_path, 'touch: G ("nTouchCount > 0" -> "nReachable = 1")\n')
    assert code == 0, err
    assert found == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "touch": "HOLDS"}
    assert "CalcJointT reads a fixed value" in err and "[RMC702]" in err
    assert "routine NewRoutine never runs" in err          # the <SMT> routine loads


@pytest.mark.parametrize("name, atom", [
    ("search hit on the PERS flag", '"nTouchCount > 0"'),
    ("search miss", '"Ended() AND nReachable = 1 AND nTouchCount = 0"'),
    ("target out of reach (CalcJointT \\\\ErrorNumber)", '"Ended() AND nReachable = 0"'),
    ("operator cancels", '"Ended() AND answer = resCancel"'),
    ("pos / num computed", '"pMiddle.y = 200 AND pMiddle.x = 700"'),
])
def test_every_outcome_stays_reachable(tmp_path, name, atom):
    code, found, err = check(tmp_path, f"never: G !{atom}\n")
    assert code == 1 and found["never"] == "VIOLATED", (name, err)
