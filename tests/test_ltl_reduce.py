"""The built-in translator's size reductions, each pinned on its own.

* rewrites of the normal form (pure eventualities and universal formulas,
  X/F/G merging): the expected result, and the same truth on random lassos;
* cube coverage (``guards.covered``), the basis of direct simulation;
* direct simulation: the greatest relation on a hand-made automaton, and
  reduction by it keeping the language on random formulas;
* degeneralisation restarting the level on edges between components.
"""
from __future__ import annotations

import random

import pytest

from ltl_cases import random_formulas, random_lasso
from rapidmc.ltl import parse_formula, to_text
from rapidmc.ltl.buchi import Buchi, Edge
from rapidmc.ltl.guards import covered
from rapidmc.ltl.lasso import accepts_lasso, holds_on_lasso
from rapidmc.ltl.normal_form import negation_normal_form
from rapidmc.ltl.simulation import reduce_by_simulation, simulation
from rapidmc.ltl.translate import degeneralise, tableau_automaton, translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


@pytest.mark.parametrize("text, expected", [
    ("a U F b", "true U b"),                      # a U e == e
    ("F(a U b)", "true U b"),                     # F(a U b) == F b
    ("G(a R b)", "false R b"),                    # G(a R b) == G b
    ("a R G b", "false R b"),                     # a R u == u
    ("X G F a", "false R true U a"),            # X s == s (G F a is both kinds)
    ("X F G a", "true U false R a"),
    ("X a & X b", "X (a & b)"),
    ("X a | X b", "X (a | b)"),
    ("F a | F b", "true U (a | b)"),
    ("G a & G b", "false R (a & b)"),
    ("X F a", "X (true U a)"),                    # F a alone is not universal: X stays
    ("a U b", "a U b"),
])
def test_normal_form_rewrites(text, expected):
    assert to_text(negation_normal_form(parse_formula(text))) == expected


def test_normal_form_rewrites_keep_truth_on_random_lassos():
    rng = random.Random(7)
    atoms = ("a", "b")
    for formula in random_formulas(8, 300, atoms):
        rewritten = negation_normal_form(formula)
        for _ in range(5):
            prefix, cycle = random_lasso(rng, atoms)
            assert holds_on_lasso(rewritten, prefix, cycle) == holds_on_lasso(formula, prefix,
                                                                              cycle), formula


@pytest.mark.parametrize("cube, others, expected", [
    ((0, 0), [(1, 0), (0, 1)], True),             # a | !a covers true
    ((0, 0), [(1, 0), (2, 0)], False),            # a | b does not
    ((1, 0), [(3, 0), (1, 2)], True),             # a covered by a&b | a&!b
    ((1, 0), [(3, 0)], False),
    ((3, 0), [(1, 0)], True),                     # a&b implies a
    ((0, 0), [], False),
    ((0, 0), [(1, 0), (2, 1), (0, 3)], True),     # a | (b & !a) | (!a & !b)
])
def test_cube_coverage(cube, others, expected):
    assert covered(cube, others) is expected


def test_simulation_of_a_hand_made_automaton():
    # 0 --p--> 1, 0 --true--> 2; 1 and 2 accepting with a true self-loop each (both universal)
    automaton = Buchi(("p",), 0, frozenset({1, 2}),
                      ((Edge(1, 0, 1), Edge(0, 0, 2)), (Edge(0, 0, 1),), (Edge(0, 0, 2),)))
    assert simulation(automaton) == {(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 1), (2, 2)}
    reduced = reduce_by_simulation(automaton)
    assert {e.target for e in reduced.edges[0]} == {1}      # 1 and 2 merged


def test_accepting_state_is_not_simulated_by_a_rejecting_one():
    # 0: accepting, true self-loop; 1: rejecting, true self-loop
    automaton = Buchi(("p",), 0, frozenset({0}), ((Edge(0, 0, 0),), (Edge(0, 0, 1),)))
    assert (0, 1) not in simulation(automaton)
    assert (1, 0) in simulation(automaton)


@pytest.mark.parametrize("seed", [3, 4])
def test_reduction_by_simulation_keeps_the_language(seed):
    rng = random.Random(seed)
    atoms = ("a", "b", "c")
    for formula in random_formulas(seed + 20, 150, atoms):
        generalised = tableau_automaton(negation_normal_form(formula), atoms)
        unreduced = degeneralise(generalised, atoms)
        reduced = reduce_by_simulation(unreduced)
        for _ in range(8):
            prefix, cycle = random_lasso(rng, atoms)
            assert accepts_lasso(reduced, prefix, cycle) == accepts_lasso(unreduced, prefix,
                                                                          cycle), formula


@pytest.mark.parametrize("entry_level", [0, 1, 2])
def test_degeneralisation_entry_level_keeps_the_language(entry_level):
    rng = random.Random(entry_level)
    formula = parse_formula("F a & G(b -> F c) & G F(a | c) & (a U G b)")
    atoms = ("a", "b", "c")
    generalised = tableau_automaton(negation_normal_form(formula), atoms)
    automaton = degeneralise(generalised, atoms, min(entry_level, len(generalised.untils)))
    for _ in range(300):
        prefix, cycle = random_lasso(rng, atoms)
        assert accepts_lasso(automaton, prefix, cycle) == holds_on_lasso(formula, prefix, cycle)


@pytest.mark.parametrize("text, states", [
    ("G(a -> F b)", 2),
    ("X X G F a", 2),                 # X G F a is G F a: no chain of X states
    ("F a | F b", 2),
])
def test_translations_are_small(text, states):
    assert translate(parse_formula(text)).state_count == states


def test_undominated_terms_are_those_the_quadratic_filter_keeps():
    from rapidmc.ltl.translate import Tableau, conjoined_terms, undominated
    atoms = ("a", "b", "c")
    tableau = Tableau(atoms)
    formulas = [negation_normal_form(f) for f in random_formulas(31, 120, atoms)]
    checked = 0
    for left, right in zip(formulas, formulas[1:]):
        terms = conjoined_terms(tableau.terms(left), tableau.terms(right))
        naive = [t for t in dict.fromkeys(terms)
                 if not any(o != t and o.dominates(t) for o in terms)]
        assert undominated(terms) == naive
        checked += len(terms)
    assert checked > 300


def test_pruning_dominated_terms_early_keeps_the_automaton():
    # The slow case of the engine-vs-Spot runs: 110 s before early pruning, well under 1 s now.
    formula = parse_formula('!F("Ended()" xor (X DO1 U FG("Ended()" <-> '
                            '((G!"Failed()" M FG"Ended()") -> (DO1 R c)))))')
    automaton = translate(formula)
    rng = random.Random(5)
    atoms = automaton.atoms
    for _ in range(300):
        prefix, cycle = random_lasso(rng, atoms)
        assert accepts_lasso(automaton, prefix, cycle) == holds_on_lasso(formula, prefix, cycle)
