"""Folding a lasso to its shortest spelling keeps the same infinite run of model states."""
from __future__ import annotations

from hypothesis import given, settings

from rapidmc.check import check_property
from rapidmc.check.fold import fold_lasso
from rapidmc.check.result import NO_AUTOMATON, LassoStep
from test_engine import random_automata, random_models
from test_engine_models import model_successors


def steps(*pairs):
    return [LassoStep(label, state, 0) for label, state in pairs]


def unrolled(prefix, cycle, length=40):
    states = [step.state for step in prefix]
    while len(states) < length:
        states.extend(step.state for step in cycle)
    return states[:length]


def test_rolls_the_loop_back_into_the_prefix():
    # p q r | q r  (the loop q r was walked once before the automaton accepted)
    prefix = steps((None, "p"), ("a", "q"), ("b", "r"))
    cycle = steps(("c", "q"), ("b", "r"))
    folded_prefix, folded_cycle, closing = fold_lasso(prefix, cycle, "c")
    assert [(s.label, s.state) for s in folded_prefix] == [(None, "p")]
    assert [(s.label, s.state) for s in folded_cycle] == [("a", "q"), ("b", "r")]
    assert closing == "c"


def test_cuts_a_repeated_cycle():
    cycle = steps((None, "a"), ("x", "b"), ("y", "a"), ("x", "b"))
    _, folded_cycle, closing = fold_lasso([], cycle, "y")
    assert [s.state for s in folded_cycle] == ["a", "b"] and closing == "y"


def test_drops_automaton_states_and_keeps_the_input_intact():
    prefix, cycle = steps((None, 1)), steps(("t", 2))
    folded_prefix, folded_cycle, _ = fold_lasso(prefix, cycle, "t")
    assert {s.automaton_state for s in folded_prefix + folded_cycle} == {NO_AUTOMATON}
    assert prefix[0].automaton_state == 0


def test_path_without_cycle_is_unchanged():
    folded_prefix, folded_cycle, closing = fold_lasso(steps((None, 1), ("t", 2)), [], None)
    assert [(s.label, s.state) for s in folded_prefix] == [(None, 1), ("t", 2)]
    assert (folded_cycle, closing) == ([], None)


@settings(max_examples=300, deadline=None)
@given(random_models(), random_automata())
def test_folded_lasso_is_the_same_run_of_real_transitions(model, buchi):
    system, bits = model
    result = check_property(system, buchi, bits.__getitem__)
    if result.verdict != "VIOLATED":
        return
    prefix, cycle, closing = fold_lasso(result.prefix, result.cycle, result.closing_label)
    assert unrolled(prefix, cycle) == unrolled(result.prefix, result.cycle)
    assert len(prefix) <= len(result.prefix) and len(cycle) <= len(result.cycle)
    walk = prefix + cycle
    assert walk[0].label is None
    for before, after in zip(walk, walk[1:]):
        assert (after.label, after.state) in model_successors(system, before.state)
    assert (closing, cycle[0].state) in model_successors(system, cycle[-1].state)
