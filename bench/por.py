"""Benchmark of partial-order reduction between tasks: states and time with it and without.

Usage: python bench/por.py [--tasks 2,3,4,5] [--iterations 12] [--max-states N] [--no-spin]
                          [--builtins-only]

Models:

* ``independent N``: N tasks, each counting its own VAR data in a FOR loop of
  K iterations (K = ``--iterations``); property ``G "count1 <= K"``.  The
  orders of the tasks' steps are K^N-fold different paths to the same few
  states: what partial-order reduction is for.
* ``statements N``: the same count, each iteration also writing an element of
  its own array with a function's result, a component of its own record,
  the count through a procedure's INOUT parameter, and a TPWrite: the
  instructions whose independence is read from their syntax
  (``reduction/syntax_footprint.py``); N is the largest of ``--tasks``.
* ``handover``: a robot task and a feeder task handing three parts over
  through a shared PERS flag (bench/programs/handover_*.mod), property
  ``F "parts = 3"``: most steps touch shared data, so little can be left out.

For each: the states and CPU seconds of ``rapidmc check``'s searches with the
default reductions (partial-order reduction on) and with ``--no-por``
(bounded by ``--max-states``: ">= N" when the bound stops it).  When ``spin``
and ``gcc`` are installed, the equivalent Promela model of ``independent N``
(one proctype per task, its counter and loop variable local to it, the
property as an assertion) is verified with SPIN's own partial-order reduction
and with ``-DNOREDUCE``: states stored, and pan's search time.

Target (issue 27): ``independent 5`` with 12 iterations in at most 150 states
with the reduction (SPIN: 71); the last line says whether it is met.
"""
from __future__ import annotations

import argparse
import re
import shutil
import subprocess
import tempfile
import time
from pathlib import Path

from rapidmc import api

PROGRAMS = Path(__file__).resolve().parent / "programs"
TARGET_STATES = 150          # independent 5 x 12 iterations, with the reduction (issue 27)

INDEPENDENT = """MODULE Independent{n}
  VAR num count{n} := 0;
  PROC main()
    FOR i FROM 1 TO {k} DO
      count{n} := count{n} + 1;
    ENDFOR
  ENDPROC
ENDMODULE
"""

STATEMENTS = """MODULE Statements{n}
  VAR num count{n} := 0;
  VAR num buffer{n}{{{k}}};
  VAR pos spot{n};
  PROC main()
    FOR i FROM 1 TO {k} DO
      buffer{n}{{i}} := Twice(i);
      spot{n}.x := spot{n}.x + 1;
      Bump count{n};
      TPWrite "part ", \\Num:=i;
    ENDFOR
  ENDPROC
  PROC Bump(INOUT num value)
    value := value + 1;
  ENDPROC
  FUNC num Twice(num value)
    RETURN 2 * value;
  ENDFUNC
ENDMODULE
"""


