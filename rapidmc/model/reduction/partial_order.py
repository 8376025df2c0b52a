"""Partial-order reduction: steps of different tasks on their own data are not interleaved.

With several tasks, every interleaving of their steps is a path of the state
graph; when the steps touch only data of their own task, the orders lead to the
same states and no property can tell them apart.  At such a state it is enough
to follow one task: an *ample set* (Peled; Clarke, Grumberg, Peled, *Model
Checking*, ch. 10) is every transition of one task ``t`` when

* C0 the task has a transition (every one of them changes the state);
* C1 its next instruction is *independent* of every other task
  (``PartialOrder.footprint``, decided once per instruction from its code): an
  assignment, condition, TEST, FOR step, jump (``fusion`` metadata: the instruction
  as Python over ``store`` and ``locals_``), a call of a procedure without
  arguments or the end of a procedure (ENDPROC, RETURN), that
  reads only data no other task writes (a wait that keeps the value it read of data
  written outside the loaded code, ``OutsideData.written_by_waits``, writes it for
  every task that reads it) and writes only data no other task's
  code names (its own VAR data, TASK PERS, routine data, its own frames, shared
  PERS that the other tasks declare but never use; a task with GetDataVal or
  SetDataVal names all it can), reads no signal another task may set or robot
  another task moves (``cell_uses``) and calls nothing.  No step of another task depends on it or changes
  whether it can run, so the other tasks' steps commute with it.  The last
  ENDPROC of a task ends it, which a barrier (WaitSyncTask, SyncMoveOn/Off)
  observes: with barriers in the program it is not independent;
* C2 it is invisible: it writes nothing an atom of the check names (by name:
  global or routine data), it cannot fail (no successor FAILED, ERRNO and the
  frames' modes unchanged), and it leaves its task where it can go on (an
  instruction whose step always changes the state, ``never_waits``, or one
  of its steps from there does), so ``waits(task)``, the atom of
  ``no_deadlock``'s search (``model.waiting``), stays false;
* C3 cycle proviso: no successor it leads to was numbered before the state.
  The system numbers states as it hands them out (``StatePlaces``): wherever a
  choice is tried (several tasks running, no interrupt), the state first, then
  the targets of the transitions it keeps, in order, each when it has no number
  yet.  An ample transition thus always leads to a state numbered after its
  source, so along a cycle of the reduced graph the numbers cannot grow all the
  way round: some state on it is expanded fully, whatever the search order (the
  breadth-first safety searches, the depth-first product search of an LTL
  property, several searches over one system).  A state's number never changes,
  so its ample set is the same whenever it is asked for, by any search and by
  either engine: the compiled core's step machine numbers the states it steps
  in its packed table (``model.packed``), and a later search takes the very
  transitions an earlier one took.  Numbers are kept by key (``model.state_keys``:
  equal states, equal keys); a successor whose key has a number no greater than
  the state's counts as numbered before it (a collision only expands fully).

Where no task alone qualifies, the ample set may be the transitions of a group
of tasks: those whose next instructions touch data the others' code names
(``task_groups``: T_ROB1 and T_ROB2 at a handshake on a PERS flag, without a
third task polling its own data; an IDelete that deletes nothing, ``empty_deletes``).
Otherwise the state is expanded fully.
With merged steps on, each transition
then runs on through its task's next independent, invisible instructions
(``local_runs``, SPIN's statement merging between processes).  The reduced graph keeps every verdict
of the LTL properties without X (next) over these atoms, reachability of
FAILED and of states where the program waits forever; ``plan_reductions``
turns it off for a property with X, an atom on locations (AtLine, InRoutine
...), stored free inputs (every step would change them; a served edge input is kept at
0 after every step and stays on: ``reduction.inputs_stored``), environment models,
and data reached by name at run time in another task or by pattern
(``\\TaskName``, SetAllDataVal, GetNextSym); GetDataVal and SetDataVal look the
name up where the call is, so a task's SetDataVal counts as a write of every
datum the task can name.  In a state with
interrupts only a task that serves none of them may be ample (``interrupt_owners``:
each task serves its own, in its own steps; an interrupt only its own task's steps can
queue, not pending, serves nothing), and no group is tried; with a delayed
signal change due or a pending interrupt no longer connected, the state is expanded
fully.  The fair search (``check.fair``) runs on the unreduced
system (``RapidSystem.full_interleaving``).  tests/test_partial_order.py holds
the verdicts against the unreduced search.
"""
from __future__ import annotations

