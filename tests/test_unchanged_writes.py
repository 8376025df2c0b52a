"""A write of the value already stored joins a group of tasks (``reduction.unchanged_writes``).

The taeyangshim start-up handshake, in small (``test_empty_deletes``'s): a commander
clears its command (it is clear already) and waits until every worker reports Ready;
each worker clears its report, waits for the command to be clear, reports Ready, then
serves one command.
Checked there (tests/test_empty_deletes.py, ``RULES``) with the reduction and with
``--no-por``: the same verdicts (HOLDS and VIOLATED, LTL formulas and ``no_deadlock``),
fewer states than with the rule off, the same reports with both engines.  Here: a
mutant taking every write of a constant to the task's own data as changing nothing
loses a violation (a command written before a reader looked).
"""
from __future__ import annotations

from pathlib import Path

from rapidmc.api import load_program
from rapidmc.model.reduction import unchanged_writes
from rapidmc.model.reduction.partial_order import PartialOrder

from test_empty_deletes import CLEARING_TWICE, always_idle, task_files, write_handshake
from test_partial_order import check_json, verdicts

SENDER = """MODULE Sender
  PERS string stCommand := "";
  PERS num stage := 0;
  PROC main()
    stCommand := "Go";
    stage := 1;
  ENDPROC
ENDMODULE
"""
LOOKER = """MODULE Looker{n}
  PERS string stCommand := "";
  VAR num seen{n} := 0;
  PROC main()
    IF stCommand = "" seen{n} := 1;
  ENDPROC
ENDMODULE
"""


def test_a_write_of_a_new_value_taken_as_unchanged_loses_a_violation(tmp_path, monkeypatch):
    """The differential tests can fail: with every write of a constant to the task's own
    data taken as changing nothing, the sender's ``stCommand := "Go"`` alone is ample
    at the start, and no looker sees the command still clear."""
    argv = task_files(tmp_path, [SENDER, LOOKER.format(n=1), LOOKER.format(n=2)]) + \
        ["--formula", 'unseen: G "seen1 = 0"']
    assert verdicts(check_json(argv))["unseen"] == "VIOLATED"
    assert verdicts(check_json(argv + ["--no-por"]))["unseen"] == "VIOLATED"
    always_idle(monkeypatch, unchanged_writes.UnchangedWrites)
    assert verdicts(check_json(argv))["unseen"] == "HOLDS"


def test_only_a_constant_to_data_no_other_task_writes_is_judged_per_state(tmp_path):
    argv = write_handshake(tmp_path, 1, "Ack", CLEARING_TWICE)
    program = load_program([argv[0]], add_tasks=argv[2:8:2])
    order = PartialOrder(program, {"STAGE"})
    writes = order.groups.writes
    main = program.routines[program.entry]
    clears, staged = [pc for pc, instruction in enumerate(main.code)
                      if instruction.span is not None and instruction.span.line in (6, 9)]
    reader = writes.reader(0, main.index, clears)
    assert reader is not None and order.groups.may_join(0, main.index, clears)
    assert writes.reader(0, main.index, staged) is None       # (an atom names it)
    assert writes.reader(1, main.index, clears) is None       # (not the task's routine)
    worker = next(routine for routine in program.routines
                  if routine.name.upper() == "MAIN" and order.task_of_routine(
                      routine.index) == 1)
    assert writes.reader(1, worker.index, 0) is None          # (an element of shared data)
