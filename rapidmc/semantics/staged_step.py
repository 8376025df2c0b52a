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
from .edge_traps import calmed, edge_interrupt, own_edges, routine_task
from .robots import task_robot, with_task_robot
from .state import ENDED, FAILED, RUNNING, Frame, Interrupts, State, Transition
from .task_registers import put_back, task_view
from .unread_inputs import input_choices, rested, unchosen_dropped, watches_any

_new_tuple = tuple.__new__


def is_staged(program, state: State, config: CheckConfig) -> bool:
    """Whether ``staged_successors`` may stand in for the general driver at ``state``
    (a running state with tasks or interrupts, no environment reaction, no reading of
    another task's robot: a view carries its task's robot only)."""
    if program.environment_react is not None or program.reads_task_robots:
        return False
    interrupts = state[4]
    if not (state[10] or interrupts[0] or interrupts[1]):
        return False
    lazy = config.lazy_inputs
    if lazy:                             # an edge on an input chosen where read: not here
        for entry in interrupts[0]:
            source = entry[2]
            if source and source[0] in ("signal", "analog") and source[1] in lazy:
                return False
    return True


def staged_successors(program, state: State, config: CheckConfig) -> Optional[list]:
    """Every transition from ``state`` (``is_staged``), in the general driver's order;
    None when a transition would go on with a merged run (the general driver's case)."""
    tasks = state[10]
    stacks = (state[0],) + tasks
    runnable = [i for i, stack in enumerate(stacks) if stack]
    if not runnable:
        return None
    steps = view_steps(program, config)
    interrupts = state[4]
    plans = None                         # per runnable task: its plan (_task_plan)
    if interrupts[0] or interrupts[3] or interrupts[1]:
        plans = {task: _task_plan(program, stacks[task], task, steps.timer_choices(
            program, interrupts, task)) for task in runnable}
    inputs = steps.input_values(state[2])
    ready = steps.input_values(state[2], interrupts[3]) if plans and interrupts[3] else inputs
    # a task's views share their transitions (ViewSteps) only when there are several
    shared = {} if len(inputs) > 1 or (
        plans is not None and any(len(plan) > 1 for plan in plans.values())) else None
    task_labels = steps.task_labels(runnable)
    # the task each transition's label names (task_of), when no input label comes first
    # with that name
    owners = [] if len(runnable) > 1 and not steps.input_named_task else None
    views = {}                           # task -> _task_parts (without interrupts: plans)
    result = []
    time_check = config.time_check
    choices = input_choices(program, config)
    unchosen = {task: choices.unchosen(program, state, task) for task in runnable} \
        if choices is not None else {}
    standing: set = set()                # positions of transitions for several valuations
    for number, (io, ready_io, input_label) in enumerate(
            zip(inputs, ready, config.input_labels)):
        time_check()                     # (a valuation: one step per runnable task)
        for task, task_label in zip(runnable, task_labels):
            left = unchosen.get(task)
            if left:                     # (valuation 0, every input first, always runs)
                kept = choices.kept(left)
                if not kept.runs[number]:
                    continue
                start = len(result)
                _one_task(program, state, task, kept.labels[number] + task_label, io,
                          ready_io, plans, views, steps, shared, result)
                if number == 0 and watches_any(result[start:], left):
                    del result[start:]       # it makes an interrupt on one active
                    unchosen[task] = frozenset()
                    left = None
                else:
                    result[start:] = rested(result[start:], kept.rest)
                    standing.update(range(start, len(result)))
            if not left:
                label = input_label + task_label if input_label else task_label
                _one_task(program, state, task, label, io, ready_io, plans, views, steps,
                          shared, result)
            if owners is not None:
                owners += [task_label[0][1]] * (len(result) - len(owners))
    if not tasks and config.merge_points and _may_merge(result):
        return None
    if tasks and not config.idle_steps_kept:
        result = idle_steps_dropped(state, result, owners, standing)
    return edges_at_rest(result, config.edge_inputs)


