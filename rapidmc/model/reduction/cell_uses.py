"""What each task's code may touch of the cell outside its data: signals and robots.

The partial-order reduction (``partial_order``, ``task_groups``) judges an
instruction against the other tasks' code.  Data are judged by their slots
(``load.shared_data``); this module gives the same for the two parts of the
state no data slot holds:

* **signals** (``State.io``).  A signal's value changes only where a task's
  code writes it (the loaded code is the whole model once the reduction is on:
  no environment model, no stored free input, ``reduction.plan_reductions``):
  ``Set``, ``Reset``, ``SetDO``, ``PulseDO``, ``SetGO``, ``SetAO``, a move with
  a ``\\DO``, a WaitDO on an output a party left out sets too (``library.waits``)
  ... Counted conservatively: every signal a task's code passes by name to a
  call that is not a reading one (``load.outside_outputs.OUTPUT_READERS``:
  ``DOutput``, ``WaitDI`` ...) is written by it, and so is every output a party
  left out sets too that it names.  A free input nobody writes is chosen where it
  is read (``lazy_inputs``) or keeps its value: no other task's step changes it.
  Signal data bound at run time (``AliasIO`` into ``VAR signaldo``, an array of
  signal data) may stand for any signal: a task passing such data to a writing
  call writes every signal, and one reading it reads every signal.  A signal
  parameter stands for what its callers pass, which is counted at the calls.
  ``named[task]``: the signals the task's code names at all (reads or writes);
  ``written[task]``: those it may write; ``None`` for every signal.
* **robots** (``State.robot``).  A robot changes only by a predefined procedure
  modelled on the robot state (a move, ``SetSysData``) run by a task:
  ``moves[task]``.  With one robot per motion task (``Program.robot_per_task``)
  a task's step changes its own robot only (``semantics.robots``), and another
  task's robot is read only by a reading naming that task (``robot_read``):
  ``readers[task]``, the robots the task's code may read so (``EVERY_TASK``:
  a name known only at run time; a late-bound call names a procedure, never a
  reading, and the routines it may reach are walked as any other).

``robot_read(program, task, call)`` says whose robot a reading
(``CRobT``, ``CJointT``, ``CTool``, ``CWObj``, ``CPos``) reads, as
``library.position`` does.
"""
from __future__ import annotations

from typing import Optional

from ... import ast
from ...load.outside_outputs import OUTPUT_READERS
from ...semantics.configured_signals import walk_routine
from ...semantics.library import registry
from ...semantics.program import ENVIRONMENT_NAMESPACE, FIRST_TASK_NAMESPACE
from ...semantics.robots import (RUN_TIME_TASK, TASK_ARGUMENTS, argument_task,
                                 controller_task_names)
from ...semantics.scope import GLOBAL_DATA, LOCAL_DATA, SIGNAL
from ...semantics.types import SEMI_VALUE

# calls that bind signal data (no signal's value changes)
_BINDERS = frozenset({"ALIASIO", "ALIASIORESET"})
# predefined functions that read the robot: the calling task's, or with \TaskName or
# \TaskRef the named task's (``library.position``)
ROBOT_READERS = frozenset({"CROBT", "CJOINTT", "CTOOL", "CWOBJ", "CPOS"})
EVERY_TASK = -2          # ``robot_read``: a task named at run time, any task's robot


def physical_signal(program, routine, name) -> Optional[int]:
    """The io index of the configured signal ``name`` (an ``ast.Name``) means in
    ``routine``, None when it is no such signal."""
    symbol = routine.scope.lookup(name.key)
    if symbol is not None:
        return symbol.slot if symbol.kind == SIGNAL else None
    signal = program.signal_index.get(name.key)
    return None if signal is None else signal.index


def signal_data(symbol) -> bool:
    """Whether ``symbol`` is data holding a signal (``VAR signaldo``, a signal parameter):
    which signal it stands for is known only when the program runs."""
    return symbol is not None and symbol.kind in (GLOBAL_DATA, LOCAL_DATA) and \
        getattr(symbol.type, "kind", None) == SEMI_VALUE


