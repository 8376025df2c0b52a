"""bench/input_successors.py: the transitions that differ only in stored inputs' values.

A task with an interrupt on an edge input (``di1``, read by nothing else): from each state
the step chooses di1 = 0 or 1.  Where the task can start the TRAP (the interrupt ordered on
di1 and active, the task not in a TRAP) the edge starts it, so the two transitions lead to two states; elsewhere
the edge is dropped and the two lead to one state, one of them an input-only duplicate.
The test counts those states from the states themselves (interrupt table, stack) and
compares with what the tool counts by grouping labels.
"""
from __future__ import annotations

import sys
from pathlib import Path

from rapidmc import api
from rapidmc.semantics.staged_step import in_trap

sys.path.append(str(Path(__file__).resolve().parents[1] / "bench"))  # (after the rest: its
# modules are named check, engine, run ...)
from input_successors import survey  # noqa: E402

EDGE = """MODULE Edge
  VAR intnum int1;
  VAR num n := 0;
  VAR num m := 0;
  PROC main()
    CONNECT int1 WITH trap1;
    ISignalDI di1, 1, int1;
    WHILE TRUE DO
      n := (n + 1) MOD 3;
    ENDWHILE
  ENDPROC
  TRAP trap1
    m := 1;
    m := 2;
    m := 0;
  ENDTRAP
ENDMODULE
"""

PLAIN = """MODULE Plain
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      n := (n + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def test_an_edge_that_cannot_start_its_trap_is_an_input_only_duplicate(tmp_path):
    path = tmp_path / "edge.mod"
    path.write_text(EDGE)
    found = survey([str(path)], 1000)
    totals = found["totals"]
    assert found["complete"] and [name for _, name, _ in found["config"].free_inputs] == ["di1"]
    program = api.load_program([str(path)])
    system = api.prepare(program, []).system
    seen, queue, dropped = set(), list(system.initial_states()), 0
    while queue:
        state = queue.pop()
        if state in seen:
            continue
        seen.add(state)
        # (an interrupt connected but not yet ordered on di1 has no source)
        watched = any(entry[3] and entry[2] for entry in state.interrupts.table)
        dropped += not watched or in_trap(program, state.frames)
        queue += [after for _, after in system.successors(state)]
    assert totals["states"] == len(seen)
    assert totals["transitions"] == 2 * len(seen)
    assert 0 < dropped < len(seen)
    assert totals["input only"] == dropped
    assert totals["targets"] == 2 * len(seen) - dropped


def test_no_stored_input_no_duplicate(tmp_path):
    path = tmp_path / "plain.mod"
    path.write_text(PLAIN)
    totals = survey([str(path)], 1000)["totals"]
    assert totals["input only"] == 0 and totals["targets"] == totals["transitions"] > 0