def _one_task(program, state: State, task: int, label: tuple, io, ready_io,
              plans: Optional[dict], views: dict, steps: "ViewSteps", shared: Optional[dict],
              result: list) -> None:
    """The steps of ``task`` from ``state`` under one input valuation (``io``; ``ready_io``
    with the delayed signal changes done), labelled ``label``, appended to ``result``."""
    if plans is not None:
        _task_steps(state, task, label, ready_io, plans[task], steps, shared, result)
        return
    parts = views.get(task)
    if parts is None:
        parts = views[task] = _task_parts(program, state, task, state[4])
    stack = state[0] if task == 0 else state[10][task - 1]
    view = _new_tuple(State, (stack, state[1], io) + parts)
    append = result.append
    for transition in steps(view, task, shared):
        append(_in_task(program, state, task, label, transition))


def edges_at_rest(transitions: list, edges: dict) -> list:
    """``transitions`` whose targets keep every edge input at 0 (``CheckConfig.edge_inputs``:
    the step chose the value, so an edge came or not; the next step may bring another)."""
    if not edges:
        return transitions
    result = []
    for transition in transitions:
        after = transition[2]
        io = after[2]
        changed = [x for index in edges if io[index] for x in (index, 0.0)]
        if changed:
            transition = transition._replace(state=after._replace(io=io.mset(*changed)))
        result.append(transition)
    return result


def task_transitions(program, state: State, task: int,
                     config: CheckConfig) -> Optional[list]:
    """The transitions of ``task`` alone from ``state``: those of ``staged_successors``
    whose label names the task, in the same order, without the idle steps dropped;
    None where the state has delayed signal changes, stored inputs other than served
    edge inputs, or an environment reaction (or the task has ended).  With interrupts,
    as there: the task's timers may fire, a pending TRAP of its own starts instead of
    the instruction, and signal edges queue their interrupts.  With served edge inputs
    (``edge_traps``), of the valuations that lead to the same targets only the first
    is taken (``edge_choices``); inputs the step leaves unchosen (``unread_inputs``)
    are left out of its labels as there.  Partial-order reduction extends a step of one task
    with its task-local instructions (``reduction.partial_order``) without stepping
    the others."""
    interrupts = state[4]
    if program.environment_react is not None or program.reads_task_robots or \
            interrupts[3] or not edges_only(config):
        return None
    stacks = (state[0],) + state[10]
    if not stacks[task]:
        return None
    runnable = [i for i, stack in enumerate(stacks) if stack]
    steps = view_steps(program, config)
    label = steps.task_labels(runnable)[runnable.index(task)]
    inputs = steps.input_values(state[2])
    if interrupts[0] or interrupts[1]:
        if not is_staged(program, state, config):
            return None
        plan = _task_plan(program, stacks[task], task,
                          steps.timer_choices(program, interrupts, task))
        found: list = []
        for io, input_label in edge_choices(program, state, task, plan, inputs, config):
            _task_steps(state, task, input_label + label if input_label else label, io,
                        plan, steps, None, found)
        return edges_at_rest(unchosen_dropped(program, state, found, config)[0],
                             config.edge_inputs)
    # (no interrupt: an edge starts no TRAP and queues nothing; the first valuation)
    view = _new_tuple(State, (stacks[task], state[1], inputs[0]) +
                      _task_parts(program, state, task, state[4]))
    label = config.input_labels[0] + label if config.input_labels[0] else label
    found = [_in_task(program, state, task, label, transition)
             for transition in steps(view, task, None)]
    return edges_at_rest(unchosen_dropped(program, state, found, config)[0],
                         config.edge_inputs)


def edges_only(config: CheckConfig) -> bool:
    """Whether every stored free input is a served edge input (``edge_traps``: an edge
    starts a TRAP of the task whose step chose it, or is dropped), or there are none."""
    if not config.free_inputs:
        return True
    own = own_edges(config)
    return all(index in own for index, _, _ in config.free_inputs)


