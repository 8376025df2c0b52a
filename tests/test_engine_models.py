"""Toy transition systems and hand-built automata for the engine tests.

Also a reference checker built the slow, obvious way (whole product graph
in networkx, then strongly connected components), used to hold the
on-the-fly engine to the right verdicts on random inputs.  The tests in
this file pin the toy models themselves.
"""
from __future__ import annotations

from dataclasses import dataclass, field

import networkx as nx
import pytest

from rapidmc.check.transition_system import STUTTER
from rapidmc.ltl.buchi import Buchi, Edge

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

# --- toy models ------------------------------------------------------------------


@dataclass
class Graph:
    """A hand-built model: ``edges[node]`` lists (label, successor)."""

    edges: dict
    initial: tuple = (0,)
    calls: dict = field(default_factory=dict)

    def initial_states(self):
        return self.initial

    def successors(self, state):
        self.calls[state] = self.calls.get(state, 0) + 1
        return tuple(self.edges.get(state, ()))


class Counter:
    """x counts 0, 1, …, n-1, 0, … ("inc"); with ``may_stay`` it may also stay ("stay")."""

    def __init__(self, n: int, may_stay: bool = False):
        self.n = n
        self.may_stay = may_stay

    def initial_states(self):
        return (0,)

    def successors(self, x):
        following = (("inc", (x + 1) % self.n),)
        return following + (("stay", x),) if self.may_stay else following


class Chain:
    """0 -> 1 -> … -> n-1, then n-1 loops on itself ("done"), like a finished program."""

    def __init__(self, n: int):
        self.n = n

    def initial_states(self):
        return (0,)

    def successors(self, x):
        return (("done", x),) if x == self.n - 1 else (("next", x + 1),)


# --- automata of negated properties (atom p is bit 0, atom r bit 1) -----------------

P, R = 1, 2
TRUE = (0, 0)


def automaton(atoms, accepting, *edges_per_state) -> Buchi:
    """A Buchi from ``[(positive, negative, target), …]`` per state; state 0 initial."""
    return Buchi(tuple(atoms), 0, frozenset(accepting),
                 tuple(tuple(Edge(pos, neg, target) for pos, neg, target in out)
                       for out in edges_per_state))


# !(G p) = F !p
NOT_ALWAYS_P = automaton(["p"], {1}, [(P, 0, 0), (0, P, 1)], [(0, 0, 1)])
# !(F p) = G !p
NOT_EVENTUALLY_P = automaton(["p"], {0}, [(0, P, 0)])
# !(G F p) = F G !p
NOT_INFINITELY_OFTEN_P = automaton(["p"], {1}, [(0, 0, 0), (0, P, 1)], [(0, P, 1)])
# !(F G p) = G F !p
NOT_EVENTUALLY_ALWAYS_P = automaton(["p"], {1}, [(P, 0, 0), (0, P, 1)], [(P, 0, 0), (0, P, 1)])
# !(G (p -> F r)) = F (p & G !r)
NOT_RESPONSE = automaton(["p", "r"], {1}, [(0, 0, 0), (P, R, 1)], [(0, R, 1)])
# !(G (p -> X p)) = F (p & X !p)
NOT_P_STAYS = automaton(["p"], {2}, [(0, 0, 0), (P, 0, 1)], [(0, P, 2)], [(0, 0, 2)])


# --- checking a lasso against the model and the automaton ---------------------------------


def model_successors(system, state):
    successors = tuple(system.successors(state))
    return successors if successors else ((STUTTER, state),)


def automaton_moves(buchi, source, valuation_bits):
    return [edge.target for edge in buchi.edges[source] if edge.matches(valuation_bits)]


def assert_valid_lasso(system, buchi, valuation, result):
    """Every step is a real model transition matched by an automaton edge; the cycle accepts."""
    steps = result.prefix + result.cycle
    first = steps[0]
    assert first.label is None
    assert first.state in tuple(system.initial_states())
    assert first.automaton_state in automaton_moves(buchi, buchi.initial, valuation(first.state))
    pairs = list(zip(steps, steps[1:])) + [(result.cycle[-1], result.cycle[0])]
    for index, (before, after) in enumerate(pairs):
        label = result.closing_label if index == len(pairs) - 1 else after.label
        assert (label, after.state) in model_successors(system, before.state)
        assert after.automaton_state in automaton_moves(
            buchi, before.automaton_state, valuation(after.state))
    assert any(step.automaton_state in buchi.accepting for step in result.cycle)


# --- the reference checker -------------------------------------------------------------


def reference_product(system, buchi, valuation) -> tuple[nx.DiGraph, list]:
    """The whole reachable product graph, built eagerly, and its initial nodes."""
    graph = nx.DiGraph()
    initial = [(s, q) for s in system.initial_states()
               for q in automaton_moves(buchi, buchi.initial, valuation(s))]
    todo = list(initial)
    graph.add_nodes_from(initial)
    while todo:
        state, q = todo.pop()
        for _, successor in model_successors(system, state):
            for target in automaton_moves(buchi, q, valuation(successor)):
                node = (successor, target)
                if node not in graph:
                    todo.append(node)
                graph.add_edge((state, q), node)
    return graph, initial


def reference_verdict(system, buchi, valuation) -> str:
    """VIOLATED iff some nontrivial SCC (or self-loop) holds an accepting product state."""
    graph, _ = reference_product(system, buchi, valuation)
    for component in nx.strongly_connected_components(graph):
        node = next(iter(component))
        cyclic = len(component) > 1 or graph.has_edge(node, node)
        if cyclic and any(q in buchi.accepting for _, q in component):
            return "VIOLATED"
    return "HOLDS"


# --- the toy models pin their sizes ------------------------------------------------------


def test_counter_has_n_states_and_one_cycle():
    graph, _ = reference_product(Counter(7), NOT_EVENTUALLY_P, lambda x: 0)
    assert graph.number_of_nodes() == 7
    assert nx.number_of_selfloops(graph) == 0


def test_chain_ends_in_a_self_loop():
    graph, _ = reference_product(Chain(5), NOT_EVENTUALLY_P, lambda x: 0)
    assert sorted(graph.nodes) == [(x, 0) for x in range(5)]
    assert list(nx.selfloop_edges(graph)) == [((4, 0), (4, 0))]


def test_reference_treats_a_deadlock_as_repeating_its_state():
    graph, _ = reference_product(Graph({0: [("a", 1)]}), NOT_EVENTUALLY_P, lambda x: 0)
    assert graph.has_edge((1, 0), (1, 0))