class CellUses:
    """Per task, the signals its code names and may write, and whether it moves a robot
    (see the module docstring)."""

    def __init__(self, program):
        self.program = program
        tasks = len(program.task_names)
        named: list = [set() for _ in range(tasks)]
        written: list = [set() for _ in range(tasks)]
        moves = [False] * tasks
        readers: list = [set() for _ in range(tasks)]
        self.names = controller_task_names(program)
        both = {signal.index for signal in program.signals if signal.also_set_by}
        for routine in program.routines:
            task = _task_of(routine.namespace)
            if task is None or routine.ast is None:
                continue
            for node in walk_routine(routine.ast):
                if isinstance(node, ast.NameRef) and named[task] is not None:
                    index = physical_signal(program, routine, node.name)
                    if index is not None:
                        named[task].add(index)
                    elif signal_data(routine.scope.lookup(node.name.key)) and \
                            not routine.scope.lookup(node.name.key).by_reference:
                        named[task] = None     # (run-time binding: any signal)
                if isinstance(node, (ast.ProcedureCall, ast.FunctionCall,
                                     ast.LateBindingCall)):
                    moves[task] = moves[task] or _moves(routine, node)
                    robot = self.robot_read(task, node)
                    if robot is not None:
                        readers[task].add(robot)
                    if written[task] is not None:
                        written[task] = _writes(program, routine, node, written[task])
        for task in range(tasks):
            if named[task] is not None and written[task] is not None:
                named[task] |= written[task]
                written[task] |= named[task] & both
            elif named[task] is None and written[task] is not None and both:
                written[task] = None
        self.named = [None if found is None else frozenset(found) for found in named]
        self.written = [None if found is None else frozenset(found) for found in written]
        self.moves = tuple(moves)
        self.readers = tuple(frozenset(found) for found in readers)

    def robot_read(self, task: int, call) -> Optional[int]:
        """The task whose robot a reading call of ``task`` reads (``EVERY_TASK``: a name
        known only when the program runs), as ``library.position`` decides; None when
        the call is no robot reading."""
        if isinstance(call, ast.LateBindingCall) or call.name.key not in ROBOT_READERS:
            return None
        for argument in call.args:
            if argument.name is not None and argument.name.key in TASK_ARGUMENTS and \
                    call.name.key != "CPOS":
                number = argument_task(self.names, argument)
                if number == RUN_TIME_TASK:
                    return EVERY_TASK
                return task if number is None else number
        return task


def _writes(program, routine, call, written: set) -> Optional[set]:
    """``written`` with the signals ``call`` may write (None: any)."""
    key = call.name.key if not isinstance(call, ast.LateBindingCall) else ""
    if key in OUTPUT_READERS or key in _BINDERS:
        return written
    if isinstance(call, ast.FunctionCall) and routine.scope.lookup(key) is None and \
            registry.lookup_function(key) is not None:
        return written                  # (a predefined function writes no signal)
    for argument in call.args:
        if argument.value is None:
            continue
        for node, _ in ast.walk(argument.value):
            if not isinstance(node, ast.NameRef):
                continue
            index = physical_signal(program, routine, node.name)
            if index is not None:
                written.add(index)
                continue
            symbol = routine.scope.lookup(node.name.key)
            if signal_data(symbol) and not symbol.by_reference:
                return None             # (bound at run time: any signal)
    return written


def _moves(routine, call) -> bool:
    """Whether ``call`` is of a predefined procedure modelled on the robot state."""
    if not isinstance(call, ast.ProcedureCall) or routine.scope.lookup(call.name.key):
        return False
    entry = registry.lookup_procedure(call.name.key)
    return entry is not None and entry.modelled == registry.ROBOT_STATE


def _task_of(namespace: int) -> Optional[int]:
    if namespace == ENVIRONMENT_NAMESPACE:
        return None
    return 0 if namespace < FIRST_TASK_NAMESPACE else namespace - FIRST_TASK_NAMESPACE + 1


class CellView:
    """``CellUses`` judged for each task against the tasks ``others[task]`` (every other
    task, one of them, or none: ``PartialOrder.view``)."""

    def __init__(self, uses: CellUses, others: list):
        self.uses = uses
        self.others = others
        self.per_robot = uses.program.robot_per_task

    def signal_readable(self, task: int, index: Optional[int]) -> bool:
        """Whether no task of ``others[task]`` may write signal ``index`` (None: any)."""
        written = self.uses.written
        return all(written[other] is not None and
                   (index not in written[other] if index is not None else not written[other])
                   for other in self.others[task])

    def signal_own(self, task: int, index: int) -> bool:
        """Whether no task of ``others[task]`` names signal ``index``."""
        named = self.uses.named
        return all(named[other] is not None and index not in named[other]
                   for other in self.others[task])

    def robot_readable(self, task: int, call) -> Optional[bool]:
        """Whether no task of ``others[task]`` may move the robot the reading ``call``
        reads; None when the call is no robot reading."""
        robot = self.uses.robot_read(task, call)
        if robot is None:
            return None
        moves, others = self.uses.moves, self.others[task]
        if self.per_robot and robot != EVERY_TASK:
            return robot == task or robot not in others or not moves[robot]
        return not any(moves[other] for other in others)

    def robot_own(self, task: int) -> bool:
        """Whether the task's robot is its own against ``others[task]``: each motion task
        has its own robot and none of them may read this one (``CellUses.readers``), so a
        move of the task changes nothing they read or write."""
        readers = self.uses.readers
        return self.per_robot and not any(task in readers[other] or EVERY_TASK in readers[other]
                                          for other in self.others[task])
