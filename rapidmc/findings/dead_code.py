"""Statements no execution reaches whatever the inputs: those after a jump in their list.

A statement that follows, in the same statement list, one that always leaves that list
(RETURN, EXIT, ExitCycle, GOTO, RETRY, TRYNEXT, and RAISE in a routine without an ERROR
handler of its own) runs only if a GOTO leads to a label between them (or inside it):
without such a label it is dead code under any input, whatever messages, answers or readings a check
tried (the second ``RETURN robtarget_string;`` of a MARC-HT25 function).  Coverage
(``coverage_warnings``) says "under any input" for a stretch of such statements even when
other unreached code rests on the inputs tried.

A RAISE in a routine with its own ERROR handler may come back (TRYNEXT goes on after it),
and so may a RETURN there whose value can raise an error (``RETURN 10 / d;``: ERR_DIVZERO,
then TRYNEXT runs the statement after the RETURN); Stop lets the program go on: none of
them ends the list here.
"""
from __future__ import annotations

from .. import ast

# instructions, as procedure calls, that never let their statement list go on
ENDING_CALLS = frozenset({"EXITCYCLE"})
JUMPS = (ast.Return, ast.Exit, ast.Goto, ast.Retry, ast.TryNext)


def lines_after_jumps(routine_ast) -> frozenset:
    """(file, line) of every statement of the routine (nested ones included) that follows
    a jump in its statement list with no label in between."""
    handled = routine_ast.error is not None
    dead: set = set()
    for statements in _statement_lists(routine_ast):
        ended = False
        for statement in statements:
            if any(isinstance(node, ast.Label) for node, _ in ast.walk(statement)):
                ended = False             # a GOTO may lead here (or inside: kept, to be safe)
            elif ended:
                dead.update((node.span.file, node.span.line) for node, _ in ast.walk(statement)
                            if getattr(node, "span", None) is not None)
            elif _ends_list(statement, handled):
                ended = True
    return frozenset(dead)


def _ends_list(statement, handled: bool) -> bool:
    if isinstance(statement, ast.Return) and handled:
        return not _may_raise(statement.value)
    if isinstance(statement, JUMPS):
        return True
    if isinstance(statement, ast.Raise):
        return not handled
    return isinstance(statement, ast.ProcedureCall) and statement.name.key in ENDING_CALLS


def _may_raise(value) -> bool:
    """Whether evaluating a RETURN's value may raise an error: anything but nothing, a
    literal or a name (an index may be out of range, a call or an operation may fail)."""
    return value is not None and \
        not isinstance(value, (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral, ast.NameRef))


def _statement_lists(routine_ast):
    """Every statement list of the routine: its body, its handlers', and each nested one."""
    for part in (routine_ast.body, routine_ast.backward, routine_ast.undo,
                 routine_ast.error.body if routine_ast.error is not None else None):
        if part is None:
            continue
        yield tuple(part)
        for statement in part:
            for node, _ in ast.walk(statement):
                for name in ("body", "else_body", "default"):
                    inner = getattr(node, name, None)
                    if isinstance(inner, tuple) and not isinstance(node, ast.Routine):
                        yield inner