def edge_choices(program, state: State, task: int, plan: list, inputs: list,
                 config: CheckConfig) -> list:
    """(signal values, input label) of the valuations of the stored free inputs, all
    served edge inputs (``edges_only``), that a step of ``task`` from ``state`` needs: in
    order, the first of those that start the same TRAP (or none) in each ``plan`` entry.
    Nothing but an interrupt order names an edge input, and the step's end puts it at
    0 again (``edges_at_rest``), so the valuations that start the same TRAPs give the
    same targets: an edge of another task's interrupt is dropped in this task's step,
    and so is every edge where the task cannot start a TRAP (``edge_traps``)."""
    labels = config.input_labels
    if len(inputs) == 1:
        return [(inputs[0], labels[0])]
    own = own_edges(config)
    before = state[2]
    stack = state[0] if task == 0 else state[10][task - 1]
    open_plan = [] if in_trap(program, stack) else \
        [chosen[0] for _, _, _, chosen in plan if _enabled(program, chosen, task)]
    seen = set()
    kept = []
    for io, input_label in zip(inputs, labels):
        key = tuple(edge_interrupt(program, table, own, before, io, task)
                    for table in open_plan)
        if key not in seen:
            seen.add(key)
            kept.append((io, input_label))
    return kept


class ViewSteps:
    """The instruction's transitions from one-task views (through the plain drivers,
    without merge points), and what the views of one state share: the signal vector
    after each input valuation, the timers' combinations."""

    def __init__(self, program, owner: CheckConfig):
        self.program = program
        self.owner = owner
        self.config = owner.unmerged()   # without merge points: one instruction per step
        self.input_named_task = any(name == "task" for _, name, _ in owner.free_inputs)
        self.labels: dict = {}           # runnable tasks -> task_labels

    def __call__(self, view: State, task: int, shared: Optional[dict]) -> list:
        """The instruction's transitions from ``view``, a view of ``task``.  ``shared``
        (one dict per state, None when each task has one view) keeps per task the
        transitions every other view of that task in the state has too, but for its
        signals and interrupts (``_shareable``)."""
        template = shared.get(task) if shared else None
        if template is not None:
            io, interrupts = view[2], view[4]
            return [_new_tuple(Transition, (t[0], t[1], _new_tuple(
                State, t[2][:2] + (io, t[2][3], interrupts) + t[2][5:])) + t[3:])
                for t in template]
        program = self.program
        transitions = fused_successors(program, view, self.config)
        if transitions is None:
            transitions = plain_successors(program, view, self.config)
        if shared is not None and task not in shared:
            shared[task] = _shareable(program, view, transitions)
        return transitions

    def task_labels(self, runnable: list) -> tuple:
        """The label part naming the task per runnable task (none when only one runs)."""
        key = tuple(runnable)
        labels = self.labels.get(key)
        if labels is None:
            names = self.program.task_names
            labels = self.labels[key] = tuple((("task", names[task]),) for task in key) \
                if len(key) > 1 else ((),)
        return labels

    def input_values(self, io, scheduled: tuple = ()) -> list:
        """The signal vector after each valuation of the stored free inputs, in the
        general order, then the delayed signal changes ``scheduled`` (the main task's
        step with interrupts: time is abstract, they happen now)."""
        assignments_each = self.config.input_assignments
        if not scheduled and len(assignments_each) == 1 and not assignments_each[0]:
            return [io]                  # no stored inputs, no delayed changes
        values = []
        for assignments in assignments_each:
            changed = io.mset(*assignments) if assignments else io
            for _, index, value in scheduled:
                changed = changed.set(index, value)
            values.append(changed)
        return values

    @staticmethod
    def timer_choices(program, interrupts: Interrupts, task: int) -> list:
        """(label, interrupts) per combination of ``task``'s timers firing, in the general
        order (each active timer of the task not pending may fire, False before True),
        delayed signal changes done."""
        ready = interrupts._replace(scheduled=()) if interrupts[3] else interrupts
        found = []
        if ready[0]:
            _fire(program, task, ready[0], 0, ready[1], (), found)
        else:
            found.append(((), ready[1]))
        return [(label, ready if pending is ready[1] else ready._replace(pending=pending))
                for label, pending in found]


