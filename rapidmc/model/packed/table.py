"""A RAPID model's states packed for the compiled core, and the step machine's program.

``PackedStateTable`` is a ``check.states.StateTable`` (``intern``, ``[id]``,
``len``, ``memory_bytes``) over ``_native.PackedTable``: a state is stored as a
frame vector (context id, program counter, the top frame's local data) and a
data vector (global data), of value ids.  The *context* is everything else
(the frames below, the top frame's routine and handler fields, signals,
robot, interrupts, ERRNO, status, tasks ...), which the fused step never
changes: each distinct one gets an id here, with the two facts the
machine needs, whether it may step there (a plain running state, as
``fused_step.plain_successor_states`` tests) and whether the program has
failed there (the run-time error search's predicate).  With several tasks the frame
vector holds every running task's top frame and the machine steps one task's
instruction at a time (``_task_vectors``, ``python_task_successors`` for the tasks it
leaves to Python).

The table also hands the machine its program (``bytecode``): each routine's
fused blocks, the domains of the inputs chosen where read, and the atoms of
the valuations the search keeps.  It answers the machine's calls back for
the states it leaves to Python (``python_successors``, ``python_valuation``,
``predicate_holds``, ``observe``).

Under the partial-order reduction one table serves every search of a check
(``reduced_packing``): each search keeps its states in a ``_native.StateSet`` of its own
(``PackedSearch``), the proviso numbers states in the table (``PackedPlaces``), and the
machine chooses the ample sets ``PartialOrder`` would, keeping each reduced step's
successors by the state's number for the later searches.

Two states are the same stored state exactly when the Python table
(``check.states``) says so: equal contexts (tuples compared by ``==``) and
equal values (ids by ``==``, as ``_packed.c`` interns them).  tests/
test_native_engine.py compares every report with the Python engine's.
"""
from __future__ import annotations

import struct
import sys
from array import array
from typing import Callable, Hashable, Optional, Sequence

from pyrsistent import pvector

from ...check.native import _native
from ...semantics.plain_step import is_plain
from ...semantics.staged_step import task_transitions
from ..reduction.merging import executed_spans
from ..reduction.partial_order import PartialOrder
from ...semantics.state import FAILED, NORMAL, RUNNING, Frame, State
from ..reduction.projection import Projection
from .bytecode import RoutineCode, atom_code

_new_tuple = tuple.__new__
_HEAD = struct.Struct("<Ii")           # context id, program counter
RUNS = 1                               # context flags (_packed.c's add_context)
HAS_FAILED = 2
MAIN_ALONE = 4                         # one frame, of the projection's main routine
ENDED_TASK = 8                         # several tasks, one of them has ended
TASK_RUNS = 1                          # per task of a context: the machine may step it
ORDER_CANDIDATE = 1                    # per task and instruction (``_order_flags``)
ORDER_NEVER_WAITS = 2
ORDER_MERGEABLE = 4
ORDER_GROUPS = 8                       # it may be in an ample set of several tasks
ORDER_HELD = 16                        # ample where the tasks it conflicts with are held
MAX_TASKS = 64
REMEMBERED_VECTORS = 256               # states whose vectors are remembered (reduced search)
TASK_STEPS_KEPT = 1 << 13              # one task's Python steps kept (``_task_step``)
MAX_FRAMES = 512                       # a deeper call raises (``instructions.enter_routine``)
ENTERED = (NORMAL, -1, 0, -1)          # a called procedure's frame: mode ... result slot


def packed_table(system) -> Optional["PackedStateTable"]:
    """A packed table for ``system``'s states when the compiled core is built and its
    step machine can take the system's fused steps, else None.  Reduced between tasks
    (``PartialOrder``), the searches of a check share one table (``PackedSearch``: a set
    of states each) when the reduction numbers its states in it (``reduced_packing``)."""
    order = system.order
    if isinstance(order, PartialOrder):
        places = order.places()
        return PackedSearch(places.table) if isinstance(places, PackedPlaces) else None
    if order is not None:
        return None
    return _new_table(system)


