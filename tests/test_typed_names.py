"""GetDataVal reaches only data of its Value's type (``reduction.typed_names``, issue 27).

Three tasks meet at two barriers, as the COMPAS RRC controller tasks do: a writer's
init routine sets a PERS flag and a PERS level (1, then 2) between them, the robot
(the main task, which declares both and names only the level in its code) reads data by
name with GetDataVal before the second barrier and the level after it, a logger counts
on its own data.  Where the robot's GetDataVal reads
a tooldata, the writer's init writes (a bool, a num) are independent of it and the
reduction takes them alone; where it reads the level by name before the barrier, it
races with the level's.  Differential: the reduced search and ``--no-por`` give the same
verdicts (the built-in checks, ``G ("seen = 0" || "seen = 2")``, ``F "seen = 2"``),
on both engines.  Where the Value's type is not looked at (every datum its task can
name, as before), the same verdicts in more states; where GetDataVal is taken to
reach nothing, the race is missed.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.check import native
from rapidmc.model.reduction import partial_order, typed_names

from test_barrier_holds import assert_reduction_keeps, write_tasks
from test_partial_order import check_json, states, verdicts

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")

TASKS = '[["T_ROB1"], ["task 2 (writer)"], ["task 3 (logger)"]]'
# what each task declares: the two barriers' syncidents and the task list
HEADER = f"""  VAR syncident ready;
  VAR syncident done;
  PERS tasks all{{3}} := {TASKS};
"""

ROBOT = """MODULE Robot
{header}  PERS num level := 0;
  PERS bool on := FALSE;
  PERS tooldata tool1 := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];
  VAR tooldata tX;
  VAR num n := 0;
  VAR num seen := 0;
  PROC main()
    WaitSyncTask ready, all;
    {by_name}
    WaitSyncTask done, all;
    {after}
  ENDPROC
ENDMODULE
"""

WRITER = """MODULE Writer
{header}  PERS num level := 0;
  PERS bool on := FALSE;
  PROC main()
    WaitSyncTask ready, all;
    init;
    WaitSyncTask done, all;
  ENDPROC
  PROC init()
    on := TRUE;
    level := 1;
    level := 2;
  ENDPROC
ENDMODULE
"""

LOGGER = """MODULE Logger
{header}  VAR num count := 0;
  PROC main()
    WaitSyncTask ready, all;
    FOR i FROM 1 TO 3 DO
      count := count + 1;
    ENDFOR
    WaitSyncTask done, all;
  ENDPROC
ENDMODULE
"""

VARIANTS = {
    # name: (the robot's GetDataVal before the second barrier, what it does after it)
    "typed": ('GetDataVal "tool1", tX;', "seen := level;"),
    # the level read by name while the writer's init writes it
    "race": ('GetDataVal "level", n;\n    seen := n;', ""),
}

EXPECTED = {
    "typed": {"levels": "HOLDS", "reads_two": "HOLDS", "no_deadlock": "HOLDS",
              "no_runtime_error": "HOLDS"},
    "race": {"levels": "VIOLATED", "reads_two": "VIOLATED", "no_deadlock": "HOLDS",
             "no_runtime_error": "HOLDS"},
}


def write_cell(folder: Path, variant: str) -> list[str]:
    by_name, after = VARIANTS[variant]
    texts = {"robot": ROBOT.format(header=HEADER, by_name=by_name, after=after),
             "writer": WRITER.format(header=HEADER), "logger": LOGGER.format(header=HEADER)}
    return write_tasks(folder, texts, 'levels: G ("seen = 0" || "seen = 2")\n'
                                      'reads_two: F "seen = 2"\n')


@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_typed_reads_by_name_keep_the_verdicts(tmp_path, variant):
    assert_reduction_keeps(write_cell(tmp_path, variant), EXPECTED[variant])


@needs_native
@pytest.mark.parametrize("variant", sorted(VARIANTS))
def test_typed_reads_by_name_report_the_same_with_both_engines(variant, tmp_path,
                                                               monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_cell(tmp_path, variant), monkeypatch,
                                   reuse=False)
    assert document["properties"]


def test_a_typed_read_by_name_leaves_out_states(tmp_path, monkeypatch):
    """The writer's write of the flag is independent of a GetDataVal into a tooldata:
    the reduction takes it alone, where with every datum reachable it interleaves it."""
    argv = write_cell(tmp_path, "typed")
    typed = check_json(argv)
    monkeypatch.setattr(typed_names, "value_type", lambda routine, call: None)
    untyped = check_json(argv)
    assert verdicts(typed) == verdicts(untyped)
    assert states(typed)["no_runtime_error"] < states(untyped)["no_runtime_error"]


def test_a_read_by_name_taken_to_reach_nothing_misses_the_race(tmp_path, monkeypatch):
    """The mutant: GetDataVal reaches no data.  The writer's writes of the level are
    then judged independent of the robot's read by name, and the reduced search misses
    the run in which the robot reads 1."""
    argv = write_cell(tmp_path, "race")
    monkeypatch.setattr(partial_order, "reached_by_name",
                        lambda program, calls, name, task_of, accessors: {})
    assert verdicts(check_json(argv))["levels"] == "HOLDS"

