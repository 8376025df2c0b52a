"""Tasks held at a barrier by another task (``reduction.barrier_holds``, issue 27).

Three tasks meet at two barriers: the main task sets the task list (as a
controller task does before its partners start; in one variant no code writes it),
then fills a shared buffer between
them, a reader waits at the second one and then reads the buffer, a logger counts
on its own data.  While the reader waits for the main task, the main task's writes
of the buffer are its ample set alone (``PartialOrder.held_candidate``).  Differential: the reduced search and
``--no-por`` give the same verdicts (the built-in checks, a safety and a liveness
property), on both engines, for a program that keeps its barriers (HOLDS), one
whose reader reads before the barrier (a race: VIOLATED), one whose main task
leaves the second barrier out (deadlock: VIOLATED) and one whose logger empties the
task list's entry of the main task, which lets the reader pass without it (VIOLATED),
and one whose reader waits at a barrier for the logger alone, which meets it once the
main task has started writing (VIOLATED: the reader may read a part of the buffer; a
task taken as held by one it does not wait for misses that run).
Without the holds, the same verdicts in more states; which tasks a task holds, as a
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
  PERS num started := 0;
  PROC main()
    {set_list}
    WaitSyncTask ready, all;
    {start}
    buf{{1}} := 1;
    buf{{2}} := 2;
    buf{{3}} := 3;
    {second}
  ENDPROC
ENDMODULE
"""

# what the reader and the logger declare: the three barriers' syncidents and two lists
PARTNERS = f"""  VAR syncident ready;
  VAR syncident filled;
  VAR syncident pair;
  PERS tasks all{{3}} := {TASKS};
  PERS tasks pairs{{2}} := [["task 2 (reader)"], ["task 3 (logger)"]];
"""

READER = """MODULE Reader
{partners}  PERS num buf{{3}} := [0, 0, 0];
  VAR num seen := 0;
  PROC main()
    WaitSyncTask ready, all;
    {first}
    {then}
  ENDPROC
ENDMODULE
"""

LOGGER = """MODULE Logger
{partners}  PERS num started := 0;
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
PAIR = "WaitSyncTask pair, pairs;"
# the logger meets the reader once the main task has started filling the buffer
STARTED_PAIR = "WaitUntil started = 1;\n    " + PAIR

VARIANTS = {
    # name: (main task's second barrier, reader's first and then, logger's shrink)
    "kept": (BARRIER, BARRIER, READ, ""),
    # no loaded code writes the list: data written from outside, its names compared with
    # nothing, so every read takes the stored value (``load.outside_data``)
    "list_outside": (BARRIER, BARRIER, READ, ""),
    "race": (BARRIER, READ, BARRIER, ""),
    "left_out": ("", BARRIER, READ, ""),
    "list_emptied": (BARRIER, BARRIER, READ, SHRINK),
    # the reader waits for the logger alone, which waits for the main task to start
    # writing the buffer: the main task holds neither, and the reader may read a part
    "pair": ("", PAIR, READ, STARTED_PAIR),
}

EXPECTED = {
    "kept": {"whole": "HOLDS", "read_ends": "HOLDS", "no_deadlock": "HOLDS"},
    "list_outside": {"whole": "HOLDS", "read_ends": "HOLDS", "no_deadlock": "HOLDS"},
    # (the reader may read before the first write: seen stays 0)
    "race": {"whole": "VIOLATED", "read_ends": "VIOLATED", "no_deadlock": "HOLDS"},
    "left_out": {"whole": "HOLDS", "read_ends": "VIOLATED", "no_deadlock": "VIOLATED"},
    "list_emptied": {"whole": "VIOLATED", "read_ends": "VIOLATED", "no_deadlock": "HOLDS"},
    # (the logger waits at the second barrier for the main task, which has ended)
    "pair": {"whole": "VIOLATED", "read_ends": "VIOLATED", "no_deadlock": "VIOLATED"},
}


def write_cell(folder: Path, variant: str) -> list[str]:
    second, first, then, shrink = VARIANTS[variant]
    set_list = "" if variant == "list_outside" else f"all := {TASKS};"
    start = "started := 1;" if variant == "pair" else ""
    texts = {"filler": FILLER.format(tasks=TASKS, second=second, set_list=set_list,
                                     start=start),
             "reader": READER.format(partners=PARTNERS, first=first, then=then),
             "logger": LOGGER.format(partners=PARTNERS, shrink=shrink)}
    # the reader sees the whole buffer or nothing; the reader's sum is taken at last
    return write_tasks(folder, texts, 'whole: G ("seen = 0" || "seen = 6")\n'
                                      'read_ends: F "seen <> 0"\n')


def write_tasks(folder: Path, texts: dict, properties: str) -> list[str]:
    """The arguments of a check of the modules ``texts`` (name -> text), one task each,
    the first the main task, against ``properties``."""
    argv = []
    for name, text in texts.items():
        path = folder / f"{name}.mod"
        path.write_text(text)
        argv += ["--add-task", str(path)] if argv else [str(path)]
    spec = folder / "props.ltl"
    spec.write_text(properties)
    return argv + ["--ltl", str(spec), "--max-states", "40000"]


def assert_reduction_keeps(argv: list[str], expected: dict) -> None:
    """The reduced search and ``--no-por`` give the same verdicts, those ``expected``
    names as expected (the unreduced search complete)."""
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    found = verdicts(full)
    assert {name: found[name] for name in expected} == expected


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_held_tasks_keep_the_verdicts(tmp_path, variant):
    assert_reduction_keeps(write_cell(tmp_path, variant), EXPECTED[variant])


@needs_native
@pytest.mark.parametrize("variant", ["kept", "list_outside", "list_emptied", "pair"])
def test_held_tasks_report_the_same_with_both_engines(variant, tmp_path, monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_cell(tmp_path, variant), monkeypatch,
                                   reuse=False)
    assert document["properties"]


def test_a_task_held_at_its_barrier_leaves_out_states(tmp_path, monkeypatch):
    """(Where the main task's own code sets the list, ``kept``, it may change it, and
    no one is held by it.)"""
    argv = write_cell(tmp_path, "list_outside")
    held = check_json(argv)
    monkeypatch.setattr(barrier_holds.BarrierHolds, "waiting",
                        lambda self, state, stacks, running: ())
    unheld = check_json(argv)
    assert verdicts(held) == verdicts(unheld)
    assert states(held)["no_runtime_error"] < states(unheld)["no_runtime_error"]


def test_a_list_its_writer_may_change_holds_no_one():
    """(task, whom it waits for, who may write its list): task 1 waits for task 0, its
    list written by task 2 only.  Held while task 2 is held itself or has ended; not
    while task 2 runs, which could let it pass (the ``list_emptied`` program)."""
    waiting = ((1, frozenset({0}), frozenset({2})),)
    assert barrier_holds.held(waiting, 0, frozenset({0, 1, 2})) == frozenset()
    assert barrier_holds.held(waiting, 0, frozenset({0, 1})) == frozenset({1})
    both = waiting + ((2, frozenset({0}), frozenset({1})),)
    assert barrier_holds.held(both, 0, frozenset({0, 1, 2})) == frozenset({1, 2})
    # the task's own code writing the list: it may let the waiter pass
    assert barrier_holds.held(((1, frozenset({0}), frozenset({0})),), 0,
                              frozenset({0, 1})) == frozenset()
    # waiting for another task: not held by this one
    assert barrier_holds.held(((1, frozenset({3}), frozenset()),), 0,
                              frozenset({0, 1, 3})) == frozenset()
