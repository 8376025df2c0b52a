"""Tasks held at a barrier by another task: they take no step that matters until it moves.

A task ``u`` standing at a ``WaitSyncTask`` (or SyncMoveOn/Off) without
``\\TimeOut`` passes only once every task its list names has reached the same
syncident (``library.tasks``: each task's syncident holds its generation).  When a
task ``t`` is one of those it still waits for and ``t``'s next instruction is not
a barrier, nothing but a step of ``t`` changes ``t``'s syncident.  So along every
path of the other tasks' steps from the state, ``u`` stays where it is: its only
step there is its arrival, which writes its own syncident, which no instruction
but a barrier reads.  ``u`` is *held* by ``t``.  So is a task whose barrier has
released it (every task arrived) and whose next instruction is such a barrier:
its pass writes only its own syncident too.

One more thing may let ``u`` pass: a change of its task list, which the barrier
reads at each step.  So every running task whose code may write the list's data
must be held itself (a greatest fixpoint: a held task writes nothing).  A list that
is not global data holds no one, nor one written from outside the loaded code
whose reads may take several values (``load.outside_data``).  A list whose names
no code compares is read as stored (a wait's read of it stores the stored value),
and only the tasks whose code writes it change it.

``PartialOrder`` uses this for one-task ample sets: an instruction of ``t`` that
conflicts only with tasks held by ``t`` is independent of every step they can take
before ``t`` moves (issue 27: the COMPAS RRC controller task at its barrier while
the receiver's and the sender's init routines write the data it reads after it).
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
        # the other lists written outside: their reads take the stored value
        self._read_as_stored = frozenset(outside) - self._outside

    def held_by(self, state, stacks: tuple, quiet: list, task: int) -> frozenset:
        """The tasks of ``quiet`` (running tasks no interrupt may move) held by ``task``
        (module docstring)."""
        alive = frozenset(other for other, stack in enumerate(stacks) if stack)
        return held(self.waiting(state, stacks, quiet), task, alive)

    def waiting(self, state, stacks: tuple, running: list) -> tuple:
        """((task, the tasks it waits for, the tasks that may write its list), ...) for
        the running tasks at a barrier without \\TimeOut that still wait for someone, or
        released by one and next at such a barrier, and whose list only loaded code
        writes."""
        found = []
        store = state[1]
        for task in running:
            routine, pc = stacks[task][-1][:2]
            code = self.order.program.routines[routine].code
            instruction = code[pc]
            if not _plain_barrier(instruction):
                continue
            missing = self._missing(instruction, store, task)
            if not missing and 0 <= instruction.next < len(code) and \
                    _plain_barrier(code[instruction.next]):
                instruction = code[instruction.next]        # (released: it passes next)
                missing = self._missing(instruction, store, task)
            writers = self._list_writers(instruction)
            if missing and writers is not None:
                found.append((task, missing, writers))
        return tuple(found)

    def _missing(self, instruction, store, task: int) -> frozenset:
        return frozenset(self._number[name] for name in instruction.missing(store, task)
                         if name in self._number)

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
            # a wait's read of a list read as stored stores the stored value: only the
            # tasks whose code writes it change it
            written = self.order.code_written if slot in self._read_as_stored else \
                self.order._sharing[1]
            found = self._writers[slot] = frozenset(
                task for task in range(len(written)) if slot in written[task])
        return found


def _plain_barrier(instruction) -> bool:
    """A barrier without \\TimeOut."""
    return isinstance(instruction, SyncWait) and not instruction.times_out


def held(waiting: tuple, task: int, running: frozenset) -> frozenset:
    """The tasks of ``waiting`` (``BarrierHolds.waiting``) held by ``task``: waiting for
    it, their lists written by no task of ``running`` but held ones (the greatest such
    set)."""
    found = {waiter for waiter, missing, _ in waiting if task in missing and waiter != task}
    writers = {waiter: by & running for waiter, _, by in waiting}
    changed = True
    while changed:
        changed = False
        for waiter in sorted(found):
            if not writers[waiter] <= found:
                found.discard(waiter)
                changed = True
    return frozenset(found)
