"""Translation with Spot's Python bindings (used when ``import spot`` works).

The formula is handed to Spot as a syntax tree built with Spot's own
constructors (``to_spot``), never as text: Spot reads ``GRIPPER`` as
``G RIPPER`` and ``FEED_OK`` as ``F EED_OK``, so printing and re-parsing
would change the meaning of such atoms.

Spot 2.12.1 needs two precautions, both pinned by ``tests/test_ltl_spot.py``:

* ``translate(f, 'BA')`` returns transition-based acceptance (the Python
  module drops the state-based option), so ``'sbacc'`` is asked for.
* ``translate(f, 'BA', 'sbacc', ...)`` is wrong on some formulas (it
  rejects words of ``XG((a R b) U a) -> X(a | XXb)``).  We therefore let
  Spot build its default generalised automaton (``translate(f, 'small',
  'high')``, which has been right on every formula we tried) and turn it
  into a state-based Büchi automaton with ``postprocess(.., 'BA', 'sbacc',
  'small', 'high')``; and the result is checked for language equivalence
  with the formula (``checked_equivalent``).  Should that check fail, or
  be too costly to make (complementing a large nondeterministic automaton
  can exhaust memory), the built-in translator's automaton is used
  instead: a verdict must not rest on an automaton not known to be right.

The HOA output is read back with ``hoa.read_hoa`` and the atoms are put
into the caller's order.

``from_spot`` converts the other way (used by the tests that take Spot's
random formulas and pattern families as input).
"""
from __future__ import annotations

from typing import Sequence

from .buchi import Buchi, Edge
from .hoa import read_hoa
from .syntax import (And, Atom, Equiv, FalseF, Finally, Formula, Globally, Implies, Next, Not,
                     Or, Release, StrongRelease, TrueF, Until, WeakUntil, Xor)

SPOT_OPTIONS = ("BA", "sbacc", "small", "high")   # for postprocess
COMPLEMENT_LIMIT = 25    # states of a nondeterministic automaton we let Spot complement

# our node type -> name of Spot's constructor (binary for And/Or: Spot's are n-ary)
_UNARY = {Not: "Not", Next: "X", Globally: "G", Finally: "F"}
_BINARY = {Implies: "Implies", Equiv: "Equiv", Xor: "Xor", Until: "U", WeakUntil: "W",
           Release: "R", StrongRelease: "M"}
_NARY = {And: "And", Or: "Or"}


def spot_available() -> bool:
    try:
        import spot  # noqa: F401
    except ImportError:
        return False
    return True


def to_spot(formula: Formula):
    """The same formula as a ``spot.formula``, atoms kept whole whatever their spelling."""
    import spot
    kind = type(formula)
    if kind is Atom:
        return spot.formula.ap(formula.name)
    if kind is TrueF:
        return spot.formula.tt()
    if kind is FalseF:
        return spot.formula.ff()
    if kind in _UNARY:
        return getattr(spot.formula, _UNARY[kind])(to_spot(formula.operand))
    if kind in _NARY:
        return getattr(spot.formula, _NARY[kind])([to_spot(formula.left), to_spot(formula.right)])
    return getattr(spot.formula, _BINARY[kind])(to_spot(formula.left), to_spot(formula.right))


def from_spot(formula) -> Formula:
    """A ``spot.formula`` (LTL operators only) as our syntax tree."""
    import spot
    kind = formula.kind()
    if kind == spot.op_ap:
        return Atom(formula.ap_name())
    if kind == spot.op_tt:
        return TrueF()
    if kind == spot.op_ff:
        return FalseF()
    children = [from_spot(child) for child in formula]
    for ours, name in (*_UNARY.items(), *_BINARY.items(), *_NARY.items()):
        if kind == getattr(spot, "op_" + name):
            if ours in _NARY:
                result = children[0]
                for child in children[1:]:
                    result = ours(result, child)
                return result
            return ours(*children)
    raise ValueError(f"not an LTL formula rapidmc reads: {formula}")


def spot_automaton(formula: Formula):
    """Spot's state-based Büchi automaton for ``formula`` (a ``spot.twa_graph``), unchecked."""
    import spot
    generalised = spot.translate(to_spot(formula), "small", "high")
    return spot.postprocess(generalised, *SPOT_OPTIONS)


def spot_translate(formula: Formula, atoms: Sequence[str]) -> Buchi:
    """Spot's automaton for ``formula``; the built-in one unless Spot's is checked equivalent."""
    automaton = spot_automaton(formula)
    if not checked_equivalent(automaton, formula):
        from .translate import translate
        return translate(formula, atoms)
    return with_atoms(read_hoa(automaton.to_str("hoa"), file="<spot>"), atoms)


def checked_equivalent(automaton, formula: Formula) -> bool:
    """Whether ``automaton`` is known to accept exactly the words of ``formula``.

    That it accepts no word of ``!formula`` is a product with Spot's
    translation of the negation, always cheap.  That it misses no word of
    ``formula`` needs the automaton's complement, which for a
    nondeterministic automaton means determinisation: exponential, and
    Spot 2.12.1 runs out of memory on a 55-state automaton of
    ``!G!FGF(X(p <-> X((!a -> Gd) xor XGx)) W a)``.  Beyond
    ``COMPLEMENT_LIMIT`` states that half is not attempted and the answer
    is False (unchecked).
    """
    import spot
    target = to_spot(formula)
    if automaton.intersects(spot.translate(spot.formula.Not(target))):
        return False
    if automaton.num_states() > COMPLEMENT_LIMIT and not spot.is_deterministic(automaton):
        return False
    return not spot.complement(automaton).intersects(spot.translate(target))


def with_atoms(automaton: Buchi, atoms: Sequence[str]) -> Buchi:
    """The same automaton over ``atoms`` (a superset of its own), bits renumbered."""
    position = {name: i for i, name in enumerate(atoms)}

    def moved(mask: int) -> int:
        return sum(1 << position[name] for i, name in enumerate(automaton.atoms)
                   if mask >> i & 1)
    edges = tuple(tuple(Edge(moved(e.positive), moved(e.negative), e.target) for e in out)
                  for out in automaton.edges)
    return Buchi(tuple(atoms), automaton.initial, automaton.accepting, edges)
