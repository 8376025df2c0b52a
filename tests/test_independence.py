"""An instruction the partial-order reduction calls independent commutes with every other
task's step, in every reachable state (issue 27).

``PartialOrder.footprint`` decides independence once per instruction, from its code
(``reduction.syntax_footprint`` for what the compiled form does not say).  This test
checks that decision against the semantics, as the definition of independence reads
(Clarke, Grumberg, Peled, *Model Checking*, ch. 10): in every state the unreduced
search reaches, where task ``t`` stands at an independent instruction, each step ``a``
of ``t`` that does what the instruction does (no error: the reduction never leaves an
error step alone) and each step ``b`` of another task

* leave each other enabled: ``b`` has the same transitions after ``a`` as before
  (same labels), and ``a`` after ``b``;
* commute: ``b`` after ``a`` reaches the state ``a`` after ``b`` reaches.

Verdicts can hide a wrong footprint (an atom that makes the write visible keeps it from
being ample); this cannot.  The programs: the generated ones of test_partial_order
(every mode) and the footprint cases.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.cli import build_parser
from rapidmc.commands.check import prepare_model
from rapidmc.model.reduction.interrupt_owners import serving_tasks
from rapidmc.model.reduction.partial_order import PartialOrder
from rapidmc.semantics.staged_step import task_transitions
from rapidmc.semantics.step import successors as semantic_successors
from rapidmc.semantics.state import RUNNING

from reached_states import breadth_first
from task_programs import random_tasks

REACHED_STATES = 1500
FOOTPRINT_CASES = Path(__file__).resolve().parent / "por_footprints"


def independence_failures(argv: list[str], limit: int = REACHED_STATES) -> tuple[int, list]:
    """(states compared, (task, instruction line, other task) per failure)."""
    args = build_parser().parse_args(["check", *argv, "--no-merge"])
    system = prepare_model(args).system
    order = system.order
    assert isinstance(order, PartialOrder)
    plain = system.unreduced()
    program, config = plain.program, plain.config
    tasks = len(program.task_names)

    def steps(state, task) -> dict:
        if state[7] != RUNNING:
            return {}
        found = task_transitions(program, state, task, config)
        if found is None and (state[4][0] or state[4][1]):
            # (with interrupts: the task's transitions among every task's)
            name = ("task", program.task_names[task])
            alone = sum(1 for stack in (state[0],) + state[10] if stack) == 1
            found = [t for t in semantic_successors(program, state, config)
                     if alone or name in t[0]]
        # (a label names the task only while another one runs)
        return {} if found is None else {
            (tuple(c for c in t[0] if c[0] != "task"), t[1], t[3]): t[2] for t in found}

    failures = []
    compared = 0
    for state, _ in breadth_first(plain, limit):
        compared += 1
        if state[7] != RUNNING:
            continue
        stacks = (state[0],) + state[10]
        # (a task serving an interrupt is never ample: its step may enter a TRAP; one whose
        # interrupts only its own steps can queue, none pending, serves none)
        serving = serving_tasks(program, state[4], order.owners)
        for task, stack in enumerate(stacks):
            if not stack or serving is None or task in serving or \
                    not order.footprint(task, stack[-1][0], stack[-1][1]).independent:
                continue
            mine = steps(state, task)
            if not mine or any(after[5] != state[5] or after[6] != state[6] or
                               after[7] != RUNNING for after in mine.values()):
                continue            # (an error step: never ample, never merged)
            for other in range(tasks):
                if other == task or not stacks[other]:
                    continue
                theirs = steps(state, other)
                if not _commute(state, mine, theirs, steps, task, other):
                    line = program.routines[stack[-1][0]].code[stack[-1][1]].span
                    failures.append((task, f"{Path(line.file).name}:{line.line}", other))
    return compared, failures


def _commute(state, mine: dict, theirs: dict, steps, task: int, other: int) -> bool:
    for a, after_a in mine.items():
        then_theirs = steps(after_a, other)
        if set(then_theirs) != set(theirs):
            return False
        for b, after_b in theirs.items():
            if after_b[7] != RUNNING:
                # a step that stops the program (it fails, or the last task ends) ends
                # every run through it: it must do so after ``a`` too
                if then_theirs[b][7] == RUNNING:
                    return False
                continue
            then_mine = steps(after_b, task)
            if set(then_mine) != set(mine) or then_mine[a] != then_theirs[b]:
                return False
    return True


def generated(folder: Path, seed: int, **mode) -> list[str]:
    argv = []
    for number, text in enumerate(random_tasks(seed, **mode), start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    return argv + ["--fixed-outside-data"]


MODES = [("plain", {}), ("procedures", {"procedures": True}), ("arrays", {"arrays": True}),
         ("local", {"local": True}), ("calls", {"calls": True})]


@pytest.mark.parametrize("seed", range(12))
@pytest.mark.parametrize("mode", MODES, ids=lambda mode: mode[0])
def test_independent_instructions_commute_in_generated_tasks(tmp_path, mode, seed):
    compared, failures = independence_failures(generated(tmp_path, 200 + seed, **mode[1]))
    assert compared > 1 and not failures


@pytest.mark.parametrize("case", sorted(p for p in FOOTPRINT_CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_independent_instructions_commute_in_footprint_cases(case):
    files = sorted(case.glob("*.mod"))
    argv = [str(files[0])] + [x for f in files[1:] for x in ("--add-task", str(f))]
    compared, failures = independence_failures(argv)
    assert compared > 1 and not failures
