"""An edge input's interrupt starts its TRAP in the step that brings the edge.

An *edge input* (``model.edge_inputs``) is a free digital input that only interrupt
orders name; each step chooses its value and the state after keeps it at 0.  Before,
its edge queued the interrupt at the end of the step and the TRAP started in the next
one, so every edge doubled the states it passed through; and an edge that came while
its task was in a TRAP, or had interrupts disabled, stayed queued for the whole TRAP
(in the Hanoi cell's TASK1, 17,296 of the first 20,000 states had one pending).

Here, for an edge input that interrupts of one task only watch (``served_edges``), the
edge is handled at the start of the step that chooses it:

- if the step is one of that task and the task could start a TRAP now (interrupts
  enabled, not in a TRAP) it starts the TRAP of the first active interrupt the edge
  orders, in this step, instead of its instruction, ahead of any interrupt pending;
- otherwise the edge is dropped: it queues nothing.

No run of the controller is lost.  In the exact model an edge queues the interrupt,
which starts its TRAP at a later step of the task, one where it can (or is dropped
unseen by ISleep or IDelete); here that run is the one whose edge is chosen in that very
step, and the interrupts pending then are those of the exact run without the edge
inputs' (the first of them the task takes is the same).  The input is read by nothing
else, so the step its value rose in is seen by nothing but the interrupt.  The runs
added: a TRAP started at step N is the exact model's edge at step N-1, pending at the
start of step N with the same table, flags and stack, so it starts there when no other
interrupt is queued before it; and the exact run needs the input at 0 before step N-1.
So ``model.edge_inputs.realizable`` sends a counterexample in which such a TRAP starts
while an interrupt is pending, or two edges of a rising input start TRAPs in two steps
in a row, to the exact model (RMC733).  Edges that were dropped need nothing.
"""
from __future__ import annotations

from typing import Optional

from .program import FIRST_TASK_NAMESPACE


def routine_task(namespace: int) -> int:
    """The task whose steps run a routine of ``namespace`` (the environment's: the main
    task's)."""
    return namespace - FIRST_TASK_NAMESPACE + 1 if namespace >= FIRST_TASK_NAMESPACE else 0


def own_edges(config) -> tuple:
    """The edge inputs each watched by the interrupts of one task only
    (``CheckConfig.served_edges``)."""
    return getattr(config, "served_edges", ())


def calmed(before, now, own: tuple):
    """The signal values ``before`` with the inputs ``own`` at their values in ``now``: the
    step's start handled their edges, so the signal edges at its end leave them out."""
    changed = [x for index in own if now[index] != before[index] for x in (index, now[index])]
    return before.mset(*changed) if changed else before


def edge_interrupt(program, table: tuple, own: tuple, before, now, task: int) -> Optional[int]:
    """The number of the first active interrupt of ``task`` (the task that steps) in
    ``table`` ordered on one of the inputs ``own`` whose change from ``before`` to ``now``
    is its edge, else None."""
    for entry in table:
        source = entry[2]
        if not entry[3] or not source or source[0] != "signal" or source[1] not in own:
            continue
        index = source[1]
        new = now[index]
        if new == before[index] or not (source[2] == 2 or source[2] == new):
            continue
        if routine_task(program.routines[entry[1]].namespace) == task:
            return entry[0]
    return None
