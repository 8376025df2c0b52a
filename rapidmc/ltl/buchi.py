"""State-based Büchi automata over valuations of atomic propositions.

A ``Buchi`` has atoms ``atoms[0..n-1]``; a *valuation* is an ``int`` whose
bit ``1 << i`` is set exactly when atom ``i`` is true.

Run semantics.  A run over a word ``w0 w1 w2 …`` of valuations starts in
``initial``; in state ``q`` reading ``wi`` it takes an edge of ``q`` that
matches ``wi`` and moves to the edge's target.  The word is accepted iff
some run visits a state of ``accepting`` infinitely often.  So the
automaton reads the label of *every* program state, starting with the
initial program state (there is no separate "initial step").

Edges carry guards that are conjunctions of literals: ``positive`` holds
the atoms that must be true, ``negative`` those that must be false.  A
state with no matching edge rejects (the run dies).

Example::

    >>> a = Buchi(("p",), 0, frozenset({0}), ((Edge(1, 0, 0),),))
    >>> a.edges[0][0].matches(0b1), a.edges[0][0].matches(0b0)
    (True, False)
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator


@dataclass(frozen=True)
class Edge:
    """A guarded transition: all ``positive`` atoms true, all ``negative`` false."""

    positive: int
    negative: int
    target: int

    def matches(self, valuation: int) -> bool:
        return (valuation & self.positive == self.positive
                and valuation & self.negative == 0)


@dataclass(frozen=True)
class Buchi:
    """A state-based Büchi automaton; states are ``0 .. state_count - 1``."""

    atoms: tuple[str, ...]
    initial: int
    accepting: frozenset[int]
    edges: tuple[tuple[Edge, ...], ...]

    @property
    def state_count(self) -> int:
        return len(self.edges)

    def successors(self, state: int, valuation: int) -> Iterator[int]:
        """Targets of the edges of ``state`` that match ``valuation``, in edge order."""
        for edge in self.edges[state]:
            if edge.matches(valuation):
                yield edge.target

    def edge_count(self) -> int:
        return sum(len(out) for out in self.edges)
