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

import itertools
from typing import Optional

from pyrsistent import pvector

from .errors import RapidError, errno_name
from .errors_flow import deliver_error
from .instructions import ReRaise
from .machine import Machine
from .program import Program
from .state import ENDED, FAILED, RUNNING, Frame, Interrupts, State, Transition
from .lazy_inputs import InputView
from .timing import apply_scheduled, enqueue

ENVIRONMENT_STEP_LIMIT = 100_000

HOME_TARGET = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0),
               (9e9, 9e9, 9e9, 9e9, 9e9, 9e9))
HOME_JOINTS = ((0.0,) * 6, (9e9,) * 6)


class Chooser:
    """Base chooser: how a step resolves nondeterminism and time."""

    check_mode = False

    def choose(self, name: str, domain: tuple, position: int):
        return domain[0]

    def tp_answers(self, kind: str) -> tuple:
        raise NotImplementedError

    def wait_times_out(self, m: Machine, max_time: float) -> bool:
        return False

    def advance_time(self, m: Machine, seconds: float) -> None:
        pass

    def free_inputs(self, program: Program) -> tuple:
        return ()


class ScriptChooser(Chooser):
    """Check mode: follows a script of choice indices, records the domain sizes met."""

    check_mode = True

    def __init__(self, script: list, config: "CheckConfig", inputs: bool = True):
        self.script = script
        self.sizes: list[int] = []
        self.config = config
        self.inputs = inputs

    def choose(self, name: str, domain: tuple, position: int):
        self.sizes.append(len(domain))
        if position < len(self.script):
            return domain[self.script[position]]
        return domain[0]

    def tp_answers(self, kind: str) -> tuple:
        if kind == "TPReadFK":
            return self.config.fk_answers
        return self.config.tp_answers

    def wait_times_out(self, m: Machine, max_time: float) -> bool:
        return m.choose("timeout", (False, True))

    def free_inputs(self, program: Program) -> tuple:
        return self.config.free_inputs if self.inputs else ()

    def next_script(self) -> Optional[list]:
        script = list(self.script) + [0] * (len(self.sizes) - len(self.script))
        for i in range(len(self.sizes) - 1, -1, -1):
            if script[i] + 1 < self.sizes[i]:
                return script[:i] + [script[i] + 1]
        return None


class CheckConfig:
    """Model-checking choices: answer domains and which inputs are free."""

    def __init__(self, program: Program, tp_answers=(1.0, 2.0, 3.0),
                 fk_answers=(1.0, 2.0, 3.0, 4.0, 5.0), input_domains: Optional[dict] = None,
                 observed: Optional[set] = None):
        """``observed``: indices of the free inputs properties look at; the others are
        chosen when read (see lazy_inputs).  None: every free input is stored."""
        self.tp_answers = tuple(float(a) for a in tp_answers)
        self.fk_answers = tuple(float(a) for a in fk_answers)
        domains = input_domains or {}
        free = []
        lazy = {}
        for signal in program.signals:
            if signal.driven or not signal.kind.endswith("I"):
                continue
            if signal.kind == "DI":
                domain = (0.0, 1.0)
            elif signal.key in domains:
                domain = tuple(domains[signal.key])
            else:
                continue
            if observed is None or signal.index in observed:
                free.append((signal.index, signal.name, domain))
            else:
                lazy[signal.index] = (signal.name, domain)
        self.free_inputs = tuple(free)
        self.lazy_inputs = lazy
        # (routine, pc) -> visible, for instructions that join the step before them
        # (reduction.merging); empty: one instruction per step
        self.merge_points: dict = {}
        # every combination of free input values, in the order the chooser enumerates them
        self.input_valuations = tuple(itertools.product(*(d for _, _, d in free)))
        # per valuation: pvector.mset arguments and the label part naming the values
        self.input_assignments = tuple(
            tuple(x for (index, _, _), value in zip(free, valuation) for x in (index, value))
            for valuation in self.input_valuations)
        self.input_labels = tuple(
            tuple((name, value) for (_, name, _), value in zip(free, valuation))
            for valuation in self.input_valuations)


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
            io[signal.index] = float(value)
    main = program.routines[program.entry]
    robot = (HOME_TARGET, _predefined(program, "TOOL0"), _predefined(program, "WOBJ0"),
             HOME_JOINTS)
    tasks = tuple((Frame(entry, 0, program.routines[entry].initial_locals),)
                  for entry in program.task_entries)
    return State((Frame(main.index, 0, main.initial_locals),), initial_store(program),
                 pvector(io), robot, Interrupts(), tasks=tasks)


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
                                   f"{errno_name(fault.errno)}: {fault.message}")
    finally:
        m.frames = saved_frames
        m.status = saved_status
        m.waiting = saved_waiting


