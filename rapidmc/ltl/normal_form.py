"""Negation normal form with light rewriting, the input of the tableau translator.

An NNF formula uses only ``Atom``, ``Not(Atom)``, ``TrueF``, ``FalseF``,
``And``, ``Or``, ``Next``, ``Until`` and ``Release``: ``G a`` is
``false R a``, ``F a`` is ``true U a``, ``a W b`` is ``b R (a | b)`` and
``a M b`` is ``b U (a & b)``.  The smart constructors fold constants and
rewrite by LTL equivalences so that automata stay small:

* ``a U a``, ``a R a``; ``F(a U b) = F b``, ``G(a R b) = G b``;
* ``X a & X b = X(a & b)``, ``X a | X b = X(a | b)``, ``F a | F b = F(a | b)``,
  ``G a & G b = G(a & b)``;
* pure eventualities ``e`` (``e = F e``: ``F x``, ``G F x``, ``X e``, …) and
  purely universal formulas ``u`` (``u = G u``) after Etessami and Holzmann:
  ``a U e = e``, ``a R u = u``, and ``X s = s`` when ``s`` is both (as
  ``G F x`` and ``F G x`` are), which suspends such subformulas instead of
  stepping them through ``X``.

Example::

    >>> from .syntax import parse_formula
    >>> from .printing import to_text
    >>> to_text(negation_normal_form(parse_formula("!G(a -> F b)")))
    'true U (a & false R !b)'
"""
from __future__ import annotations

from functools import lru_cache

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


_plain_and = _connective(And, TRUE, FALSE)
_plain_or = _connective(Or, FALSE, TRUE)


def and_(a: Formula, b: Formula) -> Formula:
    if type(a) is Next and type(b) is Next:
        return next_(and_(a.operand, b.operand))            # X a & X b == X(a & b)
    if is_always(a) and is_always(b):
        return release(FALSE, and_(a.right, b.right))        # G a & G b == G(a & b)
    return _plain_and(a, b)


def or_(a: Formula, b: Formula) -> Formula:
    if type(a) is Next and type(b) is Next:
        return next_(or_(a.operand, b.operand))             # X a | X b == X(a | b)
    if is_eventually(a) and is_eventually(b):
        return until(TRUE, or_(a.right, b.right))            # F a | F b == F(a | b)
    return _plain_or(a, b)


def next_(a: Formula) -> Formula:
    if a in (TRUE, FALSE) or is_eventual(a) and is_universal(a):
        return a
    return Next(a)


def is_eventually(formula: Formula) -> bool:
    return type(formula) is Until and formula.left == TRUE


def is_always(formula: Formula) -> bool:
    return type(formula) is Release and formula.left == FALSE


def is_eventual(formula: Formula) -> bool:
    """A pure eventuality of NNF: ``formula`` is equivalent to ``F formula``."""
    return _absorbs(formula, Until)


def is_universal(formula: Formula) -> bool:
    """A purely universal formula of NNF: ``formula`` is equivalent to ``G formula``."""
    return _absorbs(formula, Release)


@lru_cache(maxsize=8192)
def _absorbs(formula: Formula, operator: type) -> bool:
    """Whether ``F formula == formula`` (``operator`` Until) or ``G formula == formula`` (Release).

    The two classes are dual: ``F`` is ``true U``, ``G`` is ``false R``.
    """
    unit, dual = (TRUE, Release) if operator is Until else (FALSE, Until)
    kind = type(formula)
    if kind is TrueF or kind is FalseF:
        return True
    if kind is Next:
        return _absorbs(formula.operand, operator)
    if kind is operator:
        return formula.left == unit or _absorbs(formula.right, operator)
    if kind in (And, Or, dual):
        return _absorbs(formula.left, operator) and _absorbs(formula.right, operator)
    return False


def until(a: Formula, b: Formula) -> Formula:
    if b in (TRUE, FALSE) or a == FALSE or a == b or is_eventual(b):
        return b        # a U e == e: F F x == F x, F G F x == G F x
    if a == TRUE and type(b) is Until:
        return until(TRUE, b.right)                           # F(a U b) == F b
    return Until(a, b)


def release(a: Formula, b: Formula) -> Formula:
    if b in (TRUE, FALSE) or a == TRUE or a == b or is_universal(b):
        return b        # a R u == u: G G x == G x, G F G x == F G x
    if a == FALSE and type(b) is Release:
        return release(FALSE, b.right)                        # G(a R b) == G b
    return Release(a, b)
