"""Model-checking speed: product states per second and bytes per stored state.

Usage: python bench/check.py [N_INPUTS] [LOOP_BOUND]   (defaults 3 and 60)

Two models:
* a scalable one: N free digital inputs read in a loop that counts modulo
  LOOP_BOUND in two nested counters, against the liveness property
  ``G F "c = 0"`` (HOLDS: explores the whole product);
* the pinion-sorting cell (programs A, B, C with the plant model) against
  P1-P3 of specs/sorter.ltl.
"""
from __future__ import annotations

import sys
import time
import tracemalloc
from pathlib import Path

from rapidmc import ast
from rapidmc.check import check_property
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model import RapidSystem
from rapidmc.properties import AtomCompiler, read_property_file
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program, parse_text

ROOT = Path(__file__).resolve().parent.parent


def scalable_program(inputs: int, bound: int) -> str:
    declarations = "\n".join(f"  VAR signaldi in{i};" for i in range(inputs))
    aliases = "\n".join(f'    AliasIO "IN{i}", in{i};' for i in range(inputs))
    reads = " + ".join(f"in{i}" for i in range(inputs)) or "0"
    return f"""
MODULE Scalable
{declarations}
  VAR num c := 0;
  VAR num d := 0;
  PROC main()
{aliases}
    WHILE TRUE DO
      IF ({reads}) > 0 THEN
        c := (c + 1) MOD {bound};
        IF c = 0 d := (d + 1) MOD {bound};
      ELSE
        d := (d + 1) MOD {bound};
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def measure(name: str, program, formula_text: str, formula=None, store_inputs=False) -> None:
    formula = formula or parse_formula(formula_text)
    buchi = to_buchi(Not(formula))
    atoms = AtomCompiler(program)
    valuation = atoms.valuation(buchi.atoms, {})
    # as `rapidmc check` does: inputs no atom reads are chosen when read
    # (store_inputs: keep every free input in every state instead)
    config = CheckConfig(program, observed=None if store_inputs else set(atoms.observed))
    system = RapidSystem(program, config)
    start = time.perf_counter()
    result = check_property(system, buchi, valuation, max_states=2_000_000)
    seconds = time.perf_counter() - start
    stats = result.stats
    # memory: a second, traced run of the same search (tracing slows it down)
    tracemalloc.start()
    uncached = RapidSystem(program, config)
    uncached.shared_limit = 0      # the search's own memory, without the cross-property cache
    check_property(uncached, buchi, valuation, max_states=2_000_000)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    per_state = peak / max(stats.product_states, 1)
    print(f"{name:24} {result.verdict:9} {stats.product_states:>8,} product states "
          f"{stats.model_states:>8,} model states {seconds:6.2f} s "
          f"{stats.product_states / seconds:>8,.0f} states/s {per_state:>6,.0f} bytes/state")


def main() -> None:
    inputs = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    bound = int(sys.argv[2]) if len(sys.argv) > 2 else 60
    program = build(ast.Program(parse_text(scalable_program(inputs, bound), "scalable.mod")))
    measure(f"scalable N={inputs} M={bound}", program, 'G F "d = 0"')
    measure(f"  same, inputs stored", program, 'G F "d = 0"', store_inputs=True)
    properties = read_property_file(str(ROOT / "specs" / "sorter.ltl"))
    plant = load_program([str(ROOT / "case_studies" / "sorter" / "plant.mod")])
    for letter in "abc":
        sorter = build(load_program([str(ROOT / "case_studies" / "sorter" / f"sorter_{letter}.mod")]),
                       environment=plant)
        for prop in properties:
            measure(f"sorter {letter.upper()} {prop.name}", sorter, prop.text, prop.formula)


if __name__ == "__main__":
    main()
