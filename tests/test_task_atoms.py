"""Atoms on a controller of several tasks: no unqualified name is resolved silently.

The backup tests/task_backups/qualified/backup has three tasks: T_ROB1 and T_ROB2 each
declare ``VAR num slot`` and ``PROC MoveToSlot`` (and ``main``); T_LOG alone declares
``seen``.  The verdicts of every kind of qualified atom are pinned by that case
(tests/test_task_backups.py); here: the errors for names and places that need a task.
"""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest

from rapidmc.cli import main
from cli_capture import run_cli

BACKUP = Path(__file__).resolve().parent / "task_backups" / "qualified" / "backup"


def run(tmp_path: Path, formula: str) -> tuple[int, str]:
    props = tmp_path / "props.ltl"
    props.write_text(f"p: {formula}\n")
    code, out, err = run_cli(["check", BACKUP, "--ltl", props, "--quiet"])
    return code, out + err


@pytest.mark.parametrize("formula, name, candidates", [
    ('G "slot = 1"', "slot", ["T_ROB1 (Rob1.mod:4)", "T_ROB2 (Rob2.mod:3)"]),
    ('G ("T_LOG.seen = 0" | "seen > slot")', "slot", ["T_ROB1.slot or T_ROB2.slot"]),
    ('G !"main.flag"', "main", ["T_ROB1 (Rob1.mod:5)", "T_ROB2 (Rob2.mod:4)",
                                "T_ROB1.main or T_ROB2.main"]),
])
def test_a_name_several_tasks_declare_is_an_error_with_a_caret(tmp_path, formula, name,
                                                               candidates):
    code, text = run(tmp_path, formula)
    assert code == 2, text
    assert f"'{name}' is declared by several tasks" in text and "[RMC406]" in text, text
    for candidate in candidates:
        assert candidate in text, text
    line = f"p: {formula}"
    column = line.index(name) + 1
    assert f"props.ltl:1:{column}: error:" in text, text
    assert "\n" + " " * (column - 1 + 4) + "^" in text or f"{line}\n" in text, text


def test_the_main_of_a_task_named_alone_is_not_ambiguous_for_the_logger(tmp_path):
    """T_LOG's entry is log_main: ``main`` is T_ROB1's and T_ROB2's only."""
    code, text = run(tmp_path, 'G !"main.flag"')
    assert "T_LOG (" not in text, text


@pytest.mark.parametrize("atom", ['InRoutine(\\"MoveToSlot\\")', "AtLine(9)",
                                  'AtLabel(\\"back\\")'])
def test_a_location_atom_without_a_task_is_an_error(tmp_path, atom):
    code, text = run(tmp_path, f'G !"{atom}"')
    assert code == 2, text
    assert "needs a task on a controller of several tasks (T_ROB1, T_ROB2, T_LOG)" in text
    assert "[RMC406]" in text and "name the task first, e.g." in text, text


def test_a_name_one_task_declares_works_unqualified(tmp_path):
    code, text = run(tmp_path, 'F "seen = 1"')
    assert code == 0 and "p: HOLDS" in text, text


def test_shared_pers_data_keeps_its_plain_name(tmp_path):
    """``go`` is declared by T_ROB1 and T_ROB2: one persistent, not two candidates."""
    code, text = run(tmp_path, 'G ("T_ROB1.go" <-> go)')
    assert code == 0 and "p: HOLDS" in text, text


def test_a_task_has_no_routine_of_another(tmp_path):
    code, text = run(tmp_path, 'G !"InRoutine(T_LOG, \\"MoveToSlot\\")"')
    assert code == 2 and "task T_LOG has no routine named 'MoveToSlot'" in text, text


def test_tasks_added_without_a_name_are_named_by_number(tmp_path):
    """``--add-task`` tasks are called ``task 2 (b)``: atoms name them TASK1, TASK2 ..."""
    module = ("MODULE M{n}\n  TASK PERS num mine := 0;\n  PROC main()\n    mine := {n};\n"
              "  ENDPROC\nENDMODULE\n")
    for n in (1, 2):
        (tmp_path / f"m{n}.mod").write_text(module.replace("{n}", str(n)))
    base = ["check", str(tmp_path / "m1.mod"), "--add-task", str(tmp_path / "m2.mod"), "--quiet"]

    def check(formula: str) -> tuple[int, str]:
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
            code = main(base + ["--formula", f"p: {formula}"])
        return code, out.getvalue()
    code, text = check('F G "mine = 2"')
    assert code == 2 and "name the task: TASK1.mine or TASK2.mine" in text, text
    assert check('F G ("TASK1.mine = 1" & "TASK2.mine = 2")')[0] == 0


def test_failed_names_the_task_whose_error_stopped_the_controller(tmp_path):
    (tmp_path / "m1.mod").write_text("MODULE M1\n  PROC main()\n    WaitTime 1;\n  ENDPROC\n"
                                     "ENDMODULE\n")
    (tmp_path / "m2.mod").write_text("MODULE M2\n  VAR num zero := 0;\n  PROC main()\n"
                                     "    zero := 1 / zero;\n  ENDPROC\nENDMODULE\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        main(["check", str(tmp_path / "m1.mod"), "--add-task", str(tmp_path / "m2.mod"),
              "--formula", 'two_fails: F "Failed(TASK2)"',
              "--formula", 'one_never: G !"Failed(TASK1)"',
              "--formula", 'controller: F "Failed()"'])
    text = out.getvalue()
    for verdict in ("two_fails: HOLDS", "one_never: HOLDS", "controller: HOLDS"):
        assert verdict in text, text


