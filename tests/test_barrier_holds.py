"""Tasks held at a barrier stay out of a group (``reduction.barrier_holds``, issue 27).

Three tasks meet at two barriers: the main task sets the task list (as a
controller task does before its partners start; in one variant no code writes it),
then fills a shared buffer between
them, a reader waits at the second one and then reads the buffer, a logger counts
on its own data.  While the reader waits for the main task, the main task's writes
of the buffer are a group of their own.  Differential: the reduced search and
``--no-por`` give the same verdicts (the built-in checks, a safety and a liveness
property), on both engines, for a program that keeps its barriers (HOLDS), one
whose reader reads before the barrier (a race: VIOLATED), one whose main task
leaves the second barrier out (deadlock: VIOLATED) and one whose logger empties the
task list's entry of the main task, which lets the reader pass without it (VIOLATED).
Without the holds, the same verdicts in more states; which tasks a group holds, as a
greatest fixpoint over the task lists' writers.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.check import native
from rapidmc.model.reduction import barrier_holds

from test_partial_order import check_json, states, verdicts

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")

TASKS = '[["T_ROB1"], ["task 2 (reader)"], ["task 3 (logger)"]]'

FILLER = """MODULE Filler
  VAR syncident ready;
  VAR syncident filled;
  PERS tasks all{{3}} := {tasks};
  PERS num buf{{3}} := [0, 0, 0];
  PROC main()
    {set_list}
    WaitSyncTask ready, all;
    buf{{1}} := 1;
    buf{{2}} := 2;
    buf{{3}} := 3;
    {second}
  ENDPROC
ENDMODULE
"""

READER = """MODULE Reader
  VAR syncident ready;
  VAR syncident filled;
  PERS tasks all{{3}} := {tasks};
  PERS num buf{{3}} := [0, 0, 0];
  VAR num seen := 0;
  PROC main()
    WaitSyncTask ready, all;
    {first}
    {then}
  ENDPROC
ENDMODULE
"""

LOGGER = """MODULE Logger
  VAR syncident ready;
  VAR syncident filled;
  PERS tasks all{{3}} := {tasks};
  VAR num count := 0;
  PROC main()
    WaitSyncTask ready, all;
    FOR i FROM 1 TO 3 DO
      count := count + 1;
    ENDFOR
    {shrink}
    WaitSyncTask filled, all;
  ENDPROC
ENDMODULE
"""

BARRIER = "WaitSyncTask filled, all;"
READ = "seen := buf{1} + buf{2} + buf{3};"
SHRINK = 'all := [[""], ["task 2 (reader)"], ["task 3 (logger)"]];'

VARIANTS = {
    # name: (main task's second barrier, reader's first and then, logger's shrink)
    "kept": (BARRIER, BARRIER, READ, ""),
    # no loaded code writes the list: data written from outside, its names compared with
    # nothing, so every read takes the stored value (``load.outside_data``)
    "list_outside": (BARRIER, BARRIER, READ, ""),
    "race": (BARRIER, READ, BARRIER, ""),
    "left_out": ("", BARRIER, READ, ""),
    "list_emptied": (BARRIER, BARRIER, READ, SHRINK),
}

EXPECTED = {
    "kept": {"whole": "HOLDS", "read_ends": "HOLDS", "no_deadlock": "HOLDS"},
    "list_outside": {"whole": "HOLDS", "read_ends": "HOLDS", "no_deadlock": "HOLDS"},
    # (the reader may read before the first write: seen stays 0)
    "race": {"whole": "VIOLATED", "read_ends": "VIOLATED", "no_deadlock": "HOLDS"},
    "left_out": {"whole": "HOLDS", "read_ends": "VIOLATED", "no_deadlock": "VIOLATED"},
    "list_emptied": {"whole": "VIOLATED", "read_ends": "VIOLATED", "no_deadlock": "HOLDS"},
}


def write_cell(folder: Path, variant: str) -> list[str]:
    second, first, then, shrink = VARIANTS[variant]
    set_list = "" if variant == "list_outside" else f"all := {TASKS};"
    texts = {"filler": FILLER.format(tasks=TASKS, second=second, set_list=set_list),
             "reader": READER.format(tasks=TASKS, first=first, then=then),
             "logger": LOGGER.format(tasks=TASKS, shrink=shrink)}
    argv = []
    for name, text in texts.items():
        path = folder / f"{name}.mod"
        path.write_text(text)
        argv += [str(path)] if name == "filler" else ["--add-task", str(path)]
    spec = folder / "props.ltl"
    # the reader sees the whole buffer or nothing; the reader's sum is taken at last
    spec.write_text('whole: G ("seen = 0" || "seen = 6")\n'
                    'read_ends: F "seen <> 0"\n')
    return argv + ["--ltl", str(spec), "--max-states", "40000"]


def _compared(document: dict, expected: dict) -> dict:
    found = verdicts(document)
    return {name: found[name] for name in expected}


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_held_tasks_keep_the_verdicts(tmp_path, variant):
    argv = write_cell(tmp_path, variant)
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    assert _compared(full, EXPECTED[variant]) == EXPECTED[variant]


@needs_native
@pytest.mark.parametrize("variant", ["kept", "list_outside", "list_emptied"])
def test_held_tasks_report_the_same_with_both_engines(variant, tmp_path, monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_cell(tmp_path, variant), monkeypatch,
                                   reuse=False)
    assert document["properties"]


@pytest.mark.parametrize("variant", ["kept", "list_outside"])
def test_a_task_held_at_its_barrier_leaves_out_states(tmp_path, monkeypatch, variant):
    argv = write_cell(tmp_path, variant)
    held = check_json(argv)
    monkeypatch.setattr(barrier_holds.BarrierHolds, "waiting",
                        lambda self, state, stacks, running: ())
    unheld = check_json(argv)
    assert verdicts(held) == verdicts(unheld)
    assert states(held)["no_runtime_error"] < states(unheld)["no_runtime_error"]


def test_a_list_its_writer_may_change_holds_no_one(monkeypatch):
    """(task, whom it waits for, who may write its list): task 1 waits for task 0 of
    the group, its list written by task 2 only.  Held while task 2 is in the group,
    held itself, or ended; not while task 2 runs outside the group, which could let
    it pass (the ``list_emptied`` program).  With the writers left unchecked it is
    held there too."""
    waiting = ((1, frozenset({0}), frozenset({2})),)
    assert barrier_holds.held(waiting, {0}, {0, 1, 2}) == frozenset()
    assert barrier_holds.held(waiting, {0, 2}, {0, 1, 2}) == frozenset({1})
    assert barrier_holds.held(waiting, {0}, {0, 1}) == frozenset({1})
    both = waiting + ((2, frozenset({0}), frozenset({1})),)
    assert barrier_holds.held(both, {0}, {0, 1, 2}) == frozenset({1, 2})
    # waiting for a task outside the group: not held by it
    assert barrier_holds.held(((1, frozenset({3}), frozenset()),), {0}, {0, 1, 3}) == \
        frozenset()
    monkeypatch.setattr(barrier_holds, "_writers_held", lambda writers, group, found: True)
    assert barrier_holds.held(waiting, {0}, {0, 1, 2}) == frozenset({1})
