"""Arguments given to a parameter its routine never names (issue 27).

PickMaster's supervision task logs an event with the names of the signals involved::

    PmErrorLog 2384, ERRSTR_TASK, "pmProject_giDefaultHeight", ERRSTR_CONTEXT,
               "pmProject_diSetDefaultHeight", ERRSTR_UNUSED \\EventType:=TYPE_WARN;

A string naming a signal counts as a read of that signal (code may reach it by name:
AliasIO, GetDataVal), so the input stays stored in every state.  But a string given to a
parameter the called routine never names reaches nothing: the routine cannot pass it on,
compare it or bind a signal with it.  A routine of a stubs module is empty (its assumption
says so: ``stub PmErrorLog is empty``), so none of its parameters is named.
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.configured_signals import walk_routine
from ..semantics.library.registry import matched_parameters
from ..semantics.scope import ROUTINE
from .reduction.relevance import DATA_BY_NAME


def idle_literals(program) -> set:
    """ids of the string literals passed, as a whole argument, to a parameter of a loaded
    routine that the routine's code never names."""
    named: dict = {}                # routine index -> keys its code names
    found = set()
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            continue
        for node in walk_routine(routine.ast):
            if not isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                continue
            symbol = routine.scope.lookup(node.name.key)
            if symbol is None or symbol.kind != ROUTINE:
                continue
            callee = program.routines[symbol.slot]
            if callee.ast is None:
                continue
            if symbol.slot not in named:
                named[symbol.slot] = _named_keys(callee.ast)
            keys = named[symbol.slot]
            for argument, parameter in matched_parameters(node.args, callee.parameters):
                if isinstance(argument.value, ast.StringLiteral) and parameter is not None \
                        and keys is not None and parameter.key not in keys:
                    found.add(id(argument.value))
    return found


def _named_keys(tree: ast.Routine) -> Optional[frozenset]:
    """Every name a routine's code refers to: data read or written, an optional parameter
    passed on (``\\Sig?Sig``), a string that may name data; None (all of them) when the
    routine reaches data by a name (GetDataVal ...) or late-bound calls."""
    keys = set()
    for node in walk_routine(tree):
        if isinstance(node, ast.LateBindingCall) or \
                isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                node.name.key in DATA_BY_NAME:
            return None
        if isinstance(node, ast.NameRef):
            keys.add(node.name.key)
        elif isinstance(node, ast.StringLiteral):
            keys.add(node.value.upper())
        for argument in getattr(node, "args", None) or ():
            if argument.source is not None:
                keys.add(argument.source.key)
    return frozenset(keys)
