"""What a re-run of the user functions in a WaitUntil condition could see change.

A user FUNC in an expression takes steps of its own, so the statement compiler
calls it before the statement and the statement reads its result
(``StatementCompiler.hoist``).  A controller evaluates a WaitUntil condition
anew at every poll, the function calls included, so a wait whose function
returned FALSE must call them again when what they read may have changed: else
``WaitUntil Started()`` waits forever for a flag another task, a trap or the
outside sets (``instructions.WaitRerun``).  Calling them again at every try
would make a wait that nothing can end a loop without end rather than a wait:
``no_deadlock`` would no longer find it.  So the wait calls them again only when
the global data they read changed since their last call; when they read what
may change without a step of the program (a signal, PERS data written outside
the loaded code, a predefined routine reading the controller, a routine named at
run time), at every try, as a wait on a free input may always end.
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from .scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE
from .types import SEMI_VALUE

# predefined functions whose result depends only on their arguments
_PURE_FUNCTIONS = frozenset({
    "ABS", "ROUND", "TRUNC", "SQRT", "EXP", "POW", "SIN", "COS", "TAN", "ASIN", "ACOS",
    "ATAN", "ATAN2", "DIM", "PRESENT", "STRLEN", "STRPART", "STRFIND", "STRMATCH", "STRMEMB",
    "STRORDER", "STRMAP", "NUMTOSTR", "DNUMTOSTR", "VALTOSTR", "STRTOVAL", "STRTOBYTE",
    "BYTETOSTR", "OFFS", "RELTOOL", "ORIENTZYX", "EULERZYX", "NORIENT", "BITAND", "BITOR",
    "BITXOR", "BITNEG", "BITLSH", "BITRSH", "BITCHECK", "NUMTODNUM", "DNUMTONUM"})


def global_reads(linker, expr, scope, callees: list) -> Optional[tuple]:
    """The global data slots the wait's condition ``expr`` (in ``scope``) and the user
    routines ``callees`` it calls read, transitively, in slot order; None when any of them
    reads something that may change without a step of the program, or names data this
    cannot follow."""
    slots: set = set()
    seen: set = set()
    if not _reads(linker, expr, scope, slots, seen):
        return None
    for callee in callees:
        if not _routine_reads(linker, callee, slots, seen):
            return None
    return tuple(sorted(slots))


def _routine_reads(linker, routine, slots: set, seen: set) -> bool:
    if routine.index in seen:
        return True
    seen.add(routine.index)
    scope = getattr(routine, "scope", None)
    if routine.ast is None or scope is None:
        return False
    return _reads(linker, routine.ast, scope, slots, seen)


def _reads(linker, tree, scope, slots: set, seen: set) -> bool:
    outside = linker.outside_data
    for node, _ in ast.walk(tree):
        if isinstance(node, ast.LateBindingCall):
            return False
        if isinstance(node, (ast.FunctionCall, ast.ProcedureCall)):
            symbol = scope.lookup(node.name.key)
            if symbol is not None and symbol.kind == ROUTINE:
                if not _routine_reads(linker, linker.routine_by_index(symbol.slot), slots, seen):
                    return False
            elif node.name.key not in _PURE_FUNCTIONS:
                return False
        elif isinstance(node, ast.NameRef):
            symbol = scope.lookup(node.name.key)
            if symbol is None:
                return False             # a system variable, a signal of the controller
            if getattr(symbol.type, "kind", None) == SEMI_VALUE:
                return False             # data bound to a signal (AliasIO)
            if symbol.kind == GLOBAL_DATA:
                if symbol.slot in outside:
                    return False
                slots.add(symbol.slot)
            elif symbol.kind not in (CONSTANT, LOCAL_DATA, ROUTINE):
                return False             # a signal
    return True
