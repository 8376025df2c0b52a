"""Several RAPID tasks: shared (non-TASK) PERS data, one task steps at a time."""
from __future__ import annotations

import json
from pathlib import Path

from rapidmc.cli import main

ROBOT = """MODULE RobotTask
  PERS bool part_ready := FALSE;
  PERS num parts := 0;
  PROC main()
    WHILE parts < 3 DO
      WaitUntil part_ready;
      parts := parts + 1;
      TPWrite "robot took part " \\Num:=parts;
      part_ready := FALSE;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

FEEDER = """MODULE Feeder
  PERS bool part_ready := FALSE;
  VAR num fed := 0;
  PROC main()
    WHILE fed < 3 DO
      WaitUntil NOT part_ready;
      fed := fed + 1;
      part_ready := TRUE;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

COUNTER = """MODULE Counter{n}
  PERS num count := 0;
  TASK PERS num mine := 0;
  PROC main()
    VAR num copy;
    FOR i FROM 1 TO 2 DO
      copy := count;
      count := copy + 1;
      mine := mine + 1;
    ENDFOR
  ENDPROC
ENDMODULE
"""


def files(tmp_path: Path, **modules: str) -> dict[str, str]:
    paths = {}
    for name, text in modules.items():
        path = tmp_path / f"{name}.mod"
        path.write_text(text)
        paths[name] = str(path)
    return paths


