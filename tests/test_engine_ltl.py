"""The engine with automata from ``rapidmc.ltl.to_buchi``: X, U, R, W on toy models.

Verdicts in ``CASES`` are derived by hand.  Every counterexample is also
checked against the formula directly: the lasso's word of atom valuations
must falsify it (``rapidmc.ltl.lasso.holds_on_lasso``, which does not use
automata).  Models with one successor per state are a single lasso word,
so there the verdict itself must agree with ``holds_on_lasso``.
"""
from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rapidmc.check import check_property
from rapidmc.check.fold import fold_lasso
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.lasso import holds_on_lasso
from test_engine_models import Chain, Counter, Graph, assert_valid_lasso

REQUESTS = {0: [("ask", 1)], 1: [("wait", 1), ("answer", 2)], 2: [("idle", 0)]}

CHAIN_ATOMS = {"p": lambda x: x == 3, "r": lambda x: x >= 2, "q": lambda x: x < 2}
COUNTER_ATOMS = {"p": lambda x: x == 0, "q": lambda x: x <= 1}
REQUEST_ATOMS = {"p": lambda x: x == 0, "r": lambda x: x == 2}

CASES = [
    # (model, atoms, formula, verdict); Chain(4) runs 0 1 2 3 3 3 …
    (Chain(4), CHAIN_ATOMS, "F p", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "G p", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "X X X p", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "X X p", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "!p U r", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "r U p", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "q U r", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "q U p", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "q W r", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "r W p", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "p R r", "VIOLATED"),
    (Chain(4), CHAIN_ATOMS, "r R !p", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "F G p", "HOLDS"),
    (Chain(4), CHAIN_ATOMS, "G (r -> X r)", "HOLDS"),
    # Counter(4, may_stay=True): x may increase modulo 4 or stay, forever
    (Counter(4, True), COUNTER_ATOMS, "G F p", "VIOLATED"),
    (Counter(4, True), COUNTER_ATOMS, "X !p", "VIOLATED"),
    (Counter(4, True), COUNTER_ATOMS, "X q", "HOLDS"),
    (Counter(4, True), COUNTER_ATOMS, "!p R q", "HOLDS"),
    (Counter(4, True), COUNTER_ATOMS, "q U !p", "VIOLATED"),
    (Counter(4, True), COUNTER_ATOMS, "G (p -> X (p | q))", "HOLDS"),
    (Counter(4), COUNTER_ATOMS, "G F p", "HOLDS"),
    # requests: 0 asks (p), 1 may wait forever, 2 answers (r)
    (Graph(REQUESTS), REQUEST_ATOMS, "G (p -> F r)", "VIOLATED"),
    (Graph(REQUESTS), REQUEST_ATOMS, "G (p -> X !p)", "HOLDS"),
    (Graph(REQUESTS), REQUEST_ATOMS, "G (r -> X p)", "HOLDS"),
    (Graph(REQUESTS), REQUEST_ATOMS, "G (p -> X (!p U r))", "VIOLATED"),
    (Graph(REQUESTS), REQUEST_ATOMS, "G (p -> X (!p W r))", "HOLDS"),
]


def check_formula(system, atoms, text, **bounds):
    """(negated-property automaton, valuation, result) for ``text`` on ``system``."""
    buchi = to_buchi(parse_formula(f"!({text})"), backend="builtin")
    predicates = [atoms[name] for name in buchi.atoms]

    def valuation(state):
        return sum(1 << index for index, holds in enumerate(predicates) if holds(state))

    return buchi, valuation, check_property(system, buchi, valuation, **bounds)


def letters(steps, atoms):
    return [{name for name, holds in atoms.items() if holds(step.state)} for step in steps]


def assert_counterexample_falsifies(formula_text, atoms, result):
    formula = parse_formula(formula_text)
    assert not holds_on_lasso(formula, letters(result.prefix, atoms), letters(result.cycle, atoms))
    prefix, cycle, _ = fold_lasso(result.prefix, result.cycle, result.closing_label)
    assert not holds_on_lasso(formula, letters(prefix, atoms), letters(cycle, atoms))


@pytest.mark.parametrize("system, atoms, text, verdict", CASES,
                         ids=[f"{type(c[0]).__name__} {c[2]}" for c in CASES])
def test_verdicts_with_translated_automata(system, atoms, text, verdict):
    buchi, valuation, result = check_formula(system, atoms, text)
    assert result.verdict == verdict
    if verdict == "VIOLATED":
        assert_valid_lasso(system, buchi, valuation, result)
        assert_counterexample_falsifies(text, atoms, result)


# --- random formulas on single-word models ------------------------------------------------

ATOMS = ("p", "r")


def formulas(depth=3):
    leaves = st.sampled_from(["p", "r", "true", "false"])
    return st.recursive(leaves, lambda sub: st.one_of(
        st.tuples(st.sampled_from(["!", "X ", "F ", "G "]), sub).map(lambda t: f"{t[0]}({t[1]})"),
        st.tuples(sub, st.sampled_from(["U", "R", "W", "&", "|", "->"]), sub).map(
            lambda t: f"({t[0]}) {t[1]} ({t[2]})")), max_leaves=5)


@st.composite
def single_word_models(draw):
    """0 -> 1 -> … -> n-1 -> loop_to: one infinite word; bits give p (1) and r (2)."""
    size = draw(st.integers(1, 6))
    loop_to = draw(st.integers(0, size - 1))
    edges = {n: [("next", n + 1 if n + 1 < size else loop_to)] for n in range(size)}
    bits = draw(st.lists(st.integers(0, 3), min_size=size, max_size=size))
    return Graph(edges), bits, loop_to


@settings(max_examples=200, deadline=None)
@given(single_word_models(), formulas())
def test_single_word_verdict_agrees_with_direct_evaluation(model, text):
    system, bits, loop_to = model
    atoms = {"p": lambda x: bool(bits[x] & 1), "r": lambda x: bool(bits[x] & 2)}
    word = [{name for name, holds in atoms.items() if holds(x)} for x in range(len(bits))]
    expected = holds_on_lasso(parse_formula(text), word[:loop_to], word[loop_to:])
    _, _, result = check_formula(system, atoms, text)
    assert result.verdict == ("HOLDS" if expected else "VIOLATED")
    if not expected:
        assert_counterexample_falsifies(text, atoms, result)
