"""The search's fast paths change nothing a check reports (differential tests).

A check's fast paths: target states without labels (``successor_states``),
the fused step's entries, the generated valuation of atoms (``fused_atoms``)
and states collapsed into component ids (``check.states``).  Each test runs
every property of generated programs twice, once as the search runs it and
once with all of those off (labels built and dropped, states kept whole,
every atom evaluated on a ``Machine``), and compares verdicts, state and
transition counts and the counterexample lassos.  The fused step's entries
are also run with so small a line budget that they go on in the dispatch
loop after one block.
"""
from __future__ import annotations

import pytest

from rapidmc import api
from rapidmc.check import check_property
from rapidmc.model import RapidSystem
from rapidmc.reduction import ALL, NONE
from rapidmc.semantics import fused_step

from reduction_programs import properties, random_program
from test_plain_step import FUSED_FORMS, compare_drivers, formulas, load
from test_reduction import counters

MAX_STATES = 20_000


class Unhurried(RapidSystem):
    """The same system searched without the fast paths of the search (see above)."""

    split_state = None                  # states kept whole in a dict
    successor_states = None             # the store drops the labels of ``successors``


def outcomes(model, system, fast: bool) -> list:
    """Per property: verdict, product states, transitions and the lasso."""
    found = []
    for _, buchi, valuation in model.jobs:
        if not fast:
            valuation = model.atoms.valuation(buchi.atoms, {}, memo=False)
        result = check_property(system, buchi, valuation, max_states=MAX_STATES)
        lasso = [(step.label, step.state, step.automaton_state)
                 for step in result.prefix + result.cycle]
        found.append((result.verdict, result.stats.product_states, result.stats.transitions,
                      lasso, result.closing_label))
    return found


def assert_same_checks(program, props, reductions) -> None:
    model = api.prepare(program, props, api.CheckOptions(reductions=reductions))
    system = model.system
    slow = Unhurried(system.program, system.plain_config, system.plan)
    assert outcomes(model, system, True) == outcomes(model, slow, False)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
@pytest.mark.parametrize("seed", range(16))
def test_generated_programs_check_alike(tmp_path, seed, reductions):
    program = load(tmp_path, random_program(seed))
    assert_same_checks(program, formulas(*properties(seed, with_next=seed % 2 == 1)),
                       reductions)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_counters_check_alike(tmp_path, reductions):
    program = load(tmp_path, counters(3, statistics=True))
    assert_same_checks(program, formulas('b: G ("c0 < 4" & "c1 < 4")', 'v: G "c2 < 3"'),
                       reductions)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_entries_past_their_budget_agree(tmp_path, monkeypatch, reductions):
    """Entries cut after one block go on in the dispatch loop, with the same result."""
    monkeypatch.setattr(fused_step, "ENTRY_LINES", 1)
    for text in (FUSED_FORMS, counters(3)):
        program = load(tmp_path, text)
        plain, fused = compare_drivers(program, formulas('b: G "n < 5"' if text is FUSED_FORMS
                                                         else 'b: G "c0 < 4"'), reductions)
        assert fused > 0
