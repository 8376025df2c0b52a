"""A RAPID program (with its environment) as a transition system for the checker.

``RapidSystem`` adapts the semantics (``semantics.step``) to the engine's
``TransitionSystem`` protocol: states are semantic ``State`` values, labels
are ``(choices, span, output)``.  ``RapidDescriber`` turns states and
labels into what a robot programmer reads in a counterexample, and
``replay`` re-executes a counterexample through the step function before it
is printed.
"""
from __future__ import annotations

import copy
import re
from typing import Hashable, Mapping, Optional, Sequence

from pyrsistent import pvector

from .. import ast
from ..check import TransitionInfo
from ..check.native import native_search
from ..check.trace import CallFrame
from ..check.result import LassoStep, SearchResult, TaskPlace
from ..diagnostics import TRACE_REPLAY, SourceCache, error
from ..load.stubs.module_text import is_stub_module
from ..semantics.program import (ENVIRONMENT_NAMESPACE,
                                PROGRAM_NAMESPACE, Program)
from ..semantics.robots import ROBOT_TCP, task_namespace
from ..semantics.scope import LOCAL_DATA
from ..semantics.types import POS, ArrayType
from ..semantics.library.tasks import SyncWait
from ..semantics.state import ENDED, FAILED, RUNNING, STOPPED, State
from ..semantics.task_registers import ERRNO_NAME
from ..semantics.plain_step import is_plain
from ..semantics.step import (OPERATOR_CHOICE, CheckConfig, ScriptChooser, initial_states,
                             successors)
from ..semantics.fused_step import plain_successor_states, stop_pcs, written_globals
from ..semantics.values import format_num, format_value
from ..semantics.errors import errno_name, error_detail
from ..semantics.resting_inputs import AT_REST
from .reduction import NO_PLAN, Plan
from .kept_successors import KeptSuccessors
from .state_keys import StateKeys
from .task_atoms import task_qualifier
from .task_waits import WHOLE_PROGRAM, TaskWaits
from .value_text import DESCRIBED_TYPES, OPAQUE_KINDS, untyped_text, value_text
from .reduction.expansion import expand_lasso
from .reduction.merging import executed_spans
from .reduction.partial_order import PartialOrder, StatePlaces


_new_tuple = tuple.__new__
RESTING_TEXT = "0 or 1 (no interrupt watches it: not stored)"
_last_split_store: tuple = (None, ())     # (a global data vector, it as a tuple)


