"""Which tasks' steps interrupts touch: the tasks that may still be ample in such a state.

A state with connected or pending interrupts used to be expanded fully.  Yet each
task serves the interrupts it connected, on its own stack, in its own steps
(``semantics.step._step_some_task``): in a step of task ``t``

* a timer may fire only when ``t`` connected it (``_timers_may_fire``);
* an edge input's edge starts a TRAP only in a step of the task whose interrupts
  watch it; in any other step it is dropped (``edge_traps``);
* a pending interrupt starts its TRAP only in its own task, except one no longer
  connected, which whichever task steps drops (``staged_step.next_pending``);
* delayed signal changes (PulseDO, ``\\SDelay``) happen in the next step of any task
  (``timing.apply_scheduled``);
* a signal edge queues the interrupt watching it: only a step that changes a signal
  does that, and the partial-order reduction already counts a signal named by another
  task's code (its ISignalDI/ISignalDO names it) as shared (``cell_uses``).

So where no delayed change is due and every pending interrupt is connected, a task
that serves no connected interrupt steps as it would without them: its step reads
and writes nothing of the interrupt state, and whatever the serving tasks do with
their interrupts (queue, enter a TRAP, run it: the TRAP's code is their code, whose
data the reduction already judges) commutes with it as their other steps do.  Such a
task may be an ample set by the usual conditions (``partial_order``); a task serving
an interrupt may not (its step may start a TRAP instead of its instruction).
"""
from __future__ import annotations

from typing import Optional

from ...semantics.edge_traps import routine_task


def serving_tasks(program, interrupts) -> Optional[frozenset]:
    """The tasks whose next step the interrupt state ``interrupts`` may change (their
    own TRAPs; none without interrupts), or None when it may change any task's (a
    delayed signal change due, a pending interrupt no longer connected)."""
    table, pending, scheduled = interrupts[0], interrupts[1], interrupts[3]
    if not (table or pending or scheduled):
        return frozenset()
    if scheduled:
        return None
    connected = {entry[0] for entry in table}
    if any(number not in connected for number in pending):
        return None
    routines = program.routines
    return frozenset(routine_task(routines[entry[1]].namespace) for entry in table)
