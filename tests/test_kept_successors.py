"""The successors kept between searches are node ids, and give back the step's successors.

``RapidSystem.successors`` keeps what it found at states of the general step (tasks,
interrupts, stored inputs) for the next search over the program
(``model.kept_successors``).  Kept as the step made them, each state held its successors'
whole object graphs: 40 KB a state on a PickMaster task, 2.0 GB at 21,231 states.  Here,
on a program whose interrupts watch stored inputs:

- the successors given back from what was kept are those the step gives (equal, with
  the same types all through: labels, frames, data, signals), on both engines;
- what is kept reaches no state, frame, signal vector or label object, only bytes of
  node ids (and the node table the searches share);
- the memory a kept state retains is bounded (the old holder took 5.6 KB a state on
  this program, the node ids about 0.9 KB);
- where a check's searches share a packed table under the partial-order reduction, the
  table keeps the successors of the states Python steps (as the parts it gave them) and
  the model keeps none: no successor's parts are interned a second time (on
  joseballester's backup that second interning cost 3 of 12.6 CPU s in 20,000 states).
"""
from __future__ import annotations

import gc
import json
import tracemalloc

import pytest
from pyrsistent import pvector

from rapidmc import ast
from rapidmc.ast import Span
from rapidmc.check import native
from rapidmc.check.nodes import NodeTable, shared_nodes
from rapidmc.model import kept_successors
from rapidmc.model.packed import table as packed
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.semantics.link import build
from rapidmc.semantics.state import Frame, State
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import parse_text

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)
PVECTOR = type(pvector())
EXPANDED = 1500
BYTES_PER_STATE = 4000     # (the step's successors kept whole: 5.6 KB a state here)

TEXT = """MODULE Prog
  VAR intnum iStart;
  VAR intnum iStop;
  VAR num hits := 0;
  VAR num n := 0;
  VAR bool busy := FALSE;
  VAR num parts{20};
  VAR string note := "";
  TRAP tStart
    hits := (hits + 1) MOD 4;
    busy := TRUE;
  ENDTRAP
  TRAP tStop
    parts{hits + 1} := n;
    note := "stop " + NumToStr(n, 0);
  ENDTRAP
  PROC main()
    CONNECT iStart WITH tStart;
    ISignalDI diStart, 1, iStart;
    CONNECT iStop WITH tStop;
    ISignalDI diStop, 1, iStop;
    WHILE TRUE DO
      n := (n + 1) MOD 7;
      IF diMode = 1 THEN
        SetDO doLamp, 1;
        busy := FALSE;
      ELSE
        SetDO doLamp, 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
"""


# two tasks; the first's timer interrupt keeps the machine from its states, so Python steps
# them whole (``python_labelled`` / ``python_successors``)
TIMED_TASK = """MODULE Main
  PERS num shared := 0;
  VAR intnum tick;
  VAR num hits := 0;
  VAR num n := 0;
  TRAP onTick
    hits := (hits + 1) MOD 2;
  ENDTRAP
  PROC main()
    CONNECT tick WITH onTick;
    ITimer 1, tick;
    WHILE TRUE DO
      n := (n + 1) MOD 3;
      IF n = 0 shared := (shared + 1) MOD 2;
      WaitTime 0.1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""
OTHER_TASK = """MODULE Other
  PERS num shared := 0;
  VAR num m := 0;
  PROC main()
    WHILE TRUE DO
      m := (m + shared) MOD 3;
      IF m = 2 shared := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def _system(limit: int = RapidSystem.shared_limit) -> RapidSystem:
    program = build(ast.Program(parse_text(TEXT, "prog.mod")))
    system = RapidSystem(program, CheckConfig(program))
    system.shared_limit = limit
    return system


def _explore(system: RapidSystem, count: int, visit=None) -> int:
    """Expand up to ``count`` states depth first (``visit(state)`` at each); how many."""
    seen = set(system.initial_states())
    frontier = list(seen)
    expanded = 0
    while frontier and expanded < count:
        state = frontier.pop()
        expanded += 1
        if visit is not None:
            visit(state)
        for _, after in system.successors(state):
            if after not in seen:
                seen.add(after)
                frontier.append(after)
    return expanded


def typed(value):
    """``value`` with the type of each part: equal exactly when the parts are (``1``,
    ``1.0`` and ``True`` differ)."""
    if isinstance(value, (tuple, PVECTOR)):
        return type(value), tuple(typed(item) for item in value)
    return type(value), value


@pytest.mark.parametrize("engine", ENGINES)
def test_kept_successors_are_the_steps(engine):
    with native.engine_used(engine):
        system, fresh = _system(), _system(limit=0)
        compared = []

        def visit(state):
            first = system.successors(state)          # stepped, then kept
            again = system.successors(state)          # from what was kept
            assert again is not first
            assert typed(again) == typed(first) == typed(fresh.successors(state))
            compared.append(len(again))

        _explore(system, 300, visit)
    assert len(system._shared) == len(compared) == 300
    assert sum(compared) > 3 * len(compared)         # (stored inputs: several successors)


