"""Oracles on ultimately periodic words ``prefix cycle^ω`` and Büchi emptiness.

A letter is the collection of atom names that are true at that position.

* ``holds_on_lasso(formula, prefix, cycle)`` evaluates LTL directly: the
  word has ``len(prefix) + len(cycle)`` distinct positions, the last one
  followed by the first position of the cycle; ``U`` is a least and ``R``
  a greatest fixpoint over those positions.
* ``accepts_lasso(buchi, prefix, cycle)``: the product of the automaton
  with the lasso holds a reachable cycle through an accepting state.
* ``product_is_empty(a, b)``: no word is accepted by both automata.

Example::

    >>> from .syntax import parse_formula
    >>> holds_on_lasso(parse_formula("G F p"), [], [{"p"}, set()])
    True
    >>> holds_on_lasso(parse_formula("F G p"), [], [{"p"}, set()])
    False
"""
from __future__ import annotations

from typing import Collection, Sequence

from .buchi import Buchi
from .graph import is_cyclic, strongly_connected_components
from .syntax import (And, Atom, Equiv, FalseF, Finally, Formula, Globally, Implies, Next, Not,
                     Or, Release, StrongRelease, TrueF, Until, WeakUntil, Xor)

Letter = Collection[str]


def holds_on_lasso(formula: Formula, prefix: Sequence[Letter], cycle: Sequence[Letter]) -> bool:
    if not cycle:
        raise ValueError("the cycle of a lasso word must not be empty")
    word = list(prefix) + list(cycle)
    successor = list(range(1, len(word))) + [len(prefix)]
    return _truth(formula, word, successor, {})[0]


def _truth(formula: Formula, word, successor, memo) -> list[bool]:
    if formula not in memo:
        memo[formula] = _evaluate(formula, word, successor, memo)
    return memo[formula]


def _evaluate(formula, word, successor, memo) -> list[bool]:
    def sub(f):
        return _truth(f, word, successor, memo)
    kind, n = type(formula), len(word)
    if kind is Atom:
        return [formula.name in letter for letter in word]
    if kind in (TrueF, FalseF):
        return [kind is TrueF] * n
    if kind is Not:
        return [not v for v in sub(formula.operand)]
    if kind is Next:
        values = sub(formula.operand)
        return [values[successor[i]] for i in range(n)]
    if kind is Finally:
        return sub(Until(TrueF(), formula.operand))
    if kind is Globally:
        return sub(Release(FalseF(), formula.operand))
    a, b = sub(formula.left), sub(formula.right)
    if kind in BOOLEAN:
        return [BOOLEAN[kind](x, y) for x, y in zip(a, b)]
    if kind is Until:
        return _fixpoint(lambda i, v: b[i] or (a[i] and v[successor[i]]), n, False)
    if kind is Release:
        return _fixpoint(lambda i, v: b[i] and (a[i] or v[successor[i]]), n, True)
    if kind is WeakUntil:
        return _fixpoint(lambda i, v: b[i] or (a[i] and v[successor[i]]), n, True)
    assert kind is StrongRelease, formula
    return _fixpoint(lambda i, v: b[i] and (a[i] or v[successor[i]]), n, False)


BOOLEAN = {And: lambda x, y: x and y, Or: lambda x, y: x or y,
           Implies: lambda x, y: (not x) or y, Equiv: lambda x, y: x == y,
           Xor: lambda x, y: x != y}


def _fixpoint(step, n: int, start: bool) -> list[bool]:
    """Least (start False) or greatest (start True) fixpoint of a pointwise step."""
    values = [start] * n
    while True:
        updated = [step(i, values) for i in range(n)]
        if updated == values:
            return values
        values = updated


def valuation(letter: Letter, atoms: Sequence[str]) -> int:
    return sum(1 << i for i, name in enumerate(atoms) if name in letter)


def accepts_lasso(buchi: Buchi, prefix: Sequence[Letter], cycle: Sequence[Letter]) -> bool:
    if not cycle:
        raise ValueError("the cycle of a lasso word must not be empty")
    word = [valuation(letter, buchi.atoms) for letter in list(prefix) + list(cycle)]
    successor = list(range(1, len(word))) + [len(prefix)]

    def successors(node: tuple[int, int]) -> list[tuple[int, int]]:
        state, position = node
        return [(target, successor[position])
                for target in dict.fromkeys(buchi.successors(state, word[position]))]
    return _has_accepting_cycle([(buchi.initial, 0)], successors,
                                [lambda node: node[0] in buchi.accepting])


def _has_accepting_cycle(roots, successors, acceptance_sets) -> bool:
    """Some reachable cyclic component meets every acceptance set (generalised Büchi)."""
    memo: dict = {}

    def cached(node):
        if node not in memo:
            memo[node] = successors(node)
        return memo[node]
    for component in strongly_connected_components(roots, cached):
        if is_cyclic(component, cached) and all(
                any(accepts(node) for node in component) for accepts in acceptance_sets):
            return True
    return False


def _remap(mask: int, source: Sequence[str], index: dict[str, int]) -> int:
    return sum(1 << index[name] for i, name in enumerate(source) if mask >> i & 1)


def product_is_empty(a: Buchi, b: Buchi) -> bool:
    """Whether no word over the union of both atom sets is accepted by both."""
    atoms = list(dict.fromkeys(a.atoms + b.atoms))
    index = {name: i for i, name in enumerate(atoms)}
    edges_a = [[(_remap(e.positive, a.atoms, index), _remap(e.negative, a.atoms, index),
                 e.target) for e in out] for out in a.edges]
    edges_b = [[(_remap(e.positive, b.atoms, index), _remap(e.negative, b.atoms, index),
                 e.target) for e in out] for out in b.edges]

    def successors(node: tuple[int, int]) -> list[tuple[int, int]]:
        pairs = {}
        for positive_a, negative_a, target_a in edges_a[node[0]]:
            for positive_b, negative_b, target_b in edges_b[node[1]]:
                if (positive_a | positive_b) & (negative_a | negative_b) == 0:
                    pairs[(target_a, target_b)] = None
        return list(pairs)
    return not _has_accepting_cycle([(a.initial, b.initial)], successors,
                                    [lambda node: node[0] in a.accepting,
                                     lambda node: node[1] in b.accepting])
