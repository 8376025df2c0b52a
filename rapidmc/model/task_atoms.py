"""Which task an atom's names and places belong to, on a controller of several tasks.

Every RAPID task has its own data and routines: two motion tasks may each declare
``VAR num slot`` and a routine ``main``.  An atom names one task's by qualifying it
with the task's name, as the backup names the task:

* ``T_ROB2.slot``: task data (global in the task's modules); ``T_ROB2.main.flag``:
  routine data of the innermost active call of that task's ``main``;
* ``InRoutine(T_ROB2, "MoveToSlot")``, ``AtLine(T_ROB2, 42)``, ``AtLabel(T_ROB2, "lbl")``,
  ``Ended(T_LOG)``, ``Failed(T_LOG)``, ``Waiting(T_ROB1)``: where that task is.

A task whose name is no identifier (``--add-task`` names them ``task 2 (feeder)``) is
named by its number, ``TASK2``, as a backup's folders count; ``TASK1`` is the main task.

A name declared by one task alone (or shared PERS data, one object for every task that
declares it) may stay unqualified.  A name that several tasks declare as different
objects is never resolved silently: it is an error that lists the candidates
(``AMBIGUOUS_NAME``), and so is a location atom without a task on a controller of
several tasks.  ``Ended()`` and ``Failed()`` without a task speak of the whole
controller (every task ended; an uncaught error stopped every task).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterator, Optional

from .. import ast
from ..diagnostics import AMBIGUOUS_NAME, ATOM, SourceCache, error
from ..semantics.program import FIRST_TASK_NAMESPACE, PROGRAM_NAMESPACE, Program
from ..semantics.scope import GLOBAL_DATA, ROUTINE, Scope, Symbol


_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")


@dataclass(frozen=True)
class Task:
    """One task of the controller: its number (the main task is 0), name and namespace."""

    number: int
    name: str
    namespace: int

    @property
    def qualifier(self) -> str:
        """How an atom names the task: its name (``T_ROB2``), or ``TASK2`` (its number from
        1, as a backup's folders count) when the name is no identifier (``--add-task``)."""
        return self.name if _IDENTIFIER.fullmatch(self.name) else f"TASK{self.number + 1}"


def task_qualifier(program: Program, namespace: int) -> str:
    """How atoms and traces name the task of ``namespace`` (``Task.qualifier``)."""
    number = 0 if namespace == PROGRAM_NAMESPACE else namespace - FIRST_TASK_NAMESPACE + 1
    return Task(number, program.task_names[number], namespace).qualifier


def task_stack(m, number: int) -> tuple:
    """The call stack of task ``number`` in the machine's state (empty: it has ended)."""
    return m.frames if number == 0 else m.tasks[number - 1]


class ControllerTasks:
    """The tasks of a program and the names they declare, for atoms."""

    def __init__(self, program: Program):
        self.program = program
        namespaces = (PROGRAM_NAMESPACE,) + tuple(
            FIRST_TASK_NAMESPACE + i for i in range(len(program.task_names) - 1))
        self.tasks = [Task(number, name, namespace) for number, (name, namespace)
                      in enumerate(zip(program.task_names, namespaces))]
        self._by_key = {f"TASK{task.number + 1}": task for task in self.tasks}
        self._by_key.update((task.name.upper(), task) for task in self.tasks
                            if _IDENTIFIER.fullmatch(task.name))

    @property
    def several(self) -> bool:
        return len(self.tasks) > 1

    @property
    def motion(self) -> list[Task]:
        """The tasks that move a robot (``semantics.robots``), in task order."""
        return [self.tasks[number] for number in self.program.motion_tasks]

    def named(self, expr) -> Optional[Task]:
        """The task ``expr`` names (a bare task name), on a controller of several tasks."""
        if self.several and isinstance(expr, ast.NameRef):
            return self._by_key.get(expr.name.key)
        return None

    def scope(self, task: Task) -> Scope:
        """The names task ``task``'s modules declare (not LOCAL), then the system's."""
        return self.program.scopes.namespaces[task.namespace]

    def task_of_namespace(self, namespace: int) -> Optional[Task]:
        return next((task for task in self.tasks if task.namespace == namespace), None)

    def declarations(self, key: str) -> list[tuple[Task, Symbol]]:
        """Each task's own declaration of ``key`` (not the system's)."""
        found = []
        for task in self.tasks:
            symbol = self.scope(task).names.get(key)
            if symbol is not None:
                found.append((task, symbol))
        return found

    def unqualified_scope(self) -> Scope:
        """The names an atom may write without a task: every task's, where one object."""
        if not self.several:
            return Scope(self.scope(self.tasks[0]))
        scope = Scope(self.program.scopes.system)
        for task in reversed(self.tasks):       # the main task's symbol last: it wins ties
            scope.names.update(self.scope(task).names)
        return scope

    def shared(self, symbol: Symbol) -> bool:
        """Whether ``symbol`` is PERS data every task that declares it shares (not TASK PERS)."""
        return symbol.kind == GLOBAL_DATA and symbol.storage == "PERS" and \
            not self.program.globals[symbol.slot].task_local

    def ambiguous(self, key: str) -> list[tuple[Task, Symbol]]:
        """The declarations of ``key`` when several tasks declare different objects."""
        found = self.declarations(key)
        if len({_identity(symbol) for _, symbol in found}) > 1:
            return found
        return []

    def check_unambiguous(self, expr: ast.Expr, where: ast.Span, atom: str) -> None:
        """An error at the first name in ``expr`` that several tasks declare differently,
        or at the first location atom without a task, on a controller of several tasks."""
        if not self.several:
            return
        for node in unqualified_nodes(expr, self):
            if isinstance(node, ast.NameRef):
                candidates = self.ambiguous(node.name.key)
                if candidates:
                    raise _ambiguous_name(node.name, candidates, where, atom)
            elif isinstance(node, ast.FunctionCall) and not self.names_task(node):
                if _task_slot_misnamed(node):
                    raise _no_such_task(node, self.tasks, where, atom)
                if node.name.key in NEEDS_TASK:
                    raise _location_without_task(node, self.tasks, where, atom)
                if node.name.key in ROBOT_ATOMS and self.program.robot_per_task:
                    raise _robot_without_task(node, self.motion, where, atom)

    def names_task(self, call: ast.FunctionCall) -> bool:
        """Whether ``call``'s first argument names a task (``InRoutine(T_ROB2, ...)``)."""
        return bool(call.args) and self.named(call.args[0].value) is not None


def _identity(symbol: Symbol) -> tuple:
    """What a declaration denotes: shared PERS data is one slot for every task."""
    if symbol.kind in (GLOBAL_DATA, ROUTINE):
        return symbol.kind, symbol.slot
    return symbol.kind, id(symbol)


def tasks_read(expr: ast.Expr, tasks: ControllerTasks) -> tuple[str, ...]:
    """The tasks (``Task.qualifier``) whose own data or places an atom's expression reads,
    in task order: those it names, and those that alone declare a name it writes bare.
    Shared PERS data, signals and ``Ended()``/``Failed()`` of the controller belong to no
    task.  Empty on a controller of one task."""
    if not tasks.several:
        return ()
    found: set[int] = set()
    from ..semantics.configured_signals import _walk_expression
    for node in _walk_expression(expr):
        if isinstance(node, ast.FunctionCall) and node.args:
            task = tasks.named(node.args[0].value)
        elif isinstance(node, ast.Component):
            task = tasks.named(node.base)
        else:
            task = None
        if task is not None:
            found.add(task.number)
    for node in unqualified_nodes(expr, tasks):
        if isinstance(node, ast.NameRef):
            owners = [task for task, symbol in tasks.declarations(node.name.key)
                      if not tasks.shared(symbol)]
            if len(owners) == 1:
                found.add(owners[0].number)
        elif isinstance(node, ast.FunctionCall) and node.name.key in ROBOT_ATOMS and \
                not tasks.names_task(node) and len(tasks.motion) == 1:
            found.add(tasks.motion[0].number)     # the one robot: its motion task's
    return tuple(task.qualifier for task in tasks.tasks if task.number in found)


# location atoms that read where one task is (Ended, Failed: the whole controller)
NEEDS_TASK = frozenset({"INROUTINE", "ATLINE", "ATLABEL", "WAITING"})
# atoms that read a robot: with several motion tasks, one robot per task (semantics.robots)
ROBOT_ATOMS = frozenset({"ATTARGET", "CPOS", "CROBT", "CJOINTT", "CTOOL", "CWOBJ"})
# the most arguments each of them takes after its task that can start with a bare name
# (AtLine's two-argument form starts with a file name in quotes)
_MOST_ARGUMENTS = {"INROUTINE": 1, "ATLINE": 1, "ATLABEL": 1, "WAITING": 0, "ATTARGET": 1,
                   "CPOS": 0, "CROBT": 0, "CJOINTT": 0, "CTOOL": 0, "CWOBJ": 0}


def unqualified_nodes(expr: ast.Expr, tasks: ControllerTasks) -> Iterator[object]:
    """The nodes of ``expr`` outside task-qualified names and task arguments."""
    if isinstance(expr, ast.Component) and _qualified_root(expr, tasks):
        return
    yield expr
    if isinstance(expr, ast.FunctionCall):
        args = [arg.value for arg in expr.args if arg.value is not None]
        if args and tasks.named(args[0]) is not None:
            args = []       # read in that task's names: AtTarget(T_ROB2, p10) is T_ROB2's p10
        for arg in args:
            yield from unqualified_nodes(arg, tasks)
    for field in ("base", "operand", "left", "right"):
        child = getattr(expr, field, None)
        if child is not None:
            yield from unqualified_nodes(child, tasks)
    for child in getattr(expr, "indices", ()) or getattr(expr, "items", ()) or ():
        yield from unqualified_nodes(child, tasks)


def _qualified_root(expr: ast.Component, tasks: ControllerTasks) -> bool:
    """Whether ``expr`` is ``TASK.name`` or ``TASK.routine.name``."""
    base = expr.base
    if isinstance(base, ast.Component):
        base = base.base
    return tasks.named(base) is not None


def atom_position(where: ast.Span, span: Optional[ast.Span]) -> ast.Span:
    """Where a node of an atom's expression is in the property file (``where``: the atom,
    with its opening quote if quoted; ``span``: the node within the atom's text)."""
    if span is None or span.line != ATOM_TEXT_LINE:
        return where
    line = SourceCache.line(where.file, where.line) or ""
    quoted = line[where.column - 1:where.column] == '"'
    column = where.column + int(quoted) + span.column - 1
    return ast.Span(where.file, where.line, column)


ATOM_TEXT_LINE = 4      # the line of the atom's text in properties._WRAPPER_HEAD + text


def _ambiguous_name(name: ast.Name, candidates, where: ast.Span, atom: str):
    listed = ", ".join(f"{task.name} ({_declared_at(symbol)})" for task, symbol in candidates)
    written = " or ".join(f"{task.qualifier}.{name.text}" for task, _ in candidates)
    return error(AMBIGUOUS_NAME, f"atom \"{atom}\": '{name.text}' is declared by several "
                 f"tasks: {listed}", atom_position(where, name.span),
                 f"name the task: {written}")


def _declared_at(symbol: Symbol) -> str:
    span = symbol.span
    if span is None:
        return "declared"
    from pathlib import Path
    return f"{Path(span.file).name}:{span.line}"


def _location_without_task(call: ast.FunctionCall, tasks, where: ast.Span, atom: str):
    names = ", ".join(task.name for task in tasks)
    first = tasks[0].qualifier
    example = ", ".join([first] + [_argument_text(arg) for arg in call.args])
    return error(AMBIGUOUS_NAME, f"atom \"{atom}\": {call.name.text} needs a task on a "
                 f"controller of several tasks ({names})", atom_position(where, call.span),
                 f"name the task first, e.g. {call.name.text}({example})")


def _robot_without_task(call: ast.FunctionCall, motion, where: ast.Span, atom: str):
    names = ", ".join(task.name for task in motion)
    example = ", ".join([motion[0].qualifier] + [_argument_text(arg) for arg in call.args])
    return error(AMBIGUOUS_NAME, f"atom \"{atom}\": {call.name.text} reads a robot, and each "
                 f"of the motion tasks {names} moves its own", atom_position(where, call.span),
                 f"name the robot's task first, e.g. {call.name.text}({example})")


def _task_slot_misnamed(call: ast.FunctionCall) -> bool:
    """Whether ``call`` (naming no task) starts with a bare name where only a task fits:
    ``CPos(T_ROB9)``, ``InRoutine(T_ROB9, main)`` (one argument more than it takes)."""
    most = _MOST_ARGUMENTS.get(call.name.key)
    return most is not None and len(call.args) > most and \
        isinstance(call.args[0].value, ast.NameRef)


def _no_such_task(call: ast.FunctionCall, tasks, where: ast.Span, atom: str):
    name = call.args[0].value.name.text
    return error(ATOM, f"atom \"{atom}\": {call.name.text} takes a task first, and no task is "
                 f"named {name}", atom_position(where, call.span),
                 f"the tasks: {', '.join(task.name for task in tasks)}")


def _argument_text(arg: ast.Argument) -> str:
    value = arg.value
    if isinstance(value, ast.StringLiteral):
        return f'"{value.value}"'
    if isinstance(value, ast.NumLiteral):
        return f"{value.value:g}" if isinstance(value.value, float) else str(value.value)
    if isinstance(value, ast.NameRef):
        return value.name.text
    return "..."
