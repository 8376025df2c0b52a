"""Benchmark of the general step driver: programs with several tasks or with interrupts.

Usage: python bench/tasks.py [--max-states N] [--repeat R] [--only NAME]

Plain states (one task, no interrupts) take the fused and plain drivers; every
other state takes the general one (``semantics.step.general_successors``).
Real cells run several tasks (a motion task beside a PLC or socket task) and
use interrupts, so their checks live in the general driver.  Models
(bench/programs/):

* ``two tasks PERS``: a motion task and a PLC task sharing PERS data, free
  inputs read in both (cell_motion.mod, cell_plc.mod);
* ``interrupts``: one task, two signal interrupts on free inputs and a timer,
  each with a TRAP (alarm_cell.mod);
* ``socket server``: a socket task receiving commands and a motion task running
  them, handed over through PERS data (server_socket.mod, server_motion.mod).

Each row explores the reachable states as a check does (the default
reductions), one property's product search (``check_property``) over a
property that holds, so the whole space is searched: product states,
transitions, CPU seconds, product states per second.  ``--repeat`` runs each
model R times and prints every run (the machine may be shared).

``--drivers`` adds a row per model for the step drivers alone: the states that
search expanded, in its order, stepped by the general driver
(``general_successors``) and by ``successors`` (the staged driver for these
states), microseconds of CPU per state, the best of R runs.
"""
from __future__ import annotations

import argparse
import gc
import time
from pathlib import Path

from rapidmc import api
from rapidmc.check import check_property
from rapidmc.semantics.step import general_successors, successors

ROOT = Path(__file__).resolve().parent
PROGRAMS = ROOT / "programs"

# name, files of the main task, files of a second task, property, check options
MODELS = (
    ("two tasks PERS", ["cell_motion.mod"], ["cell_plc.mod"],
     'taken: G "nPartsTaken < 4"', {}),
    ("interrupts", ["alarm_cell.mod"], [],
     'counted: G "nParts < 3"', {}),
    ("socket server", ["server_socket.mod"], ["server_motion.mod"],
     'moves: G "nMoves < 4"', {"socket_messages": ("1", "2", "3", "x")}),
    ("ROS server", ["ros_common.sys", "ros_socket.mod"], ["ros_common.sys", "ros_motion.mod"],
     'bounded: G "trajSize <= 2"',
     {"socket_messages": ("-1 0 0 0 0 0 0", "-3 20 0 0 0 90 0")}),
)


def load(files: list[str], task: list[str]):
    """The program of ``files`` (main task), with the files of ``task`` as a second task."""
    return api.load_program([str(PROGRAMS / f) for f in files],
                            add_tasks=[",".join(str(PROGRAMS / f) for f in task)] if task else [])


def measure(program, formula: str, options: dict, max_states: int, expanded=None):
    """(verdict, stats, CPU seconds) of one property's search; ``expanded``: a list
    that receives the states the search expands, in its order."""
    prop = api.property_from_text(formula)
    model = api.prepare(program, [prop], api.CheckOptions(**options))
    system = model.system
    system.shared_limit = 0              # the search's own work, no cross-property cache
    if expanded is not None:
        step = system.successors
        system.successors = lambda state: expanded.append(state) or step(state)
    _, buchi, valuation = model.jobs[0]
    start = time.process_time()          # CPU time: the machine may be shared
    result = check_property(system, buchi, valuation, max_states=max_states)
    return result.verdict, result.stats, time.process_time() - start


def driver_row(name: str, program, options: dict, formula: str, states: list,
               repeat: int) -> str:
    """Microseconds of CPU per state of the general driver and of ``successors``."""
    config = api.prepare(program, [api.property_from_text(formula)],
                         api.CheckOptions(**options)).system.config
    gc.collect()
    gc.freeze()                          # as a search does (check.collector)
    try:
        times = []
        for driver in (general_successors, successors):
            best = float("inf")
            for _ in range(repeat):
                start = time.process_time()
                for state in states:
                    driver(program, state, config)
                best = min(best, time.process_time() - start)
            times.append(1e6 * best / max(len(states), 1))
    finally:
        gc.unfreeze()
    return (f"{name:16} drivers over {len(states):,} states: general {times[0]:.1f} us/state, "
            f"successors {times[1]:.1f} us/state (x{times[0] / max(times[1], 1e-9):.2f})")


HEADER = f"{'model':16} {'verdict':8} {'states':>9} {'transitions':>11} {'cpu s':>8} {'states/s':>9}"


def row(name: str, measured) -> str:
    verdict, stats, seconds = measured
    return (f"{name:16} {verdict:8} {stats.product_states:>9,} {stats.transitions:>11,} "
            f"{seconds:>8.2f} {stats.product_states / max(seconds, 1e-9):>9,.0f}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-states", type=int, default=1_000_000)
    parser.add_argument("--repeat", type=int, default=1, help="runs per model")
    parser.add_argument("--only", help="run only the model whose name contains this")
    parser.add_argument("--drivers", action="store_true",
                        help="also time the step drivers alone on the states searched")
    args = parser.parse_args()
    print(HEADER)
    for name, files, tasks, formula, options in MODELS:
        if args.only and args.only not in name:
            continue
        program = load(files, tasks)
        for _ in range(args.repeat):
            print(row(name, measure(program, formula, options, args.max_states)), flush=True)
        if args.drivers:
            states: list = []
            measure(program, formula, options, args.max_states, states)
            print(driver_row(name, program, options, formula, states, args.repeat), flush=True)


if __name__ == "__main__":
    main()
