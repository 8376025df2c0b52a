"""Which routines of a program some chain of calls reaches.

Coverage (``findings.tried_inputs``) calls a routine no call reaches "never reached
under any input"; the message domains (``load.message_domains``) take no values from
what such a routine compares (its comparisons choose nothing a search can reach).
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.library.program_control import CALLS_BY_NAME
from ..semantics.program import Program
from ..semantics.scope import ROUTINE


def called_routines(program: Program) -> Optional[frozenset]:
    """Names of the routines some chain of calls from an entry routine or a TRAP reaches
    (None: a late-bound call may name any routine).  Calls are matched by name, across
    tasks and modules: a name reaches every routine so named."""
    by_name: dict[str, list] = {}
    for routine in program.routines:
        if routine.ast is not None:
            by_name.setdefault(routine.key, []).append(routine)
    starts = [program.routines[i] for i in (program.entry, *program.task_entries)
              if isinstance(i, int)]
    pending = starts + [r for r in program.routines if r.ast is not None and r.kind == "TRAP"]
    seen: set = set()
    while pending:
        routine = pending.pop()
        if routine.index in seen or routine.ast is None:
            continue
        seen.add(routine.index)
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.LateBindingCall) or (
                    isinstance(node, ast.ProcedureCall) and node.name.key in CALLS_BY_NAME):
                return None
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                pending.extend(by_name.get(node.name.key, ()))
            elif isinstance(node, ast.Connect):
                pending.extend(by_name.get(node.trap.key, ()))
    return frozenset(program.routines[index].name for index in seen)


class TaskRoutines:
    """The routines with code of ``routines``, each task's apart: a call resolves as the
    linker resolved it, to the routine of the caller's task (every task has its ``main``)
    and, among LOCAL routines of one name, of the caller's module."""

    def __init__(self, routines):
        self.routines = [routine for routine in routines if routine.ast is not None]
        self._numbered = {routine.index: routine for routine in self.routines}
        self._named = {(routine.namespace, routine.key): routine for routine in self.routines}

    def called(self, caller, key: str):
        """The routine a call of ``key`` in ``caller`` runs (None: none of the program's)."""
        return called_routine(caller, key, self._numbered) or \
            self._named.get((caller.namespace, key))


def called_routine(caller, key: str, numbered: dict):
    """The routine of ``numbered`` (index -> routine) that the name ``key`` denotes in
    ``caller``'s scope, else None."""
    scope = getattr(caller, "scope", None)
    symbol = scope.lookup(key) if scope is not None else None
    return numbered.get(symbol.slot) if symbol is not None and symbol.kind == ROUTINE else None