class RapidSystem:
    """The program's state graph, explored lazily.

    Successors of states that take the general step (environment models,
    tasks, interrupts, stored inputs) are remembered (up to ``shared_limit``
    states; as node ids, ``kept_successors``) so that the searches for several
    properties of one program compute them once.  Plain states (``semantics.plain_step``) are not: their
    successors cost less to compute again than to hash, keep and have the
    garbage collector scan (counters N=6, ``rapidmc check``: 3.3 s remembered,
    2.2 s not).  A reduction ``plan`` (``rapidmc.model.reduction``) resets
    sliced data in every state and merges steps; ``unreduced()`` is the
    same system without it (for replaying counterexamples in full).
    """

    shared_limit = 100_000

    def __init__(self, program: Program, config: CheckConfig, plan: Plan = NO_PLAN):
        self.program = program
        self.plain_config = config
        skipped = plan.slicing.total_writes if plan.projection is not None else frozenset()
        if plan.merge_points != config.merge_points or skipped != config.skipped_writes:
            config = copy.copy(config)
            config.merge_points = plan.merge_points
            config.skipped_writes = skipped
        self.config = config
        self._task_waits: Optional[TaskWaits] = None    # (made when first asked)
        self.plan = plan
        self.project = plan.projection
        # the projection of the fused step's targets (None where they are projected
        # already: the writes it would undo are the ones the step skips)
        self.project_fused = self.project
        if self.project is not None and self.project.keeps_fused_targets(
                set(plan.slicing.globals), written_globals(program, config.skipped_writes),
                stop_pcs(program.routines[program.entry])):
            self.project_fused = None
        # successors kept for the next searches (one per property) over the same program
        self._shared = KeptSuccessors(self.split_state, self.join_state)
        self._keys = StateKeys()
        self.order = plan.order          # ample sets between tasks (reduction.partial_order)
        if getattr(self.order, "keys", None) is not None:
            # (its proviso keys the very states this cache does: one memory of their parts)
            self.order.keys = self._keys
        if isinstance(self.order, PartialOrder):
            self.order.places_made = self._reduction_places
        self._full: Optional["RapidSystem"] = None      # see full_interleaving

    @staticmethod
    def split_state(state: State) -> tuple:
        """The parts stored separately (``check.states``): the call stack, global data (as
        a tuple: smaller than a persistent vector), signals, robot, interrupts, and the rest
        (ERRNO ... further tasks).  Signals stay a vector: they rarely change, and a vector
        handed on unchanged is found by identity.  The global data of the state split
        last are given as the same tuple while its vector is handed on (a state's
        successors, split by the table and the kept successors: found by identity)."""
        global _last_split_store
        store = state[1]
        last = _last_split_store
        if last[0] is not store:
            last = _last_split_store = (store, tuple(store))
        return (state[0], last[1], state[2], state[3], state[4], state[5:])

    @staticmethod
    def join_state(parts: tuple) -> State:
        return _new_tuple(State, (parts[0], pvector(parts[1])) + parts[2:5] + parts[5])

    def packed_table(self):
        """A state table of packed states whose fused steps the compiled core runs
        (``model.packed``), or None when the core is not built or cannot take them."""
        from .packed.table import packed_table
        return packed_table(self)

    def _reduction_places(self):
        """Where the partial-order reduction's proviso numbers states: in a packed table
        that every search of the check shares when the compiled core searches now and its
        step machine takes the system's steps (``packed.table.reduced_packing``), else by
        key in Python (``StatePlaces``)."""
        from .packed.table import reduced_packing
        places = reduced_packing(self) if native_search() else None
        return places if places is not None else StatePlaces(self._keys)

    def unreduced(self) -> "RapidSystem":
        """The same program and configuration without reductions."""
        if not self.plan.active:
            return self
        config = copy.copy(self.plain_config)
        config.merge_points = {}
        return RapidSystem(self.program, config)

    def full_interleaving(self) -> "RapidSystem":
        """This system with every interleaving of the tasks' steps (no ample sets; a
        task's step still runs on through its local instructions, ``local_runs``, as in
        the reduced search, whose paths are rebuilt here)."""
        if self.order is None or self.order is self.order.every_order():
            return self
        if self._full is None:
            self._full = copy.copy(self)
            self._full.order = self.order.every_order()
            self._full._shared = KeptSuccessors(self.split_state, self.join_state)
            self._full._keys = StateKeys()
        return self._full

    def path_system(self) -> "RapidSystem":
        """Where the checker rebuilds paths through stored states (``check.transition_system``):
        the full interleaving.  Ample sets depend on the states expanded before (their
        proviso), so asking this system again after the search may give another task's
        steps than the search took from that state."""
        return self.full_interleaving()

    def initial_states(self) -> list[State]:
        states = initial_states(self.program, lambda script: ScriptChooser(script, self.config))
        if self.config.start_targets and not self.program.robot_per_task:
            # a coverage probe's robot may also start at a target the program names
            # (findings.start_positions): only the TCP, the rest as at home
            states = list(dict.fromkeys(
                start._replace(robot=(target,) + tuple(start.robot[1:]))
                for start in states for target in (start.robot[0],) + self.config.start_targets))
        project = self.project
        return states if project is None else list(dict.fromkeys(map(project, states)))

    def successors(self, state: State, keep: bool = True) -> list[tuple[Hashable, State]]:
        """The labelled successors of ``state``; ``keep`` False: none kept or looked up
        for the next searches (a caller that keeps them itself: a packed table's rows,
        ``packed.table.reduced_packing``)."""
        # (plain states are never kept: see the class docstring)
        kept = keep and not is_plain(self.program, state, self.config)
        if kept:
            found = self._shared.get(state)
            if found is not None:
                return found
        transitions = successors(self.program, state, self.config)
        project = self.project
        if project is None:
            result = [((label, span, output), after)
                      for label, span, after, output, _ in transitions]
        else:
            result = [((label, span, output), project(after))
                      for label, span, after, output, _ in transitions]
        if self.order is not None:
            result = self.order.ample(state, result, self.config)
        if kept and len(self._shared) < self.shared_limit:
            self._shared.keep(state, result, self)
        return result

    def successor_states(self, state: State, keep: bool = True) -> list[State]:
        """The states of ``successors(state, keep)``, in order, without their labels: what
        the search stores (built faster at plain states, ``plain_successor_states``, which
        skips the writes to sliced data the projection resets anyway)."""
        found = plain_successor_states(self.program, state, self.config)
        if found is None:
            return [after for _, after in self.successors(state, keep)]
        project = self.project_fused
        return found if project is None else [project(after) for after in found]

    # built-in safety checks ------------------------------------------------
    @staticmethod
    def failed(state: State) -> bool:
        return state.status == FAILED

    def stuck(self, state: State) -> bool:
        """The program runs but no step can change anything but free inputs: it waits forever.

        Free inputs are chosen before each step, so if some input values let
        the program go on, the successor with those values differs in more
        than the inputs.
        """
        return self.stuck_among(state, self.successors(state))

    def stuck_among(self, state: State, found: Sequence) -> bool:
        """``stuck(state)`` given ``found``, the state's successors (as ``successors`` gives)."""
        return self.stuck_at(state, [after for _, after in found])

    def stuck_at(self, state: State, targets: Sequence[State]) -> bool:
        """``stuck(state)`` given ``targets``, its successor states (``successor_states``)."""
        if state.status != RUNNING:
            return False
        if state[10] and self.blocked_at_barrier(state):
            return True
        # a successor whose call stack or data differ is not a state with other inputs:
        # decided without masking the inputs of every successor (the usual case)
        frames, store = state[0], state[1]
        for after in targets:
            if after[0] is not frames and after[0] != frames or \
                    after[1] is not store and after[1] != store:
                return False
        return self._same_but_inputs(state, targets)

    def blocked_at_barrier(self, state: State) -> list[tuple[int, list[str]]]:
        """(task, the ended tasks it waits for) per task at a barrier (WaitSyncTask,
        SyncMoveOn/Off) that waits for a task that has ended: it waits forever, whatever
        the others do."""
        stacks = (state[0],) + state[10]
        names = self.program.task_names
        blocked = []
        for task, waiting_for in barrier_waits(self.program, state, timeouts=False):
            ended = [name for name in waiting_for if not stacks[names.index(name)]]
            if ended:
                blocked.append((task, ended))
        return blocked

    def task_places(self, state: State) -> tuple:
        """Where each task stands in ``state`` (``TaskPlace``), in task order."""
        places = []
        for name, stack in zip(self.program.task_names, (state[0],) + state[10]):
            if not stack:
                places.append(TaskPlace(name, "", "", 0, ""))
                continue
            routine = self.program.routines[stack[-1].routine]
            span = _frame_span(routine, stack[-1].pc)
            places.append(TaskPlace(name, routine.name, span.file, span.line,
                                    (SourceCache.line(span.file, span.line) or "").strip()))
        return tuple(places)

    def describe_waits(self, state: State, only: Optional[set] = None) -> Optional[str]:
        """Which task waits where, and for which tasks, in a state where the program waits
        forever (None for a program of one task: its trace says it).  ``only``: the tasks
        to name (default: those blocked at a barrier, else every running task)."""
        names = self.program.task_names
        if len(names) == 1:
            return None
        stacks = (state[0],) + state[10]
        barriers = dict(barrier_waits(self.program, state))
        if only is None:
            only = {task for task, _ in self.blocked_at_barrier(state)} or set(range(len(names)))
        parts = []
        for task, place in enumerate(self.task_places(state)):
            if not place.routine or task not in only:
                continue
            part = f"{place.task} waits at {place.file}:{place.line} ({place.statement})"
            if task in barriers:
                part += " for " + ", ".join(
                    f"{name} (ended)" if not stacks[names.index(name)] else name
                    for name in barriers[task])
            parts.append(part)
        return "waits forever: " + "; ".join(parts) if parts else None

    def _same_but_inputs(self, state: State, targets: Sequence[State]) -> bool:
        """Whether every successor of the running ``state`` is ``state`` with other free
        inputs (and, with merged steps, every single instruction's too), and so is every
        successor of those: every valuation is one step away, and from another one an
        interrupt's edge may come (``ISignalDI di, 1``: with ``di`` stored at 1, it must
        go back to 0 first).  ``task_waits`` decides what the environment changes, for
        the whole program: only the inputs (every interrupt queued is some task's)."""
        waits = self._task_waits
        if waits is None or waits.config is not self.config:
            waits = self._task_waits = TaskWaits(self.program, self.config)
        if not self._stays(state, state, targets, waits):
            return False
        if not state[4][0]:
            return True
        return all(self._stays(state, after, self.successor_states(after), waits)
                   for after in dict.fromkeys(targets) if after != state)

    def _stays(self, origin: State, state: State, targets: Sequence[State],
               waits: TaskWaits) -> bool:
        """Whether ``targets``, the successors of ``state``, are all ``origin`` with other
        free inputs (and, with merged steps, every single instruction's too)."""
        if any(waits.own_change(WHOLE_PROGRAM, origin, after) for after in targets):
            return False
        if not self.config.merge_points and (self.order is None or self.order.runs is None):
            return True
        # A merged step (or a task's local run, ``reduction.local_runs``) that changes nothing may still run around a loop (a busy wait):
        # decide on single instructions, as the unmerged semantics does.  (A merged step
        # that changes something starts with a single step that does.)
        project = self.project or (lambda s: s)
        return not any(waits.own_change(WHOLE_PROGRAM, origin, project(t.state))
                       for t in successors(self.program, state, self.plain_config))


