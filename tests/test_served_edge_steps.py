"""One task's steps with served edge inputs (``staged_step.task_transitions``).

The PickMaster backup's stored free inputs are five edge inputs that only interrupt
orders name, each served by the tasks whose interrupts watch it (``edge_traps``).  The
partial-order reduction asks for one task's steps (is the task waiting after an ample
step? a local run's next instruction); before, ``task_transitions`` gave None wherever
there were stored inputs, and the reduction stepped the whole state instead.  Now it
steps the task alone, and of the valuations of the edge inputs that start the same TRAPs
of the task (or none) it takes the first (``edge_choices``): the others lead to the same
targets.

Tests, on small two-task programs of the pattern (a manager orders an interrupt on an
input; a server waits for a TRAP of its own input to let it go on, and in the second
program watches the manager's input too):

* at every reachable state, for each task, ``task_transitions`` reaches the same targets
  as the task's steps over every valuation, with fewer transitions where edges cannot
  start a TRAP (a mutant keeping only the first valuation fails);
* on the first program, the reduced check gives the verdicts and lines never reached of
  ``--no-por`` and, for the properties that do not depend on it, of ``--exact-edges``, on
  both engines.  (On the second, a VIOLATED counterexample whose TRAP starts by the shared
  edge goes to the exact model, RMC733, whose search of that program did not end in
  five minutes: left out.)
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.semantics import staged_step
from rapidmc.semantics.state import RUNNING

from test_partial_order import check_json, never_reached, states, verdicts

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

MANAGER = """MODULE Manager
  PERS num status := 0;
  VAR intnum iStop;
  VAR num n1 := 0;
  VAR num stops := 0;
  PROC main()
    CONNECT iStop WITH onStop;
    ISignalDI \\Single, diStop, 1, iStop;
    n1 := 1;
    n1 := 2;
    WaitUntil status = 1;
  ENDPROC
  TRAP onStop
    stops := stops + 1;
  ENDTRAP
ENDMODULE
"""
SERVER = """MODULE Server
  PERS num status := 0;
  VAR intnum iOwn;
  VAR num hits := 0;
  VAR bool go := FALSE;
  VAR num n2 := 0;
  PROC main()
    CONNECT iOwn WITH onOwn;
    ISignalDI diOwn, 1, iOwn;
    WaitUntil go;
    n2 := 1;
    status := 1;
  ENDPROC
  TRAP onOwn
    go := TRUE;
    IF hits < 2 hits := hits + 1;
  ENDTRAP
ENDMODULE
"""
# the server watches the manager's input too (``edge_inputs.shared_edges``)
SERVER_SHARING = SERVER.replace("    WaitUntil go;", """    CONNECT iSeen WITH onSeen;
    ISignalDI diStop, 1, iSeen;
    WaitUntil go;""").replace("  VAR intnum iOwn;", "  VAR intnum iOwn;\n  VAR intnum iSeen;\n"
                               "  VAR num seen := 0;").replace("ENDMODULE", """  TRAP onSeen
    seen := 1;
  ENDTRAP
ENDMODULE""")
FORMULAS = ["--formula", 'once: G "stops <= 1"', "--formula", 'twice: G "hits < 2"']


def _write(folder: Path, server: str) -> list[str]:
    (folder / "m.mod").write_text(MANAGER)
    (folder / "s.mod").write_text(server)
    return [str(folder / "m.mod"), "--add-task", str(folder / "s.mod")]


def _every_valuation(program, state, task, plan, inputs, config):
    return list(zip(inputs, config.input_labels))


def _reachable(system, limit: int = 5000) -> list:
    seen, work = {}, list(system.initial_states())
    while work and len(seen) < limit:
        state = work.pop()
        if state in seen:
            continue
        seen[state] = True
        work += [after for _, after in system.successors(state) if after not in seen]
    assert not work, "the program's states did not end"
    return list(seen)


@pytest.mark.parametrize("server", [SERVER, SERVER_SHARING], ids=["own", "sharing"])
def test_one_task_reaches_every_target_of_its_steps(tmp_path, monkeypatch, server):
    argv = _write(tmp_path, server)
    program = api.load_program([argv[0]], add_tasks=[argv[2]])
    system = api.prepare(program, [], api.CheckOptions()).system
    config = system.config
    assert len(config.input_assignments) > 1 and staged_step.edges_only(config)
    fewer = 0
    for state in _reachable(system):
        if state.status != RUNNING:
            continue
        for task, stack in enumerate((state[0],) + state[10]):
            if not stack:
                continue
            found = staged_step.task_transitions(program, state, task, config)
            with monkeypatch.context() as patch:
                patch.setattr(staged_step, "edge_choices", _every_valuation)
                every = staged_step.task_transitions(program, state, task, config)
            assert found is not None and every is not None
            assert {t.state for t in found} == {t.state for t in every}
            assert {t.label for t in found} <= {t.label for t in every}
            # the labels the whole state's step gives the task's steps that change
            # something (idle ones it may drop), inputs a step leaves unchosen
            # (``unread_inputs``) named in neither
            whole = staged_step.staged_successors(program, state, config) or []
            mine = {t.label for t in whole
                    if staged_step.task_of(t) in (None, program.task_names[task])}
            if mine:
                assert {t.label for t in found if t.state != state} <= mine
            fewer += len(found) < len(every)
    assert fewer


@pytest.mark.parametrize("engine", ENGINES)
def test_the_reduction_with_served_edges_keeps_the_verdicts(tmp_path, engine):
    argv = _write(tmp_path, SERVER) + FORMULAS + ["--engine", engine]
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert verdicts(reduced) == verdicts(full) == {
        "no_runtime_error": "HOLDS", "no_deadlock": "VIOLATED", "once": "HOLDS",
        "twice": "VIOLATED"}
    assert never_reached(reduced) == never_reached(full)
    assert states(reduced)["once"] < states(full)["once"]
    # (no_deadlock too since the waiting manager's steps that carry the environment's
    # input change count as waiting: ``model.task_waits``, tests/test_task_waits.py)
    assert verdicts(check_json(argv + ["--exact-edges"])) == verdicts(reduced)
