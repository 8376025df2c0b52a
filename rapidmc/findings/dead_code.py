"""Statements no execution reaches whatever the inputs: those after a jump in their list.

A statement that follows, in the same statement list, one that always leaves that list
(RETURN, EXIT, ExitCycle, GOTO, RETRY, TRYNEXT, and RAISE in a routine without an ERROR
handler of its own; a ``WHILE TRUE`` loop with no GOTO inside: RAPID's EXIT ends the
program, so only a GOTO leaves such a loop) runs only if a GOTO leads to a label between
them (or inside it):
without such a label it is dead code under any input, whatever messages, answers or readings a check
tried (the second ``RETURN robtarget_string;`` of a MARC-HT25 function).  Coverage
(``coverage_warnings``) says "under any input" for a stretch of such statements even when
other unreached code rests on the inputs tried.

A RAISE in a routine whose ERROR handler holds a TRYNEXT may come back (TRYNEXT goes on
with the statement after it), and so may a RETURN there whose value can raise an error
(``RETURN 10 / d;``: ERR_DIVZERO, then TRYNEXT runs the statement after the RETURN).  A
handler without TRYNEXT never comes back after the statement that raised (RETRY runs it
again, RAISE passes the error on, the handler's end leaves the routine), and an error
raised inside the handler itself goes to the caller.  Stop lets the program go on: it does
not end the list.

Likewise the statements of an ``IF Present(p)`` branch, in a procedure whose every call
(there is at least one) leaves the optional parameter ``p`` out: no call passes it, so
``Present(p)`` is FALSE whatever the inputs (``ROS_receive_msg_joint_traj_pt``'s branch
for a ``\\wait_time`` that the motion server never gives; ``lines_behind_absent_options``).
"""
from __future__ import annotations

from .. import ast
from ..semantics.library.program_control import CALLS_BY_NAME

# instructions, as procedure calls, that never let their statement list go on
ENDING_CALLS = frozenset({"EXITCYCLE"})
JUMPS = (ast.Return, ast.Exit, ast.Goto, ast.Retry, ast.TryNext)


def lines_after_jumps(routine_ast) -> frozenset:
    """(file, line) of every statement of the routine (nested ones included) that follows
    a jump in its statement list with no label in between."""
    return frozenset(jumps_before(routine_ast))


def jumps_before(routine_ast) -> dict:
    """(file, line) -> the jump statement it follows, for every line of
    ``lines_after_jumps`` (the cause a coverage warning names: ``unreached_causes``)."""
    dead: dict = {}
    for statements, comes_back in _statement_lists(routine_ast):
        ended = None
        for statement in statements:
            if any(isinstance(node, ast.Label) for node, _ in ast.walk(statement)):
                ended = None              # a GOTO may lead here (or inside: kept, to be safe)
            elif ended is not None:
                for node, _ in ast.walk(statement):
                    if getattr(node, "span", None) is not None:
                        dead.setdefault((node.span.file, node.span.line), ended)
            elif leaves_list(statement, comes_back):
                ended = statement
    return dead


def errors_come_back(routine_ast) -> bool:
    """Whether an error raised in the routine's body (not in its handler) may go on with the
    statement after the one that raised: its ERROR handler holds a TRYNEXT."""
    handler = routine_ast.error
    return handler is not None and any(isinstance(node, ast.TryNext)
                                       for statement in handler.body
                                       for node, _ in ast.walk(statement))


def leaves_list(statement, comes_back: bool) -> bool:
    """Whether execution never goes on with the statement after this one in its list;
    ``comes_back``: errors raised here may come back by TRYNEXT (``errors_come_back``)."""
    if isinstance(statement, ast.Return) and comes_back:
        return not _may_raise(statement.value)
    if isinstance(statement, JUMPS):
        return True
    if isinstance(statement, ast.Raise):
        return not comes_back
    if isinstance(statement, ast.While):
        return endless(statement)
    return isinstance(statement, ast.ProcedureCall) and statement.name.key in ENDING_CALLS


def endless(loop) -> bool:
    """Whether a WHILE loop never lets its list go on: its condition is the literal TRUE
    and no GOTO inside may jump out (an error raised inside comes back, by RETRY or
    TRYNEXT, inside the loop, or leaves the routine)."""
    return isinstance(loop.condition, ast.BoolLiteral) and loop.condition.value is True \
        and not any(isinstance(node, ast.Goto) for statement in loop.body
                    for node, _ in ast.walk(statement))


def _may_raise(value) -> bool:
    """Whether evaluating a RETURN's value may raise an error: anything but nothing, a
    literal or a name (an index may be out of range, a call or an operation may fail)."""
    return value is not None and \
        not isinstance(value, (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral, ast.NameRef))


def _statement_lists(routine_ast):
    """Every statement list of the routine (its body, its handlers', and each nested one),
    each with whether an error raised in it may come back by TRYNEXT."""
    comes_back = errors_come_back(routine_ast)
    for part, part_comes_back in ((routine_ast.body, comes_back),
                                  (routine_ast.backward, comes_back),
                                  (routine_ast.undo, comes_back),
                                  (routine_ast.error.body if routine_ast.error is not None
                                   else None, False)):
        if part is None:
            continue
        for statements in ast.statement_lists(part):
            yield statements, part_comes_back


def lines_behind_absent_options(routines) -> frozenset:
    """(file, line) of the statements of each ``IF Present(p)`` (or ELSEIF) branch of a
    procedure that some call reaches and whose every call, among ``routines`` (the ASTs
    of every routine of the program), leaves the optional parameter ``p`` out (a
    conditional argument ``\\p?q`` passes it).  Empty when a procedure may be called by
    a name computed at run time (a late-bound call, CallByVar ...)."""
    calls: dict = {}                  # procedure key -> the parameter keys some call passes
    for routine_ast in routines:
        for node, _ in ast.walk(routine_ast):
            if isinstance(node, ast.LateBindingCall) or (
                    isinstance(node, ast.ProcedureCall) and node.name.key in CALLS_BY_NAME):
                return frozenset()
            if isinstance(node, ast.ProcedureCall):
                calls.setdefault(node.name.key, set()).update(
                    argument.name.key for argument in node.args if argument.name is not None)
    dead: set = set()
    for routine_ast in routines:
        passed = calls.get(routine_ast.name.key)
        if passed is None:
            continue                      # (not called: an entry, or no call reaches it)
        absent = {parameter.name.key for parameter in routine_ast.parameters
                  if parameter.optional} - passed
        for node, _ in ast.walk(routine_ast):
            if isinstance(node, ast.IfBranch) and _presence_of(node.condition) in absent:
                dead.update((inner.span.file, inner.span.line)
                            for statement in node.body for inner, _ in ast.walk(statement)
                            if getattr(inner, "span", None) is not None)
    return frozenset(dead)


def _presence_of(condition):
    """The parameter key of a condition ``Present(p)``, else None."""
    if isinstance(condition, ast.FunctionCall) and condition.name.key == "PRESENT" and \
            len(condition.args) == 1 and isinstance(condition.args[0].value, ast.NameRef):
        return condition.args[0].value.name.key
    return None
