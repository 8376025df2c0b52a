"""The small-step semantics: initial states and successors of a state.

One transition of the model is:

1. the environment sets the inputs: every free digital input (not driven by
   an environment module) may take either value (check mode only; in run
   mode inputs keep the values given with ``--io``);
2. interrupts: timers may fire, a pending interrupt starts its TRAP;
3. the program executes ONE instruction (a simple statement, a condition,
   a routine entry or exit) — or the TRAP entry of step 2;
4. signal edges ordered with ISignalDI/ISignalDO become pending interrupts;
5. the environment modules' ``react`` procedure runs to completion.

Nondeterministic choices (input values, FlexPendant answers, AnyBool/AnyNum
in environment modules, wait timeouts) are made through a *chooser*.
``successors`` enumerates every combination of choices by re-running the
(pure, deterministic given the choices) transition with each choice script,
so the step code stays straight-line.
"""
from __future__ import annotations

from typing import Optional

from pyrsistent import pvector

from .errors import errno_name, error_detail
from .values import UNCONNECTED_AXIS, signal_value
from .machine import Machine
from .program import Program
from .state import ENDED, FAILED, RUNNING, STOPPED, Frame, Interrupts, State, Transition
from .lazy_inputs import InputView
from .resting_inputs import at_rest
from .unread_inputs import unchosen_dropped
from .robots import NoTaskRobot, initial_robots, task_robot, with_task_robot
from .choosers import Chooser, CheckConfig, ScriptChooser  # noqa: F401 (the step's interface)
from .fused_step import fused_successors
from .plain_step import (MERGED_STEP_LIMIT, is_plain, plain_successors,  # noqa: F401
                         run_instruction, run_merged)
from .staged_step import (deactivated, edges_at_rest, idle_steps_dropped, in_trap, interrupt_task,
                          is_staged, next_pending, signal_edges_pending, staged_successors)
from .edge_traps import calmed, edge_interrupt, own_edges
from .task_registers import give_back, initial_registers, take_task_view
from .timing import apply_scheduled, enqueue

ENVIRONMENT_STEP_LIMIT = 100_000

HOME_TARGET = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0),
               (UNCONNECTED_AXIS,) * 6)
HOME_JOINTS = ((0.0,) * 6, (UNCONNECTED_AXIS,) * 6)


# ---------------------------------------------------------------------------
# Initial states
# ---------------------------------------------------------------------------

def initial_store(program: Program):
    return pvector(g.initial for g in program.globals)


def start_state(program: Program, io_values: Optional[dict] = None) -> State:
    """The state after data initialisation, at the entry of main (before environment init)."""
    io = [0.0] * len(program.signals)
    for key, value in (io_values or {}).items():
        signal = program.signal(key)
        if signal is not None:
            io[signal.index] = signal_value(signal.kind, value)
    main = program.routines[program.entry]
    robot = initial_robots(program, (HOME_TARGET, _predefined(program, "TOOL0"),
                                     _predefined(program, "WOBJ0"), HOME_JOINTS))
    tasks = tuple((Frame(entry, 0, program.routines[entry].initial_locals),)
                  for entry in program.task_entries)
    errno, intno, enabled = initial_registers(program)
    return State((Frame(main.index, 0, main.initial_locals),), initial_store(program),
                 pvector(io), robot, Interrupts(enabled=enabled), errno, intno, tasks=tasks)


def _predefined(program: Program, key: str):
    from .library.data import PREDEFINED_DATA
    return PREDEFINED_DATA[key].value


def initial_states(program: Program, chooser_factory) -> list[State]:
    """All initial states: the start state after the environment's ``init`` (if any)."""
    start = start_state(program)
    if program.environment_init is None:
        return [start]
    states = []
    for _, state, _ in enumerate_choices(lambda chooser: _run_environment(
            program, start, chooser, program.environment_init), chooser_factory):
        states.append(state)
    return list(dict.fromkeys(states))


def _run_environment(program: Program, state: State, chooser, routine_index: int):
    m = Machine(program, state, chooser)
    run_environment_routine(m, routine_index)
    return m.choices, m.to_state(), m.output


