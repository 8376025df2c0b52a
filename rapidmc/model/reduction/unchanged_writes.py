"""A write of the value already stored: a step that changes no data.

``stCommand:=""`` of a task that sends commands to the others through the PERS
``stCommand`` conflicts with every task reading it (``PartialOrder.footprint``):
where ``stCommand`` holds ``"RUN"``, a reader's step before the write and one
after it read different values.  Yet where it already holds ``""`` (its initial
value, as at a start-up routine that clears it before the first command) the
write leaves every datum as it was and only moves its task on.

When no other task writes the datum (``SyntaxReads.readable``), no code outside
the loaded code writes it, and the value written is a constant, no step of
another task changes whether the datum holds that value: the step is
independent of every other task in that state and in every state the others'
steps lead to.  So it may be a group's member, alone too (``task_groups``),
judged per state as an IDelete that deletes nothing (``empty_deletes``); its
errors (none) and its task going on are checked per step as for every ample
transition.  A write of a datum an atom names is left out (C2 judges the
instruction, not the state).
"""
from __future__ import annotations

from typing import Callable, Optional

from ...semantics.instructions import Action
from .empty_deletes import IdleSteps


class UnchangedWrites(IdleSteps):
    """Per instruction of a task, how to read in a state whether it is an assignment of a
    constant to global data only its task writes that writes the value already stored
    (see the module docstring)."""

    def _find(self, task: int, routine_index: int, pc: int) -> Optional[Callable]:
        order = self.order
        instruction = order.program.routines[routine_index].code[pc]
        if type(instruction) is not Action or instruction.fusion is None or \
                order.task_of_routine(routine_index) != task:
            return None
        where, slot, value = instruction.fusion
        reads = order.syntax.reads
        if where != "store" or not value.is_constant or slot in reads.outside or \
                not reads.readable(task, slot) or \
                order.program.globals[slot].key in order.visible:
            return None
        written = value.constant
        # (the same type too: a num 1 where 1.0 is stored is a state of its own)
        return lambda stack, state: type(state[1][slot]) is type(written) and \
            state[1][slot] == written
