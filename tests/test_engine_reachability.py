"""Breadth-first reachability: shortest paths, deadlocks, bounds."""
from __future__ import annotations

import networkx as nx
from hypothesis import given, settings
from hypothesis import strategies as st

from rapidmc.check import find_reachable
from rapidmc.check.result import NO_AUTOMATON
from test_engine_models import Chain, Counter, Graph

# A long way 0-1-2-3-4 and a short cut 0-5-4; depth-first along the first edge would take the long way.
DETOUR = Graph({0: [("long", 1), ("short", 5)], 1: [("a", 2)], 2: [("b", 3)], 3: [("c", 4)],
                5: [("d", 4)], 4: [("end", 4)]})


def test_shortest_path_with_labels():
    result = find_reachable(DETOUR, lambda x: x == 4)
    assert result.verdict == "VIOLATED" and result.cycle == []
    assert [(step.label, step.state) for step in result.prefix] == [(None, 0), ("short", 5), ("d", 4)]
    assert {step.automaton_state for step in result.prefix} == {NO_AUTOMATON}


def test_bad_initial_state_is_a_one_step_path():
    result = find_reachable(Counter(3), lambda x: x == 0)
    assert [(step.label, step.state) for step in result.prefix] == [(None, 0)]


def test_unreachable_target_holds_after_the_whole_space():
    result = find_reachable(Counter(50), lambda x: x < 0)
    assert result.verdict == "HOLDS"
    assert result.stats.model_states == 50 and result.stats.transitions == 50


def test_state_limit_gives_unknown():
    result = find_reachable(Counter(50), lambda x: x < 0, max_states=49)
    assert (result.verdict, result.reason) == ("UNKNOWN", "state limit 49 reached")
    assert find_reachable(Counter(50), lambda x: x < 0, max_states=50).verdict == "HOLDS"


def test_time_limit_gives_unknown():
    result = find_reachable(Chain(10_000), lambda x: x < 0, max_seconds=0)
    assert (result.verdict, result.reason) == ("UNKNOWN", "time limit 0 s reached")


def test_deadlocks_are_counted_or_targeted():
    stuck = Graph({0: [("go", 1)], 1: [], 2: [("x", 2)]}, initial=(0, 2))
    searched = find_reachable(stuck, lambda x: False)
    assert searched.verdict == "HOLDS" and searched.stats.deadlocks == 1
    found = find_reachable(stuck, lambda x: False, deadlock_is_target=True)
    assert [step.state for step in found.prefix] == [0, 1]


def test_long_chain():
    result = find_reachable(Chain(100_000), lambda x: x == 99_999)
    assert len(result.prefix) == 100_000 and result.stats.max_depth == 100_000


@settings(max_examples=200, deadline=None)
@given(st.integers(1, 8).flatmap(lambda n: st.tuples(
    st.just(n), st.lists(st.lists(st.integers(0, n - 1), max_size=3), min_size=n, max_size=n),
    st.integers(0, n - 1))))
def test_path_length_is_the_graph_distance(case):
    size, successors, goal = case
    system = Graph({n: [(f"{n}>{m}", m) for m in targets] for n, targets in enumerate(successors)})
    graph = nx.DiGraph()
    graph.add_nodes_from(range(size))
    graph.add_edges_from((n, m) for n, targets in enumerate(successors) for m in targets)
    result = find_reachable(system, lambda x: x == goal)
    if nx.has_path(graph, 0, goal):
        assert result.verdict == "VIOLATED"
        assert len(result.prefix) - 1 == nx.shortest_path_length(graph, 0, goal)
        states = [step.state for step in result.prefix]
        assert all(graph.has_edge(a, b) for a, b in zip(states, states[1:]))
        assert states[-1] == goal
    else:
        assert result.verdict == "HOLDS"
