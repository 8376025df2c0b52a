"""The property searches walk the state graph of the complete run-time error search.

Differential: ``rapidmc check --format json`` with the graph reused (the
default) and with every property search stepping the program again
(``CheckOptions.reuse_explored=False``) prints the same report, timing and
memory figures aside (every verdict, every count, every counterexample,
coverage and vacuity warnings), on the data-driven check cases and on
generated programs (tests/reduction_programs.py).  The other tests pin when
a graph is kept: only after a complete exact search, only for its own system.
"""
from __future__ import annotations

import contextlib
import io
import json
from dataclasses import replace

import pytest

from rapidmc import api
from rapidmc.check import find_reachable
from rapidmc.check.engine import check_property
from rapidmc.check.graph_store import GraphStore
from rapidmc.cli import main
from rapidmc.commands import check as check_command
from rapidmc.ltl import to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem

from reduction_programs import properties, random_program
from test_check_cases import run_check, verdict_cases

MEASURED = {"seconds", "states_per_second", "bytes_per_state"}   # vary from run to run
COUNTERS = """MODULE Counters
  VAR signaldi in0;
  VAR signaldi in1;
  VAR num c0 := 0;
  VAR num c1 := 0;
  PROC main()
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    WHILE TRUE DO
      IF in0 = 1 c0 := (c0 + 1) MOD 3;
      IF in1 = 1 c1 := (c1 + 1) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def without_measurements(value):
    if isinstance(value, dict):
        return {key: without_measurements(item) for key, item in value.items()
                if key not in MEASURED}
    if isinstance(value, list):
        return [without_measurements(item) for item in value]
    return value


def report(argv: list[str], monkeypatch, reuse: bool) -> tuple[int, dict]:
    """Exit code and JSON report (measurements dropped) of an in-process check."""
    options = check_command.check_options
    with monkeypatch.context() as patch:
        patch.setattr(check_command, "check_options",
                      lambda args: replace(options(args), reuse_explored=reuse))
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = main(["check", *argv, "--format", "json", "--quiet"])
    return code, without_measurements(json.loads(out.getvalue()))


def case_arguments(case, monkeypatch) -> list[str]:
    """A check case's arguments (run from its folder) without the format options that
    ``report`` adds."""
    monkeypatch.chdir(case.folder)
    argv = case.argv()[1:]
    at = argv.index("--format")
    del argv[at:at + 3]
    return argv


def default_report(case, monkeypatch) -> tuple[int, dict]:
    """``report(case_arguments(case, monkeypatch), monkeypatch, True)``, the check with the
    case's own options and the default reuse of the graph, taken from the run that
    tests/test_check_cases.py shares (one per process, case and engine)."""
    assert api.CheckOptions.reuse_explored, "the default run reuses the graph"
    code, stdout, _ = run_check(case, monkeypatch)
    assert case.argv() == ["check", *case_arguments(case, monkeypatch), "--format", "json",
                           "--quiet"], "report() would run another command line"
    return code, without_measurements(json.loads(stdout))


@pytest.mark.parametrize("case", verdict_cases(), ids=lambda case: case.name)
def test_check_cases_report_the_same_with_and_without_the_reused_graph(case, monkeypatch):
    argv = case_arguments(case, monkeypatch)
    assert default_report(case, monkeypatch) == report(argv, monkeypatch, False)


@pytest.mark.parametrize("seed", range(12))
def test_generated_programs_report_the_same_with_and_without_the_reused_graph(
        seed, tmp_path, monkeypatch):
    (tmp_path / "random.mod").write_text(random_program(seed))
    (tmp_path / "props.ltl").write_text("\n".join(properties(seed, seed % 2 == 1)) + "\n")
    monkeypatch.chdir(tmp_path)
    argv = ["random.mod", "--ltl", "props.ltl", "--max-states", "20000"]
    reused = report(argv, monkeypatch, True)
    assert reused == report(argv, monkeypatch, False)
    assert reused[1]["properties"], "the program's properties were checked"


def model_of(text: str, formula: str, tmp_path, options=api.CheckOptions()):
    (tmp_path / "prog.mod").write_text(text)
    program = api.load_program([str(tmp_path / "prog.mod")])
    return api.prepare(program, [api.property_from_text(formula)], options)


class Counting:
    """Counts the calls of a system's ``successors``."""

    def __init__(self, system: RapidSystem):
        self.calls = 0
        self.successors = system.successors
        system.successors = self

    def __call__(self, state, *keep):
        self.calls += 1
        return self.successors(state, *keep)