def test_waiting_without_a_task_in_a_program_of_one_task(tmp_path):
    (tmp_path / "m.mod").write_text("MODULE M\n  VAR bool go := FALSE;\n  PROC main()\n"
                                    "    WaitUntil go;\n  ENDPROC\nENDMODULE\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        main(["check", str(tmp_path / "m.mod"), "--formula", 'p: F G "Waiting()"'])
    assert "p: HOLDS" in out.getvalue(), out.getvalue()


def test_a_task_that_declares_no_such_name_says_who_does(tmp_path):
    code, text = run(tmp_path, 'G "T_LOG.slot = 1"')
    assert code == 2 and "task T_LOG declares no 'slot'" in text, text
    assert "note: declared by T_ROB1, T_ROB2" in text, text


def test_the_controller_tcp_compares_with_numbers_for_a_zone_box(tmp_path):
    (tmp_path / "r.mod").write_text(
        "MODULE R\n  CONST robtarget p1 := [[900,0,300],[1,0,0,0],[0,0,0,0],"
        "[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC main()\n    MoveJ p1, v1000, fine, tool0;\n"
        "  ENDPROC\nENDMODULE\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        main(["check", str(tmp_path / "r.mod"),
              "--formula", 'inside: F "CPos().x > 800 AND CPos().x < 1000 AND CPos().z < 400"',
              "--formula", 'outside: G !"CPos().x > 950"'])
    assert "inside: HOLDS" in out.getvalue() and "outside: HOLDS" in out.getvalue()


# --- robots: tests/task_backups/robots/backup, where T_ROB1 and T_ROB2 each move their own
# robot (the verdicts of AtTarget(T_ROB2, p10), CPos(T_ROB1).x ... are pinned by that case)

ROBOTS = Path(__file__).resolve().parent / "task_backups" / "robots" / "backup"


def run_robots(tmp_path: Path, formula: str) -> tuple[int, str]:
    props = tmp_path / "props.ltl"
    props.write_text(f"p: {formula}\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        code = main(["check", str(ROBOTS), "--ltl", str(props), "--quiet"])
    return code, out.getvalue()


@pytest.mark.parametrize("atom, example", [
    ("AtTarget(p10)", "AtTarget(T_ROB1, p10)"),
    ("CPos().x > 1000", "CPos(T_ROB1)"),
    ("CRobT().trans.z < 400", "CRobT(T_ROB1)"),
])
def test_a_robot_atom_without_a_task_is_an_error_with_a_caret(tmp_path, atom, example):
    code, text = run_robots(tmp_path, f'G !"{atom}"')
    assert code == 2, text
    name = atom.split("(")[0]
    assert f"{name} reads a robot, and each of the motion tasks T_ROB1, T_ROB2 moves its own" \
        in text and "[RMC406]" in text, text
    assert f"name the robot's task first, e.g. {example}" in text, text
    assert "props.ltl:1:8: error:" in text, text        # at the call, inside the quote


def test_a_task_that_moves_no_robot_has_no_robot_atom(tmp_path):
    code, text = run_robots(tmp_path, 'G !"CPos(T_LOG).x > 0"')
    assert code == 2 and "CPos: task T_LOG moves no robot" in text, text
    assert "the motion tasks: T_ROB1, T_ROB2" in text, text


@pytest.mark.parametrize("atom", ["CPos(T_ROB9).x > 0", "AtTarget(T_ROB9, p10)",
                                  "InRoutine(T_ROB9, main)", "Waiting(T_ROB9)"])
def test_a_task_name_no_task_has_is_named_as_such(tmp_path, atom):
    """A misspelt task where an atom takes one: the message names it as an unknown task,
    not as a missing one (whose example would put a task before the misspelt one)."""
    code, text = run_robots(tmp_path, f'G !"{atom}"')
    assert code == 2, text
    assert "no task is named T_ROB9" in text and "[RMC402]" in text, text
    assert "the tasks: T_ROB1, T_ROB2, T_LOG" in text and ", T_ROB9" not in text, text
    assert "props.ltl:1:8: error:" in text, text        # at the call, inside the quote


def test_at_target_reads_the_target_in_the_named_task(tmp_path):
    """Both tasks declare p10; T_LOG declares none."""
    code, text = run_robots(tmp_path, 'G !"AtTarget(T_LOG, p10)"')
    assert code == 2 and "AtTarget: task T_LOG moves no robot" in text, text
    assert run_robots(tmp_path, 'F ("AtTarget(T_ROB2, p10)" & "CPos(T_ROB2).x = 1500")')[0] == 0


def test_a_controller_with_one_motion_task_keeps_its_robot_atoms_unqualified(tmp_path):
    """The qualified backup's SYS.cfg marks T_ROB1 and T_ROB2 motion tasks; with a logger
    beside one robot task that moves, an unqualified robot atom reads that robot and the
    report names its task."""
    (tmp_path / "r.mod").write_text(
        "MODULE R\n  CONST robtarget p1 := [[900,0,300],[1,0,0,0],[0,0,0,0],"
        "[9E9,9E9,9E9,9E9,9E9,9E9]];\n  PROC main()\n    MoveJ p1, v1000, fine, tool0;\n"
        "  ENDPROC\nENDMODULE\n")
    (tmp_path / "log.mod").write_text("MODULE L\n  VAR num n := 0;\n  PROC main()\n"
                                      "    n := 1;\n  ENDPROC\nENDMODULE\n")
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(out):
        code = main(["check", str(tmp_path / "r.mod"), "--add-task", str(tmp_path / "log.mod"),
                     "--formula", 'at: G !"AtTarget(p1)"',
                     "--formula", 'box: F "CPos(TASK1).x > 800"'])
    text = out.getvalue()
    assert code == 1 and "at: VIOLATED" in text and "box: HOLDS" in text, text
    assert 'atoms: "AtTarget(p1)" (TASK1)' in text, text