def barrier_waits(program: Program, state: State,
                  timeouts: bool = True) -> list[tuple[int, list[str]]]:
    """(task, the tasks it waits for) per task whose next instruction is a barrier that
    not every task of its list has reached (``timeouts``: barriers with \\TimeOut too)."""
    found = []
    for task, stack in enumerate((state[0],) + state[10]):
        if not stack:
            continue
        frame = stack[-1]
        instruction = program.routines[frame[0]].code[frame[1]]
        if isinstance(instruction, SyncWait) and (timeouts or not instruction.times_out):
            missing = instruction.missing(state[1], task)
            if missing:
                found.append((task, missing))
    return found


def _shown(rapid_type) -> bool:
    """Whether data of this type has a value to show: not a signal, clock, syncident ...,
    but a socket or an I/O device, whose state RAPID names (``<socketdev: connected>``)."""
    element = rapid_type.element if isinstance(rapid_type, ArrayType) else rapid_type
    return getattr(element, "kind", "") not in OPAQUE_KINDS or \
        getattr(element, "key", "") in DESCRIBED_TYPES


def _local_types(routine) -> dict:
    """The declared type of each frame slot of ``routine``'s parameters and data (a FOR
    variable or a temporary has none: it shows by what it holds)."""
    scope = getattr(routine, "scope", None)
    if scope is None:
        return {}
    return {symbol.slot: symbol.type for symbol in scope.names.values()
            if symbol.kind == LOCAL_DATA and symbol.type is not None}