class EnvironmentFault(Exception):
    """The environment model itself went wrong (a modelling error, reported to the user)."""


# ---------------------------------------------------------------------------
# Transitions
# ---------------------------------------------------------------------------

def enumerate_choices(run, chooser_factory):
    """Run ``run(chooser)`` once per combination of choices; yield its results."""
    script: Optional[list] = []
    while script is not None:
        chooser = chooser_factory(script)
        yield run(chooser)
        script = chooser.next_script()


def successors(program: Program, state: State, config: CheckConfig) -> list[Transition]:
    """Every transition from ``state`` (check mode), in a deterministic order."""
    if state.status != RUNNING:
        return [Transition((), None, state, "")]
    if config.free_inputs and not _inputs_matter(program, state):
        return _successors_inputs_after(program, state, config)
    transitions = list(enumerate_choices(lambda chooser: step(program, state, chooser),
                                         lambda script: ScriptChooser(script, config)))
    if state.tasks:
        transitions = _no_idle_task_steps(state, transitions)
    return transitions


def _no_idle_task_steps(state: State, transitions: list[Transition]) -> list[Transition]:
    """Tasks share the controller fairly: a task whose step changes nothing (it waits)
    does not take the turn from a task that can go on.  If no task can go on, every
    idle step stays (the program may be deadlocked)."""
    def task_of(transition):
        return next((value for name, value in transition.label if name == "task"), None)

    moving = {task_of(t) for t in transitions if t.state != state}
    if not moving:
        return transitions
    return [t for t in transitions
            if t.state != state or not (moving - {task_of(t)})]


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
                                   lambda script: ScriptChooser(script, config, inputs=False)))
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
        span = _run_merged(m, chooser.config.merge_points, state.frames, span)
    output = "".join(line + "\n" for line in m.output) if m.output else ""
    return Transition(tuple(m.choices), span, m.to_state(), output, m.waiting)


MERGED_STEP_LIMIT = 10_000


def _run_merged(m: Machine, points: dict, frames_before: tuple, span):
    """Go on executing merge points (see ``reduction.merging``) within this transition.

    ``points`` maps a routine index to one kind per pc: 0 invisible, 1
    visible, 2 invisible loop head (never joins), 3 never joins.  At most
    one visible instruction runs per transition (the first one counts as
    visible unless it is of kind 0 or 2), and no instruction that may read
    a signal joins once a choice was made (each combination of choices
    re-runs the whole transition).  Loop heads never join, so the program
    counter only grows while merging.  Returns the span of the step, or
    the tuple of every span executed when more than one instruction ran.
    Stops as soon as the program waits, stops, raises, calls or returns,
    or has interrupts or tasks.
    """
    if not frames_before:
        return span
    frame = frames_before[-1]
    kinds = points.get(frame[0])
    seen_visible = kinds is None or kinds[frame[1]] in (1, 3)
    spans = [span]
    errno = m.errno
    depth = len(m.frames)                # calls and returns never join: it stays
    routines = m.program.routines
    for _ in range(MERGED_STEP_LIMIT):
        frames = m.frames
        if m.status != RUNNING or m.waiting or m.tasks or m.errno != errno or \
                len(frames) != depth:
            break
        interrupts = m.interrupts
        if interrupts.table or interrupts.pending or interrupts.scheduled:
            break
        frame = frames[-1]
        kinds = points.get(frame[0])
        if kinds is None:
            break
        kind = kinds[frame[1]]
        if kind >= 2 or frame[3] != 0 or (kind == 1 and seen_visible):
            break
        if m.choices and routines[frame[0]].code[frame[1]].reads_io:
            break                            # one choice point per transition (as in SPIN)
        if kind == 1:
            seen_visible = True
        if m.lazy_values is not None:
            m.lazy_values = {}               # each instruction reads inputs afresh
        spans.append(run_instruction(m))
    return spans[0] if len(spans) == 1 else tuple(spans)


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
        span = _step_main_task(m, io_before)
    if program.environment_react is not None and m.status == RUNNING:
        io_mid = m.io
        run_environment_routine(m, program.environment_react)
        if m.interrupts.table and m.io != io_mid:
            signal_edges(m, io_mid)
    return span