def write_modules(folder: Path, texts: list[str]) -> list[str]:
    paths = []
    for number, text in enumerate(texts, start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        paths.append(str(path))
    return paths


def measure(paths: list[str], formula: str, por: bool, max_states: int) -> tuple:
    """(verdicts, the largest search's states, whether a bound stopped it, CPU seconds)."""
    program = api.load_program(paths[:1], add_tasks=paths[1:])
    reductions = api.reduction.ALL if por else api.reduction.Reductions(partial_order=False)
    options = api.CheckOptions(max_states=max_states, reductions=reductions)
    start = time.process_time()
    properties = [api.property_from_text(formula)] if formula else []
    report = api.check(program, properties, options)
    seconds = time.process_time() - start
    states = max(r.result.stats.product_states for r in report.results)
    return report.verdicts, states, "UNKNOWN" in report.verdicts.values(), seconds


def rapidmc_row(name: str, paths: list[str], formula: str, max_states: int) -> tuple[str, int]:
    """The row of a model, and its states with the reduction."""
    cells = []
    verdicts = []
    counts = []
    for por in (True, False):
        found, states, bounded, seconds = measure(paths, formula, por, max_states)
        verdicts.append(found)
        counts.append(states)
        shown = f">= {states:,}" if bounded else f"{states:,}"
        cells.append(f"{shown:>12} {seconds:>8.2f}")
    agree = "" if verdicts[0] == verdicts[1] or "UNKNOWN" in verdicts[1].values() \
        else "  VERDICTS DIFFER"
    verdict = "/".join(sorted(set(verdicts[0].values())))
    return f"{name:18} {'rapidmc':8} {verdict:14} {cells[0]}   {cells[1]}{agree}", counts[0]


def independent_promela(tasks: int, iterations: int) -> str:
    """The Promela model of ``independent N``: each task's data local to its proctype."""
    processes = []
    for n in range(1, tasks + 1):
        check = f"  assert(count <= {iterations});\n" if n == 1 else ""
        processes.append(
            f"active proctype Task{n}() {{\n  byte count = 0;\n  byte i = 1;\n"
            f"  do\n  :: i <= {iterations} -> count++;\n{check}     i++\n"
            f"  :: else -> break\n  od\n}}\n")
    return "\n".join(processes)


def spin_states(folder: Path, reduce: bool) -> tuple[int, float]:
    flags = ["-DSAFETY"] + ([] if reduce else ["-DNOREDUCE"])
    subprocess.run(["gcc", "-O2", *flags, "-o", "pan", "pan.c"], cwd=folder, check=True,
                   capture_output=True)
    out = subprocess.run(["./pan", "-m1000000"], cwd=folder, check=True, capture_output=True,
                         text=True).stdout
    states = int(re.search(r"(\d+) states, stored", out).group(1))
    elapsed = float(re.search(r"elapsed time ([\d.e+-]+)", out).group(1))
    errors = int(re.search(r"errors: (\d+)", out).group(1))
    if errors:
        raise RuntimeError(f"SPIN found an assertion violation:\n{out}")
    return states, elapsed


def spin_row(tasks: int, iterations: int) -> str:
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        (folder / "model.pml").write_text(independent_promela(tasks, iterations))
        subprocess.run(["spin", "-a", "model.pml"], cwd=folder, check=True, capture_output=True)
        cells = [spin_states(folder, reduce) for reduce in (True, False)]
    shown = "   ".join(f"{states:>12,} {seconds:>8.2f}" for states, seconds in cells)
    return f"{'independent ' + str(tasks):18} {'SPIN':8} {'HOLDS':14} {shown}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tasks", default="2,3,4,5")
    parser.add_argument("--iterations", type=int, default=12)
    parser.add_argument("--max-states", type=int, default=200_000)
    parser.add_argument("--no-spin", action="store_true")
    parser.add_argument("--builtins-only", action="store_true",
                        help="independent N: only the built-in checks (no property whose atom "
                             "makes task 1's count visible), as SPIN's assertion")
    args = parser.parse_args()
    spin = not args.no_spin and shutil.which("spin") and shutil.which("gcc")
    print(f"{'model':18} {'tool':8} {'verdicts':14} {'states POR':>12} {'CPU s':>8}   "
          f"{'states all':>12} {'CPU s':>8}")
    with tempfile.TemporaryDirectory() as name:
        folder = Path(name)
        reduced_states = {}
        for tasks in (int(t) for t in args.tasks.split(",")):
            paths = write_modules(folder, [INDEPENDENT.format(n=n, k=args.iterations)
                                           for n in range(1, tasks + 1)])
            formula = "" if args.builtins_only else f'bounded: G "count1 <= {args.iterations}"'
            row, reduced_states[tasks] = rapidmc_row(f"independent {tasks}", paths, formula,
                                                     args.max_states)
            print(row, flush=True)
            if spin:
                print(spin_row(tasks, args.iterations), flush=True)
        largest = max(reduced_states)
        paths = write_modules(folder, [STATEMENTS.format(n=n, k=args.iterations)
                                       for n in range(1, largest + 1)])
        print(rapidmc_row(f"statements {largest}", paths, formula, args.max_states)[0],
              flush=True)
        paths = [str(PROGRAMS / "handover_robot.mod"), str(PROGRAMS / "handover_feeder.mod")]
        print(rapidmc_row("handover", paths, 'done: F "parts = 3"', args.max_states)[0])
    if 5 in reduced_states and args.iterations == 12:
        states = reduced_states[5]
        print(f"target: independent 5 in at most {TARGET_STATES} states with the reduction "
              f"(SPIN: 71): {states:,}, {'met' if states <= TARGET_STATES else 'NOT MET'}")


if __name__ == "__main__":
    main()