# statements a run may leave for the one after them, with steps between that a
DATA_CHOICE = re.compile(r"[^.{]*")    # the datum a choice of a datum's value names

# counterexample may tell in one line (``RapidDescriber.compound_exits``)
COMPOUNDS = (ast.If, ast.For, ast.While, ast.Test)


class RapidDescriber:
    """Printable views of states and transitions, in RAPID terms."""

    # the program's status is in a view only while it is not running: a restart after
    # Stop changes it back to this
    absent_values = {"program": "running"}

    def __init__(self, program: Program, config: Optional[CheckConfig] = None):
        self.program = program
        lazy = config.lazy_inputs if config is not None else {}
        # inputs chosen when read are not stored: their values show in the step's inputs
        self.signals = [s for s in program.signals if s.index not in lazy]
        self.resting = config.resting_inputs if config is not None else {}
        self.several_tasks = len(program.task_names) > 1
        self.globals = [(g.slot, self._qualified(g), g.type) for g in program.globals
                        if g.namespace == PROGRAM_NAMESPACE and _shown(g.type)]
        self.environment = [(g.slot, self._qualified(g), g.type) for g in program.globals
                            if g.namespace != PROGRAM_NAMESPACE and _shown(g.type)]
        self._declared_in = {g.slot: g.span.file if g.span else None for g in program.globals}
        self._stub_data: Optional[frozenset] = None
        self._texts: dict[int, tuple] = {}      # slot -> (value, its text), the latest
        self._slot_types: dict[int, dict] = {}  # routine index -> its frame slots' types
        self._compound_exits: Optional[dict] = None
        self._data_names: Optional[frozenset] = None

    def _local_types(self, routine) -> dict:
        types = self._slot_types.get(routine.index)
        if types is None:
            types = self._slot_types[routine.index] = _local_types(routine)
        return types

    def _qualified(self, data) -> str:
        """env.name for environment data; on a controller of several tasks <task>.name for a
        task's own data, as atoms name it (shared PERS data keeps its plain name)."""
        if data.namespace == ENVIRONMENT_NAMESPACE:
            return f"env.{data.name}"
        if not self.several_tasks or (data.storage == "PERS" and not data.task_local):
            return data.name
        return f"{self._task_name(data.namespace)}.{data.name}"

    def _task_name(self, namespace: int) -> str:
        return task_qualifier(self.program, namespace)

    def _signal_text(self, value, rapid_type) -> Optional[str]:
        """``<signaldo: doReady>`` for a signal parameter: the signal its caller passed (it
        holds the signal's index), so that a wait in a helper routine (``WaitDO s, 1``)
        says which signal it waits for; None for other data."""
        if not getattr(rapid_type, "signal_kind", "") or isinstance(value, bool) or \
                not isinstance(value, (int, float)) or not 0 <= value < len(self.program.signals):
            return None
        return f"<{rapid_type.name}: {self.program.signals[int(value)].name}>"

    def _text(self, value, slot: int, rapid_type) -> str:
        """``value_text`` of a global's value, kept while the state holds the very same value
        (consecutive states share most of their data: big arrays are written out once)."""
        kept = self._texts.get(slot)
        if kept is not None and kept[0] is value:
            return kept[1]
        text = value_text(value, rapid_type)
        self._texts[slot] = (value, text)
        return text

    @property
    def stub_data(self) -> frozenset:
        """The shown names of data declared by a module of ``rapidmc stubs`` (a stub's value)."""
        if self._stub_data is None:
            stubs = {file for file in {g.span.file for g in self.program.globals if g.span}
                     if is_stub_module(file)}
            self._stub_data = frozenset(name for slot, name, _ in self.globals + self.environment
                                        if self._declared_in[slot] in stubs)
        return self._stub_data

    @property
    def handler_starts(self) -> frozenset:
        """(file, line) of the first statement of every ERROR handler: a step that the next
        step follows there raised an error (a counterexample keeps it shown)."""
        starts = set()
        for routine in self.program.routines:
            if 0 <= routine.handler_pc < len(routine.code):
                span = routine.code[routine.handler_pc].span
                if span is not None:
                    starts.add((span.file, span.line))
        return frozenset(starts)

    @property
    def compound_exits(self) -> Mapping[tuple, tuple]:
        """{(file, line) of an IF, FOR, WHILE or TEST: (its last line, (file, line) of the
        statement after it)} for each such statement that another follows in its statement
        list: a run that goes from the one to the other left it without a jump, so the
        steps between decided nothing but what they wrote (a counterexample may tell them
        in one line)."""
        if self._compound_exits is None:
            exits = {}
            for routine in self.program.routines:
                if routine.ast is None:
                    continue
                parts = (routine.ast.body, routine.ast.backward, routine.ast.undo,
                         routine.ast.error.body if routine.ast.error is not None else None)
                for statements in (listed for part in parts if part
                                   for listed in ast.statement_lists(part)):
                    for statement, after in zip(statements, statements[1:]):
                        span, next_span = statement.span, after.span
                        if isinstance(statement, COMPOUNDS) and span.end_line and \
                                next_span.line > span.end_line:
                            exits[(span.file, span.line)] = \
                                (span.end_line, (next_span.file, next_span.line))
            self._compound_exits = exits
        return self._compound_exits

    def describe_state(self, state: State) -> Mapping[str, str]:
        view: dict[str, str] = {}
        store = state.store
        for slot, name, rapid_type in self.globals:
            view[name] = self._text(store[slot], slot, rapid_type)
        stacks = (state.frames,) + state.tasks
        for frame in (frame for stack in stacks for frame in stack):
            routine = self.program.routines[frame.routine]
            # a name several slots share means the FOR counter whose loop the frame is in
            # (the raising statement's, in an ERROR handler), else the routine data
            hidden = routine.hidden_slots(frame.error_pc if frame.mode and frame.error_pc >= 0
                                           else frame.pc)
            for slot, (name, value) in enumerate(zip(routine.local_names, frame.locals)):
                if name.startswith("<") or slot in hidden:
                    continue                       # FOR bounds, temporaries, shadowed names
                if isinstance(value, tuple) and len(value) == 3 and isinstance(value[0], int) \
                        and isinstance(value[2], tuple):
                    continue                       # a reference parameter
                rapid_type = self._local_types(routine).get(slot)
                view[self._routine_prefix(routine) + name] = untyped_text(value) \
                    if rapid_type is None else self._signal_text(value, rapid_type) or \
                    value_text(value, rapid_type)
        for signal in self.signals:
            value = state.io[signal.index]
            # (a stored input no interrupt watches: ``semantics.resting_inputs``)
            view[f"signal {signal.name}"] = RESTING_TEXT if value == AT_REST and \
                signal.index in self.resting else format_num(value)
        if self.program.robot_per_task:        # each motion task's robot (semantics.robots)
            for number in self.program.motion_tasks:
                name = self._task_name(task_namespace(number))
                view[f"{name}.{ROBOT_TCP}"] = value_text(state.robot[number][0][0], POS)
        else:
            view[ROBOT_TCP] = value_text(state.robot[0][0], POS)
        for slot, name, rapid_type in self.environment:
            view[name] = self._text(store[slot], slot, rapid_type)
        if self.program.registers_per_task:  # each task's own (semantics.task_registers)
            for number, errno in enumerate(state.errno):
                if errno:
                    name = self._task_name(task_namespace(number))
                    view[f"{name}.{ERRNO_NAME}"] = errno_name(int(errno))
        elif state.errno:
            view[ERRNO_NAME] = errno_name(int(state.errno))
        if state.status == ENDED:
            view["program"] = "ended"
        elif state.status == STOPPED:
            view["program"] = "stopped by Stop/Break (the operator may restart it)"
        elif state.status == FAILED:
            view["program"] = f"stopped: {fault_text(state.fault)}"
        return view

    def _routine_prefix(self, routine) -> str:
        """``main.`` for routine data; ``T_ROB2.main.`` on a controller of several tasks."""
        if self.several_tasks and routine.namespace != ENVIRONMENT_NAMESPACE:
            return f"{self._task_name(routine.namespace)}.{routine.name}."
        return f"{routine.name}."

    def describe_stack(self, state: State) -> tuple[CallFrame, ...]:
        """Every task's active routines, outermost first, each at its next statement; on a
        controller of several tasks each frame names its task as the data do (``T_ROB2``,
        ``TASK2``: ``task_qualifier``)."""
        stacks = (state.frames,) + state.tasks
        named = len(stacks) > 1
        frames = []
        for number, stack in enumerate(stacks):
            task = self._task_name(task_namespace(number)) if named else ""
            for frame in stack:
                routine = self.program.routines[frame.routine]
                span = _frame_span(routine, frame.pc)
                frames.append(CallFrame(routine.name, span.file, span.line, task))
        return tuple(frames)

    def source_lines(self) -> dict[str, tuple[str, ...]]:
        """The lines of every source file of the program and its environment, in link order."""
        spans = [r.span for r in self.program.routines] + \
                [g.span for g in self.program.globals]
        files = dict.fromkeys(span.file for span in spans if span is not None and span.file)
        sources = {}
        for file in files:
            lines = SourceCache.lines(file)
            if lines is not None:
                sources[file] = lines
        return sources

    def _data_choice(self, name: str) -> bool:
        """Whether the choice ``name`` is a read of the program's data (``stCommand``,
        ``nRunningStep{*}``, ``pk.code``), whose strings are values, not names."""
        if self._data_names is None:
            self._data_names = frozenset(g.name for g in self.program.globals)
        return DATA_CHOICE.match(name).group(0) in self._data_names

    def describe_transition(self, label, at_last: bool = False) -> TransitionInfo:
        """What a transition did; a merged step is shown at its first statement, or with
        ``at_last`` at its last one (the statement that raised the error a path ends in)."""
        choices, span, output = label
        inputs = {name: _choice_text(value, self._data_choice(name)) for name, value in choices}
        spans = executed_spans(span)
        span = spans[-1] if at_last else spans[0]
        if span is None:
            source = "(the program has stopped: this state repeats forever)" if not choices \
                else "(the program continues after the Stop)" if inputs.get(OPERATOR_CHOICE) \
                else ""
            return TransitionInfo(None, None, source, inputs, output)
        source = _statement_text(span)
        statements = tuple(_whole_statement(s) for s in spans)
        if statements == (source,):
            statements = ()
        return TransitionInfo(span.file, span.line, source, inputs, output, statements)

    def describe_ending_transition(self, label) -> TransitionInfo:
        """The last transition of a path that ends in an error, at the statement that raised
        it: a merged step's last statement, not its first."""
        return self.describe_transition(label, at_last=True)


