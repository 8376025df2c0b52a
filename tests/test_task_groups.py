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
from rapidmc.model.reduction import task_groups
from rapidmc.model.reduction.partial_order import PartialOrder

from task_group_programs import group_properties, group_tasks
from test_partial_order import check_json, never_reached, states, verdicts

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")


def write_group_tasks(folder: Path, seed: int) -> list[str]:
    argv = []
    for number, text in enumerate(group_tasks(seed, chain=seed % 2 == 1), start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    spec = folder / "props.ltl"
    spec.write_text("\n".join(group_properties(seed)) + "\n")
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
    monkeypatch.setattr(task_groups.TaskGroups, "candidates", lambda self, stacks, running: ())
    alone = check_json(argv)
    assert verdicts(grouped) == verdicts(full) == verdicts(alone)
    assert states(grouped)["no_runtime_error"] < states(alone)["no_runtime_error"] < \
        states(full)["no_runtime_error"]