import re
from typing import Optional

from ... import ast
from ...load.shared_data import data_uses
from ...semantics.configured_signals import walk_routine
from ...semantics.edge_traps import own_edges
from ...semantics.instructions import (Action, Branch, Call, ControlAction, EndRoutine,
                                       ForInit, ForNext, Jump, Return, TestDispatch, Wait)
from ...semantics.library.tasks import SyncWait
from ...semantics.program import ENVIRONMENT_NAMESPACE, FIRST_TASK_NAMESPACE, Program
from ...semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA
from ...semantics.state import RUNNING, State
from ...semantics.task_registers import others_unchanged
from ..state_keys import StateKeys
from ..task_waits import TASK_CHOICE, TaskWaits
from .local_runs import LocalRuns
from .cell_uses import CellUses, CellView
from .interrupt_owners import InterruptOwners, serving_tasks
from .relevance import DATA_BY_NAME
from .task_groups import TaskGroups
from .barrier_holds import BarrierHolds
from .typed_names import reached_by_name
from .syntax_footprint import (LOCAL, SHARED, VISIBLE, Footprint, ReferenceParameters,
                               StatementFootprints, SyntaxReads)

_STORE_READ = re.compile(r"\bstore\[(\d+)\]")
_OWN_TASK_BY_NAME = frozenset({"GETDATAVAL", "SETDATAVAL"})



