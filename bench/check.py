"""Model-checking benchmark: what each reduction saves, and SPIN on the same model.

Usage: python bench/check.py [--sizes 4,5,6,7] [--modulo 4] [--statistics-sizes 3,4,5]
                             [--max-states N] [--statistics-max-states N]
                             [--no-spin] [--no-sorter] [--memory]

Models:
* the counters family: N free digital inputs, N counters modulo K; each
  loop iteration adds 1 to counter i when input i is set; property "every
  counter stays below K" (holds, so the whole state space is explored);
* the statistics variant: the same plus what every real cell has, a cycle
  counter and a log string nothing reads
  (``nCycles := nCycles + 1; lastLog := "cycle " + NumToStr(nCycles, 0);``);
* the pinion-sorting cell (case_studies/sorter, program B and plant) against P1-P3.

For each counters size a "check cmd" row times the whole ``rapidmc check`` command
(wall clock: what a user waits for), to compare with SPIN's spin -a + gcc + pan.

Each model is checked with every reduction, with each one off, and with
none (``--no-reduce``); one row per run: verdict, product states,
transitions, CPU seconds of the search, product states per second and bytes
per stored state (the engine's own accounting, ``SearchStats``).  With
``--memory`` a second, traced run measures the Python heap per state too
(tracemalloc: slow).  When ``spin`` and ``gcc`` are installed, the
careful Promela model of the counters (inputs chosen where they are read,
as rapidmc does) is verified with ``spin -a``, ``gcc -O2`` and ``./pan -a``
and timed beside it.
"""
from __future__ import annotations

import argparse
import os
import re
import resource
import shutil
import subprocess
import sys
import tempfile
import time
import tracemalloc
from pathlib import Path

from rapidmc import ast
from rapidmc.check import check_property
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.properties import AtomCompiler, read_property_file
from rapidmc.model.reduction import ALL, NONE, Reductions, plan_reductions
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program, parse_text

ROOT = Path(__file__).resolve().parent.parent
VARIANTS = (("all", ALL), ("no merge", Reductions(merge_steps=False)),
            ("no dead", Reductions(dead_data=False)), ("no slice", Reductions(slice_data=False)),
            ("none", NONE))


def counters_program(inputs: int, modulo: int, statistics: bool = False) -> str:
    """The counters family in RAPID (``statistics``: with the unread cycle counter and log)."""
    data = [f"  VAR signaldi in{i};" for i in range(inputs)]
    data += [f"  VAR num c{i} := 0;" for i in range(inputs)]
    aliases = [f'    AliasIO "IN{i}", in{i};' for i in range(inputs)]
    body = [f"      IF in{i} = 1 THEN\n        c{i} := (c{i} + 1) MOD {modulo};\n      ENDIF"
            for i in range(inputs)]
    if statistics:
        data += ["  VAR num nCycles := 0;", '  VAR string lastLog := "";']
        body += ["      nCycles := nCycles + 1;",
                 '      lastLog := "cycle " + NumToStr(nCycles, 0);']
    lines = ["MODULE Counters", *data, "  PROC main()", *aliases, "    WHILE TRUE DO", *body,
             "    ENDWHILE", "  ENDPROC", "ENDMODULE", ""]
    return "\n".join(lines)


def counters_formula(inputs: int, modulo: int) -> str:
    return "G (" + " & ".join(f'"c{i} < {modulo}"' for i in range(inputs)) + ")"


def counters_promela(inputs: int, modulo: int) -> str:
    """The Promela model a careful SPIN user writes: each input chosen where it is read."""
    data = "\n".join(f"byte c{i} = 0;" for i in range(inputs))
    body = ";\n".join(f"     if :: c{i} = (c{i} + 1) % {modulo} :: skip fi"
                      for i in range(inputs))
    bound = " && ".join(f"c{i} < {modulo}" for i in range(inputs))
    return (f"{data}\nactive proctype main() {{\n  do\n  :: {body.lstrip()}\n  od\n}}\n"
            f"ltl bounded {{ [] ({bound}) }}\n")


