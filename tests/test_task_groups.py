"""Ample sets of several tasks (``reduction.task_groups``, issue 27) keep every verdict.

Differential: programs of four tasks in two pairs (tests/task_group_programs.py),
where at most states no task is independent of all others, are checked with
the reduction and with ``--no-por``: the same verdicts (the built-in checks
included) and the same lines never reached; both engines give the same
reports.  Besides: which tasks an instruction conflicts with, and that the
groups leave out states the one-task ample sets keep.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.api import load_program
from rapidmc.check import native
from rapidmc.model.reduction import cell_uses, task_groups
from rapidmc.model.reduction.partial_order import PartialOrder

from task_group_programs import group_properties, group_tasks
from test_partial_order import check_json, never_reached, states, verdicts

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")


def write_group_tasks(folder: Path, seed: int, cell: bool = False) -> list[str]:
    argv = []
    for number, text in enumerate(group_tasks(seed, chain=seed % 2 == 1, cell=cell),
                                  start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    spec = folder / "props.ltl"
    spec.write_text("\n".join(group_properties(seed, cell)) + "\n")
    return argv + ["--ltl", str(spec), "--max-states", "40000"]


@pytest.mark.parametrize("seed", range(24))
def test_generated_pairs_of_tasks_keep_their_verdicts(tmp_path, seed):
    argv = write_group_tasks(tmp_path, seed)
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    assert never_reached(reduced) == never_reached(full)


@needs_native
@pytest.mark.parametrize("seed", [0, 1, 5, 8, 9, 12])
def test_generated_pairs_of_tasks_report_the_same_with_both_engines(seed, tmp_path,
                                                                     monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_group_tasks(tmp_path, seed), monkeypatch,
                                   reuse=seed % 3 != 0)
    assert document["properties"]


# the seeds of 0-19 whose unreduced search ends within the bound (1, 6, 9 and 11 reach it)
CELL_SEEDS = [seed for seed in range(20) if seed not in (1, 6, 9, 11)]


@pytest.mark.parametrize("seed", CELL_SEEDS)
def test_generated_tasks_on_signals_and_robots_keep_their_verdicts(tmp_path, seed):
    """Signals one task of a pair sets and the other reads (or waits for), free inputs
    and outputs of one task only, readings of the task's own robot, of a task no task is
    named (the caller's), and of another motion task's robot (``cell_uses``)."""
    argv = write_group_tasks(tmp_path, seed, cell=True)
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    assert never_reached(reduced) == never_reached(full)


@needs_native
@pytest.mark.parametrize("seed", [0, 3, 6, 11])
def test_generated_tasks_on_signals_and_robots_report_the_same_with_both_engines(
        seed, tmp_path, monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_group_tasks(tmp_path, seed, cell=True),
                                   monkeypatch, reuse=seed % 2 == 0)
    assert document["properties"]


CELL_READER = """MODULE Reader
  VAR num seen := 0;
  PROC main()
    IF {reading} THEN
      seen := 1;
    ENDIF
  ENDPROC
ENDMODULE
"""
CELL_WRITER = """MODULE Writer
  CONST robtarget pFar := [[510,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    {writing}
  ENDPROC
ENDMODULE
"""
CELL_MOVER = CELL_WRITER.replace("Writer", "Mover")


def write_cell_tasks(folder: Path, reading: str, writing: str) -> list[str]:
    """A reader of a signal or a robot, a task writing it, a task moving its own robot."""
    texts = (CELL_READER.format(reading=reading), CELL_WRITER.format(writing=writing),
             CELL_MOVER.format(writing="MoveJ pFar, v100, fine, tool0;"))
    argv = []
    for number, text in enumerate(texts, start=1):
        path = folder / f"cell{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    return argv + ["--formula", 'never_seen: G "seen = 0"']


@pytest.mark.parametrize("reading, writing, conflicts", [
    ("doLamp = 1", "Set doLamp;", {1}),                      # the task setting it
    ("diFree = 1 AND doLamp = 0", "Set doOther;", set()),    # nobody sets them
    ('CRobT(\\TaskName:="task 3 (cell3)").trans.x > 505', "Set doOther;", {2}),   # its mover
    ('CRobT(\\TaskName:="T_GANTRY").trans.x > 505', "MoveJ pFar, v100, fine, tool0;", set()),
])
def test_a_reading_conflicts_with_the_tasks_that_change_what_it_reads(tmp_path, reading,
                                                                     writing, conflicts):
    argv = write_cell_tasks(tmp_path, reading, writing)
    program = load_program([argv[0]], add_tasks=argv[2:6:2])
    order = PartialOrder(program, set())
    main = program.entry
    assert order.groups.conflicts(0, main, 0) == frozenset(conflicts)


@pytest.mark.parametrize("reading, writing, mutant", [
    ("doLamp = 1", "Set doLamp;", "signal_readable"),
    ('CRobT(\\TaskName:="task 2 (cell2)").trans.x > 505', "MoveJ pFar, v100, fine, tool0;",
     "robot_readable"),
])
def test_a_reading_taken_as_independent_loses_a_violation(tmp_path, monkeypatch, reading,
                                                          writing, mutant):
    """The differential tests can fail: with a signal (a robot) read as if no task set
    (moved) it, the reader's step alone is ample at the start, reads the first value and
    ends, and ``seen = 1`` is never reached, which the writer's step first makes possible."""
    argv = write_cell_tasks(tmp_path, reading, writing)
    expected = {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "never_seen": "VIOLATED"}
    assert verdicts(check_json(argv)) == verdicts(check_json(argv + ["--no-por"])) == expected
    monkeypatch.setattr(cell_uses.CellView, mutant, lambda self, task, what: True)
    assert verdicts(check_json(argv))["never_seen"] == "HOLDS"


def test_a_move_of_a_robot_another_task_reads_is_shared(tmp_path):
    """A move writes its task's robot only: it conflicts with the tasks reading that robot
    (``CRobT(\\TaskName:=...)``), and with no task where none does (``cell_uses.readers``)."""
    argv = write_cell_tasks(tmp_path, 'CRobT(\\TaskName:="task 2 (cell2)").trans.x < 505',
                            "MoveJ pFar, v100, fine, tool0;")
    program = load_program([argv[0]], add_tasks=argv[2:6:2])
    order = PartialOrder(program, set())
    mover, still = (program.task_entries[number] for number in (0, 1))
    assert order.groups.conflicts(1, mover, 0) == frozenset({0})    # read by the reader
    assert order.is_ample_candidate(2, still, 0)                    # read by no task


def test_a_move_taken_as_its_own_loses_a_violation(tmp_path, monkeypatch):
    """The differential tests can fail: with the mover's robot taken as its own although
    the reader reads it, the move alone is ample at the start, the reader sees the robot
    moved, and ``seen = 1`` (read before the move) is never reached."""
    argv = write_cell_tasks(tmp_path, 'CRobT(\\TaskName:="task 2 (cell2)").trans.x < 505',
                            "MoveJ pFar, v100, fine, tool0;")
    expected = {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "never_seen": "VIOLATED"}
    assert verdicts(check_json(argv)) == verdicts(check_json(argv + ["--no-por"])) == expected
    monkeypatch.setattr(cell_uses.CellView, "robot_own", lambda self, task: True)
    assert verdicts(check_json(argv))["never_seen"] == "HOLDS"


HANDSHAKE = """MODULE Task{n}
  PERS bool ready{pair} := FALSE;
  PERS num link{pair} := 0;
  VAR num own{n} := 0;
  PROC main()
    FOR i FROM 1 TO 3 DO
      WaitUntil ready{pair} = {waits};
      own{n} := (own{n} + 1) MOD 2;
      link{pair} := (link{pair} + own{n}) MOD 3;
      ready{pair} := {sets};
    ENDFOR
  ENDPROC
ENDMODULE
"""


def write_handshakes(folder: Path) -> list[str]:
    """Two pairs of tasks, each pair handing a flag back and forth."""
    argv = []
    for n, pair, waits, sets in ((1, 12, "FALSE", "TRUE"), (2, 12, "TRUE", "FALSE"),
                                 (3, 34, "FALSE", "TRUE"), (4, 34, "TRUE", "FALSE")):
        path = folder / f"task{n}.mod"
        path.write_text(HANDSHAKE.format(n=n, pair=pair, waits=waits, sets=sets))
        argv += [str(path)] if n == 1 else ["--add-task", str(path)]
    return argv


def test_an_instruction_conflicts_with_the_tasks_naming_its_data(tmp_path):
    argv = write_handshakes(tmp_path)
    program = load_program([argv[0]], add_tasks=argv[2::2])
    order = PartialOrder(program, set())
    main = program.entry
    lines = {instruction.span.line: pc
             for pc, instruction in enumerate(program.routines[main].code)}
    # the wait for the pair's flag, the write of the pair's data: task 2 only (tasks 3
    # and 4 never name it); the task's own count: no other task (a one-task ample set)
    assert order.groups.conflicts(0, main, lines[7]) == frozenset({1})
    assert order.groups.conflicts(0, main, lines[10]) == frozenset({1})
    assert order.groups.conflicts(0, main, lines[8]) == frozenset()
    # an atom's data: no group (C2)
    visible = PartialOrder(program, {"READY12"})
    assert visible.groups.conflicts(0, main, lines[10]) is None


def test_groups_leave_out_states_one_task_ample_sets_keep(tmp_path, monkeypatch):
    argv = write_handshakes(tmp_path)
    grouped, full = check_json(argv), check_json(argv + ["--no-por"])
    monkeypatch.setattr(task_groups.TaskGroups, "candidates", lambda self, stacks, running, state: ())
    alone = check_json(argv)
    assert verdicts(grouped) == verdicts(full) == verdicts(alone)
    assert states(grouped)["no_runtime_error"] < states(alone)["no_runtime_error"] < \
        states(full)["no_runtime_error"]


MOVER = """MODULE Mover{n}
  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PERS num served{n} := 0;
  PROC main()
    FOR i FROM 1 TO 3 DO
      MoveJ Offs(pHome, i * 10, 0, 0), v100, fine, tool0;
      MoveL Offs(pHome, i * 10, {n} * 10, 0), v100, fine, tool0;
    ENDFOR
    served{n} := 1;
  ENDPROC
ENDMODULE
"""


def test_moves_of_robots_no_other_task_reads_leave_out_states(tmp_path, monkeypatch):
    """Three motion tasks, each moving its own robot (read by no other task): their moves
    are not interleaved (a one-task ample set each), which ``robot_own`` allows."""
    argv = []
    for n in (1, 2, 3):
        path = tmp_path / f"mover{n}.mod"
        path.write_text(MOVER.format(n=n))
        argv += [str(path)] if n == 1 else ["--add-task", str(path)]
    argv += ["--formula", 'all_served: F "served1 = 1"']
    own, full = check_json(argv), check_json(argv + ["--no-por"])
    monkeypatch.setattr(cell_uses.CellView, "robot_own", lambda self, task: False)
    shared = check_json(argv)
    assert verdicts(own) == verdicts(full) == verdicts(shared)
    assert states(own)["no_runtime_error"] < states(shared)["no_runtime_error"] <= \
        states(full)["no_runtime_error"]
