"""RMC808: statements no execution reaches, after RETURN, EXIT, RAISE, ExitCycle, GOTO
(and RETRY or TRYNEXT in an ERROR handler), up to the next label.

``Stop`` does not end a block: the operator may start the program again, and it goes
on with the statement after the Stop (``rapidmc run`` does the same).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import UNREACHABLE, Diagnostic
from .context import nested_bodies, routine_sections
from .registry import rule

_ENDS = (ast.Return, ast.Exit, ast.Raise, ast.Goto, ast.Retry, ast.TryNext)
_ENDING_CALLS = {"EXITCYCLE"}


def ends_block(statement) -> bool:
    """Does execution never continue with the statement after this one?"""
    kind = type(statement)
    if kind in _ENDS:
        return True
    if kind is ast.ProcedureCall:
        return statement.name.key in _ENDING_CALLS
    if kind is ast.If and statement.else_body is not None:
        bodies = [branch.body for branch in statement.branches] + [statement.else_body]
        return all(body and ends_block(body[-1]) for body in bodies)
    if kind is ast.Test and statement.default is not None:
        bodies = [case.body for case in statement.cases] + [statement.default]
        return all(body and ends_block(body[-1]) for body in bodies)
    return False


@rule(UNREACHABLE, "warning",
      bad="""
          MODULE M
            PROC main()
              TPWrite "done";
              RETURN;
              TPWrite "never shown";
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PROC main()
              TPWrite "done";
              TPWrite "shown";
              RETURN;
            ENDPROC
          ENDMODULE
          """,
      why="Code after an unconditional RETURN, EXIT, RAISE or GOTO never runs: usually a "
          "debugging shortcut left in, or a block that lost its IF.")
def unreachable(context):
    for module in context.modules:
        for routine in module.routines:
            for _, body in routine_sections(routine):
                yield from _check_body(body)


def _check_body(body):
    ended_by, reported = None, False
    for statement in body:
        if type(statement) is ast.Label:
            ended_by, reported = None, False
        elif ended_by is not None and not reported:
            yield Diagnostic(UNREACHABLE, f"this statement is never reached: the "
                             f"{_describe(ended_by)} on line {ended_by.span.line} comes first",
                             statement.span, severity="warning")
            reported = True             # one finding per unreachable stretch
        for inner, _ in nested_bodies(statement):
            yield from _check_body(inner)
        if ended_by is None and ends_block(statement):
            ended_by = statement


def _describe(statement) -> str:
    kind = type(statement)
    if kind is ast.ProcedureCall:
        return statement.name.text
    if kind in (ast.If, ast.Test):
        return f"{kind.__name__.upper()} whose every branch leaves"
    return kind.__name__.upper()