def measure(program, formula_text: str, reductions: Reductions, max_states: int,
            formula=None, traced: bool = False):
    """(verdict, stats, seconds, heap bytes per state or None) of one property check."""
    formula = formula or parse_formula(formula_text)
    buchi = to_buchi(Not(formula))
    atoms = AtomCompiler(program)
    valuation = atoms.valuation(buchi.atoms, {})
    config = CheckConfig(program, observed=set(atoms.observed))
    plan = plan_reductions(program, config, buchi.atoms, [formula], reductions)
    system = RapidSystem(program, config, plan)
    system.shared_limit = 0            # the search's own memory, no cross-property cache
    start = time.process_time()          # CPU time: the machine may be shared
    result = check_property(system, buchi, valuation, max_states=max_states)
    seconds = time.process_time() - start
    heap = None
    if traced:
        traced_system = RapidSystem(program, config, plan)
        traced_system.shared_limit = 0
        tracemalloc.start()
        check_property(traced_system, buchi, valuation, max_states=max_states)
        _, peak = tracemalloc.get_traced_memory()
        tracemalloc.stop()
        heap = peak / max(result.stats.product_states, 1)
    return result.verdict, result.stats, seconds, heap


HEADER = (f"{'model':22} {'reductions':10} {'verdict':8} {'states':>9} {'transitions':>11} "
          f"{'cpu s':>8} {'states/s':>9} {'B/state':>8}")


def row(name: str, variant: str, measured) -> str:
    verdict, stats, seconds, heap = measured
    text = (f"{name:22} {variant:10} {verdict:8} {stats.product_states:>9,} "
            f"{stats.transitions:>11,} {seconds:>8.2f} "
            f"{stats.product_states / max(seconds, 1e-9):>9,.0f} {stats.bytes_per_state:>8,.0f}")
    return text + (f"  heap {heap:,.0f} B/state" if heap is not None else "")


def spin_row(inputs: int, modulo: int) -> str:
    """Verify the Promela counters with SPIN; the figures pan prints and the wall times."""
    with tempfile.TemporaryDirectory() as folder:
        model = Path(folder) / "counters.pml"
        model.write_text(counters_promela(inputs, modulo))
        started = time.perf_counter()
        subprocess.run(["spin", "-a", model.name], cwd=folder, check=True,
                       capture_output=True)
        subprocess.run(["gcc", "-O2", "-o", "pan", "pan.c"], cwd=folder, check=True,
                       capture_output=True)
        compiled = time.perf_counter()
        out = subprocess.run(["./pan", "-a", "-m1000000"], cwd=folder, check=True,
                             capture_output=True, text=True).stdout
        finished = time.perf_counter()
    states = int(re.search(r"(\d+) states, stored", out).group(1))
    errors = int(re.search(r"errors: (\d+)", out).group(1))
    elapsed = float(re.search(r"elapsed time ([\d.e+-]+)", out).group(1))
    vector = re.search(r"State-vector (\d+) byte", out).group(1)
    verdict = "HOLDS" if errors == 0 else "VIOLATED"
    return (f"{'counters N=' + str(inputs):22} {'SPIN':10} {verdict:8} {states:>9,} "
            f"{'':>11} {finished - compiled:>8.2f} {states / max(elapsed, 1e-3):>9,.0f} "
            f"{vector:>8}  (pan search {elapsed:.2f} s; spin -a + gcc "
            f"{compiled - started:.2f} s; B/state = SPIN's state vector)")


VERDICT_RUNS = 5      # the verdict row is the best of this many runs (the machine may be shared)


