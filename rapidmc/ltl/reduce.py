"""Language-preserving reductions of Büchi automata.

* ``prune``: keep only states that are reachable and can reach an accepting
  cycle (no accepted word passes through any other state).
* ``merge_bisimilar``: merge states with the same acceptance and the same
  guarded edges up to the merge (partition refinement).
* ``simplify_guards``: per target, drop cubes implied by another cube and
  join cubes that differ in one literal.

States are renumbered breadth first from the initial state, edges sorted by
(target, guard), so results are deterministic.

Example::

    >>> from .buchi import Buchi, Edge
    >>> twins = Buchi(("p",), 0, frozenset({1, 2}),
    ...               ((Edge(1, 0, 1), Edge(0, 1, 2)), (Edge(0, 0, 2),), (Edge(0, 0, 1),)))
    >>> simplify(twins).edges
    ((Edge(positive=0, negative=0, target=1),), (Edge(positive=0, negative=0, target=1),))
"""
from __future__ import annotations

from .buchi import Buchi, Edge
from .graph import is_cyclic, strongly_connected_components
from .simulation import reduce_by_simulation


def simplify(automaton: Buchi) -> Buchi:
    """All reductions, repeated while they shrink the automaton."""
    current = prune(simplify_guards(automaton))
    while True:
        smaller = prune(simplify_guards(reduce_by_simulation(merge_bisimilar(current))))
        if (smaller.state_count, smaller.edge_count()) == (current.state_count,
                                                           current.edge_count()):
            return smaller
        current = smaller


def targets(automaton: Buchi, state: int) -> list[int]:
    return list(dict.fromkeys(edge.target for edge in automaton.edges[state]))


def useful_states(automaton: Buchi) -> set[int]:
    """Reachable states from which some accepting cycle is reachable."""
    def successors(state: int) -> list[int]:
        return targets(automaton, state)
    useful: set[int] = set()
    for component in strongly_connected_components([automaton.initial], successors):
        # reverse topological order: successors' components are decided first
        accepting_cycle = (is_cyclic(component, successors)
                           and any(s in automaton.accepting for s in component))
        if accepting_cycle or any(t in useful for s in component for t in successors(s)):
            useful.update(component)
    return useful


def prune(automaton: Buchi) -> Buchi:
    useful = useful_states(automaton)
    if automaton.initial not in useful:
        return Buchi(automaton.atoms, 0, frozenset(), ((),))
    edges = tuple(tuple(e for e in out if e.target in useful) if q in useful else ()
                  for q, out in enumerate(automaton.edges))
    return renumber(Buchi(automaton.atoms, automaton.initial, automaton.accepting, edges))


def renumber(automaton: Buchi) -> Buchi:
    """Reachable states only, numbered breadth first; edges sorted, duplicates dropped."""
    numbers = {automaton.initial: 0}
    order = [automaton.initial]
    for state in order:
        for target in sorted(targets(automaton, state)):
            if target not in numbers:
                numbers[target] = len(order)
                order.append(target)
    edges = tuple(
        tuple(sorted(dict.fromkeys(Edge(e.positive, e.negative, numbers[e.target])
                                   for e in automaton.edges[state]),
                     key=lambda e: (e.target, e.positive, e.negative)))
        for state in order)
    accepting = frozenset(numbers[q] for q in order if q in automaton.accepting)
    return Buchi(automaton.atoms, 0, accepting, edges)


def merge_bisimilar(automaton: Buchi) -> Buchi:
    block = [int(q in automaton.accepting) for q in range(automaton.state_count)]
    while True:
        signatures = [(block[q], frozenset((e.positive, e.negative, block[e.target])
                                           for e in automaton.edges[q]))
                      for q in range(automaton.state_count)]
        numbering: dict = {}
        refined = [numbering.setdefault(sig, len(numbering)) for sig in signatures]
        if len(numbering) == len(set(block)):
            break
        block = refined
    representative: dict[int, int] = {}
    for q in range(automaton.state_count):
        representative.setdefault(block[q], q)
    edges = tuple(tuple(Edge(e.positive, e.negative, representative[block[e.target]])
                        for e in automaton.edges[q])
                  for q in range(automaton.state_count))
    return renumber(Buchi(automaton.atoms, representative[block[automaton.initial]],
                          automaton.accepting, edges))


def simplify_guards(automaton: Buchi) -> Buchi:
    edges = []
    for out in automaton.edges:
        by_target: dict[int, list[tuple[int, int]]] = {}
        for edge in out:
            by_target.setdefault(edge.target, []).append((edge.positive, edge.negative))
        edges.append(tuple(Edge(p, n, target) for target, cubes in by_target.items()
                           for p, n in minimal_cubes(cubes)))
    return Buchi(automaton.atoms, automaton.initial, automaton.accepting, tuple(edges))


def minimal_cubes(cubes: list[tuple[int, int]]) -> list[tuple[int, int]]:
    """An equivalent disjunction: subsumed cubes dropped, ``x&c | !x&c`` joined to ``c``."""
    current = list(dict.fromkeys(cubes))
    changed = True
    while changed:
        changed = False
        current = [c for c in current
                   if not any(o != c and _implies(c, o) for o in current)]
        for i, (p1, n1) in enumerate(current):
            for p2, n2 in current[i + 1:]:
                difference = (p1 ^ p2) | (n1 ^ n2)
                if (p1 ^ p2) == (n1 ^ n2) and difference and difference & (difference - 1) == 0:
                    joined = (p1 & ~difference, n1 & ~difference)
                    current = [joined] + [c for c in current if c not in ((p1, n1), (p2, n2))]
                    changed = True
                    break
            if changed:
                break
    return current


def _implies(cube: tuple[int, int], other: tuple[int, int]) -> bool:
    """Whether ``cube`` implies ``other`` (``other`` has a subset of its literals)."""
    return other[0] & ~cube[0] == 0 and other[1] & ~cube[1] == 0
