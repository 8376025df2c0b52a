"""Automaton sizes of the built-in translator against SPIN's (``spin -f``) and Spot's.

    python bench/ltl.py [--count N] [--seed S]

Prints one row per formula set: formulas translated, SPIN timeouts, and
mean/max states of ours and of SPIN's never claims, plus the time per
translation of the paper's property.  Where Spot's Python bindings are
installed, also the total states and (source, target) edges of ours and of
Spot's state-based Büchi automata on ``ltl_cases.SPOT_RANDOM_SETS``.  Every compared pair is also checked
for language equivalence (a disagreement is printed and the exit code is 1).
"""
from __future__ import annotations

import argparse
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path
from statistics import mean

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from ltl_cases import (WITHOUT_EQUIVALENCES, dwyer_patterns, random_formulas,  # noqa: E402
                       spot_random_formulas)
from rapidmc.ltl import parse_formula, to_text  # noqa: E402
from rapidmc.ltl.spin import cross_check  # noqa: E402
from rapidmc.ltl.spot_backend import from_spot, spot_automaton, spot_available  # noqa: E402
from rapidmc.ltl.translate import translate  # noqa: E402

PAPER_PROPERTY = "G(!c_in & s1 & s2 -> F(s3 & !s4))"


def compare(formulas, atoms, timeout):
    with ThreadPoolExecutor(max_workers=4) as pool:
        return list(pool.map(lambda f: cross_check(f, translate, atoms, timeout), formulas))


def row(name: str, results) -> tuple[str, bool]:
    checked = [r for r in results if r.agrees is not None]
    for r in results:
        if r.agrees is False:
            print(f"DISAGREEMENT {to_text(r.formula)}: {r.detail}")
    ours = [r.our_states for r in checked]
    spins = [r.spin_states for r in checked]
    line = (f"{name:<28} {len(checked):>6} {len(results) - len(checked):>8} "
            f"{mean(ours):>9.2f} {max(ours):>8} {mean(spins):>9.2f} {max(spins):>8}")
    return line, all(r.agrees is not False for r in results)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=500)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=5.0)
    args = parser.parse_args()
    atoms = ("a", "b", "c")
    sets = [
        ("random X-free, 3 atoms", compare(random_formulas(
            args.seed, args.count, atoms, False, 6, WITHOUT_EQUIVALENCES), atoms, args.timeout)),
        ("Dwyer patterns", compare([parse_formula(t) for _, t in dwyer_patterns()],
                                   ("p", "q", "r", "s"), 60.0)),
    ]
    print(f"{'formula set':<28} {'count':>6} {'timeouts':>8} {'ours mean':>9} {'ours max':>8} "
          f"{'spin mean':>9} {'spin max':>8}")
    ok = True
    for name, results in sets:
        line, agrees = row(name, results)
        print(line)
        ok &= agrees
    formula = parse_formula(PAPER_PROPERTY)
    start = time.perf_counter()
    for _ in range(100):
        translate(formula)
    print(f"paper property {PAPER_PROPERTY}: {translate(formula).state_count} states, "
          f"{(time.perf_counter() - start) * 10:.2f} ms per translation")
    if spot_available():
        print(spot_sizes())
    return 0 if ok else 1


def spot_sizes() -> str:
    ours = [0, 0, 0.0]
    spots = [0, 0, 0.0]
    count = 0
    for formula in spot_random_formulas():
        count += 1
        start = time.perf_counter()
        built_in = translate(from_spot(formula))
        middle = time.perf_counter()
        reference = spot_automaton(from_spot(formula))
        end = time.perf_counter()
        ours[0] += built_in.state_count
        ours[1] += sum(len({e.target for e in out}) for out in built_in.edges)
        ours[2] += middle - start
        spots[0] += reference.num_states()
        spots[1] += reference.num_edges()
        spots[2] += end - middle
    return (f"spot randltl, {count} formulas: built-in {ours[0]} states, {ours[1]} edges, "
            f"{ours[2]:.1f} s; Spot {spots[0]} states, {spots[1]} edges, {spots[2]:.1f} s; "
            f"ratio {ours[0] / spots[0]:.3f} states, {ours[1] / spots[1]:.3f} edges")


if __name__ == "__main__":
    sys.exit(main())