def run_environment_routine(m: Machine, routine_index: int) -> None:
    """Run an environment procedure to completion inside the current transition."""
    routine = program_routine = m.program.routines[routine_index]
    saved_frames = m.frames
    saved_status = m.status
    saved_waiting = m.waiting            # the program's own wait, not the environment's
    saved_robot = m.robot
    if m.program.robot_per_task:
        m.robot = NoTaskRobot(m.program)
    # environment code runs with the main task's ERRNO, INTNO and IEnable flag
    registers = take_task_view(m, 0)
    m.waiting = False
    m.frames = [Frame(routine.index, 0, routine.initial_locals)]
    m.status = RUNNING
    steps = 0
    try:
        while m.frames and m.status == RUNNING:
            run_instruction(m)
            if m.waiting:
                raise EnvironmentFault(f"environment routine {program_routine.name} waits "
                                       "(waits are not allowed in an environment reaction)")
            steps += 1
            if steps > ENVIRONMENT_STEP_LIMIT:
                raise EnvironmentFault(f"environment routine {program_routine.name} did not "
                                       f"finish within {ENVIRONMENT_STEP_LIMIT} steps")
        if m.status == FAILED:
            fault = m.fault
            raise EnvironmentFault(f"environment routine {program_routine.name} stopped with "
                                   f"{_named_fault(fault)}")
    finally:
        give_back(m, 0, registers)
        m.frames = saved_frames
        m.status = saved_status
        m.waiting = saved_waiting
        m.robot = saved_robot


def _named_fault(fault) -> str:
    """``ERR_DIVZERO: division by zero``, the name once."""
    detail = error_detail(fault.errno, fault.message)
    return f"{errno_name(fault.errno)}: {detail}" if detail else errno_name(fault.errno)


class EnvironmentFault(Exception):
    """The environment model itself went wrong (a modelling error, reported to the user)."""


# ---------------------------------------------------------------------------
# Transitions
# ---------------------------------------------------------------------------

def enumerate_choices(run, chooser_factory, time_check=None):
    """Run ``run(chooser)`` once per combination of choices; yield its results.
    ``time_check`` (``CheckConfig.time_check``) is called before each run but the first."""
    script: Optional[list] = []
    while script is not None:
        chooser = chooser_factory(script)
        yield run(chooser)
        script = chooser.next_script()
        if script is not None and time_check is not None:
            time_check()


# The environment's choice at a program stopped by Stop or Break.
OPERATOR_CHOICE = "operator"
OPERATOR_RESTARTS = "restarts the program (Start)"


def final_or_stopped(state: State) -> list[Transition]:
    """The transitions of a state that does not run: an ended or failed program repeats
    forever; a stopped one may stay stopped for ever (first) or the operator restarts it
    at the instruction after the Stop (second)."""
    stay = Transition((), None, state, "")
    if state.status != STOPPED:
        return [stay]
    return [stay, Transition(((OPERATOR_CHOICE, OPERATOR_RESTARTS),), None,
                             state._replace(status=RUNNING), "")]


def successors(program: Program, state: State, config: CheckConfig) -> list[Transition]:
    """Every transition from ``state`` (check mode), in a deterministic order."""
    if state.status != RUNNING:
        return final_or_stopped(state)
    return _at_rest(program, state, config, _driven_successors)


def _driven_successors(program: Program, state: State, config: CheckConfig) -> list:
    """``successors`` by the fastest driver that takes the state, before stored inputs
    no interrupt watches are put at rest (``resting_inputs``)."""
    if is_plain(program, state, config):
        fused = fused_successors(program, state, config)
        return fused if fused is not None else plain_successors(program, state, config)
    if is_staged(program, state, config):
        staged = staged_successors(program, state, config)
        if staged is not None:
            return staged
    return general_driver_successors(program, state, config)


def general_successors(program: Program, state: State, config: CheckConfig) -> list[Transition]:
    """``successors`` through the general driver (every choice script run through ``step``):
    the reference ``plain_successors`` must agree with."""
    if state.status != RUNNING:
        return final_or_stopped(state)
    return _at_rest(program, state, config, general_driver_successors)


