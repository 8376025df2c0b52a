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

``declared_values`` gives, for a task checked alone, the declarations with a value that
tasks not loaded hold of shared PERS: one persistent declared in several tasks is one
object, and a declaration without a value takes the value of another that has one (as
the controller does; the linker applies it: ``Linker._values_declared_elsewhere``).
"""
from __future__ import annotations

import re
from functools import lru_cache
from pathlib import Path
from typing import Iterable, Iterator, Optional

from .. import ast
from ..diagnostics import TASKS_LOADED, Diagnostic, UserError
from ..semantics.library import lookup_function, lookup_procedure
from ..semantics.library.registry import matched_parameters, mode_may_write
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
    routines = {routine.name.key: routine for module in program.modules
                for routine in module.routines}
    written = set()
    for module in program.modules:
        for routine in module.routines:
            for node, _ in ast.walk(routine):
                if isinstance(node, (ast.Assignment, ast.Connect)):
                    written.add(_root(node.target))
                elif isinstance(node, ast.LateBindingCall):
                    written.update(_root(arg.value) for arg in node.args)
                elif isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                    written.update(_root(arg.value) for arg in node.args
                                   if _may_write(node, arg, routines))
    written.discard(None)
    return written


class _Named:
    """A user routine's parameter as ``matched_parameters`` wants it."""

    def __init__(self, parameter: ast.Parameter):
        self.key = parameter.name.key
        self.optional = parameter.optional
        self.mode = parameter.mode


def _may_write(call, argument, routines: dict) -> bool:
    if argument.value is None:
        return False
    routine = routines.get(call.name.key)
    if routine is not None:
        parameters = [_Named(p) for p in routine.parameters]
    else:
        entry = lookup_procedure(call.name.key) if isinstance(call, ast.ProcedureCall) \
            else lookup_function(call.name.key)
        if entry is None:
            return True                  # a routine of encrypted code or an option: unknown
        parameters = entry.signature.parameters
    for arg, parameter in matched_parameters(call.args, parameters):
        if arg is argument:
            return parameter is None or mode_may_write(parameter.mode)
    return True


def _root(expr) -> Optional[str]:
    while expr is not None and not isinstance(expr, ast.NameRef):
        expr = getattr(expr, "base", None)
    return expr.name.key if expr is not None else None
