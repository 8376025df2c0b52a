"""The built-in LTL → Büchi translator (tableau construction, then degeneralisation).

1. The formula goes to negation normal form (``normal_form``).
2. Tableau: a state is a set of NNF formulas that must hold from the
   current position on.  Expanding a state gives *terms*: a cube of literals
   the current valuation must satisfy, the formulas owed from the next
   position on, and the ``U`` formulas it postpones (``a U b`` expands to
   ``b``, or ``a`` and ``X(a U b)``, postponing it).  Terms dominated by
   another term of the same state (weaker guard, fewer obligations, fewer
   postponements) are dropped.  This gives a transition-based generalised
   Büchi automaton whose acceptance set for ``a U b`` holds the
   transitions that do not postpone it (Couvreur's construction).
3. Degeneralisation: a counter over the acceptance sets turns it into a
   state-based Büchi automaton; states where the counter completes a round
   accept.  The initial state may start on level 0 or on a completed round
   (same language); the smaller result is kept.
4. ``reduce.simplify`` drops useless states and merges bisimilar ones.

A state reads the valuation of the current position, so the tableau state
``{φ}`` is the initial state and no extra start state is needed.

Example::

    >>> from .syntax import parse_formula
    >>> translate(parse_formula("G F p")).state_count
    2
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Iterable, Sequence

from .buchi import Buchi, Edge
from .graph import strongly_connected_components
from .guards import TRUE_CUBE, Cube, conjoin
from .normal_form import FALSE, TRUE, negation_normal_form
from .printing import to_text
from .reduce import simplify
from .syntax import And, Atom, Formula, Next, Not, Or, Release, Until, atoms_of

Obligations = frozenset  # of NNF formulas


@dataclass(frozen=True)
class Term:
    """One way to satisfy a state at the current position."""

    cube: Cube
    obligations: Obligations
    postponed: frozenset   # of Until formulas

    def dominates(self, other: "Term") -> bool:
        return (self.cube[0] & ~other.cube[0] == 0 and self.cube[1] & ~other.cube[1] == 0
                and self.obligations <= other.obligations and self.postponed <= other.postponed)


def undominated(terms: list[Term]) -> list[Term]:
    """``terms`` without those another (different) term dominates, in their order.

    A dominating term is never larger (literals, obligations, postponements
    counted), so trying the smaller terms first finds every dominator among
    the terms kept so far.
    """
    def size(term: Term) -> int:
        return (bin(term.cube[0]).count("1") + bin(term.cube[1]).count("1")
                + len(term.obligations) + len(term.postponed))
    kept: list[Term] = []
    for term in sorted(dict.fromkeys(terms), key=size):
        if not any(other.dominates(term) for other in kept):
            kept.append(term)
    survivors = set(kept)
    return [t for t in dict.fromkeys(terms) if t in survivors]


def conjoined_terms(left: Sequence[Term], right: Sequence[Term]) -> list[Term]:
    terms: dict[Term, None] = {}
    for a in left:
        for b in right:
            cube = conjoin(a.cube, b.cube)
            if cube is not None:
                terms[Term(cube, a.obligations | b.obligations, a.postponed | b.postponed)] = None
    return list(terms)


def obligations_of(formula: Formula) -> Obligations:
    """A formula as a set of conjuncts (``true`` vanishes)."""
    if type(formula) is And:
        return obligations_of(formula.left) | obligations_of(formula.right)
    return frozenset() if formula == TRUE else frozenset([formula])


class Tableau:
    """Expansion of NNF formulas and obligation sets, memoised."""

    def __init__(self, atoms: Sequence[str]):
        self.bits = {name: 1 << index for index, name in enumerate(atoms)}
        self._terms: dict[Formula, list[Term]] = {}
        self._keys: dict[Formula, str] = {}

    def key(self, formula: Formula) -> str:
        if formula not in self._keys:
            self._keys[formula] = to_text(formula)
        return self._keys[formula]

    def ordered(self, formulas: Iterable[Formula]) -> list[Formula]:
        return sorted(formulas, key=self.key)

    def terms(self, formula: Formula) -> list[Term]:
        if formula not in self._terms:
            self._terms[formula] = self._expand(formula)
        return self._terms[formula]

    def _expand(self, formula: Formula) -> list[Term]:
        kind = type(formula)
        if formula == TRUE:
            return [Term(TRUE_CUBE, frozenset(), frozenset())]
        if formula == FALSE:
            return []
        if kind is Atom:
            return [Term((self.bits[formula.name], 0), frozenset(), frozenset())]
        if kind is Not:
            return [Term((0, self.bits[formula.operand.name]), frozenset(), frozenset())]
        if kind is And:
            return conjoined_terms(self.terms(formula.left), self.terms(formula.right))
        if kind is Or:
            return list(dict.fromkeys(self.terms(formula.left) + self.terms(formula.right)))
        if kind is Next:
            return [Term(TRUE_CUBE, obligations_of(formula.operand), frozenset())]
        if kind is Until:
            again = Term(TRUE_CUBE, frozenset([formula]), frozenset([formula]))
            return list(dict.fromkeys(self.terms(formula.right)
                                      + conjoined_terms(self.terms(formula.left), [again])))
        assert kind is Release, formula
        again = Term(TRUE_CUBE, frozenset([formula]), frozenset())
        right = self.terms(formula.right)
        return list(dict.fromkeys(conjoined_terms(right, self.terms(formula.left))
                                  + conjoined_terms(right, [again])))

    def state_terms(self, state: Obligations) -> list[Term]:
        """The undominated terms of a state (all its formulas at once).

        Dominated terms are dropped after each conjunction, not only at the
        end: if ``o`` dominates ``t`` then ``o & x`` dominates ``t & x`` for
        every further term ``x``, so the result is the same and the
        intermediate products stay small.
        """
        terms = [Term(TRUE_CUBE, frozenset(), frozenset())]
        for formula in self.ordered(state):
            terms = undominated(conjoined_terms(terms, self.terms(formula)))
        return terms


@dataclass(frozen=True)
class GeneralisedBuchi:
    """Transition-based generalised Büchi automaton from the tableau."""

    states: tuple[Obligations, ...]
    transitions: tuple[tuple[tuple[Cube, int, frozenset], ...], ...]  # (cube, target, postponed)
    untils: tuple[Formula, ...]  # one acceptance set each: transitions not postponing it


def tableau_automaton(formula: Formula, atoms: Sequence[str]) -> GeneralisedBuchi:
    tableau = Tableau(atoms)
    initial = obligations_of(formula)
    numbers: dict[Obligations, int] = {initial: 0}
    states, transitions = [initial], []
    postponed_anywhere: set[Formula] = set()
    for state in states:                    # grows while we walk it (breadth first)
        outgoing = []
        for term in tableau.state_terms(state):
            if term.obligations not in numbers:
                numbers[term.obligations] = len(states)
                states.append(term.obligations)
            outgoing.append((term.cube, numbers[term.obligations], term.postponed))
            postponed_anywhere |= term.postponed
        transitions.append(tuple(outgoing))
    return GeneralisedBuchi(tuple(states), tuple(transitions),
                            tuple(tableau.ordered(postponed_anywhere)))


def degeneralise(automaton: GeneralisedBuchi, atoms: Sequence[str],
                 entry_level: int = 0) -> Buchi:
    """State-based Büchi automaton: states are (tableau state, level) pairs.

    A run is accepted by what it does in the strongly connected component
    it finally stays in, so the level a run has reached when it enters a
    component changes no accepted word: the initial state and every edge
    into another component start on ``entry_level`` (any value in
    ``0 .. len(untils)`` gives the same language), which spares the level
    copies of transient states.
    """
    rounds = len(automaton.untils)
    component = _components(automaton)
    numbers: dict[tuple[int, int], int] = {(0, entry_level): 0}
    pairs: list[tuple[int, int]] = [(0, entry_level)]
    edges: list[tuple[Edge, ...]] = []
    for state, level in pairs:
        outgoing = []
        for cube, target, postponed in automaton.transitions[state]:
            start = entry_level if component[target] != component[state] else level
            next_level = 0 if start == rounds else start
            while next_level < rounds and automaton.untils[next_level] not in postponed:
                next_level += 1
            pair = (target, next_level)
            if pair not in numbers:
                numbers[pair] = len(pairs)
                pairs.append(pair)
            outgoing.append(Edge(cube[0], cube[1], numbers[pair]))
        edges.append(tuple(outgoing))
    accepting = frozenset(n for n, (_, level) in enumerate(pairs) if level == rounds)
    return Buchi(tuple(atoms), 0, accepting, tuple(edges))


def _components(automaton: GeneralisedBuchi) -> dict[int, int]:
    """The strongly connected component (a number) of each tableau state."""
    def successors(state: int) -> list[int]:
        return [target for _, target, _ in automaton.transitions[state]]
    return {state: number
            for number, members in enumerate(strongly_connected_components([0], successors))
            for state in members}


def translate(formula: Formula, atoms: Sequence[str] | None = None) -> Buchi:
    """A state-based Büchi automaton accepting exactly the words satisfying ``formula``.

    ``atoms`` fixes the atom order (default: order of first appearance); it
    must include every atom of the formula.
    """
    return _translated(formula, tuple(atoms) if atoms is not None else atoms_of(formula))


# A process that checks again (the language server, the API's callers, the tests) translates
# the same formulas again: the automaton (immutable) is a function of the formula and atoms.
@functools.lru_cache(maxsize=1024)
def _translated(formula: Formula, atoms: tuple[str, ...]) -> Buchi:
    generalised = tableau_automaton(negation_normal_form(formula), atoms)
    candidates = (simplify(degeneralise(generalised, atoms, level))
                  for level in sorted({0, len(generalised.untils)}))
    return min(candidates, key=lambda a: (a.state_count, a.edge_count()))
