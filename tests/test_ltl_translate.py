"""The built-in translator: the lasso oracle, differential tests against it, sizes, speed."""
from __future__ import annotations

import random
import time
from pathlib import Path

import pytest

from ltl_cases import random_formulas, random_lasso
from rapidmc.diagnostics import USAGE, UserError
from rapidmc.ltl import parse_formula, to_buchi, to_text
from rapidmc.ltl.buchi import Buchi, Edge
from rapidmc.ltl.lasso import accepts_lasso, holds_on_lasso, product_is_empty
from rapidmc.ltl.normal_form import negation_normal_form
from rapidmc.ltl.syntax import Not
from rapidmc.ltl.translate import translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DATA = Path(__file__).parent / "ltl"
PAPER_PROPERTY = "G(!c_in & s1 & s2 -> F(s3 & !s4))"


def _letters(text: str) -> list[frozenset]:
    return [frozenset() if word == "-" else frozenset(word) for word in text.split()]


def _lasso_cases():
    for line in (DATA / "lasso_cases.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            formula, word, holds = (part.strip() for part in line.split("|"))
            prefix, cycle = word.split(";")
            yield formula, _letters(prefix), _letters(cycle), holds == "True"


@pytest.mark.parametrize("formula, prefix, cycle, holds", list(_lasso_cases()))
def test_lasso_oracle_on_hand_checked_words(formula, prefix, cycle, holds):
    assert holds_on_lasso(parse_formula(formula), prefix, cycle) is holds


@pytest.mark.parametrize("formula, prefix, cycle, holds", list(_lasso_cases()))
def test_translation_accepts_hand_checked_words(formula, prefix, cycle, holds):
    assert accepts_lasso(translate(parse_formula(formula)), prefix, cycle) is holds


@pytest.mark.parametrize("atoms, seed", [(("a", "b", "c"), 1), (("a", "b", "c", "d"), 2)])
def test_translation_agrees_with_lasso_oracle_on_random_formulas(atoms, seed):
    rng = random.Random(seed)
    formulas = random_formulas(seed, 600, atoms)
    for formula in formulas:
        automaton = translate(formula, atoms)
        for _ in range(8):
            prefix, cycle = random_lasso(rng, atoms)
            assert accepts_lasso(automaton, prefix, cycle) == holds_on_lasso(
                formula, prefix, cycle), (to_text(formula), prefix, cycle)


def test_negation_normal_form_preserves_meaning():
    rng = random.Random(5)
    atoms = ("a", "b", "c")
    for formula in random_formulas(5, 300, atoms):
        normal = negation_normal_form(formula)
        negated = negation_normal_form(formula, positive=False)
        for _ in range(5):
            prefix, cycle = random_lasso(rng, atoms)
            holds = holds_on_lasso(formula, prefix, cycle)
            assert holds_on_lasso(normal, prefix, cycle) == holds, to_text(formula)
            assert holds_on_lasso(negated, prefix, cycle) != holds, to_text(formula)


@pytest.mark.parametrize("text, states", [
    ("true", 1), ("false", 1), ("p", 2), ("G p", 1), ("F p", 2), ("G F p", 2), ("F G p", 2),
    ("a U b", 2), ("G(a -> F b)", 2), (PAPER_PROPERTY, 2), ("GF a & GF b & GF c", 4),
])
def test_automata_stay_small(text, states):
    assert translate(parse_formula(text)).state_count == states


def test_unsatisfiable_formula_gives_empty_automaton():
    automaton = translate(parse_formula("G a & F !a"))
    assert automaton.state_count == 1 and not automaton.accepting


def test_paper_property_translates_in_milliseconds():
    formula = parse_formula(PAPER_PROPERTY)
    start = time.perf_counter()
    for _ in range(20):
        translate(formula)
    assert (time.perf_counter() - start) / 20 < 0.02


def test_atoms_keep_the_requested_order():
    automaton = translate(parse_formula("G(b -> F a)"), atoms=("a", "b", "c"))
    assert automaton.atoms == ("a", "b", "c")
    assert accepts_lasso(automaton, [], [{"b"}, {"a"}])
    assert not accepts_lasso(automaton, [{"a"}], [{"b"}])


def test_to_buchi_builtin_backend_and_unknown_backend():
    assert to_buchi(parse_formula("F p"), backend="builtin") == translate(parse_formula("F p"))
    with pytest.raises(UserError) as caught:
        to_buchi(parse_formula("F p"), backend="ltl3ba")
    assert caught.value.diagnostics[0].code is USAGE


def test_product_is_empty_decides_intersection():
    always_a, eventually_not_a = (translate(parse_formula(t)) for t in ("G a", "F !a"))
    eventually_b = translate(parse_formula("F b"))
    assert product_is_empty(always_a, eventually_not_a)
    assert not product_is_empty(always_a, eventually_b)      # over the union {a, b}
    formula = parse_formula("G F a -> G F b")
    assert product_is_empty(translate(formula), translate(Not(formula)))


def test_product_needs_both_acceptance_sets_on_one_cycle():
    # a: accepts words with infinitely many p; b: only words ending in !p forever.
    infinitely_p = Buchi(("p",), 0, frozenset({1}),
                         ((Edge(0, 1, 0), Edge(1, 0, 1)), (Edge(0, 1, 0), Edge(1, 0, 1))))
    finitely_p = Buchi(("p",), 0, frozenset({1}),
                       ((Edge(0, 0, 0), Edge(0, 1, 1)), (Edge(0, 1, 1),)))
    assert product_is_empty(infinitely_p, finitely_p)
    assert not product_is_empty(infinitely_p, infinitely_p)
