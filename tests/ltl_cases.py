"""Shared LTL test inputs: seeded random formulas and lassos, pattern data (no tests here)."""
from __future__ import annotations

import random
from pathlib import Path

from rapidmc.ltl.syntax import (And, Atom, Equiv, FalseF, Finally, Globally, Implies, Next, Not,
                                Or, Release, StrongRelease, TrueF, Until, WeakUntil, Xor)

UNARY = (Not, Next, Globally, Finally)
BINARY = (And, Or, Implies, Equiv, Xor, Until, WeakUntil, Release, StrongRelease)
WITHOUT_EQUIVALENCES = tuple(op for op in BINARY if op not in (Equiv, Xor))


def random_formula(rng: random.Random, atoms, size: int, with_next: bool = True,
                   binary=BINARY):
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
        return rng.choice(unary)(random_formula(rng, atoms, size - 1, with_next, binary))
    left = rng.randint(0, size - 1)
    return rng.choice(binary)(random_formula(rng, atoms, left, with_next, binary),
                              random_formula(rng, atoms, size - 1 - left, with_next, binary))


def random_letter(rng: random.Random, atoms) -> frozenset:
    return frozenset(a for a in atoms if rng.random() < 0.5)


def random_lasso(rng: random.Random, atoms):
    prefix = [random_letter(rng, atoms) for _ in range(rng.randint(0, 3))]
    cycle = [random_letter(rng, atoms) for _ in range(rng.randint(1, 4))]
    return prefix, cycle


DATA = Path(__file__).parent / "ltl"


def dwyer_patterns() -> list[tuple[str, str]]:
    """(name, formula text) pairs from tests/ltl/dwyer_patterns.txt."""
    pairs = []
    for line in (DATA / "dwyer_patterns.txt").read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            name, text = line.split(":", 1)
            pairs.append((name.strip(), text.strip()))
    return pairs


def random_formulas(seed: int, count: int, atoms, with_next: bool = True, max_size: int = 7,
                    binary=BINARY):
    rng = random.Random(seed)
    return [random_formula(rng, atoms, rng.randint(1, max_size), with_next, binary)
            for _ in range(count)]
