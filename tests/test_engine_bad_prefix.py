"""Bad prefixes: a property search that stops at its bound after seeing a state from which
every run violates the property is VIOLATED with that finite path (``check.emptiness``,
the automaton states of ``ltl.universal``).

* On a model that never repeats a state after the bad one (a cycle counter) the search
  closes no loop: the verdict was UNKNOWN, now VIOLATED with the path and no cycle, the
  same on both engines; without a state bound it stops ``BAD_PREFIX_GRACE`` states after
  seeing the bad prefix.
* Searches that complete within the grace are unchanged (verdict, lasso and counts),
  checked against the search without the automaton's universal states on random models
  and formulas.
* Every bad prefix reported is one: the formula is false on the prefix's word followed by
  any continuation (``holds_on_lasso``, which uses no automaton).
* The universal states accept every word (``accepts_lasso`` from each of them).
"""
from __future__ import annotations

from dataclasses import replace
from itertools import product as words_of

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rapidmc.check import native
from rapidmc.check import product as product_module
from rapidmc.check.budget import BAD_PREFIX_GRACE
from rapidmc.check.result import BAD_PREFIX
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.lasso import accepts_lasso, holds_on_lasso
from rapidmc.ltl.universal import covers_everything, universal_states
from test_engine_ltl import check_formula, formulas, letters
from test_engine_models import Counter, Graph, automaton_moves, model_successors

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)
LETTERS = [frozenset(), frozenset({"p"}), frozenset({"r"}), frozenset({"p", "r"})]


class Unbounded:
    """x counts 0, 1, 2, ... for ever ("inc"); with ``fork`` it may also jump by 2: no
    state repeats, so no search closes a loop."""

    def __init__(self, fork: bool = False):
        self.fork = fork

    def initial_states(self):
        return (0,)

    def successors(self, x):
        return (("inc", x + 1), ("jump", x + 2)) if self.fork else (("inc", x + 1),)


def search(system, atoms, text, engine, universal=True, **bounds):
    """``check_formula`` on ``engine``; without the automaton's universal states (the
    search before bad prefixes) when ``universal`` is false."""
    with native.engine_used(engine), pytest.MonkeyPatch.context() as patch:
        if not universal:
            patch.setattr(product_module, "universal_states", lambda buchi: frozenset())
        return check_formula(system, atoms, text, **bounds)


def comparable(result):
    """A result's verdict, path and counts (the time aside)."""
    stats = replace(result.stats, seconds=0.0, bytes_per_state=0.0, engine="")
    return (result.verdict, result.reason, result.prefix, result.cycle, result.closing_label,
            result.ending, stats)


@pytest.mark.parametrize("engine", ENGINES)
def test_a_safety_violation_on_an_unbounded_counter_is_a_bad_prefix(engine):
    atoms = {"p": lambda x: x != 5}
    _, _, before = search(Unbounded(), atoms, "G p", engine, universal=False, max_states=100)
    assert before.verdict == "UNKNOWN"
    buchi, valuation, result = search(Unbounded(), atoms, "G p", engine, max_states=100)
    assert result.verdict == "VIOLATED" and result.reason is None
    assert [step.state for step in result.prefix] == [0, 1, 2, 3, 4, 5]
    assert result.cycle == [] and result.closing_label is None
    assert result.ending == BAD_PREFIX
    assert result.prefix[-1].automaton_state in universal_states(buchi)
    # the search went on to its bound, as before: the same counts
    assert result.stats.product_states == before.stats.product_states == 100
    assert result.stats.transitions == before.stats.transitions


@pytest.mark.parametrize("engine", ENGINES)
def test_a_search_without_a_bound_stops_a_grace_after_the_bad_prefix(engine):
    """Without a state bound the search of a model that never ends would never end; after a
    bad prefix it goes on for ``BAD_PREFIX_GRACE`` states (to find a loop), then stops."""
    atoms = {"p": lambda x: x != 5}
    _, _, result = search(Unbounded(), atoms, "G p", engine, max_states=None)
    assert result.verdict == "VIOLATED" and not result.cycle
    assert [step.state for step in result.prefix] == [0, 1, 2, 3, 4, 5]
    # seen when x = 4 was stored, its successor 5 being the bad state
    assert result.stats.product_states == 5 + BAD_PREFIX_GRACE
    _, _, initial = search(Unbounded(), {"p": lambda x: x > 0}, "G p", engine, max_states=None)
    assert [step.state for step in initial.prefix] == [0]
    assert initial.stats.product_states == BAD_PREFIX_GRACE


@pytest.mark.parametrize("engine", ENGINES)
def test_a_loop_found_within_the_grace_is_kept(engine):
    """A finite model whose loop closes after the bad state: the lasso, as before."""
    atoms = {"p": lambda x: x != 5}
    _, _, result = search(Counter(40), atoms, "G p", engine, max_states=None)
    assert result.verdict == "VIOLATED" and result.cycle and result.ending is None