def _statement_text(span) -> str:
    """The source line a statement starts on, stripped (empty when the file is gone)."""
    if span is None:
        return ""
    text = SourceCache.line(span.file, span.line)
    return text.strip() if text is not None else ""


def _whole_statement(span) -> str:
    """A statement's text over all its lines: a simple statement's up to its ``;``, a
    compound statement's head up to its THEN or DO (its body runs as steps of its own)."""
    if span is None:
        return ""
    lines = []
    for number in range(span.line, max(span.end_line, span.line) + 1):
        text = SourceCache.line(span.file, number)
        if text is None:
            break
        code = text.split("!", 1)[0].strip() if '"' not in text else text.strip()
        lines.append(code)
        if code.endswith(";") or HEAD_END.search(code) or \
                (number == span.line and code.upper().startswith("TEST ")):
            break
    return " ".join(lines)


HEAD_END = re.compile(r"\b(THEN|DO)$", re.IGNORECASE)


def fault_text(fault) -> str:
    """``uncaught ERR_DIVZERO: division by zero`` (the name once, when the message repeats it)."""
    name = errno_name(fault.errno)
    message = error_detail(fault.errno, fault.message)
    return f"uncaught {name}: {message}" if message else f"uncaught {name}"


def _frame_span(routine, pc: int):
    """Where a frame is: the statement at its program counter (a caller: the call)."""
    if 0 <= pc < len(routine.code) and routine.code[pc].span is not None:
        return routine.code[pc].span
    return routine.end_span or routine.span


