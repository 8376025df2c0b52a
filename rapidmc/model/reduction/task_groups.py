"""Ample sets of several tasks: the tasks whose next steps touch the same data.

``partial_order`` keeps the transitions of one task where its next instruction
is independent of every other task.  At a handshake (T_ROB1 reading the PERS
flag T_ROB2 is about to write) no single task qualifies, and the state was
expanded fully, interleaving every other task too (a logger, a task polling its
own signals).  Here the ample set may be the transitions of a *group* ``G`` of
the running tasks (a stubborn set of tasks, Valmari; a persistent set,
Godefroid, *Partial-Order Methods for the Verification of Concurrent Systems*,
ch. 4), built from one task ``t``:

* ``G`` starts as ``{t}``; for each task ``g`` of ``G``, every running task
  ``u`` whose code (any of its instructions, from its declarations:
  ``data_uses``) writes data ``g``'s next instruction reads, or names data that
  instruction writes, joins ``G`` (``conflicts``: ``g``'s instruction judged by
  ``PartialOrder.footprint`` as if ``u`` were the only other task).  A task
  that has ended takes no step again and never joins.  An instruction that is
  not independent even of no other task (a signal, a call of a predefined
  routine, data written outside the loaded code, an atom's data) stops the
  group.  Judged in a group only: a WaitUntil without a time limit reads its
  condition (its task may wait there, below), and ExitCycle writes only its
  task's frames when no routine of the task has an UNDO handler.  Judged per
  state: an IDelete of an intnum holding 0 that no other task writes deletes
  nothing (``empty_deletes``), and a constant written where it is already stored
  to data no other task writes changes nothing (``unchanged_writes``): each
  conflicts with no task there.
* The tasks outside ``G`` then never touch what ``G``'s next instructions read
  or write, whatever they run next: every path of their steps from the state
  commutes with each of ``G``'s transitions and neither enables nor disables
  them, so ``G``'s transitions are a persistent set (C1).  A task of ``G`` that
  waits (every step of its changes nothing, at a WaitUntil) gives no
  transition; the tasks that may end its wait write what it reads, so they are
  in ``G``, and until one of ``G``'s transitions is taken it keeps waiting.
* Each task of ``G`` that does not wait must have transitions, none of them
  idle, each one as ``PartialOrder._invisible_step`` asks of a one-task ample
  set: no error, the task goes on after it, the target not numbered before the
  state (C3); no instruction of ``G`` is visible (C2); and after each of them
  every other task of ``G`` waits as before (``waits`` of ``no_deadlock``
  unchanged: the waiting still wait, the others can go on).  At least one task
  of ``G`` does not wait, and a group of every running task is the full
  expansion and is not tried.  A group of one task is tried where its
  instruction is independent in a group only (ExitCycle, an IDelete that deletes
  nothing): the one-task ample sets of ``PartialOrder`` already covered the others.

Signals and robots count as data here (``cell_uses``): a signal read conflicts
with the tasks whose code may set the signal, a robot reading with the task
moving that robot, a move with the tasks reading its robot.

Groups are tried only where no one-task ample set exists, from each running
task in order, and the first that passes is kept: both engines pick the same
one (the compiled core asks ``PackedTable.python_group_ample``, where each
task's steps are Python's).  tests/test_task_groups.py holds the verdicts
against the unreduced search.
"""
from __future__ import annotations

from typing import Callable, Optional

from ...semantics.staged_step import task_transitions
from ...semantics.instructions import Wait
from ...semantics.state import State
from .empty_deletes import EmptyDeletes
from .unchanged_writes import UnchangedWrites

GROUPS_KEPT = 1 << 14        # the groups per combination of the tasks' instructions kept