def verdict_row(inputs: int, modulo: int) -> str:
    """Time to verdict: the whole ``rapidmc check`` command as a user runs it (start-up,
    parsing, the built-in checks and the property), wall-clock and CPU seconds, best of
    ``VERDICT_RUNS``; bytecode may be cached, as after an install."""
    env = {key: value for key, value in os.environ.items() if key != "PYTHONDONTWRITEBYTECODE"}
    walls, cpus = [], []
    with tempfile.TemporaryDirectory() as folder:
        program = Path(folder) / "counters.mod"
        program.write_text(counters_program(inputs, modulo))
        spec = Path(folder) / "counters.ltl"
        spec.write_text(f"bounded: {counters_formula(inputs, modulo)}\n")
        for _ in range(VERDICT_RUNS):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            started = time.perf_counter()
            done = subprocess.run([sys.executable, "-m", "rapidmc", "check", str(program),
                                   "--ltl", str(spec), "--quiet"], capture_output=True,
                                  text=True, env=env)
            walls.append(time.perf_counter() - started)
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            cpus.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
    verdict = "HOLDS" if done.returncode == 0 else f"exit {done.returncode}"
    return (f"{'counters N=' + str(inputs):22} {'check cmd':10} {verdict:8} {'':>9} {'':>11} "
            f"{min(walls):>8.2f}  (wall s of the whole `rapidmc check`, best of {VERDICT_RUNS}: "
            f"start-up, parse, run-time error and deadlock checks, the property; "
            f"CPU {min(cpus):.2f} s)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="4,5,6,7", help="N of the counters family")
    parser.add_argument("--statistics-sizes", default="3,4,5",
                        help="N of the statistics variant")
    parser.add_argument("--modulo", type=int, default=4, help="K of the counters family")
    parser.add_argument("--max-states", type=int, default=1_000_000)
    parser.add_argument("--statistics-max-states", type=int, default=200_000,
                        help="state bound of the statistics variant (infinite without slicing)")
    parser.add_argument("--no-spin", action="store_true", help="do not run SPIN")
    parser.add_argument("--no-sorter", action="store_true", help="skip the sorting cell")
    parser.add_argument("--memory", action="store_true",
                        help="also measure the heap per state with tracemalloc (slow)")
    args = parser.parse_args()
    spin = not args.no_spin and shutil.which("spin") and shutil.which("gcc")
    print(HEADER)
    for inputs in (int(n) for n in args.sizes.split(",")):
        program = build(ast.Program(parse_text(counters_program(inputs, args.modulo),
                                               "counters.mod")))
        for variant, reductions in VARIANTS:
            measured = measure(program, counters_formula(inputs, args.modulo), reductions,
                               args.max_states, traced=args.memory)
            print(row(f"counters N={inputs}", variant, measured), flush=True)
        print(verdict_row(inputs, args.modulo), flush=True)
        if spin:
            print(spin_row(inputs, args.modulo), flush=True)
    for inputs in (int(n) for n in args.statistics_sizes.split(",")):
        program = build(ast.Program(parse_text(counters_program(inputs, args.modulo, True),
                                               "statistics.mod")))
        for variant, reductions in VARIANTS:
            measured = measure(program, counters_formula(inputs, args.modulo), reductions,
                               args.statistics_max_states, traced=args.memory)
            print(row(f"statistics N={inputs}", variant, measured), flush=True)
    if args.no_sorter:
        return
    plant = load_program([str(ROOT / "case_studies" / "sorter" / "plant.mod")])
    sorter = build(load_program([str(ROOT / "case_studies" / "sorter" / "sorter_b.mod")]),
                   environment=plant)
    for prop in read_property_file(str(ROOT / "specs" / "sorter.ltl")):
        for variant, reductions in (VARIANTS[0], VARIANTS[-1]):
            measured = measure(sorter, prop.text, reductions, args.max_states, prop.formula,
                               traced=args.memory)
            print(row(f"sorter B {prop.name}", variant, measured), flush=True)


if __name__ == "__main__":
    main()