def _at_rest(program: Program, state: State, config: CheckConfig, driver) -> list:
    """``driver``'s transitions of ``state`` with the stored inputs no active interrupt
    watches put at rest (``resting_inputs``)."""
    found = driver(program, state, config)
    if config.resting_inputs:
        found = at_rest(state, found, config.resting_inputs,
                        lambda exact: driver(program, exact, config))
    return found


def general_driver_successors(program: Program, state: State, config: CheckConfig) -> list:
    """``general_successors`` before stored inputs no interrupt watches are put at rest:
    what the staged driver must give alike."""
    if config.free_inputs and not _inputs_matter(program, state):
        return edges_at_rest(_successors_inputs_after(program, state, config),
                             config.edge_inputs)
    transitions = list(enumerate_choices(lambda chooser: step(program, state, chooser),
                                         lambda script: ScriptChooser(script, config),
                                         config.time_check))
    if state.tasks:
        transitions, standing = unchosen_dropped(program, state, transitions, config)
        if not config.idle_steps_kept:
            transitions = idle_steps_dropped(state, transitions, standing=standing)
    return edges_at_rest(transitions, config.edge_inputs)


def _inputs_matter(program: Program, state: State) -> bool:
    """Whether this step's behaviour can depend on the free inputs' new values."""
    if state.interrupts.table or state.interrupts.pending or program.environment_reads_io \
            or state.tasks:
        return True
    frame = state.frames[-1]
    return program.routines[frame.routine].code[frame.pc].reads_io


def _successors_inputs_after(program: Program, state: State,
                             config: CheckConfig) -> list[Transition]:
    """The same successors as the general case, for a step that reads no signal.

    The program's behaviour does not depend on the inputs' new values, so the
    step runs once per other choice and every input valuation is applied to
    its result, instead of re-running the step for each valuation.
    """
    inner = list(enumerate_choices(lambda chooser: step(program, state, chooser),
                                   lambda script: ScriptChooser(script, config, inputs=False),
                                   config.time_check))
    config.time_check()                  # the valuations below cost a state each
    result = []
    append = result.append
    for assignments, input_label in zip(config.input_assignments, config.input_labels):
        for label, span, after, output, waiting in inner:
            fields = list(after)
            fields[2] = after.io.mset(*assignments)
            append(Transition(input_label + label, span, State(*fields), output, waiting))
    return result


def step(program: Program, state: State, chooser: Chooser) -> Transition:
    """One transition from ``state`` with the choices ``chooser`` makes."""
    if state.status != RUNNING:
        return Transition((), None, state, "")
    m = Machine(program, state, chooser)
    if chooser.check_mode and chooser.config.lazy_inputs:
        m.io = InputView(m.io, chooser.config.lazy_inputs, m)
        m.lazy_values = {}
    span = execute_step(m)
    if chooser.check_mode and chooser.config.merge_points and m.status == RUNNING:
        span = run_merged(m, chooser.config.merge_table(program), state.frames, span)
    output = "".join(line + "\n" for line in m.output) if m.output else ""
    return Transition(tuple(m.choices), span, m.to_state(), output, m.waiting)


def execute_step(m: Machine):
    """Carry out one transition on the machine ``m``; returns the span executed.

    ``step`` wraps this for immutable states; ``rapidmc run`` calls it on one
    machine for the whole run, so states need not be packed between steps.
    """
    program = m.program
    io_before = m.io
    if m.chooser.check_mode:
        for index, name, domain in m.chooser.free_inputs(program):
            m.io = m.io.set(index, m.choose(name, domain))
    if m.tasks:
        span = _step_some_task(m, io_before)
    else:
        span = _step_task(m, io_before)
    if program.environment_react is not None and m.status == RUNNING:
        io_mid = m.io
        run_environment_routine(m, program.environment_react)
        if m.interrupts.table and m.io != io_mid:
            signal_edges(m, io_mid)
    return span