class TaskGroups:
    """The candidate groups of a state's running tasks (see the module docstring)."""

    def __init__(self, order):
        self.order = order                  # PartialOrder: footprints and the proviso
        self.tasks = len(order.names)
        self._conflicts: dict = {}          # (task, routine, pc) -> frozenset or None
        self._groups: dict = {}             # the tasks' (task, routine, pc, empty) -> groups
        self.deletes = EmptyDeletes(order)  # IDelete of an intnum holding 0, per state
        self.writes = UnchangedWrites(order)  # a write of the value stored, per state

    def conflicts(self, task: int, routine: int, pc: int) -> Optional[frozenset]:
        """The other tasks whose code touches what the instruction at ``pc`` of ``routine``
        reads or writes (empty: it is independent of all); None when it may not be in a
        group (not independent of no other task, or visible)."""
        key = (task, routine, pc)
        if key in self._conflicts:
            return self._conflicts[key]
        order = self.order
        found: Optional[frozenset] = frozenset()
        if order.task_of_routine(routine) not in (None, task):
            found = None                  # (another task's routine: never its to run)
        elif order.is_ample_candidate(task, routine, pc):
            pass                          # (independent of every other task)
        elif not _local(order.footprint(task, routine, pc, order.view(None))):
            found = None
        else:
            found = frozenset(other for other in range(self.tasks) if other != task and
                              not _local(order.footprint(task, routine, pc,
                                                         order.view(other))))
        self._conflicts[key] = found
        return found

    def may_join(self, task: int, routine: int, pc: int) -> bool:
        """Whether the instruction may be in a group other than the one-task ample sets
        ``PartialOrder`` tries: it conflicts with some other task but not with every
        task, or with none while it is judged independent in a group only (ExitCycle)."""
        found = self.conflicts(task, routine, pc)
        if found is None:
            return self.idle_reader(task, routine, pc) is not None
        return bool(found) or not self.order.is_ample_candidate(task, routine, pc)

    def idle_reader(self, task: int, routine: int, pc: int) -> Optional[Callable]:
        """``idle(stack, state)``: whether the instruction's step touches nothing another
        task reads or writes in that state (``empty_deletes``, ``unchanged_writes``);
        None when it never does."""
        for found in (self.deletes, self.writes):
            reader = found.reader(task, routine, pc)
            if reader is not None:
                return reader
        return None

    def candidates(self, stacks: tuple, running: list, state: State) -> tuple:
        """The groups of fewer than all running tasks, in the order of the task each is
        built from (each once), but for the one-task ample sets already tried."""
        empty = self._idle_tasks(stacks, running, state)
        key = tuple((task, stacks[task][-1][0], stacks[task][-1][1], task in empty)
                    for task in running)
        found = self._groups.get(key)
        if found is None:
            found = []
            for task in running:
                group = self._closure(task, stacks, set(running), empty)
                if group is not None and len(group) < len(running) and \
                        group not in found and (len(group) > 1 or not self.order.
                                                is_ample_candidate(task, *stacks[task][-1][:2])):
                    found.append(group)
            found = tuple(found)
            if len(self._groups) >= GROUPS_KEPT:
                self._groups.clear()
            self._groups[key] = found
        return found

    def _idle_tasks(self, stacks: tuple, running: list, state: State) -> frozenset:
        """The running tasks at an IDelete that deletes nothing or a write that changes
        nothing in ``state`` (``idle_reader``): independent of every other task there."""
        found = []
        for task in running:
            frame = stacks[task][-1]
            reader = self.idle_reader(task, frame[0], frame[1])
            if reader is not None and reader(stacks[task], state):
                found.append(task)
        return frozenset(found)

    def _closure(self, task: int, stacks: tuple, running: set,
                 empty: frozenset) -> Optional[tuple]:
        group, work = {task}, [task]
        while work:
            member = work.pop()
            frame = stacks[member][-1]
            found = frozenset() if member in empty else \
                self.conflicts(member, frame[0], frame[1])
            if found is None:
                return None
            for other in found & running:
                if other not in group:
                    group.add(other)
                    work.append(other)
        return tuple(sorted(group))

    def choose(self, state: State, stacks: tuple, running: list, config, here: int,
               targets: Callable) -> Optional[list]:
        """The transitions of the first candidate group that qualifies (the module
        docstring), None when there is none.  ``targets(task, found)``: the task's
        transitions ``found`` (``task_transitions``) as the caller keeps them, (item,
        target state) each."""
        for group in self.candidates(stacks, running, state):
            chosen = self._group_transitions(state, group, config, here, targets)
            if chosen is not None:
                return chosen
        return None

    def _group_transitions(self, state: State, group: tuple, config, here: int,
                           targets: Callable) -> Optional[list]:
        order, program = self.order, self.order.program
        stacks = stacks_of(state)
        moving, waiting = [], []
        for task in group:               # (first the cheap test of every task)
            found = task_transitions(program, state, task, config)
            if not found:
                return None
            idle = [transition[2] == state for transition in found]
            if all(idle) and type(_instruction(program, stacks[task])) is Wait:
                waiting.append(task)          # (it waits: no transition of its is kept)
            elif any(idle):
                return None
            else:
                moving.append((task, found))
        if not moving:
            return None
        # whether another task of the group waits after a step: at an instruction that
        # never waits it cannot (``PartialOrder.never_waits``)
        watched = [other for other in group
                   if other in waiting or not order.never_waits(*stacks[other][-1][:2])]
        chosen = []
        for task, found in moving:
            kept = targets(task, found)
            for _, after in kept:
                if not order._invisible_step(task, state, after, config, here):
                    return None
                # no step of one task of the group changes whether another one waits
                # (``waits`` of ``no_deadlock``): the waiting ones still wait, the others
                # can still go on
                if not all(self._waits(other, after, config) == (other in waiting)
                           for other in watched if other != task):
                    return None
            chosen += kept
        return chosen

    def _waits(self, task: int, state: State, config) -> bool:
        """Whether ``task`` cannot go on at ``state`` (``task_waits``, the one definition)."""
        return self.order.task_waits(config).waits_now(task, state)

def _local(footprint) -> bool:
    return footprint.independent and not footprint.visible


def stacks_of(state: State) -> tuple:
    return (state[0],) + state[10]


def _instruction(program, stack: tuple):
    frame = stack[-1]
    return program.routines[frame[0]].code[frame[1]]