class PartialOrder:
    """The ample sets of one program's states (see the module docstring)."""

    def __init__(self, program: Program, visible_names: set[str], merge: bool = False,
                 project=None):
        self.program = program
        self.names = program.task_names
        self.visible = visible_names
        self._task_waits: Optional[TaskWaits] = None     # (for the configuration asked)
        tasks = len(self.names)
        accessors = _accessors(program)
        uses = [data_uses(program, _namespace(task), moves_read=True) for task in range(tasks)]
        written = [found[1] for found in uses]
        # the slots each task's code writes (no wait's read: ``barrier_holds``' task lists)
        self.code_written = tuple(written)
        used = [found[0] | found[1] for found in uses]
        # a wait's read of data another party writes stores the value it took
        # (``OutsideData.written_by_waits``: a WaitUntil, a WHILE, a polled IF): a write by
        # the task waiting, which no assignment shows; every task reading it may wait for it
        for data in (getattr(program, "outside_data", None) or {}).values():
            if data.written_by_waits:
                for task in range(tasks):
                    if data.slot in uses[task][0]:
                        written[task] = written[task] | {data.slot}
        # SetDataVal and GetDataVal look the name up where the call is: any data its task
        # can name of the Value's type (``typed_names``)
        calls = list(_calls_by_name(program))
        for task, slots in reached_by_name(program, calls, "SETDATAVAL", _task_of_namespace,
                                           accessors).items():
            written[task] = written[task] | slots
            used[task] = used[task] | slots
        for task, slots in reached_by_name(program, calls, "GETDATAVAL", _task_of_namespace,
                                           accessors).items():
            used[task] = used[task] | slots
        # per task: the slots it may write (no other task's code names them: a PERS that
        # every task declares, in a module each loads, is still one task's when only its
        # code reads or writes it), and those it may read (written by no other task)
        self._sharing = (accessors, written, used)
        self.own, self.stable = self._sharing_sets(lambda task, by: by)
        # the signals and robots each task's code touches (``cell_uses``)
        self.cell = CellUses(program)
        # interrupts only their own task's steps can queue (``interrupt_owners``)
        self.owners = InterruptOwners(program, self.cell.written, _intnum_sharing(program,
                                                                                  accessors))
        self.entries = (program.entry,) + tuple(program.task_entries)
        # a barrier (WaitSyncTask, SyncMoveOn/Off) observes whether its partners have ended
        self.barriers = any(isinstance(instruction, SyncWait)
                            for routine in program.routines for instruction in routine.code)
        self._local: dict = {}          # (task, routine, pc) -> bool
        # data written outside the loaded code (PERS a PC writes): each read a choice
        self._outside = getattr(program, "outside_data", None) or {}
        self._references = ReferenceParameters(program)
        self.syntax = self._statements(self.own, self.stable, frozenset(range(tasks)))
        # the footprints against one other task alone (``view``): that task -> (own,
        # stable, statements); None: against no other task
        self._views: dict = {}
        self._undoing: Optional[set] = None     # the tasks with an UNDO handler
        self.groups = TaskGroups(self)
        self.holds = BarrierHolds(self)     # tasks at a barrier waiting for another one
        self.project = project
        self.keys = StateKeys()
        # the cycle proviso's numbering of states (``StatePlaces``), made when first asked:
        # ``places_made`` gives it (a system sets it: its packed table's, in the compiled
        # core, when the step machine takes the reduced steps)
        self._places: Optional["StatePlaces"] = None
        self.places_made = lambda: StatePlaces(self.keys)
        # a task's step goes on through its local instructions (``local_runs``)
        self.runs = LocalRuns(program, self, visible_names, project) if merge else None

    def every_order(self) -> Optional["EveryOrder"]:
        """The stand-in of the ample sets in the full interleaving: every transition, with
        the same local runs (None when steps are not merged)."""
        return EveryOrder(self.runs) if self.runs is not None else None

    def ample(self, state: State, successors: list, config) -> list:
        """``successors`` (labelled, as ``RapidSystem.successors`` gives them) or the
        ample subset of one task's transitions (``config``: the system's, with which a
        task's steps are computed to tell whether it waits)."""
        # the tasks whose next steps interrupts may change (None: every task's)
        serving = serving_tasks(self.program, state[4], self.owners, own_edges(config)) \
            if state[7] == RUNNING else None
        stacks = (state[0],) + state[10]
        running = [task for task, stack in enumerate(stacks) if stack]
        if state[7] != RUNNING or serving is None or len(running) < 2:
            return successors if self.runs is None else self.runs.extend(state, successors,
                                                                         config)
        places = self.places()
        here = places.number(state)
        chosen = self._choose(state, stacks, [task for task in running if task not in serving],
                              successors, config, here)
        if chosen is None and len(running) > 2 and not state[4][0]:
            chosen = self.groups.choose(state, stacks, running, config, here,
                                        lambda task, found: self._labelled(state, found,
                                                                           config))
        if chosen is None:
            chosen = successors if self.runs is None else self.runs.extend(state, successors,
                                                                           config)
        for _, after in chosen:
            places.number(after)
        return chosen

    def places(self) -> "StatePlaces":
        """The numbering of states the proviso reads (made when first asked)."""
        if self._places is None:
            self._places = self.places_made()
        return self._places

    def _choose(self, state: State, stacks: tuple, running: list, successors: list,
                config, here: int) -> Optional[list]:
        for task in running:
            frame = stacks[task][-1]
            if not self.is_ample_candidate(task, frame[0], frame[1]) and \
                    not self.held_candidate(state, stacks, running, task):
                continue
            name = self.names[task]
            mine = [entry for entry in successors if (TASK_CHOICE, name) in entry[0][0]]
            if self.runs is not None:
                mine = self.runs.extend(state, mine, config)
            if mine and self._all_invisible(task, state, mine, config, here):
                return mine
        return None

    def _all_invisible(self, task: int, state: State, entries: list, config,
                       here: int) -> bool:
        """Whether every step of ``entries`` (one task's, from ``state``) may be ample
        (``_invisible_step``), judged once per target: the valuations of edge inputs
        that start no TRAP of the task lead to one state (``staged_step.edge_choices``)."""
        judged: dict = {}               # key -> [(target, judgement)]
        key = self.keys.key
        for _, after in entries:
            met = judged.setdefault(key(after), [])
            found = next((verdict for target, verdict in met if target == after), None)
            if found is None:
                found = self._invisible_step(task, state, after, config, here)
                met.append((after, found))
            if not found:
                return False
        return True

    def _labelled(self, state: State, found: list, config) -> list:
        """One task's transitions ``found`` (``task_transitions``) as the system gives
        them: labelled, projected, run on through the task's local instructions."""
        project = self.project
        entries = [((label, span, output), after if project is None else project(after))
                   for label, span, after, output, _ in found]
        return entries if self.runs is None else self.runs.extend(state, entries, config)

    def _invisible_step(self, task: int, state: State, after: State, config,
                        here: int) -> bool:
        """Whether a step of ``task`` from ``state`` to ``after`` may be ample: it did what
        its instruction does without an error (ERRNO is every task's, and a handler or an
        unwinding changes the task's frames) or started a TRAP of the task (its own INTNO
        changes: ``interrupt_owners``, edge inputs), the task can go on in ``after`` (so
        ``waits(task)`` of ``no_deadlock``'s search stays false, as in ``state``, where
        its instruction was independent), and ``after`` was not numbered before the state,
        whose number is ``here`` (C3)."""
        if after[7] != RUNNING or after == state or after[5] != state[5] or \
                not others_unchanged(self.program, state[6], after[6], task) or \
                0 <= self.places().place(after) <= here:
            return False
        before = state[0] if task == 0 else state[10][task - 1]
        stack = after[0] if task == 0 else after[10][task - 1]
        if not stack:
            return True              # the task ended (its EndRoutine was local: no barrier)
        # the frames that went on keep their modes and the ones the step (run on
        # through calls and returns) pushed are normal: an error would have sent a frame
        # into its handler
        kept = min(len(stack), len(before))
        if any(stack[i][3] != before[i][3] for i in range(kept)) or \
                any(frame[3] != 0 for frame in stack[kept:]):
            return False
        return self.never_waits(stack[-1][0], stack[-1][1]) or \
            self._goes_on(task, after, config)

    def _goes_on(self, task: int, state: State, config) -> bool:
        """Whether ``task`` can go on from ``state``: it does not wait there
        (``task_waits``, the definition ``fairness.TaskFairness.excused`` uses)."""
        return not self.task_waits(config).waits_now(task, state)

    def task_waits(self, config) -> TaskWaits:
        """The tasks' ``waits`` under ``config`` (made when first asked)."""
        waits = self._task_waits
        if waits is None or waits.config is not config:
            waits = self._task_waits = TaskWaits(self.program, config)
        return waits

    def held_at(self, state: State, task: int, config) -> bool:
        """``held_candidate`` where ``ample`` tries one task's ample set: the program
        runs and no interrupt may move the task."""
        if state[7] != RUNNING:
            return False
        serving = serving_tasks(self.program, state[4], self.owners, own_edges(config))
        stacks = (state[0],) + state[10]
        if serving is None or task in serving:
            return False
        quiet = [other for other, stack in enumerate(stacks) if stack and other not in serving]
        return self.held_candidate(state, stacks, quiet, task)

    def held_candidate(self, state: State, stacks: tuple, running: list, task: int) -> bool:
        """Whether the task's instruction, not an ample candidate, conflicts only with
        running tasks its task holds at their barriers (``barrier_holds``), none of
        which an interrupt may move (``running``: the tasks no interrupt may move)."""
        routine, pc = stacks[task][-1][:2]
        if not self.may_be_held(task, routine, pc):
            return False
        alive = {other for other, stack in enumerate(stacks) if stack}
        return self.groups.conflicts(task, routine, pc) & alive <= \
            self.holds.held_by(state, stacks, running, task)

    def may_be_held(self, task: int, routine: int, pc: int) -> bool:
        """Whether the instruction conflicts with some other tasks only (not a wait: a
        task there may wait, which ``task_groups`` alone judges in a view)."""
        instruction = self.program.routines[routine].code[pc]
        if isinstance(instruction, (Wait, SyncWait)) or \
                self.is_ample_candidate(task, routine, pc):
            return False
        return bool(self.groups.conflicts(task, routine, pc))

    def is_ample_candidate(self, task: int, routine: int, pc: int) -> bool:
        """Whether the instruction at ``pc`` of ``routine`` is independent of every step of
        the other tasks (C1) and changes no atom of the check (C2)."""
        key = (task, routine, pc)
        found = self._local.get(key)
        if found is None:
            footprint = self.footprint(task, routine, pc)
            found = self._local[key] = footprint.independent and not footprint.visible
        return found

    def footprint(self, task: int, routine_index: int, pc: int,
                  view: Optional[tuple] = None) -> "Footprint":
        """What the instruction at ``pc`` of ``routine`` touches, as far as the other tasks
        and the atoms are concerned (see ``Footprint``); ``view``: (own, stable,
        statements) judged against some of the other tasks only (``view``), else all."""
        own, stable, syntax = view or (self.own, self.stable, self.syntax)
        readable = stable[task]
        routine = self.program.routines[routine_index]
        instruction = routine.code[pc]
        kind = type(instruction)
        # (a signal read is judged from the syntax: the tasks that may write the signal,
        # ``cell_uses``; the fused forms below read none)
        if kind is Jump:
            return LOCAL if instruction.target != pc else SHARED
        if kind is ForNext:
            return self._local_write(routine, instruction.slot)
        if kind is ForInit:
            if instruction.fusion is None or \
                    not self._reads_allowed(readable, *instruction.fusion):
                return SHARED
            return self._local_write(routine, instruction.slot)
        if kind is Branch:
            if pc in (instruction.target_true, instruction.target_false):
                return SHARED
            if instruction.fusion is not None and \
                    self._reads_allowed(readable, instruction.fusion):
                return LOCAL
            # a condition the fused step does not take (an indexed array ...) or whose
            # compiled form reads through a reference: what it reads, from its syntax
            return LOCAL if syntax.reads.allowed(task, routine,
                                                      instruction.expression) else SHARED
        if kind is TestDispatch:
            # TEST compares its subject with the CASE values and goes on at one of its
            # branches: as a condition, when they read only data no other task writes
            fusion = instruction.fusion
            return LOCAL if fusion is not None and self._reads_allowed(
                readable, fusion[0], *(value for values in fusion[1] for value in values)) \
                else SHARED
        if kind is Call:
            # entering a procedure without arguments pushes a frame of the task's own
            if not instruction.binders and instruction.routine.kind == "PROC":
                return LOCAL
            return syntax.call(task, routine, instruction)
        if kind is Return and instruction.value_fn is not None:
            return syntax.returned(task, routine, instruction)
        if kind is EndRoutine or kind is Return and instruction.value_fn is None:
            # leaving a procedure writes only the task's frames; the task's last one ends
            # the task, which a barrier waiting for it observes (``blocked_at_barrier``)
            if routine.kind != "PROC":
                return SHARED
            ends_task = routine_index == self.entries[task]
            return SHARED if ends_task and self.barriers else LOCAL
        if kind is Action and instruction.fusion is not None:
            where, slot, value = instruction.fusion
            if self._reads_allowed(readable, value):
                if where != "store":
                    return self._local_write(routine, slot)
                if slot in own[task]:
                    return VISIBLE if self.program.globals[slot].key in self.visible \
                        else LOCAL
        if kind is Wait and view is not None:
            # (in a group only: its task may wait there, ``task_groups``)
            return syntax.wait(task, routine, instruction)
        if kind is ControlAction and view is not None and \
                syntax.restarts_cycle(routine, instruction):
            # (in a group only) ExitCycle: the task's frames, unless an UNDO handler runs
            return SHARED if self._undoes(task) else LOCAL
        if kind is Action or kind is ControlAction:
            # an element or component, Incr, a call's output, a read through a reference
            # ... (``syntax_footprint``)
            return syntax.statement(task, routine, instruction)
        return SHARED

    def view(self, other: Optional[int]) -> tuple:
        """(own, stable, statements) as if ``other`` were the only other task (None: as
        if there were none), for ``footprint``: an instruction LOCAL there touches
        nothing that task's code names or writes (``TaskGroups``)."""
        found = self._views.get(other)
        if found is None:
            others = frozenset(() if other is None else (other,))
            own, stable = self._sharing_sets(lambda task, by: others & by)
            found = self._views[other] = (own, stable, self._statements(own, stable, others))
        return found

    def _undoes(self, task: int) -> bool:
        """Whether a routine of the task has an UNDO handler (ExitCycle would run it)."""
        if self._undoing is None:
            self._undoing = {_task_of_namespace(routine.namespace)
                             for routine in self.program.routines if routine.undo_pc >= 0}
        return task in self._undoing

    def task_of_routine(self, routine: int) -> Optional[int]:
        """The task whose code declares the routine (None: the environment's)."""
        return _task_of_namespace(self.program.routines[routine].namespace)

    def _sharing_sets(self, others_of) -> tuple[list, list]:
        """Per task, the global slots it may write and those it may read, given the tasks
        ``others_of(task, by)`` of those naming a slot (``by``) that count."""
        accessors, written, used = self._sharing
        own, stable = [], []
        for task in range(len(self.names)):
            own.append(frozenset(slot for slot, by in accessors.items()
                                 if -1 not in by and not any(
                                     slot in used[other] for other in others_of(task, by)
                                     if other != task)))
            stable.append(frozenset(slot for slot, by in accessors.items()
                                    if not any(written[other] and slot in written[other]
                                               for other in others_of(task, by)
                                               if other != task)))
        return own, stable

    def _statements(self, own: list, stable: list, others: frozenset) -> StatementFootprints:
        """The footprints from the syntax, judged against the tasks ``others`` (each task
        against those of them that are not itself)."""
        cell = CellView(self.cell, [others - {task} for task in range(len(self.names))])
        reads = SyntaxReads(stable, self._outside, self._references, cell)
        found = StatementFootprints(reads, own, self.visible, self._visible_local,
                                    [data.key for data in self.program.globals])
        first = getattr(self, "syntax", None)
        if first is not None:        # (what the syntax says, found once for every view)
            reads._loops, found._nodes = first.reads._loops, first._nodes
        return found

    def never_waits(self, routine_index: int, pc: int) -> bool:
        """Whether a step of the instruction at ``pc`` always changes the state (moves the
        task on or ends it): a task there does not wait (``model.waiting``), without
        computing its steps."""
        instruction = self.program.routines[routine_index].code[pc]
        kind = type(instruction)
        if kind is Jump:
            return instruction.target != pc
        if kind is Branch:
            return pc not in (instruction.target_true, instruction.target_false)
        if kind in (ForNext, ForInit, EndRoutine, Call, Return, TestDispatch):
            return True
        return kind is Action and instruction.fusion is not None

    def _local_write(self, routine, slot: int) -> "Footprint":
        """A write of routine data (a local variable, a FOR variable): visible when an
        atom names it or its routine."""
        return VISIBLE if self._visible_local(routine, slot) else LOCAL

    @staticmethod
    def _reads_allowed(readable: frozenset, *compiled) -> bool:
        """Whether the expressions read only data of ``readable`` (the global slots no
        other task writes), and no signal."""
        for expression in compiled:
            source = expression.source
            if source is None or "cx" in source:
                return False
            for slot in _STORE_READ.findall(source):
                if int(slot) not in readable:
                    return False
        return True

    def _visible_local(self, routine, slot: int) -> bool:
        name = routine.local_names[slot] if slot < len(routine.local_names) else ""
        return name.upper() in self.visible or routine.name.upper() in self.visible


