"""Vacuity: a property that holds only because its trigger never happens.

``G(p -> F q)`` holds on every run where ``p`` is never true, whatever
``q`` does; a safety property that "holds" that way checks nothing.  The
triggers of a formula are the antecedents of its implications that are
plain state conditions (no temporal operator).  A trigger that is false
in every reachable state of the model makes its implication true at every
position of every run: the property holds vacuously.

The judgement is only as good as the set of states it is made on, so the
caller hands over the valuations of ALL reachable states (those of a
complete search) and asks only about properties that hold.

Example::

    >>> from rapidmc.ltl import parse_formula
    >>> formula = parse_formula("G((a & b) -> F c)")
    >>> watch = TriggerWatch([formula])
    >>> watch.atoms
    ('a', 'b')
    >>> watch.seen.update({0b00, 0b01})          # a alone, never a and b together
    >>> to_text(watch.never_true(formula))
    'a & b'
"""
from __future__ import annotations

from typing import Iterable, Optional

from ..ltl.printing import to_text
from ..ltl.syntax import (And, Atom, Equiv, FalseF, Formula, Implies, Not, Or, TrueF,
                          BINARY_TYPES, UNARY_TYPES, atoms_of, is_propositional)

__all__ = ["TriggerWatch", "triggers", "to_text"]


def triggers(formula: Formula) -> tuple[Formula, ...]:
    """The state-condition antecedents of the implications in ``formula``, outermost first."""
    found: list[Formula] = []
    stack = [formula]
    while stack:
        node = stack.pop()
        if isinstance(node, Implies) and is_propositional(node.left) and node.left not in found:
            found.append(node.left)
        if isinstance(node, UNARY_TYPES):
            stack.append(node.operand)
        elif isinstance(node, BINARY_TYPES):
            stack.extend((node.right, node.left))
    return tuple(found)


def holds(formula: Formula, atoms: tuple[str, ...], bits: int) -> bool:
    """The value of a state condition in a state whose atom ``atoms[i]`` is bit ``1 << i``."""
    if isinstance(formula, Atom):
        return bool(bits >> atoms.index(formula.name) & 1)
    if isinstance(formula, (TrueF, FalseF)):
        return isinstance(formula, TrueF)
    if isinstance(formula, Not):
        return not holds(formula.operand, atoms, bits)
    left, right = holds(formula.left, atoms, bits), holds(formula.right, atoms, bits)
    if isinstance(formula, And):
        return left and right
    if isinstance(formula, Or):
        return left or right
    if isinstance(formula, Implies):
        return not left or right
    if isinstance(formula, Equiv):
        return left == right
    return left != right                     # Xor


class TriggerWatch:
    """Collects which combinations of the triggers' atoms occur in the states it is shown.

    ``atoms`` are the atoms of every trigger of the given formulas; the
    caller evaluates them in each reachable state (``valuation(state)``,
    bit ``1 << i`` for ``atoms[i]``) and adds the result to ``seen``.
    """

    def __init__(self, formulas: Iterable[Formula]):
        self.triggers = {formula: triggers(formula) for formula in formulas}
        names: dict[str, None] = {}
        for found in self.triggers.values():
            for trigger in found:
                names.update(dict.fromkeys(atoms_of(trigger)))
        self.atoms = tuple(names)
        self.seen: set[int] = set()

    def never_true(self, formula: Formula) -> Optional[Formula]:
        """The first trigger of ``formula`` false in every state seen, or None."""
        for trigger in self.triggers.get(formula, ()):
            if not any(holds(trigger, self.atoms, bits) for bits in self.seen):
                return trigger
        return None
