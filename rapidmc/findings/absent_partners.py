"""Barriers that name a task the check does not load (issue 28).

A task checked alone (``--task``), or a program given as files, meets other tasks at
WaitSyncTask and SyncMoveOn barriers.  A task its TaskList names that is not loaded
cannot be followed, so the step of the barrier takes it as arrived at once
(``semantics.library.tasks``); the verdict rests on that, and ``findings.assumptions``
names each such barrier and the tasks it takes as arrived.

The TaskList is read where the code shows its value: a CONST, or module data (PERS or
VAR) at its declared value.  A list held elsewhere (a routine's data, a parameter) is
named as such: its tasks not loaded are taken as arrived too, whichever they are.
When every task of a backup is loaded, a name no task has is the program's own error
(ERR_TASKNAME), not an assumption.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator, Optional

from .. import ast
from ..semantics.library.arguments import argument_expression
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program
from ..semantics.scope import CONSTANT, GLOBAL_DATA

LISTED_BARRIERS = {"WAITSYNCTASK": "WaitSyncTask", "SYNCMOVEON": "SyncMoveOn"}
TASK_LIST_POSITION = 1          # SyncID, TaskList (the switches and \TimeOut are named)


@dataclass(frozen=True)
class AbsentPartners:
    """A barrier whose TaskList names tasks not loaded: ``absent`` their names, or None
    when the list's value is not known before the program runs."""

    what: str                   # WaitSyncTask, SyncMoveOn
    span: object
    absent: Optional[tuple]


def absent_partners(program: Program) -> Iterator[AbsentPartners]:
    """Each barrier call (every loaded task's code) naming a task that is not loaded."""
    if program.options.get("all_tasks_loaded", False):
        return
    linker = getattr(program, "scopes", None)
    loaded = {name.upper() for name in getattr(linker, "task_names", None) or ("T_ROB1",)}
    for routine in program.routines:
        if routine.ast is None or routine.namespace == ENVIRONMENT_NAMESPACE:
            continue
        for node, _ in ast.walk(routine.ast):
            if not isinstance(node, ast.ProcedureCall) or node.name.key not in LISTED_BARRIERS \
                    or routine.scope.lookup(node.name.key) is not None:
                continue
            listed = _listed_names(program, routine.scope,
                                   argument_expression(node, "TaskList", TASK_LIST_POSITION))
            if listed is None:
                yield AbsentPartners(LISTED_BARRIERS[node.name.key], node.span, None)
                continue
            absent = tuple(dict.fromkeys(name for name in listed
                                         if name.upper() not in loaded))
            if absent:
                yield AbsentPartners(LISTED_BARRIERS[node.name.key], node.span, absent)


def _listed_names(program: Program, scope, expr) -> Optional[list]:
    """The task names a TaskList expression holds before the program runs, else None."""
    if not isinstance(expr, ast.NameRef):
        return None
    symbol = scope.lookup(expr.name.key)
    if symbol is None:
        return None
    if symbol.kind == CONSTANT:
        value = symbol.value
    elif symbol.kind == GLOBAL_DATA:
        value = program.globals[symbol.slot].initial
    else:
        return None
    if not isinstance(value, (tuple, list)):
        return None
    names = []
    for item in value:
        name = item[0] if isinstance(item, (tuple, list)) and item else item
        if not isinstance(name, str):
            return None
        if name.strip():
            names.append(name.strip())
    return names