class StatePlaces:
    """The proviso's numbering of states, by key (``model.state_keys``), in the order the
    system numbered them (the module docstring, C3); the Python engine's, and the compiled
    core's where its step machine does not take the reduced steps."""

    def __init__(self, keys: StateKeys):
        self.keys = keys
        self._numbers: dict[int, int] = {}

    def place(self, state: State) -> int:
        """The state's number, -1 when it has none."""
        return self._numbers.get(self.keys.key(state), -1)

    def number(self, state: State) -> int:
        """The state's number, given now when it has none."""
        numbers = self._numbers
        return numbers.setdefault(self.keys.key(state), len(numbers))


class EveryOrder:
    """Every transition, each run on through its task's local instructions
    (``PartialOrder.every_order``): the full interleaving of the merged model."""

    def __init__(self, runs: LocalRuns):
        self.runs = runs

    def ample(self, state: State, successors: list, config) -> list:
        return self.runs.extend(state, successors, config)

    def every_order(self) -> "EveryOrder":
        return self


def _namespace(task: int) -> int:
    return 0 if task == 0 else FIRST_TASK_NAMESPACE + task - 1


def _task_of_namespace(namespace: int) -> Optional[int]:
    if namespace == ENVIRONMENT_NAMESPACE:
        return None
    return 0 if namespace < FIRST_TASK_NAMESPACE else namespace - FIRST_TASK_NAMESPACE + 1


