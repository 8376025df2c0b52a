"""When a task waits (cannot go on): the one definition of ``waits(T)``.

A task *waits* in a state when none of its steps from there changes anything of its
own: each changes at most what the environment changes in that step,

* the values of the stored free inputs (``config.free_inputs``) the step chose, and
* the interrupts those values' edges queue for *other* tasks (their TRAPs run in
  those tasks' steps; an interrupt the task itself serves, or a timer of its own that
  fires, lets it go on: a change of its own);

and, where interrupts are connected, so does each step of the task from the states
those steps lead to: an input stored at 1 falls before its rising edge comes, so a
task whose own TRAP an edge would start is not waiting where the input is at 1
(``RapidSystem.stuck`` looks two steps ahead for the same reason).

This is what ``waits(T)`` of ``no_deadlock``'s search holds at (``model.waiting``),
which tasks the fair search excuses (``fairness.TaskFairness.excused``), and which
tasks the partial-order reduction and its task groups keep waiting or going on
(``reduction.partial_order``, ``reduction.task_groups``).  The models differ only in
where the environment's change shows: the edge model keeps an edge input at 0 and
drops an edge that another task serves, so a waiting task's step leads back to the
state; the exact model (``--exact-edges``) and ``--inputs-every-step`` store the value
the step chose and queue the interrupt its edge orders.  Counting only the task's own
changes gives every model the same waiting tasks, so the same ``no_deadlock`` and
fairness verdicts (tests/test_task_waits.py).  (Which steps the model keeps,
``staged_step.idle_steps_dropped``, is another question, the model's: it keeps the
exact model's steps that carry the environment's change, and they stay in its runs.)
"""
from __future__ import annotations

from typing import Hashable, Optional, Sequence

from ..semantics.staged_step import interrupt_task, task_transitions
from ..semantics.state import RUNNING, State
from ..semantics.step import successors as semantic_successors

TASK_CHOICE = "task"
WHOLE_PROGRAM = None     # ``own_change`` for the whole program: every interrupt is its own


def running_tasks(state: State) -> list[int]:
    """The indices of the tasks that have not ended (the main task is 0)."""
    return [index for index, stack in enumerate((state.frames,) + state.tasks) if stack]


def task_choosing(names: tuple, state: State, choices: tuple) -> Optional[int]:
    """The task a step with these choices (a ``Transition.label``) runs from ``state``:
    the ``task`` choice, or the only task left running (None: none)."""
    for name, value in choices:
        if name == TASK_CHOICE:
            return names.index(value)
    if state.status != RUNNING:
        return None
    running = running_tasks(state)
    return running[0] if len(running) == 1 else None


class TaskWaits:
    """Whether a task waits in a state, for one program and configuration."""

    def __init__(self, program, config):
        self.program = program
        self.config = config
        self.names = tuple(program.task_names)
        self.free = tuple(index for index, _, _ in config.free_inputs)

    def own_change(self, task: Optional[int], before: State, after: State) -> bool:
        """Whether a step of ``task`` from ``before`` to ``after`` changes something
        besides the stored free inputs and the interrupts queued for other tasks
        (``WHOLE_PROGRAM``: besides the stored free inputs; ``RapidSystem.stuck``)."""
        if after is before:
            return False
        if task is not WHOLE_PROGRAM and after[4] is not before[4] and after[4][1] != before[4][1]:
            pending = before[4][1]
            kept = tuple(number for number in after[4][1]
                         if number in pending or self._serves(task, after[4][0], number))
            if kept != after[4][1]:
                after = after._replace(interrupts=after[4]._replace(pending=kept))
        if self.free and after[2] is not before[2]:
            io, old = after[2], before[2]
            changed = [x for index in self.free if io[index] != old[index]
                       for x in (index, old[index])]
            if changed:
                after = after._replace(io=io.mset(*changed))
        return after != before

    def _serves(self, task: int, table: tuple, number: int) -> bool:
        """Whether ``task`` serves interrupt ``number`` (one no longer connected: yes)."""
        entry = next((e for e in table if e[0] == number), None)
        return entry is None or interrupt_task(self.program, entry) == task

    def waits(self, task: int, state: State, targets: Sequence[State]) -> bool:
        """Whether ``task`` waits in the running ``state``, ``targets`` being the states
        its steps from there lead to (none: it waits)."""
        if any(self.own_change(task, state, after) for after in targets):
            return False
        if not state[4][0]:
            return True
        return not any(self.own_change(task, state, further)
                       for after in dict.fromkeys(targets) if after != state
                       for further in self.task_targets(task, after))

    def waits_now(self, task: int, state: State) -> bool:
        """``waits`` of ``task`` in the running ``state``, stepping the task there."""
        return self.waits(task, state, self.task_targets(task, state))

    def task_targets(self, task: int, state: State) -> list[State]:
        """The states the steps of ``task`` from ``state`` lead to."""
        found = task_transitions(self.program, state, task, self.config)
        if found is not None:
            return [transition[2] for transition in found]
        return [transition.state
                for transition in semantic_successors(self.program, state, self.config)
                if task_choosing(self.names, state, transition.label) == task]

    def waiting(self, state: State, transitions: Sequence) -> frozenset:
        """The running tasks that wait in ``state`` (RUNNING), given its semantic
        ``transitions`` (``step.successors``)."""
        targets: dict[Hashable, list] = {task: [] for task in running_tasks(state)}
        for transition in transitions:
            task = task_choosing(self.names, state, transition.label)
            if task in targets:
                targets[task].append(transition.state)
        return frozenset(task for task, found in targets.items()
                         if self.waits(task, state, found))