def verdicts(capsys, *argv) -> tuple[int, dict]:
    code = main(["check", *argv, "--quiet", "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    return code, {p["name"]: p["verdict"] for p in report["properties"]}


def test_tasks_hand_over_through_a_shared_persistent_when_run(tmp_path, capsys):
    f = files(tmp_path, robot=ROBOT, feeder=FEEDER)
    assert main(["run", f["robot"], "--add-task", f["feeder"]]) == 0
    assert capsys.readouterr().out == "".join(f"robot took part {n}\n" for n in (1, 2, 3))


def test_a_waiting_task_does_not_starve_the_other_when_checked(tmp_path, capsys):
    f = files(tmp_path, robot=ROBOT, feeder=FEEDER)
    code, result = verdicts(capsys, f["robot"], "--add-task", f["feeder"],
                            "--formula", 'done: F "parts = 3"',
                            "--formula", 'bounded: G "parts <= 3"')
    assert code == 0
    assert result == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS",
                      "done": "HOLDS", "bounded": "HOLDS"}


def test_a_lost_update_between_tasks_is_found(tmp_path, capsys):
    f = files(tmp_path, a=COUNTER.format(n="A"), b=COUNTER.format(n="B"))
    code, result = verdicts(capsys, f["a"], "--add-task", f["b"],
                            "--formula", 'all_counted: F G "count = 4"',
                            "--formula", 'own_count: F G "TASK1.mine = 2"')
    assert code == 1
    assert result["all_counted"] == "VIOLATED"      # both read count before either writes it
    assert result["own_count"] == "HOLDS"           # TASK PERS: each task has its own


def test_tasks_waiting_for_each_other_deadlock(tmp_path, capsys):
    first = "MODULE First\n  PERS bool a_done := FALSE;\n  PERS bool b_done := FALSE;\n" \
            "  PROC main()\n    WaitUntil b_done;\n    a_done := TRUE;\n  ENDPROC\nENDMODULE\n"
    second = "MODULE Second\n  PERS bool a_done := FALSE;\n  PERS bool b_done := FALSE;\n" \
             "  PROC main()\n    WaitUntil a_done;\n    b_done := TRUE;\n  ENDPROC\nENDMODULE\n"
    f = files(tmp_path, first=first, second=second)
    code, result = verdicts(capsys, f["first"], "--add-task", f["second"])
    assert code == 1 and result["no_deadlock"] == "VIOLATED"
    assert main(["run", f["first"], "--add-task", f["second"]]) == 1
    assert "deadlock" in capsys.readouterr().err


MOVER = """MODULE Mover{n}
  CONST robtarget there := [[{x},0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    MoveJ there, v1000, fine, tool0;
    WaitUntil CPos().x {wait};
    TPWrite "robot {n} at " \\Num:=CPos().x;
  ENDPROC
ENDMODULE
"""


def test_each_task_that_moves_reads_and_moves_its_own_robot(tmp_path, capsys):
    """Two tasks that move (motion tasks by their move instructions: no backup configures
    them) each keep their robot: each waits for a position only the other's robot has, so
    both wait for ever; with one robot for both tasks one of them would go on."""
    f = files(tmp_path, a=MOVER.format(n=1, x=900, wait="< 100"),
              b=MOVER.format(n=2, x=50, wait="> 800"))
    code, result = verdicts(capsys, f["a"], "--add-task", f["b"],
                            "--formula", 'one: G "CPos(TASK1).x = 0 OR CPos(TASK1).x = 900"',
                            "--formula", 'two: F "CPos(TASK2).x = 50"')
    assert code == 1 and result["no_deadlock"] == "VIOLATED", result
    assert result["one"] == result["two"] == "HOLDS", result
    f = files(tmp_path, a=MOVER.format(n=1, x=900, wait="> 800"),
              b=MOVER.format(n=2, x=50, wait="< 100"))
    assert main(["run", f["a"], "--add-task", f["b"]]) == 0
    assert sorted(capsys.readouterr().out.splitlines()) == ["robot 1 at 900", "robot 2 at 50"]


def test_a_backup_with_all_tasks(tmp_path, capsys):
    backup = tmp_path / "backup"
    for task, text in (("T_ROB1", ROBOT), ("T_FEED", FEEDER)):
        folder = backup / "RAPID" / task / "PROGMOD"
        folder.mkdir(parents=True)
        (folder / "Main.mod").write_text(text)
    assert main(["run", str(backup), "--task", "T_ROB1", "--all-tasks"]) == 0
    assert capsys.readouterr().out.count("robot took part") == 3


def test_environment_code_reading_the_robot_of_two_motion_tasks_is_a_modelling_error(
        tmp_path, capsys):
    """No task steps while the environment reacts: which robot CPos() means is not guessed."""
    f = files(tmp_path, a=MOVER.format(n=1, x=900, wait="> 800"),
              b=MOVER.format(n=2, x=50, wait="< 100"),
              env="MODULE Env\n  VAR signaldi di1;\n  PROC react()\n"
                  "    IF CPos().x > 800 SetDI di1, 1;\n  ENDPROC\nENDMODULE\n")
    assert main(["check", f["a"], "--add-task", f["b"], "--env", f["env"]]) == 2
    err = capsys.readouterr().err
    assert "ERR_NOT_MOVETASK" in err and "[RMC503]" in err, err
    assert "each of the motion tasks main task, task 2 (b) moves its own" in err, err
    assert main(["check", f["a"], "--env", f["env"], "--quiet"]) == 0   # one robot: read


CATCHER = """MODULE Catcher
  PERS bool caught := FALSE;
  VAR num zero := 0;
  VAR num q := 0;
  PROC main()
    q := 1 / zero;
    TPWrite "catcher ERRNO " \\Num:=ERRNO;
    caught := TRUE;
  ERROR
    TRYNEXT;
  ENDPROC
ENDMODULE
"""

LOOKER = """MODULE Looker
  PERS bool caught := FALSE;
  PROC main()
    WaitUntil caught;
    TPWrite "looker ERRNO " \\Num:=ERRNO;
  ENDPROC
ENDMODULE
"""


def test_each_task_has_its_own_errno_when_run(tmp_path, capsys):
    """``rapidmc run`` steps the tasks in turn on one machine: the error the catcher's
    handler caught sets the catcher's ERRNO only (semantics.task_registers)."""
    f = files(tmp_path, catcher=CATCHER, looker=LOOKER)
    assert main(["run", f["catcher"], "--add-task", f["looker"]]) == 0
    assert capsys.readouterr().out.splitlines() == ["catcher ERRNO 1001", "looker ERRNO 0"]
