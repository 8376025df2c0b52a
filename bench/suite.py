"""The test suite's wall-clock time, serial and under pytest-xdist, as CI runs it.

Usage: python bench/suite.py [--workers 0,auto] [--engines native,python] [--dist worksteal]
                             [-- PYTEST ARGS...]

For each engine and worker count, one row: ``RAPIDMC_ENGINE``, the workers (0: no xdist),
wall seconds, the machine's load average before the run, and pytest's last line.  The README's
test command is ``-n auto`` on the native engine; ``.ci/run`` runs that, then the python engine
with the core renamed away, leaving out the modules marked ``engine_independent`` (here
``RAPIDMC_ENGINE=python`` with the core left in place and the same marks left out, which times
the same tests but for the few that look for the core).  Run it on a quiet machine: the
load column says whether it was.
"""
from __future__ import annotations

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def run_suite(engine: str, workers: str, dist: str, extra: list[str]) -> tuple[float, str]:
    command = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider", *extra]
    if workers != "0":
        command += ["-n", workers, "--dist", dist]
    if engine == "python":      # as .ci/run: the engine-independent modules ran with the core
        command += ["-m", "not engine_independent"]
    environment = dict(os.environ, RAPIDMC_ENGINE=engine)
    started = time.perf_counter()
    done = subprocess.run(command, cwd=ROOT, capture_output=True, text=True, env=environment)
    lines = [line for line in done.stdout.splitlines() if line.strip()]
    return time.perf_counter() - started, lines[-1] if lines else f"exit {done.returncode}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--workers", default="0,auto")
    parser.add_argument("--engines", default="native")
    parser.add_argument("--dist", default="worksteal")
    parser.add_argument("pytest_args", nargs="*")
    args = parser.parse_args()
    print(f"{'engine':8} {'workers':>7} {'seconds':>8} {'load':>5}  result")
    for engine in args.engines.split(","):
        for workers in args.workers.split(","):
            load = os.getloadavg()[0]
            seconds, last = run_suite(engine, workers, args.dist, args.pytest_args)
            print(f"{engine:8} {workers:>7} {seconds:8.1f} {load:5.1f}  {last}", flush=True)


if __name__ == "__main__":
    main()
