"""The emptiness check on toy models whose verdicts are derived by hand.

Each row of ``CASES`` says: model, automaton of the negated property,
valuation of the atoms, expected verdict, and (for violations) the
expected lasso shape (prefix length, cycle length) where the shortest
answer is forced.
"""
from __future__ import annotations

import time

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rapidmc.check import STUTTER, check_property
from rapidmc.ltl.buchi import Buchi, Edge
from test_engine_models import (NOT_ALWAYS_P, NOT_EVENTUALLY_ALWAYS_P, NOT_EVENTUALLY_P,
                                NOT_INFINITELY_OFTEN_P, NOT_P_STAYS, NOT_RESPONSE, Chain,
                                Counter, Graph, assert_valid_lasso, reference_product,
                                reference_verdict)

# 0 -> 1 (stays in 1 forever) or 0 -> 2 -> 0 -> …
BRANCH = {0: [("left", 1), ("right", 2)], 1: [("stay", 1)], 2: [("back", 0)]}
# 0 raises a request (p); 1 waits; 2 answers (r); answers may be skipped forever in 1.
REQUESTS = {0: [("ask", 1)], 1: [("wait", 1), ("answer", 2)], 2: [("idle", 0)]}

CASES = {
    # name: (model, automaton, valuation, verdict, (prefix, cycle) or None)
    "counter G x<5 holds": (Counter(5), NOT_ALWAYS_P, lambda x: int(x < 5), "HOLDS", None),
    "counter G x<3 violated": (Counter(5), NOT_ALWAYS_P, lambda x: int(x < 3), "VIOLATED", None),
    "counter GF x=0 holds": (Counter(5), NOT_INFINITELY_OFTEN_P, lambda x: int(x == 0), "HOLDS", None),
    "counter FG x=0 violated": (Counter(5), NOT_EVENTUALLY_ALWAYS_P, lambda x: int(x == 0),
                                "VIOLATED", None),
    "staying counter GF x=0 violated": (Counter(5, may_stay=True), NOT_INFINITELY_OFTEN_P,
                                        lambda x: int(x == 0), "VIOLATED", None),
    # depth-first, "inc" before "stay": the first accepting cycle found is staying at 3
    "staying counter F x=4 violated by staying at 3": (Counter(5, may_stay=True), NOT_EVENTUALLY_P,
                                                       lambda x: int(x == 4), "VIOLATED", (3, 1)),
    "chain F done holds": (Chain(6), NOT_EVENTUALLY_P, lambda x: int(x == 5), "HOLDS", None),
    "chain G !done violated at the terminal self-loop": (Chain(6), NOT_ALWAYS_P,
                                                         lambda x: int(x != 5), "VIOLATED", (5, 1)),
    "branch G !p violated": (Graph(BRANCH), NOT_ALWAYS_P, lambda x: int(x != 1), "VIOLATED", (1, 1)),
    "branch F p violated by the 0-2 loop": (Graph(BRANCH), NOT_EVENTUALLY_P, lambda x: int(x == 1),
                                            "VIOLATED", (0, 2)),
    "branch p stays once reached": (Graph(BRANCH), NOT_P_STAYS, lambda x: int(x == 1), "HOLDS", None),
    "requests may go unanswered": (Graph(REQUESTS), NOT_RESPONSE,
                                   lambda x: (x == 0) | (x == 2) << 1, "VIOLATED", None),
    "requests always answered without waiting": (
        Graph({0: [("ask", 1)], 1: [("answer", 2)], 2: [("idle", 0)]}), NOT_RESPONSE,
        lambda x: (x == 0) | (x == 2) << 1, "HOLDS", None),
    "deadlock repeats its state: F stuck holds": (Graph({0: [("go", 1)]}), NOT_EVENTUALLY_P,
                                                  lambda x: int(x == 1), "HOLDS", None),
    "deadlock repeats its state: G !stuck violated": (Graph({0: [("go", 1)]}), NOT_ALWAYS_P,
                                                      lambda x: int(x != 1), "VIOLATED", (1, 1)),
    "no initial automaton edge: empty product holds": (Counter(3), NOT_EVENTUALLY_P,
                                                       lambda x: 1, "HOLDS", None),
}


