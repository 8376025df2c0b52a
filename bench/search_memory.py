"""Memory a check holds per state on the path where states step in Python (issue 27).

Usage: python bench/search_memory.py FILE... [--task T] [--stubs] [--marks 5000,10000,20000]
                                       [--not-kept]

Runs the check's first search (no_runtime_error) of the program the files name (a
controller backup folder, or module files) and prints, when it has stored each number
of states in ``--marks``: the process's resident memory (VmRSS), its CPU seconds, the
successors kept for the next searches (``RapidSystem``'s ``model.kept_successors``), and
the bytes per state between two marks (the RSS grown over the states stored in between:
what a further state costs).  ``--not-kept`` keeps no successors (``shared_limit`` 0): the
search's own cost per state, the floor.

Figures (session 17, 2 shared cores; docs/realworld-survey.md, "Memory per state where
states step in Python"), RSS at 5,000 / 10,000 states:

- PickMaster PM_PROJ_SUPERV (``--task PM_PROJ_SUPERV --stubs``): successors kept whole
  251 / 453 MB, 40 KB a state; kept as node ids 64 / 66-72 MB; none kept 64 / 66 MB.
- Hanoi Topsy 120-502354_Backup_20150401 (whole backup): kept whole 160 / 277 MB and
  504 MB at 20,000 (23 KB a state); as node ids 52 / 58 / 71 MB (1.3 KB a state);
  none kept 52 / 52 / 53 MB.
"""
from __future__ import annotations

import argparse
import sys
import time

from rapidmc import api
from rapidmc.check.progress import Progress
from rapidmc.model.rapid_system import RapidSystem


class Reached(Exception):
    """The last mark is reached: the search is stopped."""


def resident_mb() -> float:
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS"):
                return int(line.split()[1]) / 1024
    return 0.0


class Marks(Progress):
    """A progress display that prints a row at each mark instead (its ``update`` runs at
    the search's budget checkpoints)."""

    def __init__(self, marks: list[int], systems: list):
        super().__init__(quiet=True)
        self.enabled = True
        self.marks, self.systems = list(marks), systems
        self.rows: list[tuple] = []

    def update(self, states: int, transitions: int, depth: int) -> None:
        while self.marks and states >= self.marks[0]:
            self.marks.pop(0)
            kept = sum(len(system._shared) for system in self.systems)
            row = (states, resident_mb(), time.process_time(), kept)
            if self.rows:
                grown = (row[1] - self.rows[-1][1]) * 1024 * 1024
                per_state = grown / max(states - self.rows[-1][0], 1)
            else:
                per_state = float("nan")
            print(f"{states:>9,} states  RSS {row[1]:7.0f} MB  CPU {row[2]:7.1f} s  "
                  f"kept {kept:>8,}  {per_state:9,.0f} B/state since the last mark",
                  flush=True)
            self.rows.append(row)
        if not self.marks:
            raise Reached

    def finish(self) -> None:
        pass


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+")
    parser.add_argument("--task")
    parser.add_argument("--stubs", action="store_true")
    parser.add_argument("--marks", default="5000,10000,20000")
    parser.add_argument("--not-kept", action="store_true")
    args = parser.parse_args(argv)
    if args.not_kept:
        RapidSystem.shared_limit = 0
    marks = sorted(int(mark) for mark in args.marks.split(","))
    program = api.load_program(args.files, task=args.task, stubs=args.stubs)
    model = api.prepare(program, [], api.CheckOptions(max_states=marks[-1] * 2))
    print(f"loaded: RSS {resident_mb():.0f} MB, CPU {time.process_time():.1f} s", flush=True)
    progress = Marks(marks, [model.system])
    try:
        api.check_model(model, lambda: progress)
    except Reached:
        return 0
    print("the search ended before the last mark", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
