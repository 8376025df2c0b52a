"""Boolean guards as disjunctions of literal conjunctions (bit masks).

A *cube* is a pair ``(positive, negative)`` of bit masks over atom indices;
a guard in disjunctive normal form is a tuple of cubes.  Inconsistent cubes
(an atom both required and forbidden) are dropped, so ``()`` is false and
``((0, 0),)`` is true.

Example::

    >>> from .syntax import parse_formula
    >>> cubes(parse_formula("!(a & b)"), {"a": 0, "b": 1}.__getitem__)
    ((0, 1), (0, 2))
"""
from __future__ import annotations

from typing import Callable

from .syntax import (And, Atom, Equiv, FalseF, Formula, Implies, Not, Or, TrueF, Xor)

Cube = tuple[int, int]
TRUE_CUBE: Cube = (0, 0)


def conjoin(left: Cube, right: Cube) -> Cube | None:
    """The conjunction of two cubes, or ``None`` if it is inconsistent."""
    positive, negative = left[0] | right[0], left[1] | right[1]
    return None if positive & negative else (positive, negative)


def cubes(formula: Formula, atom_index: Callable[[str], int],
          polarity: bool = True) -> tuple[Cube, ...]:
    """The DNF of a propositional ``formula`` (negated when ``polarity`` is false).

    ``atom_index`` maps an atom name to its bit index; temporal operators
    are not allowed here (``TypeError``, a caller's bug).
    """
    if isinstance(formula, Atom):
        bit = 1 << atom_index(formula.name)
        return ((bit, 0),) if polarity else ((0, bit),)
    if isinstance(formula, (TrueF, FalseF)):
        return (TRUE_CUBE,) if isinstance(formula, TrueF) == polarity else ()
    if isinstance(formula, Not):
        return cubes(formula.operand, atom_index, not polarity)
    if isinstance(formula, (And, Or)):
        left = cubes(formula.left, atom_index, polarity)
        right = cubes(formula.right, atom_index, polarity)
        if isinstance(formula, And) == polarity:
            return _product(left, right)
        return _unique(left + right)
    if isinstance(formula, (Implies, Equiv, Xor)):
        return cubes(_as_and_or(formula), atom_index, polarity)
    raise TypeError(f"not a propositional formula: {formula!r}")


def _as_and_or(formula: Formula) -> Formula:
    left, right = formula.left, formula.right
    if isinstance(formula, Implies):
        return Or(Not(left), right)
    same = Or(And(left, right), And(Not(left), Not(right)))
    return same if isinstance(formula, Equiv) else Not(same)


def _product(left: tuple[Cube, ...], right: tuple[Cube, ...]) -> tuple[Cube, ...]:
    combined = (conjoin(a, b) for a in left for b in right)
    return _unique(tuple(cube for cube in combined if cube is not None))


def _unique(items: tuple[Cube, ...]) -> tuple[Cube, ...]:
    return tuple(dict.fromkeys(items))


def implies(cube: Cube, other: Cube) -> bool:
    """Whether ``cube`` implies ``other`` (``other`` has a subset of its literals)."""
    return other[0] & ~cube[0] == 0 and other[1] & ~cube[1] == 0


def covered(cube: Cube, others: tuple[Cube, ...] | list[Cube]) -> bool:
    """Whether every valuation of ``cube`` satisfies one of ``others`` (Shannon splitting)."""
    relevant = [o for o in others if conjoin(cube, o) is not None]
    if not relevant:
        return False
    if any(implies(cube, o) for o in relevant):
        return True
    fixed = cube[0] | cube[1]
    free = next((o[0] | o[1]) & ~fixed for o in relevant if (o[0] | o[1]) & ~fixed)
    bit = free & -free
    return (covered((cube[0] | bit, cube[1]), relevant)
            and covered((cube[0], cube[1] | bit), relevant))