def _shareable(program, view: State, transitions: list) -> Optional[list]:
    """``transitions`` when the other views of the task in this state have the same but
    for their own signals and interrupts; else None.

    The views of one task in one state differ only in signal values (the input
    valuation, delayed changes) and in the pending interrupts (timers that fired, a
    TRAP that was not found).  An instruction that reads no signal (``reads_io``:
    the general driver's ``_successors_inputs_after`` relies on it too) and leaves
    signals and interrupts as they were (the very same objects) has read no pending
    interrupt either: IDelete and ISleep, which read them, always write a new
    interrupts value.  Its transitions from any of those views are then the same
    but for those two parts."""
    frame = view[0][-1]
    if program.routines[frame[0]].code[frame[1]].reads_io:
        return None
    io, interrupts = view[2], view[4]
    for transition in transitions:
        after = transition[2]
        if after[2] is not io or after[4] is not interrupts:
            return None
    return transitions


def view_steps(program, config: CheckConfig) -> ViewSteps:
    """The ``ViewSteps`` of this configuration and program (made when first needed; a
    copy of the configuration makes its own)."""
    steps = config.view_steps
    if steps is None or steps.owner is not config or steps.program is not program:
        steps = config.view_steps = ViewSteps(program, config)
    return steps


def _task_parts(program, state: State, task: int, interrupts: Interrupts) -> tuple:
    """The parts of a one-task view of ``task`` in ``state`` after its stack, global data and
    signals: its robot, ``interrupts`` (every task's table and queue) with its own enable
    flag, its own ERRNO and INTNO, the rest of ``state``, no further tasks."""
    return (task_robot(program, state[3], task),) + \
        task_view(program, interrupts, state[5], state[6], task) + state[7:10] + ((),)


def _in_task(program, state: State, task: int, label: tuple,
             transition: Transition) -> Transition:
    """The transition of a one-task view as a step of ``task`` in ``state``: its stack
    back among the others' (a task that ended leaves the others running; an uncaught
    error stops every task: nothing to put back), its robot back among the others' (when
    each task has its own: ``semantics.robots``), its ERRNO, INTNO and enable flag back
    among the others' (``semantics.task_registers``), ``label`` before the view's."""
    after = transition[2]
    if program.robot_per_task:
        after = _new_tuple(State, after[:3] + (with_task_robot(program, state[3], task,
                                                               after[3]),) + after[4:])
    if program.registers_per_task:
        after = _new_tuple(State, after[:4] + put_back(
            program, state[4], state[5], state[6], task, after[4], after[5], after[6]) +
            after[7:])
    tasks = state[10]
    if tasks and after[7] != FAILED:
        if task:
            tasks = tasks[:task - 1] + (after[0],) + tasks[task:]
            head = (state[0],) + after[1:7]
        else:
            head = after[:7]
        status = after[7]
        if status == ENDED and (head[0] or any(tasks)):
            status = RUNNING
        after = _new_tuple(State, head + (status,) + after[8:10] + (tasks,))
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
# A task's step with interrupts
# ---------------------------------------------------------------------------

def interrupt_task(program, entry) -> int:
    """The task that serves interrupt ``entry``: the task whose TRAP it is (a task can
    connect only its own traps; the environment's count as the main task's)."""
    return routine_task(program.routines[entry[1]].namespace)


def next_pending(program, interrupts: Interrupts, task: int) -> Optional[int]:
    """The first pending interrupt ``task`` takes: one it connected, or one no longer
    connected (dropped by whichever task steps), None if there is none."""
    table = interrupts[0]
    for number in interrupts[1]:
        entry = next((e for e in table if e[0] == number), None)
        if entry is None or interrupt_task(program, entry) == task:
            return number
    return None