def _choice_text(value, of_data: bool = False) -> str:
    """A chosen value as RAPID writes it; names (tasks, outcomes, messages) as they are, a
    string read from data (``of_data``: PERS written outside the loaded code) quoted."""
    return value if isinstance(value, str) and not of_data else format_value(value)


def end_at_error(system: RapidSystem, result: SearchResult) -> SearchResult:
    """A safety violation's path ends where things go wrong, and says what went wrong.

    An uncaught error: the path ends in the failed state.  A state that waits
    forever: the path ends with the waiting statement run once more (it
    changes nothing), so its last step names the statement that waits.
    """
    if not result.prefix or result.cycle:
        return result
    last = result.prefix[-1]
    if last.state.status == FAILED:
        result.ending = fault_text(last.state.fault)
        return result
    wait = next((label for label, state in system.successors(last.state)
                 if state == last.state), None)
    if wait is not None:
        result.prefix.append(LassoStep(wait, last.state, last.automaton_state))
    result.ending = "the program waits here forever: no input lets it go on"
    return result


def replay(system: RapidSystem, result: SearchResult) -> None:
    """Re-execute a counterexample through the step function; a mismatch is an internal error.

    A counterexample of a reduced system is then expanded on the unreduced
    one (``reduction.expansion``): every line executed, every value shown.
    """
    steps: list[LassoStep] = result.prefix + result.cycle
    if not steps:
        return
    system = system.full_interleaving()   # a reduced path, or a fair one found without it
    if steps[0].state not in system.initial_states():
        raise AssertionError("counterexample does not start in an initial state")
    for before, after in zip(steps, steps[1:]):
        _check_step(system, before.state, after.label, after.state)
    if result.cycle:
        closing = result.closing_label
        _check_step(system, steps[-1].state, closing, result.cycle[0].state)
    expand_lasso(system, result)


def _check_step(system: RapidSystem, before: State, label, after: State) -> None:
    for candidate_label, candidate in system.successors(before):
        if candidate == after and (label is None or candidate_label == label):
            return
    raise AssertionError(f"counterexample step does not replay (label {label!r})")