@pytest.mark.parametrize("name", CASES)
def test_verdict_matches_hand_derivation(name):
    system, buchi, valuation, verdict, shape = CASES[name]
    result = check_property(system, buchi, valuation)
    assert result.verdict == verdict
    assert result.verdict == reference_verdict(system, buchi, valuation)
    if verdict == "VIOLATED":
        assert_valid_lasso(system, buchi, valuation, result)
        if shape is not None:
            assert (len(result.prefix), len(result.cycle)) == shape
    else:
        assert result.prefix == [] and result.cycle == [] and result.reason is None


@pytest.mark.parametrize("name", [name for name, case in CASES.items() if case[3] == "HOLDS"])
def test_holds_explores_the_whole_reachable_product_once(name):
    system, buchi, valuation, _, _ = CASES[name]
    graph, _ = reference_product(system, buchi, valuation)
    stats = check_property(system, buchi, valuation).stats
    assert stats.product_states == graph.number_of_nodes()
    assert stats.transitions == graph.number_of_edges()


def test_each_model_state_is_expanded_once_with_a_one_state_automaton():
    graph = Graph({n: [("a", (n + 1) % 50), ("b", (n * 7) % 50)] for n in range(50)})
    result = check_property(graph, NOT_EVENTUALLY_P, lambda x: 0)
    assert result.verdict == "VIOLATED"
    graph.calls.clear()
    never = Buchi(("p",), 0, frozenset(), ((Edge(0, 0, 0),),))
    assert check_property(graph, never, lambda x: 0).verdict == "HOLDS"
    assert set(graph.calls.values()) == {1} and len(graph.calls) == 50


def test_terminal_self_loop_lasso_names_its_label():
    result = check_property(Chain(4), NOT_ALWAYS_P, lambda x: int(x != 3))
    assert [step.state for step in result.prefix] == [0, 1, 2]
    assert [step.label for step in result.prefix] == [None, "next", "next"]
    assert [(step.label, step.state) for step in result.cycle] == [("next", 3)]
    assert result.closing_label == "done"


def test_deadlock_is_counted_and_its_loop_labelled_stutter():
    result = check_property(Graph({0: [("go", 1)]}), NOT_ALWAYS_P, lambda x: int(x != 1))
    assert result.stats.deadlocks == 1
    assert result.closing_label is STUTTER
    assert check_property(Chain(3), NOT_ALWAYS_P, lambda x: 1).stats.deadlocks == 0


def test_cycle_through_an_accepting_initial_state():
    result = check_property(Counter(3), NOT_EVENTUALLY_P, lambda x: 0)
    assert result.prefix == []
    assert [step.state for step in result.cycle] == [0, 1, 2]
    assert result.cycle[0].label is None and result.closing_label == "inc"


# --- bounds ----------------------------------------------------------------------------


def test_state_limit_gives_unknown_never_holds():
    result = check_property(Counter(100), NOT_INFINITELY_OFTEN_P, lambda x: int(x == 0),
                            max_states=10)
    assert (result.verdict, result.reason) == ("UNKNOWN", "state limit 10 reached")
    assert result.stats.product_states == 10


def test_state_limit_equal_to_the_state_count_still_holds():
    valuation = lambda x: int(x == 0)  # noqa: E731
    graph, _ = reference_product(Counter(100), NOT_INFINITELY_OFTEN_P, valuation)
    assert graph.number_of_nodes() == 199
    result = check_property(Counter(100), NOT_INFINITELY_OFTEN_P, valuation, max_states=199)
    assert result.verdict == "HOLDS"
    result = check_property(Counter(100), NOT_INFINITELY_OFTEN_P, valuation, max_states=198)
    assert result.verdict == "UNKNOWN"


def test_violation_found_within_the_limit_is_reported():
    stay_first = Graph({n: [("stay", n), ("inc", n + 1)] for n in range(100)})
    result = check_property(stay_first, NOT_ALWAYS_P, lambda x: int(x < 3), max_states=10)
    assert result.verdict == "VIOLATED"
    assert result.stats.product_states == 4


def test_time_limit_gives_unknown():
    result = check_property(Counter(20_000), NOT_INFINITELY_OFTEN_P, lambda x: int(x == 0),
                            max_seconds=0)
    assert (result.verdict, result.reason) == ("UNKNOWN", "time limit 0 s reached")
    assert result.stats.product_states < 20_000


# --- determinism and depth -----------------------------------------------------------------


