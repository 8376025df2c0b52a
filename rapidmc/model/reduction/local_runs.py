"""Merged steps between tasks: a task's step goes on through its task-local instructions.

SPIN merges a process's statements on its own local variables into the
transition before them (statement merging), with several processes too: no
other process can see the states in between.  Here a transition of task ``t``
goes on with ``t``'s next instruction while that instruction

* is a merge point of ``reduction.merging`` (a condition, FOR entry or step,
  GOTO or assignment, no special function, no loop head), invisible to every
  atom, or a call, RETURN or ENDPROC that is no loop head (a frame of the
  task's own pushed or popped, as SPIN inlines): the call stack read as a
  sequence of program counters only grows, so a run is finite;
* is independent of every other task (``PartialOrder.footprint`` LOCAL: it
  reads only data no other task writes, writes only data no other task can
  name, reads no signal);
* is not that of a task serving an interrupt of the state (``interrupt_owners``: a
  TRAP of its own may start instead);
* has one transition from there, which leaves the program running, ERRNO
  and the modes of the task's frames as they were (``_went_on``), and changes
  the state.

The state in between is dropped.  It is the state where the ample set of
``partial_order`` would be that one instruction (C0-C2 hold: it is enabled,
independent and invisible; C3: the program counter only grows within a run, so
every cycle passes through a stored state, where the proviso applies), so the
reduced graph keeps every verdict the ample sets keep: LTL without X over the
atoms, FAILED (an instruction that would fail is not merged: the run stops
before it, and the failure is a step of its own) and waiting forever (the task
never waits at a merge point; the others' enabledness does not change).  Runs
are a function of the state alone, so the search, the rebuilding of paths and
the fair search (``RapidSystem.full_interleaving``) see the same transitions;
a counterexample is re-executed step by step on the unreduced model
(``reduction.expansion``: the label holds every choice and span, in order).
"""
from __future__ import annotations

from typing import Callable, Optional

from ...semantics.staged_step import task_transitions
from ...semantics.state import RUNNING, State
from ...semantics.instructions import Call, EndRoutine, Return
from .interrupt_owners import serving_tasks
from .merging import INVISIBLE, loop_heads, merge_points

FRAME_STEPS = (Call, Return, EndRoutine)


class LocalRuns:
    """``extend(state, successors, config)``: each transition of one task extended by the
    task's merged local instructions (see the module docstring)."""

    def __init__(self, program, order, atom_keys: set[str],
                 project: Optional[Callable] = None):
        self.program = program
        self.order = order                   # PartialOrder: the instructions' footprints
        self.points = merge_points(program, atom_keys)
        self.project = project
        self.names = program.task_names
        self._mergeable: dict = {}           # (task, routine, pc) -> bool
        self._heads: dict = {}               # routine -> its loop heads

    def mergeable(self, task: int, routine: int, pc: int) -> bool:
        """Whether the instruction at ``pc`` of ``routine`` may join the step of ``task``
        before it: an invisible merge point that touches only the task's own data."""
        key = (task, routine, pc)
        found = self._mergeable.get(key)
        if found is None and self.program.reads_task_robots:
            # (a task cannot be stepped alone there, ``task_transitions``: no run goes on,
            # and the compiled core's runs keep to that)
            found = self._mergeable[key] = False
        if found is None:
            kinds = self.points.get(routine)
            point = kinds is not None and pc < len(kinds) and kinds[pc] == INVISIBLE
            found = self._mergeable[key] = (point or self._frame_step(routine, pc)) and \
                self.order.is_ample_candidate(task, routine, pc)
        return found

    def _frame_step(self, routine: int, pc: int) -> bool:
        """Whether the instruction is a call, RETURN or ENDPROC that is no loop head: it
        only pushes or pops a frame of the task's own (as SPIN inlines), and a run still
        never goes round a loop."""
        heads = self._heads.get(routine)
        if heads is None:
            heads = self._heads[routine] = loop_heads(self.program.routines[routine].code)
        instruction = self.program.routines[routine].code[pc]
        return type(instruction) in FRAME_STEPS and pc not in heads

    def extend(self, state: State, successors: list, config) -> list:
        """``successors`` (labelled, as ``RapidSystem.successors`` gives them) with each
        transition of a task run on through the task's merged instructions."""
        result = None
        for index, entry in enumerate(successors):
            longer = self._run(state, entry, config)
            if longer is not entry:
                if result is None:
                    result = list(successors)
                result[index] = longer
        return successors if result is None else result

    def _run(self, state: State, entry: tuple, config) -> tuple:
        (choices, span, output), after = entry
        task = self._task(state, choices)
        if task is None:
            return entry
        after, steps = self.run_on(state, task, after, config)
        if not steps:
            return entry
        spans = (span,) + tuple(step_span for _, step_span, _ in steps)
        for label, _, step_output in steps:
            choices = choices + label
            output = output + step_output
        return (choices, spans, output), after

    def run_on(self, state: State, task: int, after: State, config) -> tuple[State, list]:
        """A transition of ``task`` from ``state`` into ``after`` run on through the task's
        merged instructions: the state it ends in, and (label, span, output) of each step
        it took on the way (the compiled core asks for one task's transitions alone)."""
        steps: list = []
        while after[7] == RUNNING and after[5] == state[5] and after[6] == state[6]:
            stack = after[0] if task == 0 else after[10][task - 1]
            if not stack:
                break
            frame = stack[-1]
            if frame[3] != 0 or not self.mergeable(task, frame[0], frame[1]) or \
                    _serving(self.program, after[4], task, self.order.owners):
                break
            found = task_transitions(self.program, after, task, config)
            if found is None or len(found) != 1:
                break
            label, step_span, then, step_output, _ = found[0]
            if self.project is not None:
                then = self.project(then)
            if then[7] != RUNNING or then[5] != after[5] or then[6] != after[6]:
                break                    # (a failed step's state keeps no other task)
            moved = then[0] if task == 0 else then[10][task - 1]
            if then == after or not _went_on(stack, moved):
                break
            steps.append((label, step_span, step_output))
            after = then
        return after, steps

    def _task(self, state: State, choices: tuple) -> Optional[int]:
        """The task that takes the step: the one its choices name, else the only one
        running."""
        for name, value in choices:
            if name == "task":
                return self.names.index(value)
        stacks = (state[0],) + state[10]
        running = [task for task, stack in enumerate(stacks) if stack]
        return running[0] if len(running) == 1 else None


def _serving(program, interrupts, task: int, owners=None) -> bool:
    """Whether a TRAP of the task may start in its next step (``interrupt_owners``): the
    instruction alone is then no ample set."""
    serving = serving_tasks(program, interrupts, owners)
    return serving is None or task in serving


def _went_on(stack: tuple, moved: tuple) -> bool:
    """Whether one step took the task's frames from ``stack`` to ``moved`` without an
    error: the frames it kept keep their modes (an error sends a frame into its handler
    or unwinds it), and a frame it pushed is a normal one."""
    depth = len(moved) - len(stack)
    if depth not in (-1, 0, 1):
        return False
    kept = min(len(stack), len(moved))
    return all(moved[i][3] == stack[i][3] for i in range(kept)) and \
        (depth < 1 or moved[-1][3] == 0)
