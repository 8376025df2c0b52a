"""The compiled search core against the pure Python engine, and SPIN (issue 21).

Usage: python bench/native.py [--sizes 6,7,8,9] [--modulo 4] [--engines native,python]
                              [--runs 3] [--no-spin]

On the counters family of bench/check.py (N free inputs, N counters modulo K, property
"every counter stays below K", which holds: the whole state space is explored), for
each size and engine, each in a fresh process:

* "search" rows: the searches of a check, timed apart in CPU seconds (the machine may be
  shared): the run-time error search (breadth-first, keeps the state graph; with the
  native engine: how many states the step machine stepped and how many Python did), the
  property search over that graph (what ``rapidmc check`` runs), and the property search
  stepping the program itself (no graph); states per CPU second;
* a "check cmd" row: the whole ``rapidmc check --engine E`` command (start-up, parsing,
  the built-in checks, the property), wall and CPU seconds, best of ``--runs``, and bytes
  per state = the process's maximum resident set size / reachable states;
* a SPIN row (bench/check.py's careful Promela model): pan's search and spin -a + gcc.
"""
from __future__ import annotations

import argparse
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from check import counters_formula, counters_program, spin_row  # noqa: E402  (bench/check.py)

HEADER = (f"{'model':14} {'engine':7} {'what':22} {'states':>10} {'cpu s':>7} {'wall s':>7} "
          f"{'states/s':>10} {'B/state':>8}")


def searches(inputs: int, modulo: int, engine: str) -> dict:
    """CPU seconds of each search of one check (run in a child process: see ``main``)."""
    from rapidmc import api
    from rapidmc.check import check_property, find_reachable, native
    native.use_engine(engine)
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "counters.mod"
        path.write_text(counters_program(inputs, modulo))
        program = api.load_program([str(path)])
    prop = api.property_from_text(f"bounded: {counters_formula(inputs, modulo)}")
    model = api.prepare(program, [prop], api.CheckOptions(max_states=10 ** 9))
    _, buchi, valuation = model.jobs[0]
    bound = dict(max_states=10 ** 9)
    graphs: list = []
    started = time.process_time()
    runtime = find_reachable(model.system, model.system.failed, explored=graphs.append,
                             valuations=[valuation], **bound)
    searched = time.process_time()
    over_graph = check_property(model.system, buchi, valuation, explored=graphs[0], **bound)
    table = graphs[0].states
    steps = table.counts() if hasattr(table, "counts") else None
    graphs.clear()
    again = time.process_time()
    stepping = check_property(model.system, buchi, valuation, **bound)
    done = time.process_time()
    return {"states": runtime.stats.product_states, "steps": steps,
            "verdicts": [runtime.verdict, over_graph.verdict, stepping.verdict],
            "product states": [over_graph.stats.product_states, stepping.stats.product_states],
            "runtime error search": searched - started,
            "property over the graph": again - searched,
            "property, stepping": done - again,
            "engines": [runtime.stats.engine, over_graph.stats.engine, stepping.stats.engine]}


def run_measured(command: list[str]) -> tuple[int, float, float, int, str]:
    """(exit code, wall s, CPU s, max RSS bytes, stdout) of one child process."""
    with tempfile.TemporaryFile("w+") as out:
        started = time.perf_counter()
        child = subprocess.Popen(command, stdout=out, stderr=subprocess.DEVNULL)
        _, status, usage = os.wait4(child.pid, 0)
        wall = time.perf_counter() - started
        child.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        return (child.returncode, wall, usage.ru_utime + usage.ru_stime,
                usage.ru_maxrss * 1024, out.read())


def search_rows(inputs: int, modulo: int, engine: str) -> list[str]:
    code, _, _, _, out = run_measured([sys.executable, __file__, "--child", str(inputs),
                                       str(modulo), engine])
    if code != 0:
        return [f"counters N={inputs} {engine}: the searches failed (exit {code})"]
    found = json.loads(out)
    rows = []
    for index, what in enumerate(("runtime error search", "property over the graph",
                                  "property, stepping")):
        states = found["states"] if index == 0 else found["product states"][index - 1]
        seconds = found[what]
        steps = found["steps"] if index == 0 else None
        taken = f"; steps by the machine {steps['machine_steps']:,}, by Python " \
            f"{steps['python_steps']:,}" if steps else ""
        rows.append(f"{'N=' + str(inputs):14} {engine:7} {what:22} {states:>10,} "
                    f"{seconds:>7.2f} {'':>7} {states / max(seconds, 1e-9):>10,.0f} {'':>8}"
                    f"  {found['verdicts'][index]} ({found['engines'][index]}{taken})")
    return rows


def command_row(inputs: int, modulo: int, engine: str, runs: int) -> str:
    """The whole ``rapidmc check`` command, best of ``runs``; bytes per state of process
    memory (maximum RSS / reachable states)."""
    with tempfile.TemporaryDirectory() as folder:
        program = Path(folder) / "counters.mod"
        program.write_text(counters_program(inputs, modulo))
        spec = Path(folder) / "counters.ltl"
        spec.write_text(f"bounded: {counters_formula(inputs, modulo)}\n")
        command = [sys.executable, "-m", "rapidmc", "check", str(program), "--ltl", str(spec),
                   "--engine", engine, "--format", "json", "--quiet", "--max-states",
                   str(10 ** 9)]
        measured = [run_measured(command) for _ in range(runs)]
    code, _, _, _, out = measured[-1]
    if code != 0:
        return f"counters N={inputs} {engine}: check exited {code}"
    states = json.loads(out)["properties"][0]["stats"]["model_states"]
    wall = min(m[1] for m in measured)
    cpu = min(m[2] for m in measured)
    rss = min(m[3] for m in measured)
    return (f"{'N=' + str(inputs):14} {engine:7} {'check cmd':22} {states:>10,} {cpu:>7.2f} "
            f"{wall:>7.2f} {states / max(cpu, 1e-9):>10,.0f} {rss / states:>8,.0f}"
            f"  (whole command, best of {runs}; max RSS {rss / 2 ** 20:,.0f} MiB)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="6,7,8,9", help="N of the counters family")
    parser.add_argument("--modulo", type=int, default=4, help="K of the counters family")
    parser.add_argument("--engines", default="native,python")
    parser.add_argument("--runs", type=int, default=3, help="runs of the whole command")
    parser.add_argument("--no-spin", action="store_true", help="do not run SPIN")
    parser.add_argument("--child", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        inputs, modulo, engine = args.child
        print(json.dumps(searches(int(inputs), int(modulo), engine)))
        return
    spin = not args.no_spin and shutil.which("spin") and shutil.which("gcc")
    print(HEADER, flush=True)
    for inputs in (int(n) for n in args.sizes.split(",")):
        for engine in args.engines.split(","):
            for line in search_rows(inputs, args.modulo, engine):
                print(line, flush=True)
            print(command_row(inputs, args.modulo, engine, args.runs), flush=True)
        if spin:
            print(spin_row(inputs, args.modulo), flush=True)


if __name__ == "__main__":
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))
    main()
