"""What a state's successors are where stored inputs multiply them (issue 27).

Usage: python bench/input_successors.py FILE... [--task T] [--max-states N] [--stubs]

Explores the program's states breadth first, through the system a check searches (its
reductions, stored inputs at rest, edge inputs), up to ``--max-states``, and prints per
explored state on average:

- its transitions, and how many distinct targets they lead to;
- how many transitions differ from another one of the same task and instruction only in
  the values the step chose for the stored inputs, and lead to the same state: choices
  nothing read before the next step chose again (they cost a step, a projection and a
  lookup each, and add no state);
- the share of states where each task serves an interrupt (``interrupt_owners``: it may
  then not be ample) and where the partial-order reduction would be off anyway;
- the width of the last breadth-first levels (a graph that is long rather than wide keeps
  them flat).

The stored inputs, the edge inputs among them and those served by one task, and the
inputs put at rest where no interrupt watches them, are listed first.  ``--stubs``
declares each task's undeclared names from their uses, as ``bench/survey_programs.py``
does for a whole backup.
"""
from __future__ import annotations

import argparse
import tempfile
import time
from collections import Counter, deque

from rapidmc import api
from rapidmc.model.reduction.interrupt_owners import serving_tasks
from rapidmc.model.reduction.partial_order import PartialOrder
from rapidmc.semantics.state import RUNNING

from state_growth import _split, with_stubs


def input_names(config) -> set:
    """The names the labels give the stored inputs' chosen values."""
    return {name for _, name, _ in config.free_inputs}


def without_inputs(label: tuple, names: set) -> tuple:
    """A transition's label without the stored inputs' chosen values."""
    return tuple(choice for choice in label if choice[0] not in names)


def survey(words: list[str], max_states: int) -> dict:
    """The figures of the module docstring for the program ``words`` names."""
    files, task = _split(words)
    program = api.load_program(files, task=task)
    model = api.prepare(program, [], api.CheckOptions())
    system, config = model.system, model.config
    names = input_names(config)
    owners = PartialOrder(program, set()).owners if program.task_entries else None
    tasks = len(program.task_names)
    seen, queue, depth = set(), deque(), {}
    for state in system.initial_states():
        if state not in seen:
            seen.add(state)
            queue.append(state)
            depth[state] = 0
    totals = Counter()
    serving = Counter()
    started = time.process_time()
    while queue and totals["states"] < max_states:
        state = queue.popleft()
        transitions = system.successors(state)
        targets = {after for _, after in transitions}
        groups = {(without_inputs(label, names), span, output, after)
                  for (label, span, output), after in transitions}
        totals["states"] += 1
        totals["transitions"] += len(transitions)
        totals["targets"] += len(targets)
        totals["input only"] += len(transitions) - len(groups)
        if owners is not None and state.status == RUNNING:
            found = serving_tasks(program, state.interrupts, owners)
            for number in range(tasks) if found is None else found:
                serving[number] += 1
            serving["any"] += found is None or bool(found)
        for after in targets:
            if after not in seen:
                seen.add(after)
                queue.append(after)
                depth[after] = depth[state] + 1
    levels = Counter(depth.values())
    return dict(program=program, config=config, order=system.order is not None,
                totals=totals, serving=serving, seen=len(seen), complete=not queue,
                cpu=time.process_time() - started,
                levels=[levels[level] for level in sorted(levels)][-6:])


def report(found: dict) -> str:
    program, config, totals = found["program"], found["config"], found["totals"]
    signal = {s.index: s.name for s in program.signals}
    states = max(totals["states"], 1)
    lines = [
        "stored inputs: " + ", ".join(name for _, name, _ in config.free_inputs),
        "  edge inputs: " + ", ".join(signal[i] for i in sorted(config.edge_inputs)) +
        "; served by one task: " + ", ".join(signal[i] for i in config.served_edges) +
        "; at rest where unwatched: " + ", ".join(sorted(config.resting_inputs.values())),
        f"partial-order reduction: {'on' if found['order'] else 'off'}",
        f"{totals['states']} states expanded ({found['seen']} seen, "
        f"{'complete' if found['complete'] else 'bounded'}), {found['cpu']:.1f} CPU s",
        f"a state: {totals['transitions'] / states:.1f} transitions, "
        f"{totals['targets'] / states:.2f} distinct targets, "
        f"{totals['input only'] / states:.1f} that differ from another only in the inputs' "
        "values and lead to the same state",
        f"last BFS levels: {found['levels']}"]
    serving = found["serving"]
    if serving:
        lines.append("states where a task serves interrupts: " + ", ".join(
            f"{name} {100 * serving[number] / states:.0f} %"
            for number, name in enumerate(program.task_names)) +
            f"; some task: {100 * serving['any'] / states:.0f} %")
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("words", nargs="+", help="files or a backup folder, --task T")
    parser.add_argument("--max-states", type=int, default=3000)
    parser.add_argument("--stubs", action="store_true")
    args, rest = parser.parse_known_args()
    words = args.words + rest
    with tempfile.TemporaryDirectory() as scratch:
        if args.stubs:
            words = with_stubs(words, scratch)
        print(report(survey(words, args.max_states)))


if __name__ == "__main__":
    main()
