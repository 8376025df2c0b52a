"""Translation with Spot's Python bindings (used when ``import spot`` works).

Spot translates the formula (``spot.translate(f, 'BA', 'small', 'high')``:
state-based Büchi acceptance, small automaton, high effort); its HOA output
is read back with ``hoa.read_hoa``, which splits guards into cubes, and the
atoms are put into the caller's order.
"""
from __future__ import annotations

from typing import Sequence

from .buchi import Buchi, Edge
from .hoa import read_hoa
from .printing import to_text
from .syntax import Formula


def spot_available() -> bool:
    try:
        import spot  # noqa: F401
    except ImportError:
        return False
    return True


def spot_translate(formula: Formula, atoms: Sequence[str]) -> Buchi:
    import spot
    automaton = spot.translate(spot.formula(to_text(formula)), "BA", "small", "high")
    return with_atoms(read_hoa(automaton.to_str("hoa"), file="<spot>"), atoms)


def with_atoms(automaton: Buchi, atoms: Sequence[str]) -> Buchi:
    """The same automaton over ``atoms`` (a superset of its own), bits renumbered."""
    position = {name: i for i, name in enumerate(atoms)}

    def moved(mask: int) -> int:
        return sum(1 << position[name] for i, name in enumerate(automaton.atoms)
                   if mask >> i & 1)
    edges = tuple(tuple(Edge(moved(e.positive), moved(e.negative), e.target) for e in out)
                  for out in automaton.edges)
    return Buchi(tuple(atoms), automaton.initial, automaton.accepting, edges)