def test_kept_successors_reach_no_state_objects():
    system = _system()
    _explore(system, 300)
    kept = system._shared
    assert len(kept) == 300
    # every object the kept successors hold but the node table and the split and join
    # functions, containers walked through
    todo = [value for name, value in vars(kept).items() if name not in ("_nodes", "_split",
                                                                         "_join")]
    found, seen = [], set()
    while todo:
        item = todo.pop()
        if id(item) in seen:
            continue
        seen.add(id(item))
        if isinstance(item, (State, Frame, PVECTOR)) or type(item) is tuple and item:
            found.append(item)
        if isinstance(item, (dict, list, tuple, set, PVECTOR)):
            todo.extend(gc.get_referents(item))
    assert found == []
    assert all(type(key) is bytes and type(value) is bytes
               for key, value in kept._kept.items())


def _search_table(system: RapidSystem, engine: str):
    """The node table a search over ``system`` makes before it steps (``check.states``)."""
    kind = native.NativeNodeTable if engine == "native" else NodeTable
    return shared_nodes(system, kind)


def test_labels_stay_out_of_the_searches_node_table():
    """The table the searches share holds state parts only: a distributed search encodes
    its nodes, and a label's span has no canonical bytes (kept labels have a table of
    their own)."""
    system = _system()
    table = _search_table(system, "python")
    _explore(system, 200)
    assert len(system._shared) == 200
    assert system._shared._nodes is table
    values = table.values(list(range(len(table))))
    assert values and not any(isinstance(value, Span) for value in values)


@pytest.mark.parametrize("engine", ENGINES)
def test_a_kept_state_retains_few_bytes(engine):
    with native.engine_used(engine):
        system = _system()
        search_table = _search_table(system, engine)
        gc.collect()
        tracemalloc.start()
        try:
            before = tracemalloc.get_traced_memory()[0]
            expanded = _explore(system, EXPANDED)
            gc.collect()
            retained = tracemalloc.get_traced_memory()[0] - before
        finally:
            tracemalloc.stop()
    assert expanded == len(system._shared) == EXPANDED
    assert system._shared._nodes is search_table
    assert retained / expanded < BYTES_PER_STATE, retained / expanded


def _two_tasks_check(folder, engine: str) -> tuple[dict, list, int]:
    """(the JSON report, the packed tables made, the model's ``keep`` calls) of checking
    the two tasks above on ``engine``."""
    (folder / "main.mod").write_text(TIMED_TASK)
    (folder / "other.mod").write_text(OTHER_TASK)
    made, keeps = [], []
    original_table, original_keep = packed.packed_table, kept_successors.KeptSuccessors.keep

    def table_spy(system):
        table = original_table(system)
        if table is not None:
            made.append(table)
        return table

    def keep_spy(self, state, successors, owner):
        keeps.append(len(successors))
        return original_keep(self, state, successors, owner)
    packed.packed_table, kept_successors.KeptSuccessors.keep = table_spy, keep_spy
    try:
        out = run_cli(["check", str(folder / "main.mod"), "--add-task",
                       str(folder / "other.mod"), "--engine", engine, "--format", "json",
                       "--quiet"]).out
    finally:
        packed.packed_table, kept_successors.KeptSuccessors.keep = original_table, original_keep
    return json.loads(out), made, len(keeps)


def _counts(report: dict) -> list:
    return [(p["name"], p["verdict"], p["stats"]["model_states"], p["stats"]["transitions"],
             p["stats"]["deadlocks"]) for p in report["properties"]]


@pytest.mark.skipif(not native.available(), reason="the native core is not built")
def test_a_reduced_packed_search_keeps_rows_and_the_model_keeps_nothing(tmp_path):
    """The check's two searches share one packed table; the first has Python step every
    state but the first ones (an interrupt is connected) and the table keeps each one's
    row, which the second search takes instead of stepping again; the model keeps
    nothing (before: each of those states and its successors' parts interned once more,
    into a node table of its own).  Verdicts and counts are the Python engine's."""
    report, tables, keeps = _two_tasks_check(tmp_path, native.NATIVE)
    assert tables and all(isinstance(table, packed.PackedSearch) for table in tables)
    assert len({id(table.table) for table in tables}) == 1
    counts = tables[0].counts()
    assert counts["python_steps"] > 1000, counts
    assert counts["rows_reused"] >= counts["python_steps"], counts
    assert keeps == 0
    assert len(tables[0].system._shared) == 0
    reference, _, reference_keeps = _two_tasks_check(tmp_path, native.PYTHON)
    assert reference_keeps > 1000            # (the Python engine's searches: the model keeps)
    assert _counts(report) == _counts(reference)
    assert [p["verdict"] for p in report["properties"]] == ["HOLDS", "HOLDS"]


def test_a_coverage_probe_keeps_no_successors(monkeypatch):
    """A breadth-first coverage probe's model serves that one search: it keeps nothing for a
    next one (the whole joseballester check's probes kept 0.9M states' successors)."""
    from rapidmc import api
    from rapidmc.check.reachability import find_reachable as reach
    program = build(ast.Program(parse_text(TEXT, "prog.mod")))
    keeps, systems = [], []
    original_keep = kept_successors.KeptSuccessors.keep
    monkeypatch.setattr(kept_successors.KeptSuccessors, "keep",
                        lambda self, *args: keeps.append(1) or original_keep(self, *args))
    monkeypatch.setattr(api, "find_reachable",
                        lambda system, *args, **kwargs: systems.append(system) or
                        reach(system, *args, **kwargs))
    executed, _ = api._probe_search(program, api.AtomCompiler(program), CheckConfig(program),
                                    300, walks=False)
    assert executed and systems
    assert keeps == [] and all(len(system._shared) == 0 for system in systems)
