"""The states of a Büchi automaton from which every infinite word is accepted.

When the automaton of a negated property is in such a state after reading a
finite run of the model, every continuation of that run violates the
property: the run is a *bad prefix* (a safety property's violation needs no
loop).  The set found here is sound, not always the largest: the greatest
set ``U`` of accepting states such that, from each state of ``U``, the guards
of the edges that stay in ``U`` cover every valuation.  Every word then has
a run that stays in ``U`` for ever, so visits accepting states for ever.
That takes in the usual shapes of both translators: an accepting state with
a ``true`` self-loop (``F !p``), and accepting, complete components of
several states.

Example::

    >>> from .buchi import Buchi, Edge
    >>> # F !p: wait in 0 while p, then 1 (accepting) for ever
    >>> a = Buchi(("p",), 0, frozenset({1}),
    ...           ((Edge(1, 0, 0), Edge(0, 1, 1)), (Edge(0, 0, 1),)))
    >>> sorted(universal_states(a))
    [1]
"""
from __future__ import annotations

from typing import Iterable

from .buchi import Buchi
from .guards import Cube


def universal_states(buchi: Buchi) -> frozenset[int]:
    """The accepting states from which the automaton accepts every word (module docstring)."""
    kept = set(buchi.accepting)
    changed = True
    while changed:
        changed = False
        for state in sorted(kept):
            staying = [(edge.positive, edge.negative) for edge in buchi.edges[state]
                       if edge.target in kept]
            if not covers_everything(staying):
                kept.discard(state)
                changed = True
    return frozenset(kept)


def covers_everything(cubes: Iterable[Cube]) -> bool:
    """Whether the disjunction of ``cubes`` is true for every valuation (Shannon expansion
    on one atom at a time; the guards of one state are few and short).

    >>> covers_everything([(1, 0), (0, 1)]), covers_everything([(1, 0), (0, 2)])
    (True, False)
    """
    consistent = [(positive, negative) for positive, negative in cubes
                  if not positive & negative]
    if not consistent:
        return False
    if any(positive == negative == 0 for positive, negative in consistent):
        return True
    positive, negative = consistent[0]
    bit = (positive | negative) & -(positive | negative)       # the lowest atom it reads
    when_true = [(p & ~bit, n) for p, n in consistent if not n & bit]
    when_false = [(p, n & ~bit) for p, n in consistent if not p & bit]
    return covers_everything(when_true) and covers_everything(when_false)