def _fire(program, task: int, table: tuple, start: int, pending: tuple, label: tuple,
          found: list) -> None:
    for position in range(start, len(table)):
        entry = table[position]
        source = entry[2]
        if entry[3] and source and source[0] == "timer" and entry[0] not in pending and \
                interrupt_task(program, entry) == task:
            name = f"timer {entry[0]}"
            _fire(program, task, table, position + 1, pending, label + ((name, False),),
                  found)
            _fire(program, task, table, position + 1, pending + (entry[0],),
                  label + ((name, True),), found)
            return
    found.append((label, pending))


def _task_plan(program, frames: tuple, task: int, choices: list) -> list:
    """Per combination of timers: (label, interrupts, None, chosen) when the instruction of
    the task with stack ``frames`` runs, or (label, interrupts, (frames, INTNO, span),
    chosen) when a pending TRAP of that task starts instead; ``chosen``: the interrupts
    of the combination, before any TRAP started (an edge input's edge: ``edge_traps``)."""
    plan = []
    may_trap = None
    for label, interrupts in choices:
        pending = interrupts[1]
        if pending and _enabled(program, interrupts, task):
            if may_trap is None:
                may_trap = not in_trap(program, frames)
            if may_trap:
                number = next_pending(program, interrupts, task)
                if number is not None:
                    plan.append((label,) + _trap_start(program, interrupts, frames, number) +
                                (interrupts,))
                    continue
        plan.append((label, interrupts, None, interrupts))
    return plan


def _enabled(program, interrupts: Interrupts, task: int) -> bool:
    """Whether ``task`` has interrupts enabled (IEnable/IDisable)."""
    return interrupts[2][task] if program.registers_per_task else interrupts[2]


def _trap_start(program, interrupts: Interrupts, frames: tuple, number: int) -> tuple:
    """(interrupts, (frames, INTNO, span)) after interrupt ``number`` starts its TRAP on the
    stack ``frames``; (interrupts, None) when it is no longer connected (dropped)."""
    interrupts = interrupts._replace(pending=tuple(n for n in interrupts[1] if n != number))
    entry = next((e for e in interrupts[0] if e[0] == number), None)
    if entry is None:
        return interrupts, None
    trap = program.routines[entry[1]]
    source = entry[2]
    if source and source[-1] is True and source[0] != "pers":
        interrupts = interrupts._replace(table=deactivated(interrupts[0], number))
    entered = frames + (Frame(trap.index, 0, trap.initial_locals),)
    return interrupts, (entered, float(number), trap.span)


def _task_steps(state: State, task: int, label: tuple, io, plan: list, steps: ViewSteps,
                shared: Optional[dict], result: list) -> None:
    """The steps of ``task`` from signal values ``io`` (inputs set, delayed changes
    done), one per ``plan`` entry: a pending TRAP of the task starts on its stack, or the
    TRAP of an edge input's interrupt this step brings (``edge_traps``), or the
    instruction runs; then the other signal edges since ``state`` order their
    interrupts."""
    before = state[2]
    program = steps.program
    stack = state[0] if task == 0 else state[10][task - 1]
    own = own_edges(steps.owner)
    calm = calmed(before, io, own) if own else before
    for timers_label, interrupts, trap, chosen in plan:
        if calm is not before and _enabled(program, chosen, task) and \
                not in_trap(program, stack):
            number = edge_interrupt(program, chosen[0], own, before, io, task)
            if number is not None:
                interrupts, trap = _trap_start(program, chosen, stack, number)
        parts = _task_parts(program, state, task, interrupts)
        if trap is not None:
            entered, number, span = trap
            view = _new_tuple(State, (entered, state[1], io) + parts[:3] + (number,) +
                              parts[4:])
            transition = _in_task(program, state, task, label + timers_label,
                                  _new_tuple(Transition, ((), span, view, "", False)))
            result.append(transition._replace(state=_with_edges(transition[2], calm)))
            continue
        view = _new_tuple(State, (stack, state[1], io) + parts)
        for transition in steps(view, task, shared):
            transition = _in_task(program, state, task, label + timers_label, transition)
            after = _with_edges(transition[2], calm)
            if after is not transition[2]:
                transition = transition._replace(state=after)
            result.append(transition)