def _step_main_task(m: Machine, io_before):
    interrupts = m.interrupts
    if interrupts.table or interrupts.scheduled or interrupts.pending:
        return _step_with_interrupts(m, io_before)
    return run_instruction(m)


def _step_some_task(m: Machine, io_before):
    """Several tasks: one of those still running takes the step (any one when checking,
    in turn when running).  Interrupts are served in the main task."""
    names = m.program.task_names
    runnable = [i for i, stack in enumerate((m.frames,) + m.tasks) if stack]
    if len(runnable) == 1:
        task = runnable[0]
    else:
        task = names.index(m.choose("task", tuple(names[i] for i in runnable)))
    if task == 0:
        span = _step_main_task(m, io_before)
    else:
        main_frames = m.frames
        m.frames = list(m.tasks[task - 1])
        span = run_instruction(m)
        if m.status != FAILED:
            tasks = list(m.tasks)
            tasks[task - 1] = tuple(m.frames)
            m.tasks = tuple(tasks)
            m.frames = main_frames
    if m.status == ENDED and (m.frames or any(m.tasks)):
        m.status = RUNNING               # one task ended; the others go on
    return span


def _step_with_interrupts(m: Machine, io_before):
    if m.chooser.check_mode and m.interrupts.scheduled:
        apply_scheduled(m)                 # time is abstract: delayed changes happen now
    if m.chooser.check_mode and m.interrupts.table:
        _timers_may_fire(m)
    span = _execute(m)
    if m.interrupts.table and m.io != io_before:
        signal_edges(m, io_before)
    return span


def _execute(m: Machine):
    """Start a pending TRAP, or execute the instruction at the program counter."""
    program = m.program
    interrupts = m.interrupts
    if interrupts.pending and interrupts.enabled and not _in_trap(m):
        number = interrupts.pending[0]
        m.interrupts = interrupts._replace(pending=interrupts.pending[1:])
        entry = next((e for e in interrupts.table if e.number == number), None)
        if entry is not None:
            trap = program.routines[entry.trap]
            m.intno = float(number)
            m.frames.append(Frame(trap.index, 0, trap.initial_locals))
            if entry.source and entry.source[-1] is True and entry.source[0] != "pers":
                _deactivate(m, number)
            return trap.span
    return run_instruction(m)


def run_instruction(m: Machine):
    """Execute the instruction at the program counter; errors go to their handler."""
    frame = m.frames[-1]
    instruction = m.program.routines[frame.routine].code[frame.pc]
    try:
        instruction.run(m)
    except RapidError as exc:
        deliver_error(m, exc.errno, str(exc))
    except ReRaise as exc:
        deliver_error(m, exc.errno, errno_name(exc.errno), from_handler=True)
    return instruction.span


def _in_trap(m: Machine) -> bool:
    routines = m.program.routines
    return any(routines[f.routine].kind == "TRAP" for f in m.frames)


def _deactivate(m: Machine, number: int) -> None:
    m.interrupts = m.interrupts._replace(table=tuple(
        e._replace(active=False) if e.number == number else e for e in m.interrupts.table))


def signal_edges(m: Machine, before) -> None:
    for entry in m.interrupts.table:
        source = entry.source
        if not entry.active or not source or source[0] != "signal":
            continue
        _, index, trigger, _ = source
        old, new = before[index], m.io[index]
        if old == new:
            continue
        if trigger == 2 or (trigger == 1 and new == 1) or (trigger == 0 and new == 0):
            enqueue(m, entry.number)


def _timers_may_fire(m: Machine) -> None:
    for entry in m.interrupts.table:
        if entry.active and entry.source and entry.source[0] == "timer" and \
                entry.number not in m.interrupts.pending:
            if m.choose(f"timer {entry.number}", (False, True)):
                enqueue(m, entry.number)
