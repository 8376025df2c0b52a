"""The search's caches change nothing but its speed.

Differential, on generated programs (tests/reduction_programs.py) and their
properties: with the store keeping new states as the model handed them over
(for any number kept) and the product remembering automaton moves, or with
neither, every verdict, every statistic that counts something and every
counterexample (states, labels, automaton states) is the same.
"""
from __future__ import annotations

import pytest

from rapidmc import ast
from rapidmc.check import product as product_module
from rapidmc.check.budget import SearchBudget
from rapidmc.check.emptiness import search_accepting_cycle
from rapidmc.check.product import Product
from rapidmc.check.store import ModelStore
from rapidmc.ltl import to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.properties import AtomCompiler, parse_property
from rapidmc.model.reduction import ALL, plan_reductions
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import parse_text

from reduction_programs import properties, random_program


def outcome(program, text: str, keep_new: int):
    prop = parse_property(text)
    buchi = to_buchi(Not(prop.formula))
    atoms = AtomCompiler(program)
    valuation = atoms.valuation(buchi.atoms, {})
    config = CheckConfig(program, observed=set(atoms.observed))
    plan = plan_reductions(program, config, buchi.atoms, [prop.formula], ALL)
    system = RapidSystem(program, config, plan)
    system.shared_limit = 0
    product = Product(ModelStore(system, valuation, keep_new=keep_new), buchi)
    result = search_accepting_cycle(product, SearchBudget(20_000))
    stats = result.stats
    steps = [(step.label, step.state, step.automaton_state)
             for step in result.prefix + result.cycle]
    return (result.verdict, result.reason, stats.product_states, stats.model_states,
            stats.transitions, stats.max_depth, stats.deadlocks, steps, result.closing_label)


@pytest.mark.parametrize("seed", range(16))
def test_caches_change_no_verdict_count_or_counterexample(seed, monkeypatch):
    program = build(ast.Program(parse_text(random_program(seed), "random.mod")))
    for text in properties(seed, with_next=seed % 2 == 1):
        cached = outcome(program, text, keep_new=8192)
        assert outcome(program, text, keep_new=3) == cached
        with monkeypatch.context() as patch:
            patch.setattr(product_module, "MOVES_KEPT", 1)   # only the last one kept
            assert outcome(program, text, keep_new=0) == cached
