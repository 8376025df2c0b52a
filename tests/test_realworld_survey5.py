"""Survey round 5 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not reach a verdict.

* ``trajectory_follower.mod``: a YuMi arm replaying points a ROS driver task writes into
  arrays of records declared in a module that is not given. ``rapidmc stubs`` types an
  array whose elements' components are read (``finger_buffer{k}.width``) with a RECORD
  of its own, gives data of a RECORD the stubs declare a neutral value, and the
  SmartGripper's ``Hand_WaitMovingCompleted`` is known.
* ``twin_arm_sync.mod``: a task list passed to WaitSyncTask, declared in a shared module
  that is not given: the stubs declare it as the array the parameter is.
* ``twin_backup/``: a controller backup with two tasks sharing PERS data and an EIO.cfg
  listing a group input the code never reads. ``--all-tasks`` alone picks the first task
  as the main one, and the unused input needs no ``--input-domain``.
* ``foerder_zaehler.mod``: identifiers with ISO 8859-1 letters in a file saved as UTF-8
  without a byte order mark (read as UTF-8; the same file in Latin-1 still loads).
"""
from __future__ import annotations

from pathlib import Path

from tests.test_realworld_survey4 import cli, verdicts

HERE = Path(__file__).resolve().parent / "realworld" / "survey5"
BACKUP = HERE / "twin_backup"


def stubs_for(program: Path, tmp_path: Path) -> tuple[int, str]:
    output = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", output)
    return code, output.read_text() if output.exists() else err


def test_stubs_declare_arrays_of_records_read_by_component(tmp_path):
    program = HERE / "trajectory_follower.mod"
    code, _, err = cli("check", program, "--quiet")
    assert code == 2 and "Hand_WaitMovingCompleted" not in err     # the gripper wait is known
    code, text = stubs_for(program, tmp_path)
    assert code == 0, text
    assert "could not be inferred" not in text
    # elements whose component .width is read: a RECORD named after the array
    assert "RECORD finger_buffer_rec\n    num width;\n  ENDRECORD" in text
    assert "PERS finger_buffer_rec finger_buffer{10} := [[0]," in text
    # elements assigned to a record of the stubs: that record, with a neutral value
    assert "PERS Arm_point arm_buffer{10} := [[[[0,0,0,0,0,0]," in text
    code, out, err = cli("check", program, tmp_path / "Missing.mod", "--quiet",
                         "--formula", 'no_new_points: G !"new_points"')
    found = verdicts(out)
    assert found["no_runtime_error"] == "HOLDS" and found["no_new_points"] == "HOLDS", err


def test_stubs_declare_a_task_list_as_an_array(tmp_path):
    program = HERE / "twin_arm_sync.mod"
    code, text = stubs_for(program, tmp_path)
    assert code == 0, text
    assert "PERS tasks arm_tasks{10} :=" in text and "an array argument" in text
    code, out, err = cli("check", program, tmp_path / "Missing.mod", "--quiet",
                         "--formula", 'counted: F "parts_done = 3"')
    found = verdicts(out)
    assert found["no_runtime_error"] == "HOLDS" and found["counted"] == "HOLDS", err


def test_all_tasks_of_a_backup_without_naming_the_main_one():
    code, out, err = cli("check", BACKUP, "--all-tasks", "--quiet",
                         "--input-domain", "giPartType=1,2",
                         "--formula", 'taken_after_fed: G "nPartsTaken <= nPartsFed"',
                         "--formula", 'all_taken: F "nPartsTaken = 3"')
    assert "[RMC008]" not in err
    found = verdicts(out)
    assert found["taken_after_fed"] == "HOLDS" and found["all_taken"] == "HOLDS"
    # once the feeder is done, the counting task waits for a part that never comes
    assert found["no_deadlock"] == "VIOLATED" and code == 1
    code, out, err = cli("check", BACKUP, "--quiet", "--input-domain", "giPartType=1,2")
    # every task by default (issue 20), with a note naming them
    assert code == 1 and verdicts(out)["no_deadlock"] == "VIOLATED"
    assert "[RMC730]" in err and "[RMC008]" not in err


def test_only_inputs_the_code_reads_need_a_domain():
    # giPartType (4 bits in EIO.cfg) takes every value by default; giRecipe is unused
    code, out, err = cli("check", BACKUP, "--all-tasks", "--quiet")
    assert code == 1 and "no_deadlock: VIOLATED" in out
    named = [line for line in err.splitlines() if "[RMC515]" in line]
    assert len(named) == 1 and "giPartType: values 0..15 (4-bit" in named[0]   # not giRecipe
    # a property that reads the unused input makes it needed again
    code, _, err = cli("check", BACKUP, "--all-tasks", "--quiet",
                       "--input-domain", "giPartType=1", "--exact-input-domains",
                       "--formula", 'no_recipe: G "giRecipe = 0"')
    assert code == 2 and "giRecipe" in err and "[RMC502]" in err


def test_utf8_source_with_accented_identifiers(tmp_path):
    program = HERE / "foerder_zaehler.mod"
    data = program.read_bytes()
    assert not data.startswith(b"\xef\xbb\xbf") and "ä".encode() in data
    code, out, err = cli("run", program)
    assert code == 0, err
    assert out == "Größe erreicht\nFörderband leer: 3\n"
    latin = tmp_path / "foerder_zaehler.mod"
    latin.write_bytes(data.decode("utf-8").encode("latin-1"))
    code, out_latin, err = cli("run", latin)
    assert code == 0 and out_latin == out, err
    code, out, err = cli("check", program, "--quiet", "--formula", 'bounded: G "nZähler <= 3"')
    assert verdicts(out)["bounded"] == "HOLDS", err
