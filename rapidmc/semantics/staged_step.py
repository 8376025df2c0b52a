"""Staged steps: the successors of a state with several tasks or with interrupts.

The general driver (``step.general_successors``) runs the whole transition
once per combination of choices, through a ``Machine`` and a ``ScriptChooser``.
The choices of a transition come in stages, always in this order: the stored
free inputs' values, the task that steps (when more than one can), the timers
that fire (main task, interrupts connected), then the choices of the
instruction itself.  Every choice script is a path in one tree of choices and
the general driver visits the paths depth first, so the same transitions come
out, in the same order, when the first stages are enumerated once each (inputs,
then task, then timers) and under each of their combinations the instruction's
own choices are enumerated.

``staged_successors`` does that: for each combination it builds the state just
before the instruction (inputs set, delayed signal changes done, timers
queued, a pending TRAP entered instead of an instruction), hands a one-task
view of it to the plain drivers (``fused_step``, else ``plain_step``: the
instruction and nothing else, as the general step does when there are tasks
or interrupts: no merged run), and finishes each transition as ``step``
does: signal edges ordered with ISignalDI become pending interrupts, a task
that ended leaves the others running.  States with an environment reaction
are left to the general driver, and so is every state where a transition of
one task without interrupts could go on with a merged run.
tests/test_staged_step.py compares both drivers on whole state graphs.
"""
from __future__ import annotations

from typing import Optional

from .choosers import CheckConfig
from .fused_step import fused_successors
from .plain_step import plain_successors
from .state import ENDED, FAILED, RUNNING, Frame, Interrupts, State, Transition

_new_tuple = tuple.__new__


def is_staged(program, state: State, config: CheckConfig) -> bool:
    """Whether ``staged_successors`` may stand in for the general driver at ``state``
    (a running state with tasks or interrupts, no environment reaction)."""
    if program.environment_react is not None:
        return False
    interrupts = state[4]
    if not (state[10] or interrupts[0] or interrupts[1]):
        return False
    lazy = config.lazy_inputs
    if lazy:                             # an edge on an input chosen where read: not here
        for entry in interrupts[0]:
            source = entry[2]
            if source and source[0] == "signal" and source[1] in lazy:
                return False
    return True


def staged_successors(program, state: State, config: CheckConfig) -> Optional[list]:
    """Every transition from ``state`` (``is_staged``), in the general driver's order;
    None when a transition would go on with a merged run (the general driver's case)."""
    stacks = (state[0],) + state[10]
    runnable = [i for i, stack in enumerate(stacks) if stack]
    if not runnable:
        return None
    names = program.task_names
    several = len(runnable) > 1
    inner = config.unmerged()
    interrupts = state[4]
    serves_interrupts = bool(interrupts[0] or interrupts[3] or interrupts[1])
    result = []
    for assignments, input_label in zip(config.input_assignments, config.input_labels):
        io = state[2].mset(*assignments) if assignments else state[2]
        for task in runnable:
            label = input_label + (("task", names[task]),) if several else input_label
            if task == 0 and serves_interrupts:
                for timers_label, ready in _timer_choices(io, interrupts):
                    _main_step(program, state, label + timers_label, ready, inner, result)
            else:
                view = _new_tuple(State, (stacks[task], state[1], io) + state[3:10] + ((),))
                for transition in _instruction_successors(program, view, inner):
                    result.append(_in_task(state, stacks, task, label, transition))
    if not state[10] and config.merge_points and _may_merge(result):
        return None
    if state[10]:
        result = idle_steps_dropped(state, result)
    return result


def _instruction_successors(program, view: State, config: CheckConfig) -> list:
    fused = fused_successors(program, view, config)
    return fused if fused is not None else plain_successors(program, view, config)


def _in_task(state: State, stacks: tuple, task: int, label: tuple,
             transition: Transition) -> Transition:
    """The transition of the one-task view ``transition`` as a step of ``task`` in
    ``state``: its stack back among the others, a task that ended leaving the others
    running (an uncaught error stops every task: nothing to put back)."""
    after = transition[2]
    if after[7] != FAILED and state[10]:
        stacks = stacks[:task] + (after[0],) + stacks[task + 1:]
        status = after[7]
        if status == ENDED and any(stacks):
            status = RUNNING
        after = _new_tuple(State, (stacks[0],) + after[1:7] + (status,) + after[8:10] +
                           (stacks[1:],))
    return _new_tuple(Transition, (label + transition[0], transition[1], after) +
                      transition[3:])


def _may_merge(transitions: list) -> bool:
    """Whether a transition of a one-task program ends running without interrupts (the
    general step would go on with its merged run)."""
    for transition in transitions:
        after = transition[2]
        interrupts = after[4]
        if after[7] == RUNNING and not (interrupts[0] or interrupts[1] or interrupts[3]):
            return True
    return False


# ---------------------------------------------------------------------------
# The main task's step with interrupts
# ---------------------------------------------------------------------------

