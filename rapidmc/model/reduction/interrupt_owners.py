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

**Quiet interrupts.**  A task's connected interrupt that no other party can make
pending does not make it serve while it is not pending (``InterruptOwners``): one
connected but not ordered yet (``CONNECT`` before ``ISignalDO``), or ordered on the
edge of a digital *output* (``ISignalDO``) that no other task's
code may write (``CellUses.written``), that no party left out sets (``Signal.outside``,
``also_set_by``), that nothing drives or binds at run time.  Only a step of its own
task can then change that output, so only its own steps can queue the interrupt: in
the task's next step no TRAP can start, and its step is its instruction, as without
the interrupt.  A step that sets the output queues the interrupt (the next state has
it pending, and the task serves again there); no other task's step reads or writes
that entry, as long as no other task's code names the interrupt-number data of the
task (``IDelete``, ``ISleep`` ... on a shared ``intnum``: the task is never quiet
then).  Timers, persistent-data interrupts, input and analog-input edges and a
pending interrupt keep the task serving.  (The joseballester socket server orders its
reset interrupt on an output no loaded code sets to 1: it is ample again wherever the
interrupt has not come, instead of never.)

**Interrupts on edge inputs.**  An interrupt ordered on a served edge input
(``model.edge_inputs.served_edges``; ``semantics.edge_traps``) is never queued: its edge
is chosen in a step of its own task, which starts the TRAP then (pushes a frame on its own
stack, sets its own INTNO, deactivates its own entry when ``\\Single``), and in a step of
any other task the edge is dropped.  So where every connected interrupt of a task is on
such an input (or quiet) and none is pending, no other task's step reads or writes
anything of its interrupts, and the task's steps, TRAP starts among them, are its own:
the ample sets (``partial_order``, with ERRNO, INTNO and the enable flag per task,
``Program.registers_per_task``) may take all of them, its instruction judged as usual and
each TRAP start an invisible step of its task.  Local runs (``local_runs``) still stop
before such a task's next step, which may be a TRAP start instead of the instruction.  A
task whose intnum data another task's code names keeps the old rule.  (The PickMaster
supervision server serves five interrupts on edge inputs and the project manager one:
before, both served in every state once connected, and no task was ever ample.)
"""
from __future__ import annotations

from typing import Optional

from ...semantics.edge_traps import routine_task

OUTPUT_KINDS = frozenset({"DO"})     # (ISignalDI and ISignalDO order "signal" sources)


def serving_tasks(program, interrupts, quiet=None, edges: tuple = ()) -> Optional[frozenset]:
    """The tasks whose next step the interrupt state ``interrupts`` may change (their
    own TRAPs; none without interrupts), or None when it may change any task's (a
    delayed signal change due, a pending interrupt no longer connected); ``quiet``:
    an ``InterruptOwners`` whose quiet interrupts make no task serve, nor, with the
    served edge inputs ``edges``, the interrupts on them (``InterruptOwners.on_own_edge``:
    for the ample sets only, whose task's steps include those TRAP starts)."""
    table, pending, scheduled = interrupts[0], interrupts[1], interrupts[3]
    if not (table or pending or scheduled):
        return frozenset()
    if scheduled:
        return None
    connected = {entry[0] for entry in table}
    if any(number not in connected for number in pending):
        return None
    routines = program.routines
    return frozenset(routine_task(routines[entry[1]].namespace) for entry in table
                     if quiet is None or not (quiet.is_quiet(entry, pending) or
                                              edges and quiet.on_own_edge(entry, pending,
                                                                          edges)))


class InterruptOwners:
    """Which connected interrupts only their own task's steps can make pending (the
    module docstring, "Quiet interrupts"), from the tasks' code."""

    def __init__(self, program, written_signals: list, intnum_shared: set):
        self.program = program
        tasks = len(program.task_names)
        # per task: the signals the other tasks' code may write (None: any)
        self._others_write: list = []
        for task in range(tasks):
            found: Optional[set] = set()
            for other in range(tasks):
                if other == task:
                    continue
                if written_signals[other] is None:
                    found = None
                    break
                found |= written_signals[other]
            self._others_write.append(found)
        self._shared = frozenset(intnum_shared)     # tasks naming an intnum another names
        self._quiet_signal: dict = {}               # (task, signal index) -> bool

    def is_quiet(self, entry, pending: tuple) -> bool:
        """Whether interrupt ``entry`` of the table cannot start a TRAP in its task's
        next step and no other task's step can queue it."""
        if entry[0] in pending:
            return False
        task = routine_task(self.program.routines[entry[1]].namespace)
        if task in self._shared:
            return False
        source = entry[2]
        if not source:
            return True                  # connected, not ordered: nothing can fire it
        if source[0] != "signal":
            return False
        key = (task, source[1])
        found = self._quiet_signal.get(key)
        if found is None:
            found = self._quiet_signal[key] = self._own_output(task, source[1])
        return found

    def on_own_edge(self, entry, pending: tuple, edges: tuple) -> bool:
        """Whether interrupt ``entry`` is ordered on one of the served edge inputs
        ``edges`` and is not pending (the module docstring, "Interrupts on edge inputs"):
        its TRAP starts only in a step of its own task, which chooses the edge."""
        if entry[0] in pending or not self.program.registers_per_task:
            return False
        source = entry[2]
        if not source or source[0] != "signal" or source[1] not in edges:
            return False
        return routine_task(self.program.routines[entry[1]].namespace) not in self._shared

    def _own_output(self, task: int, index: int) -> bool:
        signal = self.program.signals[index]
        others = self._others_write[task]
        return signal.kind in OUTPUT_KINDS and others is not None and index not in others \
            and signal.outside is None and signal.also_set_by is None and not signal.driven \
            and signal.named_at_run_time is None
