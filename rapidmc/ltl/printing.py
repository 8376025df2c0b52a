"""Formulas as text: Spot syntax (``to_text``, round-trips) and SPIN syntax (``to_spin``).

Example::

    >>> from .syntax import parse_formula
    >>> to_text(parse_formula("a U (b U c) & !(d | e)"))
    'a U b U c & !(d | e)'
    >>> to_spin(parse_formula('"x = 1" W b'))
    '((p0 U p1) || [](p0))'
"""
from __future__ import annotations

from typing import Optional, Sequence

from .syntax import (BINARY_TYPES, IDENTIFIER, KEYWORDS, And, Atom, Equiv, FalseF, Finally,
                     Formula, Globally, Implies, Next, Not, Or, Release, StrongRelease, TrueF,
                     Until, WeakUntil, Xor, atoms_of)

# Binding strength of each binary operator and whether it groups to the right.
BINARY_SPELLING = {Implies: ("->", 1, True), Equiv: ("<->", 1, True), Or: ("|", 2, False),
                   Xor: ("xor", 3, False), And: ("&", 4, False), Until: ("U", 5, True),
                   WeakUntil: ("W", 5, True), Release: ("R", 5, True),
                   StrongRelease: ("M", 5, True)}
UNARY_SPELLING = {Not: "!", Globally: "G ", Finally: "F ", Next: "X "}
UNARY_LEVEL = 6
PRIMARY_LEVEL = 7


def atom_text(name: str) -> str:
    """An atom as Spot reads it: bare if it is a plain identifier, else quoted."""
    match = IDENTIFIER.fullmatch(name)
    if match and name not in KEYWORDS:
        return name
    return '"' + name.replace("\\", "\\\\").replace('"', '\\"') + '"'


def to_text(formula: Formula) -> str:
    """Spot syntax with the fewest parentheses that keep the structure."""
    return _text(formula)[0]


def _text(formula: Formula) -> tuple[str, int]:
    if isinstance(formula, Atom):
        return atom_text(formula.name), PRIMARY_LEVEL
    if isinstance(formula, TrueF):
        return "true", PRIMARY_LEVEL
    if isinstance(formula, FalseF):
        return "false", PRIMARY_LEVEL
    if type(formula) in UNARY_SPELLING:
        return UNARY_SPELLING[type(formula)] + _wrapped(formula.operand, UNARY_LEVEL), UNARY_LEVEL
    spelling, level, right_grouping = BINARY_SPELLING[type(formula)]
    left = _wrapped(formula.left, level + 1 if right_grouping else level)
    right = _wrapped(formula.right, level if right_grouping else level + 1)
    return f"{left} {spelling} {right}", level


def _wrapped(formula: Formula, least_level: int) -> str:
    text, level = _text(formula)
    return text if level >= least_level else f"({text})"


def to_spin(formula: Formula, atoms: Optional[Sequence[str]] = None) -> str:
    """SPIN's LTL syntax, fully parenthesised; atom ``atoms[i]`` becomes ``p<i>``.

    ``atoms`` defaults to ``atoms_of(formula)``.  SPIN has no ``W``, ``M`` or
    ``xor``: ``a W b`` becomes ``(a U b) || []a``, ``a M b`` becomes
    ``b U (a && b)``, ``a xor b`` becomes ``!(a <-> b)``.
    """
    names = {name: f"p{index}" for index, name in enumerate(atoms or atoms_of(formula))}
    return _spin(formula, names)


SPIN_BINARY = {And: "&&", Or: "||", Implies: "->", Equiv: "<->", Until: "U", Release: "V"}
SPIN_UNARY = {Not: "!", Globally: "[]", Finally: "<>", Next: "X"}


def _spin(formula: Formula, names: dict[str, str]) -> str:
    if isinstance(formula, Atom):
        return names[formula.name]
    if isinstance(formula, TrueF):
        return "true"
    if isinstance(formula, FalseF):
        return "false"
    if type(formula) in SPIN_UNARY:
        return f"{SPIN_UNARY[type(formula)]}({_spin(formula.operand, names)})"
    if isinstance(formula, WeakUntil):
        return _spin(Or(Until(formula.left, formula.right), Globally(formula.left)), names)
    if isinstance(formula, StrongRelease):
        return _spin(Until(formula.right, And(formula.left, formula.right)), names)
    if isinstance(formula, Xor):
        return _spin(Not(Equiv(formula.left, formula.right)), names)
    assert isinstance(formula, BINARY_TYPES), formula
    left, right = _spin(formula.left, names), _spin(formula.right, names)
    return f"({left} {SPIN_BINARY[type(formula)]} {right})"