@pytest.mark.parametrize("engine", ENGINES)
def test_a_property_false_in_the_initial_state_is_a_bad_prefix_of_one_step(engine):
    _, _, result = search(Unbounded(), {"p": lambda x: x > 0}, "G p", engine, max_states=50)
    assert result.verdict == "VIOLATED"
    assert [step.state for step in result.prefix] == [0] and result.cycle == []


@pytest.mark.parametrize("engine", ENGINES)
def test_the_prefix_is_a_shortest_path_to_a_bad_state(engine):
    """With jumps the depth-first path to x = 6 takes six steps; the shortest takes three."""
    _, _, result = search(Unbounded(fork=True), {"p": lambda x: x != 6}, "G p", engine,
                          max_states=200)
    assert result.verdict == "VIOLATED" and not result.cycle
    assert len(result.prefix) == 4 and result.prefix[-1].state == 6


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("text", ["G F p", "F p", "G (r -> F p)", "F G r"])
def test_properties_without_bad_prefixes_stay_unknown(engine, text):
    """No state of these negations accepts every word: a bounded search proves nothing."""
    atoms = {"p": lambda x: False, "r": lambda x: x % 2 == 0}
    _, _, result = search(Unbounded(), atoms, text, engine, max_states=100)
    assert result.verdict == "UNKNOWN"


@st.composite
def small_graphs(draw):
    """Up to 6 states, each with 0-2 successors (0: the run repeats the state); bits give
    p (1) and r (2)."""
    size = draw(st.integers(1, 6))
    edges = {n: [("step", target) for target in
                 draw(st.lists(st.integers(0, size - 1), max_size=2, unique=True))]
             for n in range(size)}
    bits = draw(st.lists(st.integers(0, 3), min_size=size, max_size=size))
    return Graph(edges), {"p": lambda x: bool(bits[x] & 1), "r": lambda x: bool(bits[x] & 2)}


@settings(max_examples=150, deadline=None)
@given(small_graphs(), formulas(), st.sampled_from(ENGINES))
def test_complete_searches_are_unchanged(model, text, engine):
    """On a finite model every bad prefix leads on to an accepting cycle: the search finds
    it as before, with the same lasso and counts."""
    system, atoms = model
    _, _, result = search(system, atoms, text, engine)
    _, _, before = search(system, atoms, text, engine, universal=False)
    assert comparable(result) == comparable(before)


@settings(max_examples=200, deadline=None)
@given(small_graphs(), formulas(), st.integers(1, 8), st.sampled_from(ENGINES))
def test_every_bad_prefix_is_violated_by_every_continuation(model, text, bound, engine):
    """Bounded searches of random models: a finite counterexample is a real path of the
    model and of the automaton, and the formula is false on its word followed by any
    word (every continuation of one or no letter, then a loop of one or two letters)."""
    system, atoms = model
    buchi, valuation, result = search(system, atoms, text, engine, max_states=bound)
    if result.verdict != "VIOLATED" or result.cycle:
        return
    assert result.ending == BAD_PREFIX
    first = result.prefix[0]
    assert first.state in system.initial_states()
    assert first.automaton_state in automaton_moves(buchi, buchi.initial, valuation(first.state))
    for before, after in zip(result.prefix, result.prefix[1:]):
        assert (after.label, after.state) in model_successors(system, before.state)
        assert after.automaton_state in automaton_moves(buchi, before.automaton_state,
                                                        valuation(after.state))
    word = letters(result.prefix, atoms)
    formula = parse_formula(text)
    for middle in [[]] + [[letter] for letter in LETTERS]:
        for loop in [list(w) for size in (1, 2) for w in words_of(LETTERS, repeat=size)]:
            assert not holds_on_lasso(formula, word + middle, loop), (middle, loop)


@settings(max_examples=200, deadline=None)
@given(formulas())
def test_universal_states_accept_every_word(text):
    buchi = to_buchi(parse_formula(f"!({text})"), atoms=("p", "r"), backend="builtin")
    for state in universal_states(buchi):
        started_there = replace(buchi, initial=state)
        for size in (1, 2):
            for loop in words_of(LETTERS, repeat=size):
                assert accepts_lasso(started_there, [], list(loop)), (state, loop)


def test_a_negated_safety_property_has_a_universal_state_and_a_liveness_one_none():
    def universal(text):
        return universal_states(to_buchi(parse_formula(f"!({text})"), backend="builtin"))
    assert universal("G p") and universal('G !("open" & "moving")')
    assert universal("G (p -> X r)") and universal("p W r")
    assert not universal("G F p") and not universal("F p") and not universal("G (p -> F r)")


def test_guards_cover_every_valuation_only_when_they_do():
    p, r = 1, 2
    assert covers_everything([(0, 0)])
    assert covers_everything([(p, 0), (0, p)])
    assert covers_everything([(p | r, 0), (0, p), (p, r)])
    assert not covers_everything([(p | r, 0), (0, p)])
    assert not covers_everything([(p, p)])           # inconsistent: no valuation
    assert not covers_everything([])