def _with_edges(after: State, before) -> State:
    """``after`` with the interrupts its signal changes since ``before`` order pending."""
    interrupts = after[4]
    if not interrupts[0] or after[2] is before or after[2] == before:
        return after
    signalled = signal_edges_pending(interrupts, before, after[2])
    if signalled is interrupts:
        return after
    return after._replace(interrupts=signalled)


def signal_edges_pending(interrupts: Interrupts, before, now) -> Interrupts:
    """``interrupts`` with each active interrupt ordered on a signal whose change from
    ``before`` to ``now`` is its edge (ISignalDI's trigger: 0 falling, 1 rising,
    2 both) or meets its analog condition (ISignalAI: ``analog_reached``) queued, in
    table order (an interrupt already pending stays once)."""
    pending = interrupts[1]
    table = interrupts[0]
    for position, entry in enumerate(interrupts[0]):
        source = entry[2]
        if not entry[3] or not source or source[0] not in ("signal", "analog"):
            continue
        index = source[1]
        old, new = before[index], now[index]
        if old == new:
            continue
        if source[0] == "analog":
            reached, source = analog_reached(source, new)
            if source is not entry[2]:
                table = table[:position] + (entry._replace(source=source),) + \
                    table[position + 1:]
            if not reached:
                continue
        elif not (source[2] == 2 or (source[2] == 1 and new == 1) or
                  (source[2] == 0 and new == 0)):
            continue
        if entry[0] not in pending:
            pending = pending + (entry[0],)
    if pending is interrupts[1] and table is interrupts[0]:
        return interrupts
    return interrupts._replace(table=table, pending=pending)


def analog_reached(source: tuple, value) -> tuple:
    """Whether the analog ``value`` orders the ISignalAI/AO interrupt of ``source``
    (``("analog", index, condition, high, low, delta, direction, reference, once)``), and
    the source with its new reference: ABB's rule, the condition holds and the value
    differs from the reference by more than DeltaValue; the reference then becomes the
    value, and the direction (1 \\DPos, -1 \\DNeg, 0 either) must match."""
    _, _, condition, high, low, delta, direction, reference, _ = source
    if not aio_condition_met(condition, high, low, value) or abs(value - reference) <= delta:
        return False, source
    moved = source[:7] + (value,) + source[8:]
    return direction == 0 or (value - reference) * direction > 0, moved


def aio_condition_met(condition: int, high: float, low: float, value) -> bool:
    """aiotrigg ``condition`` (AIO_ABOVE_HIGH = 1 ... AIO_ALWAYS = 7) at ``value``; a
    number outside them counts as AIO_ALWAYS, the condition that orders the most."""
    if condition == 1:
        return value > high
    if condition == 2:
        return value < high
    if condition == 3:
        return value > low
    if condition == 4:
        return value < low
    if condition == 5:
        return low <= value <= high
    if condition == 6:
        return value < low or value > high
    return True


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

def idle_steps_dropped(state: State, transitions: list,
                       owners: Optional[list] = None, standing=()) -> list:
    """Tasks share the controller fairly: a task whose step changes nothing (it waits)
    does not take the turn from a task that can go on.  If no task can go on, every
    idle step stays (the program may be deadlocked).  ``owners``: each transition's
    ``task_of``, when known.  ``standing``: the positions of transitions that stand
    for every value of an input the step left unchosen (``unread_inputs``): they change
    it in the model with every valuation, so they count as changes."""
    if owners is None:
        owners = [task_of(transition) for transition in transitions]
    moving = set()
    moved = []
    for position, (transition, owner) in enumerate(zip(transitions, owners)):
        change = transition[2] != state or position in standing
        moved.append(change)
        if change:
            moving.add(owner)
    if not moving or all(moved):
        return transitions
    return [t for t, owner, change in zip(transitions, owners, moved)
            if change or not (moving - {owner})]


def task_of(transition: Transition):
    """The task a transition's label names (None: only one task could step)."""
    for name, value in transition[0]:
        if name == "task":
            return value
    return None