def test_same_trace_twice():
    system = Graph({n: [("a", (n * 3 + 1) % 40), ("b", (n + 5) % 40), ("c", n // 2)]
                    for n in range(40)})
    first = check_property(system, NOT_INFINITELY_OFTEN_P, lambda x: int(x % 7 == 0))
    second = check_property(system, NOT_INFINITELY_OFTEN_P, lambda x: int(x % 7 == 0))
    assert first.verdict == "VIOLATED"
    assert (first.prefix, first.cycle, first.closing_label) == (
        second.prefix, second.cycle, second.closing_label)


def test_long_chain_needs_no_recursion():
    n = 100_000
    holds = check_property(Chain(n), NOT_EVENTUALLY_P, lambda x: int(x == n - 1))
    # the automaton of G !done has no edge reading done: the last state is never stored
    assert holds.verdict == "HOLDS" and holds.stats.max_depth == n - 1
    violated = check_property(Chain(n), NOT_ALWAYS_P, lambda x: int(x != n - 1))
    assert (len(violated.prefix), len(violated.cycle)) == (n - 1, 1)


# --- random models against the reference checker ---------------------------------------------


@st.composite
def random_models(draw):
    size = draw(st.integers(1, 7))
    node = st.integers(0, size - 1)
    edges = {n: [(f"t{i}", target) for i, target in
                 enumerate(draw(st.lists(node, max_size=3)))] for n in range(size)}
    bits = draw(st.lists(st.integers(0, 3), min_size=size, max_size=size))
    return Graph(edges, tuple(draw(st.lists(node, min_size=1, max_size=2)))), bits


@st.composite
def random_automata(draw):
    size = draw(st.integers(1, 3))
    literal = st.tuples(st.integers(0, 3), st.integers(0, 3)).map(lambda pn: (pn[0], pn[1] & ~pn[0]))
    edges = tuple(tuple(Edge(pos, neg, draw(st.integers(0, size - 1)))
                        for pos, neg in draw(st.lists(literal, max_size=3)))
                  for _ in range(size))
    accepting = frozenset(draw(st.sets(st.integers(0, size - 1))))
    return Buchi(("p", "r"), 0, accepting, edges)


@settings(max_examples=300, deadline=None)
@given(random_models(), random_automata())
def test_agrees_with_the_reference_checker(model, buchi):
    system, bits = model
    valuation = bits.__getitem__
    result = check_property(system, buchi, valuation)
    assert result.verdict == reference_verdict(system, buchi, valuation)
    if result.verdict == "VIOLATED":
        assert_valid_lasso(system, buchi, valuation, result)
    else:
        graph, _ = reference_product(system, buchi, valuation)
        assert result.stats.product_states == graph.number_of_nodes()


def test_time_limit_is_kept_with_a_slow_model():
    class SlowCounter(Counter):
        def successors(self, x):
            time.sleep(0.002)
            return super().successors(x)

    started = time.monotonic()
    result = check_property(SlowCounter(10_000), NOT_INFINITELY_OFTEN_P, lambda x: int(x == 0),
                            max_seconds=0.1)
    assert result.verdict == "UNKNOWN"
    assert time.monotonic() - started < 0.5


def test_prefix_is_a_shortest_path_into_the_accepting_cycle():
    # depth-first search reaches 4 the long way 0-1-2-3-4; the counterexample takes 0-4
    detour = Graph({0: [("a", 1), ("b", 4)], 1: [("c", 2)], 2: [("d", 3)],
                    3: [("e", 0), ("f", 4)], 4: [("end", 4)]})
    result = check_property(detour, NOT_ALWAYS_P, lambda x: int(x != 4))
    assert result.stats.max_depth == 5
    assert [(step.label, step.state) for step in result.prefix] == [(None, 0)]
    assert [(step.label, step.state) for step in result.cycle] == [("b", 4)]
    assert result.closing_label == "end"


def test_models_may_return_generators_and_deadlock_is_still_seen():
    class Lazy:
        def initial_states(self):
            return iter([0])

        def successors(self, x):
            return (("go", y) for y in ([x + 1] if x < 3 else []))

    result = check_property(Lazy(), NOT_ALWAYS_P, lambda x: int(x != 3))
    assert result.verdict == "VIOLATED" and result.stats.deadlocks == 1
    assert [step.state for step in result.prefix + result.cycle] == [0, 1, 2, 3]
