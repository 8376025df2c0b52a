"""Negation normal form with light rewriting, the input of the tableau translator.

An NNF formula uses only ``Atom``, ``Not(Atom)``, ``TrueF``, ``FalseF``,
``And``, ``Or``, ``Next``, ``Until`` and ``Release``: ``G a`` is
``false R a``, ``F a`` is ``true U a``, ``a W b`` is ``b R (a | b)`` and
``a M b`` is ``b U (a & b)``.  The smart constructors fold constants and a
few idempotent patterns (``F F a``, ``G G a``, ``a U a``) so that automata
stay small; every rewrite is an LTL equivalence.

Example::

    >>> from .syntax import parse_formula
    >>> from .printing import to_text
    >>> to_text(negation_normal_form(parse_formula("!G(a -> F b)")))
    'true U (a & false R !b)'
"""
from __future__ import annotations

from .syntax import (And, Atom, Equiv, FalseF, Finally, Formula, Globally, Implies, Next, Not,
                     Or, Release, StrongRelease, TrueF, Until, WeakUntil, Xor)

TRUE, FALSE = TrueF(), FalseF()


def negation_normal_form(formula: Formula, positive: bool = True) -> Formula:
    """``formula`` (or its negation, when ``positive`` is false) in NNF."""
    kind = type(formula)
    if kind is Atom:
        return formula if positive else Not(formula)
    if kind in (TrueF, FalseF):
        return TRUE if (kind is TrueF) == positive else FALSE
    if kind is Not:
        return negation_normal_form(formula.operand, not positive)
    if kind is Next:
        return next_(negation_normal_form(formula.operand, positive))
    if kind in (Globally, Finally):
        operand = negation_normal_form(formula.operand, positive)
        if (kind is Globally) == positive:
            return release(FALSE, operand)
        return until(TRUE, operand)
    return BINARY_RULES[kind](formula.left, formula.right, positive)


def _dual_pair(when_positive, when_negative):
    """The NNF rule of a binary operator: build from both operands in NNF."""
    def rule(left: Formula, right: Formula, positive: bool) -> Formula:
        a = negation_normal_form(left, positive)
        b = negation_normal_form(right, positive)
        return when_positive(a, b) if positive else when_negative(a, b)
    return rule


def _implies(left, right, positive):
    return BINARY_RULES[Or](Not(left), right, positive)


def _equiv(left, right, positive):
    both = and_(negation_normal_form(left), negation_normal_form(right))
    negated_left = negation_normal_form(left, False)
    if positive:
        return or_(both, and_(negated_left, negation_normal_form(right, False)))
    return or_(and_(negation_normal_form(left), negation_normal_form(right, False)),
               and_(negated_left, negation_normal_form(right)))


def _xor(left, right, positive):
    return _equiv(left, right, not positive)


# a W b == b R (a | b), and its negation !b U (!a & !b) (operands arrive negated);
# a M b == b U (a & b), and its negation !b R (!a | !b).
BINARY_RULES = {
    And: _dual_pair(lambda a, b: and_(a, b), lambda a, b: or_(a, b)),
    Or: _dual_pair(lambda a, b: or_(a, b), lambda a, b: and_(a, b)),
    Until: _dual_pair(lambda a, b: until(a, b), lambda a, b: release(a, b)),
    Release: _dual_pair(lambda a, b: release(a, b), lambda a, b: until(a, b)),
    WeakUntil: _dual_pair(lambda a, b: release(b, or_(a, b)),
                          lambda a, b: until(b, and_(a, b))),
    StrongRelease: _dual_pair(lambda a, b: until(b, and_(a, b)),
                              lambda a, b: release(b, or_(a, b))),
    Implies: _implies, Equiv: _equiv, Xor: _xor,
}


# --------------------------------------------------------------------------
# Smart constructors (each result is equivalent to the plain operator)
# --------------------------------------------------------------------------


def _complementary(a: Formula, b: Formula) -> bool:
    return (type(a) is Not and a.operand == b) or (type(b) is Not and b.operand == a)


def _connective(node, neutral: Formula, absorbing: Formula):
    """A smart ``&`` (or ``|``): folds constants, ``x op x`` and ``x op !x``."""
    def build(a: Formula, b: Formula) -> Formula:
        if absorbing in (a, b) or _complementary(a, b):
            return absorbing
        if a == neutral or a == b:
            return b
        if b == neutral:
            return a
        return node(a, b)
    return build


and_ = _connective(And, TRUE, FALSE)
or_ = _connective(Or, FALSE, TRUE)


def next_(a: Formula) -> Formula:
    return a if a in (TRUE, FALSE) else Next(a)


def is_eventually(formula: Formula) -> bool:
    return type(formula) is Until and formula.left == TRUE


def is_always(formula: Formula) -> bool:
    return type(formula) is Release and formula.left == FALSE


def until(a: Formula, b: Formula) -> Formula:
    if b in (TRUE, FALSE) or a == FALSE or a == b:
        return b
    if a == TRUE and (is_eventually(b) or is_always(b) and is_eventually(b.right)):
        return b        # F F x == F x;  F G F x == G F x
    return Until(a, b)


def release(a: Formula, b: Formula) -> Formula:
    if b in (TRUE, FALSE) or a == TRUE or a == b:
        return b
    if a == FALSE and (is_always(b) or is_eventually(b) and is_always(b.right)):
        return b        # G G x == G x;  G F G x == F G x
    return Release(a, b)