def test_a_property_search_over_the_graph_steps_the_program_for_nothing(tmp_path):
    model = model_of(COUNTERS, 'P: G ("c0 < 3" & "c1 < 3")', tmp_path)
    graphs = []
    runtime = find_reachable(model.system, model.system.failed, explored=graphs.append)
    assert runtime.verdict == "HOLDS" and len(graphs) == 1
    assert len(graphs[0]) == runtime.stats.model_states
    counting = Counting(model.system)
    _, buchi, valuation = model.jobs[0]
    result = check_property(model.system, buchi, valuation, explored=graphs[0])
    assert result.verdict == "HOLDS" and counting.calls == 0
    again = check_property(model.system, buchi, valuation)
    assert counting.calls > 0
    assert (result.stats.product_states, result.stats.model_states, result.stats.transitions,
            result.stats.max_depth) == (again.stats.product_states, again.stats.model_states,
                                        again.stats.transitions, again.stats.max_depth)


def test_a_violation_over_the_graph_has_the_same_lasso(tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 + c1 < 3"', tmp_path)
    graphs = []
    find_reachable(model.system, model.system.failed, explored=graphs.append)
    _, buchi, valuation = model.jobs[0]
    reused = check_property(model.system, buchi, valuation, explored=graphs[0])
    again = check_property(model.system, buchi, valuation)
    assert reused.verdict == again.verdict == "VIOLATED"
    assert [(s.label, s.state, s.automaton_state) for s in reused.prefix + reused.cycle] == \
        [(s.label, s.state, s.automaton_state) for s in again.prefix + again.cycle]
    assert reused.closing_label == again.closing_label
    assert reused.stats.model_states == again.stats.model_states


@pytest.mark.parametrize("bounds", [dict(max_states=5), dict(storage=("compact",))],
                         ids=["state bound", "compact"])
def test_an_incomplete_or_hashed_search_keeps_no_graph(bounds, tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    graphs = []
    result = find_reachable(model.system, model.system.failed, explored=graphs.append, **bounds)
    assert result.verdict == "UNKNOWN" or bounds.get("storage") is not None
    assert graphs == []


def test_a_search_that_finds_its_target_keeps_no_graph(tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    graphs = []
    result = find_reachable(model.system, lambda state: True, explored=graphs.append)
    assert result.verdict == "VIOLATED" and graphs == []


def test_another_systems_graph_is_refused(tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    graphs = []
    find_reachable(model.system, model.system.failed, explored=graphs.append)
    other = RapidSystem(model.program, model.config, model.plan)
    _, buchi, valuation = model.jobs[0]
    with pytest.raises(ValueError):
        check_property(other, buchi, valuation, explored=graphs[0])


def test_the_graph_store_counts_the_states_and_the_rows_it_keeps(tmp_path):
    model = model_of(COUNTERS, 'P: G ("c0 < 3" & "c1 < 3")', tmp_path)
    graphs = []
    find_reachable(model.system, model.system.failed, explored=graphs.append)
    graph = graphs[0]
    store = GraphStore(graph, model.jobs[0][2])
    rows = len(graph.starts) * graph.starts.itemsize + len(graph.targets) * graph.targets.itemsize
    assert graph.memory_bytes() >= graph.states.memory_bytes() + rows
    assert store.memory_bytes() >= graph.memory_bytes() + len(graph)    # and valuations


def test_valuations_kept_with_the_graph_are_the_states_own(tmp_path):
    model = model_of(COUNTERS, 'P: G ("c0 < 2" & "c1 < 1")', tmp_path)
    valuation = model.jobs[0][2]
    graphs = []
    find_reachable(model.system, model.system.failed, explored=graphs.append,
                   valuations=[valuation])
    graph = graphs[0]
    kept = GraphStore(graph, valuation).valuations
    assert list(kept) == [valuation(graph.states[i]) for i in range(len(graph))]
    assert len(set(kept)) > 1, "the atoms tell states apart"
