"""IDelete of an interrupt variable holding 0: a step that deletes nothing.

``IDelete irq`` reads the controller's interrupt table, one for every task
(``State.interrupts``): it removes the entry and the pending orders numbered as
``irq`` and writes 0 to ``irq`` (``library.interrupts``).  Another task's
``CONNECT`` hands out the smallest number no entry has, so where ``irq`` holds a
number, the order of the two steps decides which number that task gets: they do
not commute, and the reduction's footprint of ``IDelete`` (a predefined routine
with an effect) is shared.

Yet ``CONNECT`` numbers from 1, so where ``irq`` holds 0 (never connected, or
deleted before, as a task's start-up routine deletes its interrupts before it
connects them) the step removes nothing and writes 0 where 0 is: it only moves
its task on.  When no other task writes ``irq`` (task data, or routine data not
passed by reference), no step of another task changes that, and the step is
independent of every other task in that state and in every state the others'
steps lead to.  So it may be a group's member, alone too (``task_groups``),
judged per state as a group judges waits; its errors (none) and its task going
on are checked per step as for every ample transition.
"""
from __future__ import annotations

from typing import Callable, Optional

from ... import ast
from ...semantics.instructions import Action
from ...semantics.scope import GLOBAL_DATA, LOCAL_DATA


class IdleSteps:
    """Per instruction of a task, how to read in a state whether its step touches nothing
    another task reads or writes there (``_find``, once per instruction)."""

    def __init__(self, order):
        self.order = order              # PartialOrder: the syntax, which tasks write what
        self._readers: dict = {}        # (task, routine, pc) -> reader or None

    def reader(self, task: int, routine_index: int, pc: int) -> Optional[Callable]:
        """``idle(stack, state)`` for the instruction at ``pc`` of ``routine_index`` when
        it may be idle, else None; ``stack`` is the task's (the instruction at its top)."""
        key = (task, routine_index, pc)
        if key not in self._readers:
            self._readers[key] = self._find(task, routine_index, pc)
        return self._readers[key]

    def _find(self, task: int, routine_index: int, pc: int) -> Optional[Callable]:
        raise NotImplementedError


class EmptyDeletes(IdleSteps):
    """Per instruction of a task, how to read in a state whether it is an IDelete of data
    only its task writes that deletes nothing (see the module docstring)."""

    def _find(self, task: int, routine_index: int, pc: int) -> Optional[Callable]:
        order = self.order
        routine = order.program.routines[routine_index]
        instruction = routine.code[pc]
        if type(instruction) is not Action or instruction.fusion is not None or \
                order.task_of_routine(routine_index) != task:
            return None
        node = order.syntax._node(routine, instruction.span)
        lookup = routine.scope.lookup
        if not isinstance(node, ast.ProcedureCall) or node.name.key != "IDELETE" or \
                lookup(node.name.key) is not None or len(node.args) != 1:
            return None
        argument = node.args[0]
        target = argument.value
        if argument.name is not None or argument.kind != ast.REQUIRED or \
                not isinstance(target, ast.NameRef):
            return None
        symbol = lookup(target.name.key)
        if symbol is None:
            return None
        slot = symbol.slot
        if symbol.kind == GLOBAL_DATA and order.syntax.reads.readable(task, slot) and \
                slot not in order.syntax.reads.outside:
            return lambda stack, state: state[1][slot] == 0
        if symbol.kind == LOCAL_DATA and not symbol.by_reference and not symbol.optional:
            return lambda stack, state: stack[-1][2][slot] == 0
        return None
