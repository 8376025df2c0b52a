"""The deadlock check answered by the complete run-time error search (``api._deadlock``).

When the breadth-first search for run-time errors ends HOLDS it has expanded
every reachable state, and a watcher asked each whether the program waits
forever there; only when none does is the deadlock check answered without a
search of its own.  Pinned against the dedicated search on every check case
and case study: the same verdict, and the same states when it holds.
"""
from __future__ import annotations

import pytest

from test_case_studies import CASES as STUDIES, ROOT
from test_check_cases import verdict_cases
from rapidmc import api
from rapidmc.check import HOLDS, find_reachable
from rapidmc.cli import build_parser
from rapidmc.commands.check import prepare_model
from rapidmc.model.waiting import waits_forever


def _dedicated(model):
    """The stuck-state search; with several tasks, when no state is stuck, the search for a
    task that waits forever while the others go on (model.waiting)."""
    system, bounds = model.system, dict(max_states=model.options.max_states)
    stuck = find_reachable(system, system.stuck, **bounds)
    if stuck.verdict == HOLDS and len(system.program.task_names) > 1:
        return waits_forever(system, bounds, None), stuck
    return stuck, stuck


def _compare(argv):
    """The built-in checks of ``check`` as ``api.check_model`` runs them first (the
    properties' searches and the coverage probes after them play no part in the deadlock
    check), against the dedicated search."""
    model = prepare_model(build_parser().parse_args(argv))
    with api.environment_faults():
        builtin = api._Searches(model, lambda: None).builtin_checks()
    shortcut = next(r.result for r in builtin if r.name == "no_deadlock")
    dedicated, stuck = _dedicated(model)
    assert shortcut.verdict == dedicated.verdict
    if dedicated is stuck and dedicated.verdict == HOLDS:
        assert shortcut.stats.model_states == dedicated.stats.model_states
    return shortcut.verdict


@pytest.mark.parametrize("case", verdict_cases(), ids=lambda case: case.folder.name)
def test_check_cases_get_the_dedicated_search_verdict(case, monkeypatch):
    monkeypatch.chdir(case.folder)
    _compare(case.argv())


@pytest.mark.parametrize("name", STUDIES)
def test_case_studies_get_the_dedicated_search_verdict(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    _compare(STUDIES[name].argv())


def test_a_program_that_waits_forever_still_gets_its_counterexample(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "wait.mod").write_text(
        "MODULE M\n  PROC main()\n    WaitUntil FALSE;\n  ENDPROC\nENDMODULE\n")
    model = prepare_model(build_parser().parse_args(["check", "wait.mod"]))
    deadlock = next(r.result for r in api.check_model(model).results if r.name == "no_deadlock")
    assert deadlock.verdict == "VIOLATED" and deadlock.prefix + deadlock.cycle
