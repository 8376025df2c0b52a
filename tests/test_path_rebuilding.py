"""Paths are rebuilt on a system whose successors are a function of the state (issue 27).

Ample sets (``reduction.partial_order``) depend on the states the search
expanded before: their proviso takes a task's steps only to states not yet
expanded.  Rebuilding a counterexample asks the model for a state's
successors again, after the search, and may get another task's steps than
the search took; the transition of the path is then missing (an internal
error "no product transition 0 -> 4" on the generated programs below).  It
went unnoticed while ``RapidSystem`` kept every state's successors by value
(up to ``shared_limit`` states); here it keeps none, so the rebuilding must
not rely on them (``check.transition_system.path_system``).
"""
from __future__ import annotations

import pytest

from rapidmc.check import native
from rapidmc.model.rapid_system import RapidSystem

from test_partial_order import check_json, verdicts, write_tasks


# (CI's second run removes the core: there the native case has nothing to run on)
@pytest.mark.parametrize("engine", [
    pytest.param("native", marks=pytest.mark.skipif(not native.available(),
                                                     reason="the native core is not built")),
    "python"])
@pytest.mark.parametrize("seed", [9, 11])
def test_counterexamples_of_reduced_searches_are_rebuilt_without_kept_successors(
        tmp_path, monkeypatch, seed, engine):
    monkeypatch.setattr(RapidSystem, "shared_limit", 0)
    argv = write_tasks(tmp_path, seed) + ["--engine", engine]
    reduced = check_json(argv)             # an internal error prints no JSON
    assert verdicts(reduced) == verdicts(check_json(argv + ["--no-por"]))
    if seed == 9:                          # the case that failed has counterexamples
        assert "VIOLATED" in verdicts(reduced).values()