def _new_table(system) -> Optional["PackedStateTable"]:
    tasks = len(system.program.task_names)
    projection = system.project if tasks > 1 else system.project_fused
    if _native is None or tasks > MAX_TASKS or \
            projection is not None and (not isinstance(projection, Projection) or
                                        projection.blanks):
        return None
    config = system.config
    if config.free_inputs or system.program.environment_react is not None:
        return None
    table = (TaskStateTable if tasks > 1 else PackedStateTable)(system)
    return table if table.compiled_routines else None


def reduced_packing(system) -> Optional["PackedPlaces"]:
    """The numbering of the partial-order reduction's proviso in a packed table of the
    system's states, which every search of the check then shares, so the step machine
    chooses the ample sets Python would (``_packed.c``'s ``ample_step``); None when the
    table cannot serve (the Python engine, or a system the machine does not take)."""
    table = _new_table(system) if system.program.task_names[1:] else None
    if table is None:
        return None
    table.set_order(table.order_flags())
    table.runs = system.order.runs
    table.rows_kept = True
    # (the proviso packs a successor to ask for its number, and the search then stores it)
    table.remembered = {}
    table._vectors = table._remembered_vectors
    return PackedPlaces(table)


class PackedPlaces:
    """``partial_order.StatePlaces`` kept in a packed table (its states' segments: exact),
    where the step machine numbers the states it steps."""

    def __init__(self, table: "PackedStateTable"):
        self.table = table

    def place(self, state: State) -> int:
        table = self.table
        return table.place(*table.intern_parts(*table.vectors_of(state)), False)

    def number(self, state: State) -> int:
        table = self.table
        return table.place(*table.intern_parts(*table.vectors_of(state)), True)


class PackedSearch:
    """One search's states in a check's shared packed table: its own ids and count
    (``_native.StateSet``, as a table of its own would give them), with the table's
    values, segments, contexts, step machine, kept rows and the reduction's numbering of
    states.  Every call selects the search's set first (``machine_table``)."""

    collapsed = True
    known_ids: dict = {}

    def __init__(self, table: "PackedStateTable"):
        object.__setattr__(self, "table", table)
        object.__setattr__(self, "states", table.new_states())

    def machine_table(self) -> "PackedStateTable":
        """The shared table, with this search's states selected."""
        table = self.table
        if table.selected_states is not self.states:
            table.select_search(self.states)
        return table

    def intern(self, state: Hashable, add: bool = True) -> tuple[int, bool]:
        return self.machine_table().intern(state, add)

    def __getitem__(self, state_id: int) -> State:
        return self.machine_table()[state_id]

    def __len__(self) -> int:
        return len(self.machine_table())

    def successor_ids(self, state_id: int, valuation: int):
        return self.machine_table().successor_ids(state_id, valuation)

    def __getattr__(self, name: str):
        return getattr(self.machine_table(), name)

    def __setattr__(self, name: str, value) -> None:
        setattr(self.table, name, value)


