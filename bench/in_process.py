"""CPU time of a ``rapidmc check`` run again in the same process, as the tests run it.

Usage: python bench/in_process.py [--cases loop_toggle,runtime_div_input,tasks_fairness]
                                  [--repeats 20] [--rounds 5]

Most of the test suite calls ``rapidmc.cli.main`` in process on small programs (the check
cases under tests/check/, generated programs), so what a check costs besides its search
(arguments, parsing the modules and each atom, translating the properties, the report)
sets much of the suite's time.  For each check case (run from its folder with its
``args``, ``--format json --quiet``): the CPU milliseconds of one check, the fastest and
the median of ``--rounds`` rounds of ``--repeats`` checks, after a few warm-up checks.
"""
from __future__ import annotations

import argparse
import contextlib
import io
import os
import shlex
import time
from pathlib import Path

from rapidmc.cli import main

CASES = Path(__file__).resolve().parent.parent / "tests" / "check"


def case_argv(folder: Path) -> list[str]:
    args = folder / "args"
    extra = shlex.split(args.read_text(), comments=True) if args.is_file() else []
    spec = ["--ltl", "props.ltl"] if (folder / "props.ltl").is_file() else []
    return ["check", "prog.mod", *spec, *extra, "--format", "json", "--quiet"]


def one_check(argv: list[str]) -> None:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(argv)
    if not out.getvalue():
        raise SystemExit(f"no report from {' '.join(argv)}")


def milliseconds(argv: list[str], repeats: int, rounds: int) -> tuple[float, float]:
    for _ in range(3):
        one_check(argv)
    per_check = []
    for _ in range(rounds):
        started = time.process_time()
        for _ in range(repeats):
            one_check(argv)
        per_check.append((time.process_time() - started) / repeats * 1000)
    per_check.sort()
    return per_check[0], per_check[len(per_check) // 2]


def main_bench() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", default="loop_toggle,runtime_div_input,tasks_fairness")
    parser.add_argument("--repeats", type=int, default=20)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    print(f"{'case':28} {'fastest ms':>10} {'median ms':>10}   (CPU per check, load "
          f"{os.getloadavg()[0]:.1f})")
    here = os.getcwd()
    for name in args.cases.split(","):
        os.chdir(CASES / name)
        try:
            fastest, median = milliseconds(case_argv(CASES / name), args.repeats, args.rounds)
        finally:
            os.chdir(here)
        print(f"{name:28} {fastest:10.1f} {median:10.1f}", flush=True)


if __name__ == "__main__":
    main_bench()
