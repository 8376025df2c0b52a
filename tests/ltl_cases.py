"""Seeded random LTL formulas and lasso words for the LTL tests (no test functions here)."""
from __future__ import annotations

import random

from rapidmc.ltl.syntax import (And, Atom, Equiv, FalseF, Finally, Globally, Implies, Next, Not,
                                Or, Release, StrongRelease, TrueF, Until, WeakUntil, Xor)

UNARY = (Not, Next, Globally, Finally)
BINARY = (And, Or, Implies, Equiv, Xor, Until, WeakUntil, Release, StrongRelease)


def random_formula(rng: random.Random, atoms, size: int, with_next: bool = True):
    """A formula with about ``size`` operators over ``atoms``."""
    if size <= 0:
        roll = rng.random()
        if roll < 0.06:
            return TrueF()
        if roll < 0.12:
            return FalseF()
        return Atom(rng.choice(atoms))
    unary = [op for op in UNARY if with_next or op is not Next]
    if rng.random() < 0.4:
        return rng.choice(unary)(random_formula(rng, atoms, size - 1, with_next))
    left = rng.randint(0, size - 1)
    return rng.choice(BINARY)(random_formula(rng, atoms, left, with_next),
                              random_formula(rng, atoms, size - 1 - left, with_next))


def random_letter(rng: random.Random, atoms) -> frozenset:
    return frozenset(a for a in atoms if rng.random() < 0.5)


def random_lasso(rng: random.Random, atoms):
    prefix = [random_letter(rng, atoms) for _ in range(rng.randint(0, 3))]
    cycle = [random_letter(rng, atoms) for _ in range(rng.randint(1, 4))]
    return prefix, cycle
