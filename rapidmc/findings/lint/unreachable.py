"""RMC808: statements no execution reaches, after RETURN, EXIT, RAISE, ExitCycle, GOTO
(and RETRY or TRYNEXT in an ERROR handler) or a ``WHILE TRUE`` loop no GOTO leaves, up
to the next label.

``Stop`` does not end a block: the operator may start the program again, and it goes
on with the statement after the Stop (``rapidmc run`` does the same).  Where the routine's
ERROR handler holds a TRYNEXT, a RAISE (or a RETURN whose value may raise) does not end
its block either: TRYNEXT goes on with the statement after it (``findings.dead_code``,
which coverage shares).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import UNREACHABLE, Diagnostic
from ..dead_code import errors_come_back, leaves_list
from .context import nested_bodies, routine_sections
from .registry import rule


def ends_block(statement, comes_back: bool = False) -> bool:
    """Does execution never continue with the statement after this one?  ``comes_back``:
    an error raised here may come back by the routine's TRYNEXT."""
    kind = type(statement)
    if kind is ast.If and statement.else_body is not None:
        bodies = [branch.body for branch in statement.branches] + [statement.else_body]
        return all(body and ends_block(body[-1], comes_back) for body in bodies)
    if kind is ast.Test and statement.default is not None:
        bodies = [case.body for case in statement.cases] + [statement.default]
        return all(body and ends_block(body[-1], comes_back) for body in bodies)
    return leaves_list(statement, comes_back)


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
            comes_back = errors_come_back(routine)
            for section, body in routine_sections(routine):
                yield from _check_body(body, comes_back and section != "error")


def _check_body(body, comes_back: bool):
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
            yield from _check_body(inner, comes_back)
        if ended_by is None and ends_block(statement, comes_back):
            ended_by = statement


def _describe(statement) -> str:
    kind = type(statement)
    if kind is ast.ProcedureCall:
        return statement.name.text
    if kind in (ast.If, ast.Test):
        return f"{kind.__name__.upper()} whose every branch leaves"
    if kind is ast.While:
        return "WHILE TRUE loop (no GOTO leaves it)"
    return kind.__name__.upper()