class PackedStateTable(_native.PackedTable if _native is not None else object):
    """States of a ``RapidSystem`` as packed vectors; see the module docstring."""

    collapsed = True
    known_ids: dict = {}

    def __init__(self, system):
        self.system = system
        self.program = system.program
        initial = system.initial_states()
        first = initial[0]
        self.store_length = len(first[1])
        self._initial_store = first[1]
        self.io_length = len(first[2])
        self._contexts: dict[tuple, int] = {}
        self._context_values: list[tuple] = []
        self._context_flags: list[int] = []         # by context id (``import_context``)
        self._valuations: list[Callable] = []       # by the machine's valuation index
        self._valuation_codes: list[bytes] = []
        self._routines: list = []
        self.compiled_routines = 0
        # several tasks: each one's top frame is in the frame vector (``_task_vectors``)
        self.tasks = len(self.program.task_names)
        if self.tasks > 1:
            self.set_tasks(self.tasks)
        self._stepping: tuple = (-1, None)      # (id, state) of python_task_successors
        self._task_steps: dict = {}             # (frame, data, task, ample) -> _task_step's
        self._python_spans: list = []           # the lines its steps there ran
        self._compile()
        # what the search in progress hands over (``prepare_search``)
        self.predicate: Optional[Callable] = None
        self.observer = None
        self._last_id = -1
        self._last: tuple = ()

    # ---------------------------------------------------------- the program
    def _compile(self) -> None:
        system, program = self.system, self.program
        value_id = self._value_id
        for index in range(len(program.routines)):
            code = RoutineCode.compile(program, system.config, index, value_id,
                                       self.store_length, self._initial_store)
            self._routines.append(None if code is None else code.as_tuple())
            self.compiled_routines += code is not None and \
                any(start >= 0 for start in code.block_start)
        self._send_program()

    def _send_program(self) -> None:
        lazy = {index: self.value_ids(domain)
                for index, (_, domain) in self.system.config.lazy_inputs.items()
                if 0 <= index < self.io_length and domain}
        self.set_program(self.store_length, self.io_length, self._routines, lazy,
                         self._valuation_codes, self._projection())

    def _projection(self) -> Optional[tuple]:
        """The projection of the fused step's targets for ``set_program``, or None (with
        several tasks, the system's whole projection: a task's step is projected as
        ``RapidSystem.successors`` projects it)."""
        projection = self.system.project if self.tasks > 1 else self.system.project_fused
        if projection is None:
            return None
        main = self._resets(projection.main_resets) if projection.main_resets else None
        frames = {routine: self._resets(per_pc)
                  for routine, per_pc in projection.frame_resets.items()}
        return self._resets([projection.global_resets]), main, frames

    def _resets(self, lists: Sequence[tuple]) -> tuple[bytes, bytes]:
        """(offsets, (slot, value id) pairs) of reset lists, as ``_packed.c`` reads them."""
        offsets, pairs = array("i", [0]), array("i")
        for resets in lists:
            for slot, initial in resets:
                pairs.extend((slot, self._value_id(initial)))
            offsets.append(len(pairs) // 2)
        return offsets.tobytes(), pairs.tobytes()

    def _value_id(self, value) -> int:
        return struct.unpack("<I", self.value_ids((value,)))[0]

    def valuation_index(self, valuation: Optional[Callable]) -> int:
        """The machine's index of ``valuation`` (compiled when first asked), -1 when its
        atoms are not all compiled: Python evaluates it."""
        if valuation is None:
            return -1
        for index, known in enumerate(self._valuations):
            if known is valuation:
                return index if self._valuation_codes[index] else -1
        atoms = getattr(valuation, "fused_atoms", None)
        code = atom_code(atoms, self._value_id, self.store_length) if atoms is not None \
            else None
        self._valuations.append(valuation)
        self._valuation_codes.append(code.tobytes() if code is not None else b"")
        if code is not None:
            self._send_program()
        return len(self._valuations) - 1 if code is not None else -1

    def order_flags(self) -> list:
        """Per task, per routine, the partial-order reduction's facts about each instruction
        (``_packed.c``'s ORDER_ flags): an ample candidate (``is_ample_candidate``), it
        never waits (``never_waits``), it joins its task's step before it (``local_runs``).
        Every routine's: the machine decides a state's ample set only where it knows
        every running task's instruction."""
        order, routines = self.system.order, self.program.routines
        runs = order.runs
        flags = []
        for task in range(self.tasks):
            per_routine = []
            for index, routine in enumerate(routines):
                per_routine.append(bytes(
                    (ORDER_CANDIDATE if order.is_ample_candidate(task, index, pc) else 0) |
                    (ORDER_NEVER_WAITS if order.never_waits(index, pc) else 0) |
                    (ORDER_MERGEABLE if runs is not None and runs.mergeable(task, index, pc)
                     else 0) |
                    (ORDER_GROUPS if self.tasks > 2 and order.groups.may_join(task, index, pc)
                     else 0) |
                    (ORDER_HELD if order.may_be_held(task, index, pc) else 0)
                    for pc in range(len(routine.code))))
            flags.append(per_routine)
        return flags

    def machine_table(self) -> "PackedStateTable":
        """The table the compiled search loops run on: this one."""
        return self

    selected_states = None           # (``PackedSearch``: the search whose ids are meant)
    runs = None                      # reduced (``reduced_packing``): the tasks' local runs
    # reduced: the breadth-first loop keeps the successors of Python's steps as a row of
    # the parts this table gave them, by the state's number, for the check's later
    # searches (``_packed.c``'s ``row_keep``), so the model keeps none of its own there
    # (``RapidSystem.successors``' ``keep``: interning each successor's parts once more,
    # in a node table whose objects are not this table's, cost more than the step)
    rows_kept = False

    def select_search(self, states) -> None:
        """Ids name the states of ``states`` (a ``new_states()``) from now on; what was
        remembered by id is forgotten."""
        self.select(states)
        self.selected_states = states
        self._stepping, self._python_spans = (-1, None), []
        self._last_id, self._last = -1, ()

    # ------------------------------------------------------ StateTable protocol
    def intern(self, state: Hashable, add: bool = True) -> tuple[int, bool]:
        frame, data = self._vectors(state)
        return self.intern_vectors(frame, data, add)

    def __getitem__(self, state_id: int) -> State:
        return self._state(*self.vectors(state_id))

    def memory_bytes(self) -> int:
        contexts = sys.getsizeof(self._contexts) + sys.getsizeof(self._context_values)
        return self.native_bytes() + contexts

    # -------------------------------------------------------------- packing
    def _vectors(self, state: State) -> tuple[bytes, bytes]:
        frames = state[0]
        if frames:
            top = frames[-1]
            context = (frames[:-1], top[0], top[3:], state[2], state[3:])
            head = (top[1], top[2])
        else:
            context = ((), -1, (), state[2], state[3:])
            head = (0, ())
        context_id = self._contexts.get(context)
        if context_id is None:
            context_id = self._add_context(context, state)
        frame = _HEAD.pack(context_id, head[0]) + self.value_ids(head[1])
        return frame, self.value_ids(state[1])

    def _add_context(self, context: tuple, state: State) -> int:
        below, routine, handling, io, rest = context
        # where the fused step runs (``plain_successor_states``): a running plain state
        # whose frame is not in a handler nor counting RETRYs (``fused_step._entry``)
        runs = routine >= 0 and state[7] == RUNNING and \
            is_plain(self.program, state, self.system.config) and \
            not handling[0] and not handling[2]
        projection = self.system.project_fused
        alone = projection is not None and len(state[0]) == 1 and not state[10] and \
            routine == projection.main
        flags = (RUNS if runs else 0) | (HAS_FAILED if state[7] == FAILED else 0) | \
            (MAIN_ALONE if alone else 0)
        return self._new_context(context, flags)

    def _new_context(self, context: tuple, flags: int) -> int:
        routine, io = context[1], context[3]
        context_id = self.add_context(routine, flags, self.value_ids(io))
        self._contexts[context] = context_id
        self._context_values.append(context)
        self._context_flags.append(flags)
        return context_id

    # ------------------------------------------------------- several tasks
    # The frame vector holds every running task's top frame, in task order: the context
    # id, a 0, then per task its pc (as a value: an int) and its local values.  The
    # context is each task's frames below, its top frame's routine, handler fields and
    # number of locals (None: the task has ended), the signals and the rest of the state
    # but the tasks.
    def _remembered_vectors(self, state: State) -> tuple[bytes, bytes]:
        """``_task_vectors``, remembered for the states packed last (by identity, each kept
        alive while it is remembered)."""
        remembered = self.remembered
        known = remembered.get(id(state))
        if known is not None and known[0] is state:
            return known[1]
        if len(remembered) >= REMEMBERED_VECTORS:
            remembered.clear()
        vectors = self._task_vectors(state)
        remembered[id(state)] = (state, vectors)
        return vectors

    def _task_vectors(self, state: State) -> tuple[bytes, bytes]:
        shapes = []
        items: list = []
        for stack in (state[0],) + state[10]:
            if stack:
                top = stack[-1]
                shapes.append((stack[:-1], top[0], top[3:], len(top[2])))
                items.append(top[1])
                items += top[2]
            else:
                shapes.append(None)
        context = (tuple(shapes), state[2], state[3:10])
        context_id = self._contexts.get(context)
        if context_id is None:
            context_id = self._add_task_context(context, state)
        return _HEAD.pack(context_id, 0) + self.value_ids(items), self.value_ids(state[1])

    def _add_task_context(self, context: tuple, state: State) -> int:
        # where the machine steps a task (``staged_step`` without interrupts, stored
        # inputs or an environment; main running, so the projection's final resets do not
        # apply): a running state whose interrupt table, pending and scheduled lists are
        # empty; each task's frame then as ``_task_info`` says
        interrupts = state[4]
        runs = state[7] == RUNNING and bool(state[0]) and \
            not (interrupts[0] or interrupts[1] or interrupts[3])
        ended = any(shape is None for shape in context[0])
        flags = (RUNS if runs else 0) | (HAS_FAILED if state[7] == FAILED else 0) | \
            (ENDED_TASK if ended else 0)
        return self._new_context(context, flags)

    def _new_task_context(self, context: tuple, flags: int) -> int:
        shapes, io = context[0], context[1]
        info = array("i")
        where = 2
        for shape in shapes:
            if shape is None:
                info.extend((-1, 0, 0, 0))
                continue
            _, routine, handling, count = shape
            # (not in a handler nor counting RETRYs: ``fused_step._entry``)
            runs = not handling[0] and not handling[2]
            info.extend((routine, where, count, TASK_RUNS if runs else 0))
            where += 1 + count
        for _ in range(len(shapes), self.tasks):
            info.extend((-1, 0, 0, 0))           # (a failed state keeps no further tasks)
        first = shapes[0][1] if shapes[0] is not None else -1
        context_id = self.add_context(first, flags, self.value_ids(io), info.tobytes())
        self._contexts[context] = context_id
        self._context_values.append(context)
        self._context_flags.append(flags)
        return context_id

    def _task_state(self, context_id: int, pc: int, items: tuple, data: tuple) -> State:
        shapes, io, rest = self._context_values[context_id]
        stacks = []
        position = 0
        for shape in shapes:
            if shape is None:
                stacks.append(())
                continue
            below, routine, handling, count = shape
            start = position + 1
            top = _new_tuple(Frame, (routine, items[position], items[start:start + count]) +
                             handling)
            stacks.append(below + (top,))
            position = start + count
        return _new_tuple(State, (stacks[0], pvector(data), io) + rest + (tuple(stacks[1:]),))

    # A call or a procedure's end changes a task's frames below its top, which the context
    # holds: the machine (``_packed.c``'s ``frame_step``) asks here for the context entered
    # and makes the frame vector itself.  Running, the interrupts and the other tasks are
    # as they were, so the context's flags are too.
    def called_context(self, context_id: int, task: int, pc: int, callee: int,
                       caller_locals: bytes) -> Optional[int]:
        """The context where ``task``, at the call in ``pc`` of its top frame (whose locals
        have the value ids ``caller_locals``), has entered routine ``callee``: the caller's
        frame below the callee's (``enter_routine``); None where Python calls (the stack
        is full: ERR_STACK_OVERFLOW)."""
        shapes, io, rest = self._context_values[context_id]
        below, routine, handling, _ = shapes[task]
        if len(below) + 1 >= MAX_FRAMES:
            return None
        caller = _new_tuple(Frame, (routine, pc, self.values(caller_locals)) + handling)
        entered = (below + (caller,), callee, ENTERED,
                   len(self.program.routines[callee].initial_locals))
        return self._task_context(shapes[:task] + (entered,) + shapes[task + 1:], io, rest,
                                  context_id)

    def left_context(self, context_id: int, task: int) -> Optional[tuple]:
        """(the context, the pc and the locals' value ids of the caller going on) where
        ``task``'s top frame, a procedure's, has ended (``leave_routine``); None where
        Python steps it: the task's last frame, a trap's or a function's, a caller counting
        RETRYs (``Machine.goto`` may reset them)."""
        shapes, io, rest = self._context_values[context_id]
        below, routine, handling, _ = shapes[task]
        if not below or handling[3] >= 0 or self.program.routines[routine].kind == "TRAP":
            return None
        caller = below[-1]
        if caller[5]:
            return None
        returned = (below[:-1], caller[0], caller[3:], len(caller[2]))
        entered = self._task_context(shapes[:task] + (returned,) + shapes[task + 1:], io, rest,
                                     context_id)
        after = self.program.routines[caller[0]].code[caller[1]].next
        return entered, after, self.value_ids(caller[2])

    def _task_context(self, shapes: tuple, io, rest, like: int) -> int:
        """The id of a context of several tasks whose flags are those of context ``like``."""
        context = (shapes, io, rest)
        known = self._contexts.get(context)
        return known if known is not None else \
            self._new_task_context(context, self._context_flags[like])

    def python_task_successors(self, state_id: int, task: int) -> Optional[list]:
        """The transitions of ``task`` alone at a state of several tasks, for the machine
        that takes the others' (``_packed.c``'s ``tasks_step``): (frame id, data id,
        whether it changes the state) each, projected and, reduced, run on through the
        task's local instructions (``LocalRuns.run_on``, as ``PartialOrder`` extends the
        transitions it keeps); None to have the whole state stepped by Python (an
        observer that still wants the labels sees them there)."""
        return self._task_step(state_id, task, -1)

    def python_task_ample(self, state_id: int, task: int, here: int):
        """Whether the transitions of ``task`` at a state of several tasks, numbered
        ``here``, are its ample set, for the machine where it does not take that task's
        step (``_packed.c``'s ``ample_step``): their parts (frame id, data id) when
        they are, as ``PartialOrder._choose`` decides (projected, run on through the
        task's local instructions, each one invisible), False when they are not, None to
        have the whole state stepped by Python (the task cannot be stepped alone, or it
        has an idle step, which only the other tasks' steps tell to keep or drop)."""
        return self._task_step(state_id, task, here)

    def python_held(self, state_id: int, task: int) -> bool:
        """Whether ``task``'s instruction, not an ample candidate, is one at the state
        (``_packed.c``'s ``ample_step``): the tasks it conflicts with are held at their
        barriers (``PartialOrder.held_at``)."""
        return self.system.order.held_at(self._stepped(state_id), task, self.system.config)

    def python_group_ample(self, state_id: int, here: int):
        """The ample set of a group of tasks at a state of several tasks, numbered
        ``here``, where no task alone has one (``_packed.c``'s ``ample_step``): its
        transitions' parts (frame id, data id), as ``PartialOrder.ample`` picks them
        (``TaskGroups.choose``), or False."""
        state = self._stepped(state_id)
        stacks = (state[0],) + state[10]
        running = [task for task, stack in enumerate(stacks) if stack]
        chosen = self.system.order.groups.choose(
            state, stacks, running, self.system.config, here,
            lambda task, found: [(spans, after) for after, _, spans
                                 in self._task_targets(state, task, found)])
        if chosen is None:
            return False
        if self._labels_wanted():
            self._python_spans = [spans for spans, _ in chosen]
        return [self.intern_parts(*self._vectors(after)) for _, after in chosen]

    def _stepped(self, state_id: int) -> State:
        """The state being stepped, kept while the machine asks about it."""
        if self._stepping[0] != state_id:
            self._stepping, self._python_spans = (state_id, None), []
        state = self._stepping[1]
        if state is None:
            state = self[state_id]
            self._stepping = (state_id, state)
        return state

    def _task_step(self, state_id: int, task: int, here: int):
        """``python_task_successors`` (``here`` -1) or ``python_task_ample``, kept by the
        state's segments: a state is stepped again where an earlier step kept no row (the
        deadlock search's test whether it is stuck, an observer that wants the lines),
        and its answer is the same (a number only grows: a target not numbered before
        the state when first asked never is)."""
        if self._stepping[0] != state_id:
            self._stepping, self._python_spans = (state_id, None), []
        key = self.key(state_id)[:2] + (task, here >= 0)
        kept = self._task_steps.get(key)
        if kept is None:
            kept = self._task_answer(task, here)
            if len(self._task_steps) >= TASK_STEPS_KEPT:
                self._task_steps.clear()
            self._task_steps[key] = kept
        answer, spans = kept
        if spans and self._labels_wanted():
            # (the lines each one ran: told once the idle steps are dropped, an ample
            # set's as kept, ``note_python_spans``)
            if here >= 0:
                self._python_spans = list(spans)
            else:
                self._python_spans += spans
        return answer

    def _task_answer(self, task: int, here: int) -> tuple:
        """(``_task_step``'s answer, the spans each of its transitions ran) at the state
        being stepped."""
        state = self._stepping[1]
        if state is None:
            state = self[self._stepping[0]]
            self._stepping = (self._stepping[0], state)
        config = self.system.config
        found = task_transitions(self.program, state, task, config)
        if found is None or here >= 0 and any(transition[2] == state for transition in found):
            return None, ()
        targets = self._task_targets(state, task, found)
        spans = tuple(spans for _, _, spans in targets)
        if here < 0:
            return [self.intern_parts(*self._vectors(after)) + (moved,)
                    for after, moved, _ in targets], spans
        order = self.system.order
        if targets and all(order._invisible_step(task, state, after, config, here)
                           for after, _, _ in targets):
            return [self.intern_parts(*self._vectors(after)) for after, _, _ in targets], spans
        return False, ()

    def _labels_wanted(self) -> bool:
        observer = self.observer
        return observer is not None and observer.labels_wanted

    def _task_targets(self, state: State, task: int, found: list) -> list:
        """(target, whether the step changed the state, the spans of the instructions it
        ran) of one task's transitions ``found``: projected, and reduced, run on through
        the task's local instructions (``python_task_successors``)."""
        project, runs, config = self.system.project, self.runs, self.system.config
        targets = []
        for transition in found:
            after = transition[2]
            moved = after != state
            spans = executed_spans(transition[1])
            if project is not None:
                after = project(after)
            if runs is not None:
                after, steps = runs.run_on(state, task, after, config)
                for _, span, _ in steps:
                    spans += executed_spans(span)
            targets.append((after, moved, spans))
        return targets

    def note_python_spans(self, kinds: bytes) -> bool:
        """The observer is told the lines of the steps ``python_task_successors`` gave at
        the state just stepped that were kept (``kinds``: per successor 0 the machine's,
        1 Python's dropped as idle, 2 Python's kept; as ``python_labelled`` shows it the
        kept ones); whether it wants more."""
        marks = array("i")
        marks.frombytes(kinds)
        spans = iter(self._python_spans)
        kept = [span for mark in marks if mark for span in [next(spans)] if mark == 2]
        self._python_spans = []
        self._stepping = (-1, None)
        return self.observer.note_spans([one for spans_ in kept for one in spans_])

    # ------------------------------------- vectors between tables (workers)
    # A state's vectors hold ids that only this table gives its values and contexts.  Another
    # table (a worker of a distributed search) reads them once it has been handed the values
    # and contexts behind the ids (``exported_values`` / ``exported_contexts``, from the
    # count it was handed before: ids only grow) and mapped them to its own ids
    # (``value_ids``, ``import_context``).
    def vectors_of(self, state: State) -> tuple[bytes, bytes]:
        """The state's (frame, data) vectors, its values and context stored when new (not
        the state itself)."""
        return self._vectors(state)

    def context_count(self) -> int:
        return len(self._context_values)

    def exported_values(self, start: int) -> tuple:
        """The values of the ids from ``start`` on."""
        end = self.counts()["values"]
        return self.values(array("I", range(start, end)).tobytes()) if end > start else ()

    def exported_contexts(self, start: int) -> list[tuple[tuple, int]]:
        """(context, flags) of the context ids from ``start`` on."""
        return list(zip(self._context_values[start:], self._context_flags[start:]))

    def import_context(self, context: tuple, flags: int) -> int:
        """This table's id of a context another table exported (with its flags there: the
        flags are a function of the context, computed by the first table that met it)."""
        known = self._contexts.get(context)
        return known if known is not None else self._new_context(context, flags)

    def _state(self, context_id: int, pc: int, locals_: tuple, data: tuple) -> State:
        below, routine, handling, io, rest = self._context_values[context_id]
        if routine >= 0:
            frames = below + (_new_tuple(Frame, (routine, pc, locals_) + handling),)
        else:
            frames = below
        return _new_tuple(State, (frames, pvector(data), io) + rest)

    # ------------------------------------------- the machine's calls back
    def python_successors(self, state_id: int) -> list[tuple[int, int]]:
        """The successors of a state the machine left to Python, as interned parts."""
        state = self[state_id]
        self._stepping, self._python_spans = (-1, None), []   # (what the machine began)
        targets = self.system.successor_states(state, not self.rows_kept)
        self._last_id, self._last = state_id, (state, targets)
        return [self.intern_parts(*self._vectors(target)) for target in targets]

    def python_labelled(self, state_id: int) -> tuple[list[tuple[int, int]], bool]:
        """``python_successors`` for an observer that wants the labels: it sees them; and
        whether it wants more."""
        state = self[state_id]
        self._stepping, self._python_spans = (-1, None), []   # (what the machine began)
        labelled = list(self.system.successors(state, not self.rows_kept))
        self.observer(state, labelled)
        targets = [target for _, target in labelled]
        self._last_id, self._last = state_id, (state, targets)
        parts = [self.intern_parts(*self._vectors(target)) for target in targets]
        return parts, self.observer.labels_wanted

    def note_executed(self, pairs: bytes) -> bool:
        """The observer is told the lines of the (routine, pc) ``pairs`` the machine ran
        for the first time; whether it wants more."""
        found = array("i")
        found.frombytes(pairs)
        routines = self.program.routines
        spans = [routines[found[i]].code[found[i + 1]].span for i in range(0, len(found), 2)]
        return self.observer.note_spans([span for span in spans if span is not None])

    def failed_at(self, state_id: int) -> bool:
        """``RapidSystem.failed`` of a stored state, from its context (the state is not
        rebuilt)."""
        return bool(self._context_flags[self.key(state_id)[2]] & HAS_FAILED)

    def predicate_holds(self, state_id: int) -> bool:
        if self.tasks > 1 and self.predicate == getattr(self.system, "stuck", None):
            stuck = self._stuck(state_id)
            if stuck is not None:
                return stuck
        return bool(self.predicate(self[state_id]))

    def _stuck(self, state_id: int) -> Optional[bool]:
        """``RapidSystem.stuck`` at a state of several tasks from the machine's step (its
        own steps and Python's of single tasks, ``tasks_step``), or None where Python
        decides: the machine does not step there, a task has ended (a barrier may wait
        for it), or an observer wants the lines steps run.  Without stored free inputs
        (``packed_table``) a running state is stuck exactly when every successor is the
        state itself: the same segments."""
        observer = self.observer
        if observer is not None and observer.labels_wanted:
            return None
        frame, data, context = self.key(state_id)
        if self._context_flags[context] & ENDED_TASK:
            return None
        found = self.step(state_id)
        if found is None:
            return None
        return all(parts == (frame, data) for parts in found)

    def python_valuation(self, index: int, state_id: int) -> int:
        return self.valuations_kept[index](self[state_id])

    def observe(self, state_id: int, frames: Sequence[int], data: Sequence[int]) -> None:
        """The observer's ``states`` at a state (its successors given by their parts)."""
        self.observer.states(*self.stepped(state_id, frames, data))

    def stepped(self, state_id: int, frames: Sequence[int], data: Sequence[int]) -> tuple:
        """(the state, its successor states) of a state just stepped, its successors given
        by their parts (the states Python just stepped, as it gave them)."""
        if self._last_id == state_id:
            return self._last
        return self[state_id], [self._state(*self.parts(frame, part))
                                for frame, part in zip(frames, data)]


class TaskStateTable(PackedStateTable):
    """The packed table of a program with several tasks: each task's top frame is in the
    frame vector (``_task_vectors``).  A subclass rather than the table's own bound methods
    in its attributes: those made each table a reference cycle, which only the collector's
    rare full collections free (a coverage probe's table stayed, 100 MB each)."""
    _vectors = PackedStateTable._task_vectors
    _state = PackedStateTable._task_state
    _new_context = PackedStateTable._new_task_context

