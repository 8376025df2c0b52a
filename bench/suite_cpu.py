"""Where the test suite spends its CPU: seconds per test module and per test.

Usage: python bench/suite_cpu.py [--top 30] [--tests 20] [-- PYTEST ARGS...]

Runs pytest (by default as the README's command does, ``-n auto --dist worksteal``; give
``RAPIDMC_ENGINE=python`` and ``-m "not engine_independent"`` for .ci/run's second run, with
the core moved aside as .ci/run moves it: while it is built, the tests that compare the two
engines run too, which that run skips) with this file as a plugin, which records each test's CPU time: its process's user and system
time, plus that of the child processes it waited for (pip, pre-commit, a fresh venv).  CPU
time, unlike wall time, hardly depends on what else the machine runs, so the figures of a
busy machine still say which tests to make cheaper.  Prints the modules and the tests that
cost most, then the total of the tests and of the pytest processes (collection included).
"""
from __future__ import annotations

import argparse
import collections
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
OUTPUT = "RAPIDMC_SUITE_CPU_DIR"          # where each pytest process writes its lines


def _cpu() -> float:
    times = os.times()
    return times.user + times.system + times.children_user + times.children_system


class _Recorder:
    """One JSON line per test: its node id and CPU seconds; one at the end for the process."""

    def __init__(self, folder: str):
        worker = os.environ.get("PYTEST_XDIST_WORKER", "main")
        self.out = open(Path(folder) / f"{worker}-{os.getpid()}.jsonl", "a", encoding="utf-8")

    @pytest.hookimpl(hookwrapper=True)
    def pytest_runtest_protocol(self, item, nextitem):
        started = _cpu()
        yield
        self.write(item.nodeid, _cpu() - started)

    def pytest_unconfigure(self, config):
        self.write("", _cpu())
        self.out.close()

    def write(self, nodeid: str, seconds: float) -> None:
        self.out.write(json.dumps({"test": nodeid, "cpu": seconds}) + "\n")
        self.out.flush()


def pytest_configure(config):
    if os.environ.get(OUTPUT):
        config.pluginmanager.register(_Recorder(os.environ[OUTPUT]), "suite-cpu-recorder")


def report(folder: Path, top: int, tests: int) -> None:
    modules: collections.Counter = collections.Counter()
    counts: collections.Counter = collections.Counter()
    each, processes = [], 0.0
    paths = list(folder.glob("*.jsonl"))
    workers = any(not path.name.startswith("main-") for path in paths)
    for path in paths:
        for line in path.read_text(encoding="utf-8").splitlines():
            record = json.loads(line)
            if not record["test"]:
                # under xdist the controller's children are the workers: counted once
                processes += 0.0 if workers and path.name.startswith("main-") else record["cpu"]
                continue
            module = record["test"].split("::")[0]
            modules[module] += record["cpu"]
            counts[module] += 1
            each.append((record["cpu"], record["test"]))
    total = sum(modules.values())
    print(f"{'cpu s':>8} {'share':>6} {'tests':>6}  module")
    for module, seconds in modules.most_common(top):
        print(f"{seconds:8.1f} {100 * seconds / total:5.1f}% {counts[module]:6}  {module}")
    print(f"\n{'cpu s':>8}  test")
    for seconds, test in sorted(each, reverse=True)[:tests]:
        print(f"{seconds:8.2f}  {test}")
    print(f"\n{len(each)} tests: {total:.0f} CPU s in tests, {processes:.0f} CPU s in the "
          f"pytest processes (collection included)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--top", type=int, default=30, help="modules to list")
    parser.add_argument("--tests", type=int, default=20, help="tests to list")
    parser.add_argument("pytest_args", nargs="*")
    args = parser.parse_args()
    pytest_args = args.pytest_args or ["-n", "auto", "--dist", "worksteal"]
    with tempfile.TemporaryDirectory() as folder:
        environment = dict(os.environ, **{OUTPUT: folder})
        environment["PYTHONPATH"] = os.pathsep.join(
            filter(None, [str(ROOT / "bench"), environment.get("PYTHONPATH")]))
        started = time.perf_counter()
        done = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "suite_cpu",
                               "-p", "no:cacheprovider", *pytest_args],
                              cwd=ROOT, env=environment, capture_output=True, text=True)
        lines = [line for line in done.stdout.splitlines() if line.strip()]
        print(f"{lines[-1] if lines else f'exit {done.returncode}'} "
              f"({time.perf_counter() - started:.0f} s wall, load {os.getloadavg()[0]:.1f})\n")
        report(Path(folder), args.top, args.tests)


if __name__ == "__main__":
    main()