def _accessors(program: Program) -> dict[int, set[int]]:
    """Global slot -> the tasks that can name it (its declaring task; for shared PERS,
    every task declaring it; for system module data, every task)."""
    linker = program.scopes
    found: dict[int, set[int]] = {data.slot: set() for data in program.globals}
    scopes = [(namespace, scope) for namespace, scope in linker.namespaces.items()] + \
        [(namespace, scope) for (namespace, _), scope in linker.module_scopes.items()]
    for namespace, scope in scopes:
        task = _task_of_namespace(namespace)
        for symbol in scope.names.values():
            if symbol.kind == GLOBAL_DATA and symbol.slot in found:
                found[symbol.slot].add(task if task is not None else -1)
    # data of the system modules (tool0, wobj0, reg1 ...): one object every task names
    every = set(range(len(program.task_names)))
    for symbol in linker.system.names.values():
        if symbol.kind == GLOBAL_DATA and symbol.slot in found:
            found[symbol.slot] |= every
    return found


def _intnum_sharing(program: Program, accessors: dict) -> set[int]:
    """The tasks whose code may name interrupt-number data another task's code names too
    (``interrupt_owners``: another task's IDelete or ISleep may then touch theirs)."""
    found: set[int] = set()
    for data in program.globals:
        if getattr(data.type, "key", None) == "INTNUM":
            by = accessors.get(data.slot, set())
            if len(by) > 1 or -1 in by:
                found |= by
    return found


def reaches_data_by_name(program: Program) -> bool:
    """Whether some routine reaches data by its name at run time in a way the reduction
    cannot bound: GetDataVal or SetDataVal naming another task (``\\TaskRef``,
    ``\\TaskName``), SetAllDataVal or GetNextSym.  Without a task argument, the name is
    looked up where the call is (``library.data_access``), so the data is its task's."""
    return any(not _own_task_only(node) for _, node in _calls_by_name(program))


def _calls_by_name(program: Program):
    """(routine, call) per call that reaches data by its name at run time."""
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node in walk_routine(routine.ast):       # (handlers call them too)
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                    node.name.key in DATA_BY_NAME:
                yield routine, node


def _own_task_only(call) -> bool:
    """Whether a call reaching data by name reaches only its own task's data."""
    return call.name.key in _OWN_TASK_BY_NAME and not any(
        argument.name is not None and argument.name.key in ("TASKREF", "TASKNAME")
        for argument in call.args)