def _step_task(m: Machine, io_before, task: int = 0):
    """One step of ``task``, whose stack is ``m.frames``: an interrupt it connected may
    start its TRAP on that stack instead of the instruction."""
    interrupts = m.interrupts
    if interrupts.table or interrupts.scheduled or interrupts.pending:
        return _step_with_interrupts(m, io_before, task)
    return run_instruction(m)


def _step_some_task(m: Machine, io_before):
    """Several tasks: one of those still running takes the step (any one when checking,
    in turn when running).  Each task serves the interrupts it connected, on its own
    stack, in its own steps."""
    names = m.program.task_names
    runnable = [i for i, stack in enumerate((m.frames,) + m.tasks) if stack]
    if len(runnable) == 1:
        task = runnable[0]
    else:
        task = names.index(m.choose("task", tuple(names[i] for i in runnable)))
    robots = m.robot
    m.robot = task_robot(m.program, robots, task)      # the task moves its own robot
    if m.program.robot_per_task:
        m.robots = robots                              # (the others' stay as they are)
    registers = take_task_view(m, task)                # its own ERRNO, INTNO, IEnable flag
    if task == 0:
        span = _step_task(m, io_before)
    else:
        main_frames = m.frames
        m.frames = list(m.tasks[task - 1])
        span = _step_task(m, io_before, task)
        if m.status != FAILED:
            tasks = list(m.tasks)
            tasks[task - 1] = tuple(m.frames)
            m.tasks = tuple(tasks)
            m.frames = main_frames
    m.robot = with_task_robot(m.program, robots, task, m.robot)
    m.robots = None
    give_back(m, task, registers)
    if m.status == ENDED and (m.frames or any(m.tasks)):
        m.status = RUNNING               # one task ended; the others go on
    return span


def _step_with_interrupts(m: Machine, io_before, task: int):
    if m.chooser.check_mode and m.interrupts.scheduled:
        apply_scheduled(m)                 # time is abstract: delayed changes happen now
    edge = None
    if m.chooser.check_mode and m.interrupts.table:
        _timers_may_fire(m, task)
        own = own_edges(m.chooser.config)
        if own:                            # their edges: served now or dropped (edge_traps)
            calm = calmed(io_before, m.io, own)
            if calm is not io_before:
                edge = edge_interrupt(m.program, m.interrupts.table, own, io_before, m.io,
                                      task)
                io_before = calm
    span = _execute(m, task, edge)
    if m.interrupts.table and m.io != io_before:
        signal_edges(m, io_before)
    return span


def _execute(m: Machine, task: int, edge: Optional[int] = None):
    """Start the TRAP of interrupt ``edge`` (an edge input's this step brings, ahead of
    those pending: ``edge_traps``), else a pending TRAP of ``task``, or execute the
    instruction at the program counter."""
    program = m.program
    interrupts = m.interrupts
    if (interrupts.pending or edge is not None) and interrupts.enabled and \
            not in_trap(program, m.frames):
        number = edge if edge is not None else next_pending(program, interrupts, task)
        if number is not None:
            m.interrupts = interrupts._replace(
                pending=tuple(n for n in interrupts.pending if n != number))
            entry = next((e for e in interrupts.table if e.number == number), None)
            if entry is not None:
                trap = program.routines[entry.trap]
                m.intno = float(number)
                m.frames.append(Frame(trap.index, 0, trap.initial_locals))
                if entry.source and entry.source[-1] is True and entry.source[0] != "pers":
                    m.interrupts = m.interrupts._replace(
                        table=deactivated(m.interrupts.table, number))
                return trap.span
    return run_instruction(m)


def signal_edges(m: Machine, before) -> None:
    """Signal changes since ``before`` that are an ordered edge queue their interrupt."""
    m.interrupts = signal_edges_pending(m.interrupts, before, m.io)


def _timers_may_fire(m: Machine, task: int) -> None:
    program = m.program
    for entry in m.interrupts.table:
        if entry.active and entry.source and entry.source[0] == "timer" and \
                entry.number not in m.interrupts.pending and \
                interrupt_task(program, entry) == task:
            if m.choose(f"timer {entry.number}", (False, True)):
                enqueue(m, entry.number)
