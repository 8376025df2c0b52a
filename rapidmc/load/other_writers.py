"""PERS data that a party rapidmc does not load may write, although loaded code writes it too.

``outside_data`` gives reads of a PERS that no loaded code writes any value of a
finite domain.  A buffer that a receiver task fills and the checked task clears
is written by both: the loaded code's own write makes it look like ordinary
shared data, and a ``WaitUntil buffer{i}.startbit = TRUE`` would wait forever
when the receiver is not loaded (``--task``) or is encrypted.  This module names
such data, by the writer the check leaves out:

* a task of the backup that is not loaded (a task checked alone): each shared
  PERS it declares and its code writes (assigned, or passed to a routine that
  may write it: a parameter by reference, a routine that is not declared; every
  one when its code writes data by name, ``SetDataVal``);
* a task holding encrypted modules, loaded or not: each shared PERS its readable
  modules declare (the encrypted code may write any of them).

A task made only of encrypted modules declares nothing rapidmc can read; the
PERS it may write that no loaded code writes stay ``outside_data``'s own case.
A module of a task not loaded that rapidmc cannot parse is read as encrypted
code is: it may write each shared PERS its task declares, in the modules that
parse and in its own declarations (lines ``PERS type name``); a note (RMC730)
names it, since its writes are not known but assumed.
The reads of the named data take the stored value or any value of the domain
(``outside_data``); the verdicts name the writer under ``assumes:``.

``written_constants`` gives, for the PERS data the tasks not loaded write, the values
they write, when each write assigns a constant (``nRunningStep{1} := 3``): the reads
of such data then take its initial value or one of those (``outside_data``), not a
domain from the comparisons, which would offer values no task ever writes (an index
below 1 where every task writes 1 to 8).  Any other write (a computed value, a
routine's argument by reference, SetDataVal, an encrypted or unparsable module, a
task rapidmc cannot read) leaves the data's values unknown.

``declared_values`` gives, for a task checked alone, the declarations with a value that
tasks not loaded hold of shared PERS: one persistent declared in several tasks is one
object, and a declaration without a value takes the value of another that has one (as
the controller does; the linker applies it: ``Linker._values_declared_elsewhere``).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Iterable, Iterator, Optional

from .. import ast
from ..diagnostics import TASKS_LOADED, Diagnostic, UserError
from ..semantics.library import lookup_function, lookup_procedure
from ..semantics.library.registry import matched_parameters, mode_may_write
from ..semantics.values import to_num
from .shared_data import trees_write_by_name


_DECLARED_PERS = re.compile(r"^[ \t]*(LOCAL[ \t]+|TASK[ \t]+)?PERS[ \t]+\w+[ \t]+(\w+)",
                            re.IGNORECASE | re.MULTILINE)


def other_writers(path: Path, loaded: Iterable[str]) -> tuple[dict, list]:
    """Upper-case PERS name -> who else may write it (a phrase), for the backup at
    ``path`` whose tasks named ``loaded`` are loaded; and the notes (RMC730) naming
    the modules of tasks not loaded that rapidmc cannot parse."""
    from .backup import backup_tasks, task_encrypted, task_modules_readable, task_modules
    loaded = set(loaded)
    found: dict = {}
    notes: list = []
    for task in backup_tasks(path):
        sealed = bool(task_encrypted(task))
        if (task.name in loaded and not sealed) or not task_modules_readable(task):
            continue
        programs, unparsable = _parsed_modules(task_modules(path, task))
        shared = set().union(*(_shared_persistents(program) for program in programs))
        if sealed:
            who = f"the encrypted modules of task {task.name}"
            for key in shared:
                found.setdefault(key, who)
        if task.name in loaded:
            continue
        who = f"task {task.name} (not loaded)"
        written = set().union(*(written_names(program) for program in programs))
        if trees_write_by_name(routine for program in programs
                               for module in program.modules for routine in module.routines):
            written |= shared            # SetDataVal names its data when it runs: any PERS
        for key in sorted(written & shared):
            found.setdefault(key, who)
        for module in unparsable:
            name = Path(module).name
            declared = {m.group(2).upper() for m in
                        _DECLARED_PERS.finditer(Path(module).read_text(errors="replace"))
                        if not m.group(1)}
            who = f"module {name} of task {task.name} (not loaded, not parsed)"
            for key in sorted(shared | declared):
                found.setdefault(key, who)
            notes.append(Diagnostic(
                TASKS_LOADED, f"module {name} of task {task.name}, which is not loaded, "
                "cannot be parsed: every shared PERS its task declares counts as data it "
                "may write", ast.Span(module, 0, 0), severity="note"))
    return found, notes


@dataclass(frozen=True)
class Counting:
    """The values a FOR loop's variable takes, written where its bounds are not all
    constant: ``start``, ``start + step``, ... (each a whole number when both are)."""

    start: float
    step: float

    def holds(self, value) -> bool:
        if not isinstance(value, float):
            return False
        steps = (value - self.start) / self.step
        return steps >= 0 and steps == int(steps)


@dataclass(frozen=True)
class TaskWrites:
    """What the tasks not loaded write to one shared PERS: ``tasks``, their names;
    ``pairs``, (component path with indices left out, a constant or a ``Counting``)."""

    tasks: tuple
    pairs: tuple

    def writers(self) -> str:
        return " and ".join(f"task {name}" for name in self.tasks) + " (not loaded)"


MAX_COUNTED = 64          # a FOR loop of constant bounds with more rounds writes a Counting


def written_constants(path: Path, loaded: Iterable[str]) -> dict:
    """Upper-case PERS name -> ``TaskWrites``: what the tasks of the backup at ``path``
    not among ``loaded`` assign to it, each value a constant (a number, string, bool or
    an aggregate of them) or a FOR loop's variable (``Counting``), for each shared PERS
    they write; None for one that some write, or some party whose code is not read,
    may give another value.  Empty when a task cannot be read at all."""
    from .backup import backup_tasks, task_encrypted, task_modules_readable, task_modules
    loaded = set(loaded)
    found: dict = {}
    for task in backup_tasks(path):
        if not task_modules_readable(task):
            return {}                    # a task of encrypted code only: it may write any
        if task.name in loaded and not task_encrypted(task):
            continue
        programs, unparsable = _parsed_modules(task_modules(path, task))
        if unparsable:
            return {}                    # (its declarations and writes are not all known)
        shared = set().union(*(_shared_persistents(program) for program in programs))
        if task_encrypted(task):
            found.update((key, None) for key in shared)
            continue
        written = set().union(*(written_names(program) for program in programs)) & shared
        if trees_write_by_name(routine for program in programs
                               for module in program.modules for routine in module.routines):
            written = shared             # SetDataVal: any value
        assigned = _constant_assignments(programs, written)
        for key in sorted(written):
            pairs, before = assigned.get(key), found.get(key, TaskWrites((), ()))
            found[key] = None if pairs is None or before is None else \
                TaskWrites((*before.tasks, task.name),
                           tuple(sorted({*before.pairs, *pairs}, key=repr)))
    return found


def _constant_assignments(programs: list, names: set) -> dict:
    """Upper-case name -> the (component path, value) pairs of its assignments, for the
    ``names`` every write of which (``written_names``) assigns a constant or a FOR loop's
    variable; a name written any other way, or assigned another value, is left out."""
    every = [routine for program in programs for module in program.modules
             for routine in module.routines]
    routines = _by_name(every)
    pairs: dict = {}
    unknown: set = set()
    for routine in every:        # (LOCAL routines of two modules may share a name)
        for node, parents in ast.walk(routine):
            if isinstance(node, ast.Assignment):
                target = _target_path(node.target)
                if target is None or target[0] not in names:
                    continue
                values = _assigned_values(node.value, parents)
                if values is None:
                    unknown.add(target[0])
                else:
                    pairs.setdefault(target[0], set()).update((target[1], v) for v in values)
            else:
                unknown |= _written_otherwise(node, routines)
    return {name: frozenset(found) for name, found in pairs.items() if name not in unknown}


def _assigned_values(value, parents) -> Optional[tuple]:
    """The values an assignment's right side may give: a constant; the variable of an
    enclosing FOR loop with a constant start and step (each round's value, or a
    ``Counting`` when the loop's end is not constant or far); None: unknown."""
    constant = constant_value(value)
    if constant is not None:
        return (constant,)
    if not isinstance(value, ast.NameRef):
        return None
    loop = next((p for p in reversed(parents) if isinstance(p, ast.For)
                 and p.variable.key == value.name.key), None)
    if loop is None:
        return None
    start, stop = constant_value(loop.start), constant_value(loop.stop)
    step = constant_value(loop.step) if loop.step is not None else 1.0
    if not isinstance(start, float) or not isinstance(step, float) or step == 0:
        return None
    if isinstance(stop, float) and 0 <= (stop - start) / step < MAX_COUNTED:
        return tuple(start + k * step for k in range(int((stop - start) / step) + 1))
    return (Counting(start, step),)


def _target_path(expr) -> Optional[tuple]:
    """(upper-case root name, component path with indices left out) of an assignment's
    target ``name``, ``name{i}``, ``name{i}.c``, ...; None for any other target."""
    path = []
    while isinstance(expr, (ast.Component, ast.Index)):
        if isinstance(expr, ast.Component):
            path.append(expr.name.key)
        expr = expr.base
    return (expr.name.key, tuple(reversed(path))) if isinstance(expr, ast.NameRef) else None


def constant_value(expr):
    """The value a literal denotes (a number with its sign, a string, a bool, an aggregate
    of those as a tuple); None for any other expression."""
    if isinstance(expr, ast.Unary) and expr.op in ("-", "+") and \
            isinstance(expr.operand, ast.NumLiteral):
        value = constant_value(expr.operand)
        return -value if expr.op == "-" and value is not None else value
    if isinstance(expr, ast.NumLiteral):
        try:
            return to_num(expr.value)
        except Exception:           # beyond the num range: the write raises, no value
            return None
    if isinstance(expr, (ast.StringLiteral, ast.BoolLiteral)):
        return expr.value
    if isinstance(expr, ast.Aggregate):
        items = tuple(constant_value(item) for item in expr.items)
        return None if any(item is None for item in items) else items
    return None


def declared_values(path: Path, loaded: Iterable[str]) -> dict:
    """Upper-case PERS name -> (its declaration with a value, where: ``task T (file:line)``)
    for each shared PERS that a task of the backup at ``path`` not among ``loaded``
    declares with a value (the first such task in the backup's order)."""
    found: dict = {}
    for task, programs in _tasks_left_out(path, loaded):
        for program in programs:
            for module in program.modules:
                for data in module.data:
                    if data.storage == ast.PERS and data.init is not None and \
                            data.scope not in (ast.LOCAL, ast.TASK):
                        found.setdefault(data.name.key, (data, f"task {task.name} "
                                         f"({Path(data.span.file).name}:{data.span.line})"))
    return found


def task_output_writers(path: Path, loaded: Iterable[str]) -> dict:
    """Upper-case signal name -> the task not loaded whose code may set it (passes it to a
    call other than a reading one: ``outside_outputs.written_signals``)."""
    from .outside_outputs import written_signals
    found: dict = {}
    for task, programs in _tasks_left_out(path, loaded):
        trees = [routine for program in programs for module in program.modules
                 for routine in module.routines]
        for key in sorted(written_signals(trees) or ()):
            found.setdefault(key, f"task {task.name} (not loaded)")
    return found


def _tasks_left_out(path: Path, loaded: Iterable[str]) -> Iterator[tuple]:
    """(task, its modules that parse) for each readable task of the backup not loaded."""
    from .backup import backup_tasks, task_modules_readable, task_modules
    loaded = set(loaded)
    for task in backup_tasks(path):
        if task.name not in loaded and task_modules_readable(task):
            yield task, _parsed_modules(task_modules(path, task))[0]


def _parsed_modules(modules: list) -> tuple[list, list]:
    """The task's modules parsed (all at once, else one by one), and the modules that
    cannot be parsed (parsed once per list of unchanged files: the readers of a task not
    loaded share them, and the trees are immutable)."""
    stamps = tuple((module, _stamp(module)) for module in modules)
    return _parsed_module_list(tuple(modules), stamps)


def _stamp(module) -> tuple:
    try:
        found = Path(module).stat()
    except OSError:
        return ()
    return found.st_mtime_ns, found.st_size


@lru_cache(maxsize=32)
def _parsed_module_list(modules: tuple, stamps: tuple) -> tuple[list, list]:
    del stamps                           # (part of the cache's key only)
    from ..syntax import load_program
    try:
        return [load_program(modules)], []
    except UserError:
        pass
    programs, unparsable = [], []
    for module in modules:
        try:
            programs.append(load_program([module]))
        except UserError:
            unparsable.append(module)
    return programs, unparsable


def _shared_persistents(program: ast.Program) -> set:
    """The PERS data a task shares with the others: declared in a module, not LOCAL or TASK."""
    return {data.name.key for module in program.modules for data in module.data
            if data.storage == ast.PERS and data.scope not in (ast.LOCAL, ast.TASK)}


def written_names(program: ast.Program) -> set:
    """The upper-case names a program's code may write: assignment targets and
    arguments a routine may write (by reference, or the routine is not declared)."""
    routines = _by_name(routine for module in program.modules for routine in module.routines)
    written = set()
    for module in program.modules:
        for routine in module.routines:
            for node, _ in ast.walk(routine):
                if isinstance(node, ast.Assignment):
                    written.add(_root(node.target))
                else:
                    written |= _written_otherwise(node, routines)
    written.discard(None)
    return written


def _written_otherwise(node, routines: dict) -> set:
    """The upper-case roots a node other than an assignment may write: a CONNECT's target,
    the arguments of a late-bound call, those a routine may write (by reference, or the
    routine is not declared)."""
    if isinstance(node, ast.Connect):
        return {_root(node.target)}
    if isinstance(node, ast.LateBindingCall):
        return {_root(arg.value) for arg in node.args}
    if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
        return {_root(arg.value) for arg in node.args if _may_write(node, arg, routines)}
    return set()


class _Named:
    """A user routine's parameter as ``matched_parameters`` wants it."""

    def __init__(self, parameter: ast.Parameter):
        self.key = parameter.name.key
        self.optional = parameter.optional
        self.mode = parameter.mode


def _by_name(routines) -> dict:
    """Upper-case name -> the routines so named (LOCAL routines of two modules may share
    one)."""
    found: dict = {}
    for routine in routines:
        found.setdefault(routine.name.key, []).append(routine)
    return found


def _may_write(call, argument, routines: dict) -> bool:
    """Whether the call may write ``argument``: one of the user routines of its name may
    (a LOCAL routine of another module may be the one called), else the predefined one."""
    if argument.value is None:
        return False
    named = routines.get(call.name.key)
    if named:
        return any(_writes(call, argument, [_Named(p) for p in routine.parameters])
                   for routine in named)
    entry = lookup_procedure(call.name.key) if isinstance(call, ast.ProcedureCall) \
        else lookup_function(call.name.key)
    if entry is None:
        return True                      # a routine of encrypted code or an option: unknown
    return _writes(call, argument, entry.signature.parameters)


def _writes(call, argument, parameters) -> bool:
    for arg, parameter in matched_parameters(call.args, parameters):
        if arg is argument:
            return parameter is None or mode_may_write(parameter.mode)
    return True


def _root(expr) -> Optional[str]:
    while expr is not None and not isinstance(expr, ast.NameRef):
        expr = getattr(expr, "base", None)
    return expr.name.key if expr is not None else None
