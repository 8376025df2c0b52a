"""Controller backups of several tasks, checked together: tests/task_backups/<case>/.

Each case is a folder with a backup written for the test (``backup/``: BACKINFO,
SYSPAR, RAPID/TASKn), checked from the repository root:

* ``props.ltl`` — properties (optional); ``args`` — extra options (optional);
* ``expected`` — ``NAME VERDICT`` per property, the built-in checks included;
* ``waiting`` — text the reason of a violated ``no_deadlock`` must contain, one piece a line;
* ``warnings`` — ``RMCnnn text`` per warning or note the report must contain;
* ``not_warned`` — ``RMCnnn text`` per warning or note the report may not contain;
* ``assumes`` — text each verdict's ``assumes:`` must contain, one piece a line;
* ``not_assumed`` — text no verdict's ``assumes:`` may contain, one piece a line;
* ``error`` — text the last step of the ``no_runtime_error`` counterexample must contain
  (the error it stops with).

Besides, a barrier removed from a case that needs it must break the property it keeps.
"""
from __future__ import annotations

import json
import shlex
import shutil
from pathlib import Path

import pytest

from rapidmc.check import native
from cli_capture import run_cli

CASES = Path(__file__).resolve().parent / "task_backups"


def lines(path: Path) -> list[str]:
    if not path.exists():
        return []
    return [line.strip() for line in path.read_text().splitlines()
            if line.strip() and not line.startswith("#")]


def run_check(case: Path, backup: Path) -> tuple[int, dict, str]:
    argv = ["check", str(backup), "--format", "json", "--quiet"]
    if (case / "props.ltl").exists():
        argv += ["--ltl", str(case / "props.ltl")]
    argv += [arg for line in lines(case / "args") for arg in shlex.split(line)]
    code, out, err = run_cli(argv)
    report = json.loads(out)
    warnings = "\n".join(f"{w['code']} {w['message']}" for w in report.get("warnings") or ())
    return code, {p["name"]: p for p in report["properties"]}, err + warnings


