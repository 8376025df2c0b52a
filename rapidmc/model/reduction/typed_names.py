"""The data a call reaching data by name may reach: only data of its Value's type.

``GetDataVal name, Value`` and ``SetDataVal name, Value`` look ``name`` up where the
call is (``library.data_access``); data of another type than the Value's raises
ERR_SYMBOL_TYPE and is neither read nor written.  So such a call reaches only the
data its task can name whose type is the Value's (``types.same_type``: num and dnum
mix, an unknown type matches every one).  Where the Value is not a datum named
directly (an element, a component, an expression), its type is not looked up here
and the call may reach any data its task can name, as before.

The COMPAS RRC robot tasks (ebruun's backups) call ``GetDataVal`` into a tooldata,
a wobjdata and signals; without the types, every write of another task to a bool or a
message buffer those tasks declare conflicted with them (issue 27).
"""
from __future__ import annotations

from typing import Iterable, Optional

from ... import ast
from ...semantics.library.arguments import argument_expression
from ...semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA
from ...semantics.types import same_type


def reached_by_name(program, calls: Iterable, name: str, task_of: callable,
                    accessors: dict) -> dict:
    """Task -> the global slots its calls of ``name`` (GETDATAVAL or SETDATAVAL) among
    ``calls`` ((routine, call) pairs) may reach: of each call, the slots the task can
    name (``accessors``: slot -> the tasks naming it) of its Value's type."""
    found: dict = {}
    for routine, call in calls:
        task = task_of(routine.namespace)
        if task is None or call.name.key != name:
            continue
        wanted = value_type(routine, call)
        reached = found.setdefault(task, set())
        reached |= {slot for slot, by in accessors.items() if task in by and (
            wanted is None or same_type(program.globals[slot].type, wanted))}
    return found


def value_type(routine, call) -> Optional[object]:
    """The type of the call's Value when it is a datum named directly, else None."""
    value = argument_expression(call, "Value", 1)
    if not isinstance(value, ast.NameRef) or routine.scope is None:
        return None
    symbol = routine.scope.lookup(value.name.key)
    if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA, CONSTANT):
        return None
    return getattr(symbol, "type", None)
