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


# Seeded random formulas from Spot's randltl (all operators, X, W, M, <-> and xor included):
# (atom count, tree size, seed, how many), about 3,000 in all.
SPOT_RANDOM_SETS = [(2, 10, 11, 800), (3, 15, 12, 1200), (4, 20, 13, 800), (3, 25, 14, 200)]


def spot_random_formulas(sets=SPOT_RANDOM_SETS):
    """``spot.formula`` values (needs Spot's Python bindings)."""
    import itertools
    import spot
    for atom_count, tree_size, seed, count in sets:
        generator = spot.randltl(atom_count, seed=seed, tree_size=tree_size, simplify=0)
        yield from itertools.islice(generator, count)