@pytest.mark.parametrize("case", sorted(p for p in CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_task_backup_case(case):
    code, found, err = run_check(case, case / "backup")
    expected = dict(line.split() for line in lines(case / "expected"))
    assert {name: p["verdict"] for name, p in found.items()} == expected, err
    assert code == (1 if "VIOLATED" in expected.values() else 0)
    for piece in lines(case / "waiting"):
        assert piece in (found["no_deadlock"]["reason"] or ""), found["no_deadlock"]["reason"]
    for piece in lines(case / "error"):
        trace = found["no_runtime_error"]["trace"]
        last = json.dumps((trace["cycle"] or trace["prefix"])[-1])
        assert piece in last, last
    for piece in lines(case / "assumes"):
        for name, p in found.items():
            assert any(piece in line for line in p.get("assumes") or ()), (name, p.get("assumes"))
    for piece in lines(case / "not_assumed"):
        for name, p in found.items():
            assert not any(piece in line for line in p.get("assumes") or ()), \
                (name, p.get("assumes"))
    for line in lines(case / "warnings"):
        code_text, _, text = line.partition(" ")
        assert any(code_text in row and text in row for row in err.splitlines()), err
    for line in lines(case / "not_warned"):
        code_text, _, text = line.partition(" ")
        assert not any(code_text in row and text in row for row in err.splitlines()), err


def test_without_its_barrier_robot_1_runs_ahead(tmp_path):
    case = CASES / "sync_both"
    backup = shutil.copytree(case / "backup", tmp_path / "backup")
    module = backup / "RAPID" / "TASK1" / "PROGMOD" / "Rob1.mod"
    module.write_text(module.read_text().replace("WaitSyncTask cycle_done, pair;", ""))
    _, found, err = run_check(case, backup)
    assert found["together"]["verdict"] == "VIOLATED", err


def test_a_barrier_with_a_task_name_no_task_has_is_an_error(tmp_path):
    case = CASES / "sync_both"
    backup = shutil.copytree(case / "backup", tmp_path / "backup")
    module = backup / "RAPID" / "TASK1" / "PROGMOD" / "Rob1.mod"
    module.write_text(module.read_text().replace('[["T_ROB1"], ["T_ROB2"]]',
                                                 '[["T_ROB1"], ["T_ROB9"]]'))
    _, found, err = run_check(case, backup)
    assert found["no_runtime_error"]["verdict"] == "VIOLATED"
    steps = found["no_runtime_error"]["trace"]
    assert "ERR_TASKNAME" in json.dumps(steps)


def test_empty_entries_of_a_task_list_name_no_task(tmp_path):
    """A task list padded with empty names (``[["T_ROB1"],[""],["T_ROB2"],[""]]``, as real
    cells declare theirs) waits for the tasks it names and no other: the case's verdicts
    stay, where an empty name taken as a task would be ERR_TASKNAME at the first barrier."""
    case = CASES / "sync_both"
    backup = shutil.copytree(case / "backup", tmp_path / "backup")
    for module in backup.glob("RAPID/TASK*/PROGMOD/Rob*.mod"):
        text = module.read_text().replace('pair{2} := [["T_ROB1"], ["T_ROB2"]]',
                                          'pair{4} := [["T_ROB1"], [""], ["T_ROB2"], [""]]')
        assert "pair{4}" in text
        module.write_text(text)
    _, found, err = run_check(case, backup)
    expected = dict(line.split() for line in lines(case / "expected"))
    assert {name: p["verdict"] for name, p in found.items()} == expected, err


@pytest.mark.skipif(not native.available(), reason="the native core is not built")
@pytest.mark.parametrize("name", ["alone_output_written", "system_output", "alone_polling_while",
                                  "alone_polling_goto", "alone_wait_then_read",
                                  "alone_wait_never_met", "alone_polling_else_goto",
                                  "alone_polling_function_index",
                                  "system_output_helpers", "system_output_in_property",
                                  "system_output_set_through_option",
                                  "alone_whole_array_wait", "alone_whole_record_wait",
                                  "alone_whole_array_outside_only",
                                  "alone_whole_array_too_many", "alone_wait_function",
                                  "wait_function_together", "wait_function_never_met",
                                  "alone_whole_array_index_zero",
                                  "alone_wait_function_socket", "alone_outside_retry",
                                  "alone_written_constants", "alone_written_computed",
                                  "alone_written_constants_awaited"])
def test_outputs_set_outside_same_on_both_engines(name):
    """Outputs set outside the loaded code are free inputs of both engines alike."""
    case = CASES / name
    reports = {}
    for engine in ("native", "python"):
        argv = ["check", str(case / "backup"), "--format", "json", "--quiet", "--engine", engine]
        argv += [arg for line in lines(case / "args") for arg in shlex.split(line)]
        reports[engine] = [(p["name"], p["verdict"], p["stats"]["model_states"],
                            p["stats"]["transitions"], len(p.get("trace") or ()))
                           for p in json.loads(run_cli(argv).out)["properties"]]
    assert reports["native"] == reports["python"]


def test_a_waiting_task_is_named_by_its_file_as_the_steps_name_it(monkeypatch, tmp_path):
    # the backup by its absolute path, checked from elsewhere: T_ROB1 never steps in the
    # counterexample, yet its wait names TASK1/PROGMOD/Rob1.mod:5 relative to the folder the
    # steps are named from, never by the absolute path
    monkeypatch.chdir(tmp_path)
    backup = CASES / "sync_skip" / "backup"
    text = run_cli(["check", backup]).out
    assert "  waits forever: T_ROB1 waits at TASK1/PROGMOD/Rob1.mod:5 (WaitSyncTask" in text
    assert f"  (files relative to {backup / 'RAPID'})" in text
    assert f"{backup}/RAPID/TASK1" not in text
