"""Tasks held at a barrier: they take no step that matters until a group's task moves.

A task standing at a ``WaitSyncTask`` (or SyncMoveOn/Off) without ``\\TimeOut``
passes only once every task its list names has reached the same syncident
(``library.tasks``: each task's syncident holds its generation).  When a task
``g`` of a group (``task_groups``) is one of those it still waits for, and
``g``'s next instruction is not a barrier (no group task's is: a barrier is
never independent), nothing but a step of ``g`` changes ``g``'s syncident.  So
along every path of the other tasks' steps the waiting task stays where it is:
its only step there is its arrival, which writes its own syncident, which no
instruction of the group reads.  It cannot touch what the group's next
instructions read or write, and need not join the group, however its code
conflicts with them.

One more thing may let it pass: a change of its task list, which the barrier
reads at each step.  The task list is then held too: every running task whose
code may write the list's data is in the group or is itself held (a greatest
fixpoint: a held task writes nothing).  A list that is not global data of the
program holds no one, nor one written from outside the loaded code whose reads may
take several values (``load.outside_data``); a list whose task names no code
compares is read as stored, and only the loaded code's writes (``PartialOrder``'s
written slots, a wait's stored reads included) change it.
"""
from __future__ import annotations

from typing import Optional

from ...semantics.library.tasks import SyncWait


class BarrierHolds:
    """Per state, the running tasks at a barrier and whom they still wait for."""

    def __init__(self, order):
        self.order = order                      # PartialOrder: its tasks' written slots
        self._number = {name: number for number, name in enumerate(order.names)}
        self._writers: dict = {}                # list slot -> the tasks that may write it
        outside = getattr(order.program, "outside_data", None) or {}
        # data written outside the loaded code whose reads may choose among values: a
        # barrier's list of it may name other tasks at each step
        self._outside = {data.slot for data in outside.values() if any(
            domain is not None and len(domain) > 1 for domain in data.domains.values())}

    def waiting(self, state, stacks: tuple, running: list) -> tuple:
        """((task, the tasks it waits for, the tasks that may write its list), ...) for
        the running tasks at a barrier without \\TimeOut that still wait for someone
        and whose list only loaded code writes."""
        found = []
        for task in running:
            frame = stacks[task][-1]
            instruction = self.order.program.routines[frame[0]].code[frame[1]]
            if not isinstance(instruction, SyncWait) or instruction.times_out:
                continue
            writers = self._list_writers(instruction)
            if writers is None:
                continue
            missing = frozenset(self._number[name] for name in
                                instruction.missing(state[1], task) if name in self._number)
            if missing:
                found.append((task, missing, writers))
        return tuple(found)

    def _list_writers(self, instruction) -> Optional[frozenset]:
        plan = getattr(instruction, "machine", None)
        if plan is None:
            return None                         # (a list in routine data, a \\TimeOut)
        slot = plan.task_list
        if slot is None:
            return frozenset()                  # SyncMoveOff: no list is read
        if slot in self._outside:
            return None
        found = self._writers.get(slot)
        if found is None:
            written = self.order._sharing[1]
            found = self._writers[slot] = frozenset(
                task for task in range(len(written)) if slot in written[task])
        return found


def held(waiting: tuple, group: set, running: set) -> frozenset:
    """The tasks of ``waiting`` (``BarrierHolds.waiting``) held by ``group``: waiting
    for one of its tasks, their lists written by no running task but the group's and
    the held ones (the greatest such set)."""
    found = {task for task, missing, _ in waiting if missing & group and task not in group}
    writers = {task: by & running for task, _, by in waiting}
    changed = True
    while changed:
        changed = False
        for task in sorted(found):
            if not _writers_held(writers[task], group, found):
                found.discard(task)
                changed = True
    return frozenset(found)


def _writers_held(writers: frozenset, group: set, found: set) -> bool:
    """Whether the running tasks that may write a task list are in the group or held."""
    return writers <= group | found