def _timer_choices(io, interrupts: Interrupts):
    """(label, (io, interrupts)) per combination of timers firing, in the general order:
    delayed signal changes happen first (time is abstract), then each active timer not
    pending may fire (False before True)."""
    scheduled = interrupts[3]
    if scheduled:
        for _, index, value in scheduled:
            io = io.set(index, value)
        interrupts = interrupts._replace(scheduled=())
    if not interrupts[0]:
        return [((), (io, interrupts))]
    found = []
    _fire(interrupts[0], 0, interrupts[1], (), found)
    return [(label, (io, interrupts._replace(pending=pending) if pending is not interrupts[1]
                     else interrupts)) for label, pending in found]


def _fire(table: tuple, start: int, pending: tuple, label: tuple, found: list) -> None:
    for position in range(start, len(table)):
        entry = table[position]
        source = entry[2]
        if entry[3] and source and source[0] == "timer" and entry[0] not in pending:
            name = f"timer {entry[0]}"
            _fire(table, position + 1, pending, label + ((name, False),), found)
            _fire(table, position + 1, pending + (entry[0],), label + ((name, True),), found)
            return
    found.append((label, pending))


def _main_step(program, state: State, label: tuple, ready: tuple, config: CheckConfig,
               result: list) -> None:
    """The main task's step from the timers' combination ``ready`` (io, interrupts): a
    pending TRAP starts, or the instruction runs; then signal edges."""
    io, interrupts = ready
    frames = state[0]
    pending = interrupts[1]
    if pending and interrupts[2] and not in_trap(program, frames):
        number = pending[0]
        interrupts = interrupts._replace(pending=pending[1:])
        entry = next((e for e in interrupts[0] if e[0] == number), None)
        if entry is not None:
            trap = program.routines[entry[1]]
            source = entry[2]
            if source and source[-1] is True and source[0] != "pers":
                interrupts = interrupts._replace(table=deactivated(interrupts[0], number))
            after = _new_tuple(State, (frames + (Frame(trap.index, 0, trap.initial_locals),),
                                       state[1], io, state[3], interrupts, state[5],
                                       float(number)) + state[7:])
            after = _with_edges(after, state[2])
            result.append(_new_tuple(Transition, (label, trap.span, after, "", False)))
            return
    stacks = (frames,) + state[10]
    view = _new_tuple(State, (frames, state[1], io, state[3], interrupts) + state[5:10] + ((),))
    for transition in _instruction_successors(program, view, config):
        transition = _in_task(state, stacks, 0, label, transition)
        after = _with_edges(transition[2], state[2])
        if after is not transition[2]:
            transition = transition._replace(state=after)
        result.append(transition)


def _with_edges(after: State, before) -> State:
    """``after`` with the interrupts its signal changes since ``before`` order pending."""
    interrupts = after[4]
    if not interrupts[0] or after[2] == before:
        return after
    signalled = signal_edges_pending(interrupts, before, after[2])
    if signalled is interrupts:
        return after
    return after._replace(interrupts=signalled)


def signal_edges_pending(interrupts: Interrupts, before, now) -> Interrupts:
    """``interrupts`` with each active interrupt ordered on a signal whose change from
    ``before`` to ``now`` is its edge (ISignalDI's trigger: 0 falling, 1 rising,
    2 both) queued, in table order (an interrupt already pending stays once)."""
    pending = interrupts[1]
    for entry in interrupts[0]:
        source = entry[2]
        if not entry[3] or not source or source[0] != "signal":
            continue
        _, index, trigger, _ = source
        old, new = before[index], now[index]
        if old == new:
            continue
        if trigger == 2 or (trigger == 1 and new == 1) or (trigger == 0 and new == 0):
            if entry[0] not in pending:
                pending = pending + (entry[0],)
    return interrupts if pending is interrupts[1] else interrupts._replace(pending=pending)


def in_trap(program, frames) -> bool:
    routines = program.routines
    return any(routines[frame[0]].kind == "TRAP" for frame in frames)


def deactivated(table: tuple, number: int) -> tuple:
    """The interrupt table with interrupt ``number`` asleep (a single-shot one after its
    first delivery)."""
    return tuple(e._replace(active=False) if e[0] == number else e for e in table)


# ---------------------------------------------------------------------------
# Fairness between tasks
# ---------------------------------------------------------------------------

def idle_steps_dropped(state: State, transitions: list) -> list:
    """Tasks share the controller fairly: a task whose step changes nothing (it waits)
    does not take the turn from a task that can go on.  If no task can go on, every
    idle step stays (the program may be deadlocked)."""
    moving = set()
    idle = False
    for transition in transitions:
        if transition[2] != state:
            moving.add(task_of(transition))
        else:
            idle = True
    if not moving or not idle:
        return transitions
    return [t for t in transitions if t[2] != state or not (moving - {task_of(t)})]


def task_of(transition: Transition):
    """The task a transition's label names (None: only one task could step)."""
    for name, value in transition[0]:
        if name == "task":
            return value
    return None
