"""Why a program's state space grows: the data that take the most values (issue 28).

Usage: python bench/state_growth.py FILE... [--task T] [--max-states N] [--top K]
                                     [--stubs] [--survey ROWS.json --outcomes LIST]

Explores the program's reachable states breadth first as a check does (the default
reductions: sliced data are already reset in these states) up to ``--max-states``, and
counts, per datum the counterexample view names (``describe_state``: global data, routine
data, signals, the robot's TCP, ERRNO), the distinct values it takes, and the distinct
values of the clock and of each task's position (routine and pc).  The data with the most
values are why the search does not end: a counter, a clock, a growing string, the robot's
drifting position, or many inputs.  ``--stubs`` first writes the module ``rapidmc stubs``
would for names no module declares (as bench/survey_programs.py does).

``--survey ROWS.json`` runs this for each row of a survey whose outcome ``--outcomes``
names (default ``unknown,cpu limit``), each under a CPU limit of ``--cpu`` seconds, and
prints one line per program with its top data.
"""
from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from collections import Counter, defaultdict, deque
from pathlib import Path

from rapidmc import api
from rapidmc.check.transition_system import as_sequence


def growth(words: list[str], max_states: int, seconds: float,
           stubs: bool = False) -> tuple[int, dict, bool]:
    """(states explored, name -> set of values, complete) of the program ``words`` names;
    ``stubs``: each task's undeclared names declared from their uses (a whole backup's
    tasks, which one stub module given beside the folder cannot serve)."""
    files, task = _split(words)
    program = api.load_program(files, task=task, stubs=stubs)
    model = api.prepare(program, [], api.CheckOptions())
    system, describer = model.system, model.describer
    values: dict[str, set] = defaultdict(set)
    views: list[dict] = []
    seen = set()
    queue = deque()
    depth: dict = {}
    for state in system.initial_states():
        if state not in seen:
            seen.add(state)
            queue.append(state)
            depth[state] = 0
    deadline = time.process_time() + seconds
    while queue and len(seen) < max_states and time.process_time() < deadline:
        state = queue.popleft()
        view = dict(describer.describe_state(state))
        view["<clock>"] = state.clock
        for number, stack in enumerate((state.frames,) + state.tasks):
            view[f"<task {number} at>"] = tuple((f.routine, f.pc) for f in stack)
            view[f"<task {number} hidden>"] = repr(tuple(f.locals for f in stack))
        view["<robot>"] = repr(state.robot)
        view["<interrupts>"] = repr(state.interrupts)
        view["<rest>"] = repr((state.errno, state.intno, state.status, state.fault))
        for name, text in view.items():
            values[name].add(text)
        views.append(view)
        for _, successor in as_sequence(system.successors(state)):
            if successor not in seen:
                seen.add(successor)
                queue.append(successor)
                depth[successor] = depth[state] + 1
    levels = Counter(depth.values())
    values["<levels>"] = [levels[level] for level in sorted(levels)][-6:]
    return len(seen), values, not queue, views


def merged_without(views: list[dict]) -> dict[str, int]:
    """name -> how many fewer distinct states the explored ones would be without it."""
    names = sorted({name for view in views for name in view})
    # (data with one value tell no states apart)
    varying = [name for name in names if len({view.get(name) for view in views}) > 1]
    whole = len({tuple(view.get(name) for name in varying) for view in views})
    gains = {}
    for left_out in varying:
        kept = [name for name in varying if name != left_out]
        gains[left_out] = whole - len({tuple(view.get(name) for name in kept) for view in views})
    return gains


def _split(words: list[str]) -> tuple[list[str], str | None]:
    if "--task" in words:
        at = words.index("--task")
        return words[:at] + words[at + 2:], words[at + 1]
    return words, None


def with_stubs(words: list[str], scratch: str) -> list[str]:
    """``words`` with the stub module of their undeclared names, when rapidmc writes one."""
    missing = str(Path(scratch) / "Missing.mod")
    subprocess.run([sys.executable, "-m", "rapidmc", "stubs", *words, "-o", missing],
                   capture_output=True)
    if not Path(missing).is_file():
        return words
    files, task = _split(words)
    return [*files, missing, *(["--task", task] if task else [])]


def summary(count: int, values: dict, complete: bool, views: list, top: int) -> str:
    """The data with most values (name=values), then those whose removal merges most
    explored states (name-merged)."""
    last_levels = values.pop("<levels>")
    ranked = sorted(values.items(), key=lambda item: -len(item[1]))[:top]
    gains = merged_without(views)
    merging = sorted(((gain, name) for name, gain in gains.items() if gain), reverse=True)[:top]
    end = "complete" if complete else "bounded"
    return (f"{count} states ({end}), last BFS levels {last_levels}: values " +
            ", ".join(f"{name}={len(seen)}" for name, seen in ranked) +
            " | merged without: " + ", ".join(f"{name}-{gain}" for gain, name in merging))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("words", nargs="*")
    parser.add_argument("--task", default=None)
    parser.add_argument("--max-states", type=int, default=5000)
    parser.add_argument("--seconds", type=float, default=60.0, help="CPU seconds of the walk")
    parser.add_argument("--top", type=int, default=8)
    parser.add_argument("--stubs", action="store_true")
    parser.add_argument("--survey", type=Path, default=None)
    parser.add_argument("--outcomes", default="unknown,cpu limit")
    parser.add_argument("--cpu", type=int, default=90)
    args = parser.parse_args()
    if args.survey is None:
        words = args.words + (["--task", args.task] if args.task else [])
        with tempfile.TemporaryDirectory() as scratch:
            whole = args.stubs and len(args.words) == 1 and Path(args.words[0]).is_dir()
            if args.stubs and not whole:
                words = with_stubs(words, scratch)
            count, values, complete, views = growth(words, args.max_states, args.seconds,
                                                    stubs=whole)
        print(summary(count, values, complete, views, args.top))
        return 0
    wanted = set(args.outcomes.split(","))
    for row in json.loads(args.survey.read_text()):
        if row["outcome"] not in wanted:
            continue
        command = [sys.executable, __file__, *row["command"], "--max-states",
                   str(args.max_states), "--seconds", str(args.cpu - 10), "--top", str(args.top)]
        if row.get("stubbed"):
            command.append("--stubs")

        def limit() -> None:
            resource.setrlimit(resource.RLIMIT_CPU, (args.cpu, args.cpu + 1))
        done = subprocess.run(command, capture_output=True, text=True, preexec_fn=limit)
        last = (done.stdout.strip().splitlines() or [done.stderr.strip()[-200:]])[-1]
        print(f"{row['outcome']:9} {row['name']}\n    {last}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
