"""A packed state table is freed by reference counting when its search is dropped.

The coverage probes after a check each search the program again with a table of their
own; a table that formed a reference cycle (it kept its own bound methods in its
attributes, as the table of several tasks did) waited for one of the cycle collector's
rare full collections, and eleven probes after a two-task backup's check kept 3.8 GB.
"""
from __future__ import annotations

import gc

import pytest

from rapidmc.api import load_program
from rapidmc.check import native
from rapidmc.model.packed.table import PackedStateTable, TaskStateTable, packed_table
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.semantics.step import CheckConfig

TASK = """MODULE {name}
  VAR num n := 0;
  PROC main()
    WHILE n < 3 DO
      n := n + 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

pytestmark = pytest.mark.skipif(not native.available(), reason="the compiled core is not built")


class Freed:
    """Records in ``log`` when the object holding it is freed."""

    def __init__(self, log: list):
        self.log = log

    def __del__(self):
        self.log.append("freed")


@pytest.mark.parametrize("tasks", [1, 2])
def test_a_table_is_freed_without_the_cycle_collector(tmp_path, tasks):
    files = []
    for number in range(1, tasks + 1):
        path = tmp_path / f"task{number}.mod"
        path.write_text(TASK.format(name=f"Task{number}"))
        files.append(str(path))
    program = load_program(files[:1], add_tasks=files[1:])
    table = packed_table(RapidSystem(program, CheckConfig(program)))
    assert type(table) is (TaskStateTable if tasks > 1 else PackedStateTable)
    log: list = []
    table.held = Freed(log)
    gc.disable()
    try:
        del table
        assert log == ["freed"]
    finally:
        gc.enable()
