"""The run-time error search without labels reports what the labelled search reports.

Differential: ``rapidmc check --format json`` as it runs (the breadth-first
search steps with ``successor_states`` whenever no observer needs labels:
always for the dedicated searches, and for the run-time error search once
coverage has seen every line it reports on; stuck states decided first by
call stack and data) and with the labels built at every state and every
stuck test masking the inputs of every successor (the search before these
fast paths) print the same report, timing and memory figures aside: every
verdict, count, counterexample, coverage and vacuity warning.  On the
data-driven check cases and on generated programs.  The other tests pin when
the search does without labels.
"""
from __future__ import annotations

import pytest

from rapidmc import api
from rapidmc.check import find_reachable, native
from rapidmc.findings.coverage import StatementWatch
from rapidmc.findings.explored import ExploredFacts
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.semantics.state import RUNNING

from reduction_programs import properties, random_program
from test_check_cases import verdict_cases
from test_graph_reuse import COUNTERS, case_arguments, default_report, model_of, report

DEAD_CODE = """MODULE Dead
  VAR num x := 0;
  PROC main()
    WHILE TRUE DO
      x := (x + 1) MOD 3;
      IF x > 5 THEN
        x := 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def stuck_by_masking(system: RapidSystem, state, targets) -> bool:
    """``stuck_at`` as it was: every successor's inputs masked and compared (after the
    barrier rule both keep: a task waiting at a barrier for a task that has ended)."""
    if state.status == RUNNING and state[10] and system.blocked_at_barrier(state):
        return True
    return state.status == RUNNING and system._same_but_inputs(state, targets)


def labelled_report(argv, monkeypatch):
    """The report of the search that builds labels everywhere (see the module docstring)."""
    with monkeypatch.context() as patch:
        patch.setattr(RapidSystem, "successor_states", None)
        patch.setattr(RapidSystem, "stuck_at", stuck_by_masking)
        return report(argv, monkeypatch, True)


@pytest.mark.parametrize("case", verdict_cases(), ids=lambda case: case.name)
def test_check_cases_report_the_same_with_and_without_labels(case, monkeypatch):
    argv = case_arguments(case, monkeypatch)
    assert default_report(case, monkeypatch) == labelled_report(argv, monkeypatch)


@pytest.mark.parametrize("seed", range(12))
def test_generated_programs_report_the_same_with_and_without_labels(seed, tmp_path,
                                                                    monkeypatch):
    (tmp_path / "random.mod").write_text(random_program(seed))
    (tmp_path / "props.ltl").write_text("\n".join(properties(seed, seed % 2 == 1)) + "\n")
    monkeypatch.chdir(tmp_path)
    argv = ["random.mod", "--ltl", "props.ltl", "--max-states", "20000"]
    fast = report(argv, monkeypatch, True)
    assert fast == labelled_report(argv, monkeypatch)
    assert fast[1]["properties"], "the program's properties were checked"


class CountingSteps:
    """Counts the labelled and the unlabelled steps a search asks of a system (the labelled
    steps ``successor_states`` takes at states the fused step does not take aside)."""

    def __init__(self, system: RapidSystem):
        self.labelled = self.unlabelled = 0
        self._inside = False
        successors, successor_states = system.successors, system.successor_states

        def labelled(state, *keep):
            self.labelled += not self._inside
            return successors(state, *keep)

        def unlabelled(state, *keep):
            self.unlabelled += 1
            self._inside = True
            try:
                return successor_states(state, *keep)
            finally:
                self._inside = False
        system.successors, system.successor_states = labelled, unlabelled


def watched_search(text: str, formula: str, tmp_path, engine: str = native.PYTHON):
    """The run-time error search with the check's watch, on ``engine`` (the Python engine
    by default: the counts below are of its Python loop)."""
    model = model_of(text, formula, tmp_path)
    facts = ExploredFacts(model.program, [p.formula for p in model.properties], model.atoms)
    steps = CountingSteps(model.system)
    with native.engine_used(engine):
        result = find_reachable(model.system, model.system.failed, observe=api._StuckWatch(
            model.system, facts))
    facts.finish(model.system, result)
    return result, facts, steps


def test_labels_stop_once_every_line_has_run(tmp_path):
    result, facts, steps = watched_search(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    assert result.verdict == "HOLDS" and facts.warnings() == []
    assert steps.labelled + steps.unlabelled == result.stats.model_states
    assert 0 < steps.labelled < steps.unlabelled


def test_a_line_never_run_keeps_the_labels_to_the_end(tmp_path):
    result, facts, steps = watched_search(DEAD_CODE, 'P: G "x < 3"', tmp_path)
    assert [d.span.line for d in facts.warnings()] == [7]
    assert steps.unlabelled == 0 and steps.labelled == result.stats.model_states


@pytest.mark.skipif(not native.available(), reason="the native core is not built")
def test_the_step_machine_names_the_lines_it_runs(tmp_path):
    """With the compiled core's step machine, coverage comes from the lines the machine
    says it ran: the same warning, with next to no Python step (labelled or not)."""
    result, facts, steps = watched_search(DEAD_CODE, 'P: G "x < 3"', tmp_path, native.NATIVE)
    assert result.verdict == "HOLDS" and [d.span.line for d in facts.warnings()] == [7]
    assert steps.labelled + steps.unlabelled < result.stats.model_states // 2


@pytest.mark.parametrize("engine", native.ENGINES if native.available() else [native.PYTHON])
def test_a_search_without_observer_builds_no_labels(engine, tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    steps = CountingSteps(model.system)
    with native.engine_used(engine):
        result = find_reachable(model.system, model.system.failed)
    assert result.verdict == "HOLDS" and steps.labelled == 0
    if engine == native.PYTHON:
        assert steps.unlabelled == result.stats.model_states
    else:                       # the machine steps all but the AliasIO calls
        assert steps.unlabelled == 2


def test_a_cleared_watch_wants_labels_again():
    from rapidmc.ast import Span
    watch = StatementWatch()
    watch._asked = frozenset({("a.mod", 3)})
    watch("s", [(((), Span("a.mod", 3, 1), ""), "t")])
    assert watch.saturated
    watch.clear()
    assert not watch.saturated and watch.executed == set()
