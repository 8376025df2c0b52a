"""Direct simulation between the states of a state-based Büchi automaton.

State ``r`` *directly simulates* ``q`` when ``r`` accepts wherever ``q``
does and, for every letter, each move of ``q`` can be matched by a move of
``r`` into a state that again simulates ``q``'s target.  Every run from
``q`` then has a run from ``r`` that visits accepting states at the same
positions, so (Somenzi and Bloem, "Efficient Büchi automata from LTL
formulae", CAV 2000):

* states that simulate each other can be merged;
* an edge ``s --g--> q`` can be dropped when ``s`` has edges into states
  that strictly simulate ``q`` whose guards together cover ``g``: each run
  using the dropped edge has a run through the bigger brother instead.

Both keep the language.  Guards are cubes; "for every letter" is decided
by ``guards.covered`` without enumerating valuations.

Example::

    >>> from .buchi import Buchi, Edge
    >>> # state 1 (p, then anything accepting) and state 2 (anything accepting)
    >>> a = Buchi(("p",), 0, frozenset({1, 2}),
    ...           ((Edge(1, 0, 1), Edge(0, 0, 2)), (Edge(0, 0, 1),), (Edge(0, 0, 2),)))
    >>> sorted(simulation(a))  # pairs (q, r): r simulates q; 1 and 2 accept everything
    [(0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 1), (2, 2)]
"""
from __future__ import annotations

from .buchi import Buchi, Edge
from .guards import covered, implies


def simulation(automaton: Buchi) -> set[tuple[int, int]]:
    """The greatest direct simulation: pairs ``(q, r)`` where ``r`` simulates ``q``."""
    states = range(automaton.state_count)
    accepting = automaton.accepting
    relation = {(q, r) for q in states for r in states
                if q not in accepting or r in accepting}
    changed = True
    while changed:
        changed = False
        for q, r in sorted(relation):
            if q != r and not _matches(automaton, q, r, relation):
                relation.discard((q, r))
                changed = True
    return relation


def _matches(automaton: Buchi, q: int, r: int, relation: set[tuple[int, int]]) -> bool:
    """Whether every edge of ``q`` is matched by edges of ``r`` into simulating targets."""
    for edge in automaton.edges[q]:
        answers = [(e.positive, e.negative) for e in automaton.edges[r]
                   if (edge.target, e.target) in relation]
        if not covered((edge.positive, edge.negative), answers):
            return False
    return True


def reduce_by_simulation(automaton: Buchi) -> Buchi:
    """Mutually simulating states merged, edges into strictly simulated states dropped."""
    relation = simulation(automaton)
    representative = {}
    for q in range(automaton.state_count):
        representative[q] = next(r for r in range(q + 1)
                                 if (q, r) in relation and (r, q) in relation)
    edges = []
    for q in range(automaton.state_count):
        if representative[q] != q:
            edges.append(())
            continue
        moved = list(dict.fromkeys(Edge(e.positive, e.negative, representative[e.target])
                                   for e in automaton.edges[q]))
        edges.append(tuple(e for e in moved if not _little_brother(e, moved, relation)))
    accepting = frozenset(q for q in automaton.accepting if representative[q] == q)
    return Buchi(automaton.atoms, representative[automaton.initial], accepting, tuple(edges))


def _little_brother(edge: Edge, edges: list[Edge], relation: set[tuple[int, int]]) -> bool:
    bigger = [(e.positive, e.negative) for e in edges
              if (edge.target, e.target) in relation and (e.target, edge.target) not in relation]
    cube = (edge.positive, edge.negative)
    return bool(bigger) and (any(implies(cube, b) for b in bigger) or covered(cube, bigger))
