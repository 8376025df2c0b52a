"""RMC801: NOT over an AND/OR/XOR chain without parentheses.

RAPID's NOT has the lowest priority: ``a AND NOT b AND c`` reads ``a AND NOT (b AND
c)``, which is rarely what the writer of the sorting cell's program meant.
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import NOT_CHAIN, Diagnostic
from .registry import rule

_LOGICAL = ("AND", "OR", "XOR")


@rule(NOT_CHAIN, "warning",
      bad="""
          MODULE M
            PROC main()
              VAR bool gate;
              gate := c_in = 0 AND NOT s1 = 1 AND s2 = 1;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PROC main()
              VAR bool gate;
              gate := c_in = 0 AND NOT (s1 = 1 AND s2 = 1);
            ENDPROC
          ENDMODULE
          """,
      why="NOT binds weakest in RAPID: it negates everything to its right up to the end of "
          "the expression or parenthesis, not the next comparison.")
def not_chain(context):
    for expression, site, routine, module in context.of_type(ast.Unary):
        if expression.op != "NOT":
            continue
        operand = expression.operand
        if type(operand) is not ast.Binary or operand.op not in _LOGICAL:
            continue
        if _parenthesised(context, expression, operand):
            continue
        yield Diagnostic(
            NOT_CHAIN, f"NOT negates the whole '{operand.op}' chain to its right; "
            "write the parentheses: NOT (...) if that is meant, (NOT ...) otherwise",
            expression.span, severity="warning")


def _parenthesised(context, negation, operand) -> bool:
    """Is there an opening parenthesis between NOT and its operand in the source?"""
    start, end = negation.span, operand.span
    if start.line != end.line:
        return _text_between(context, start, end).find("(") >= 0
    line = context.source_line(start.file, start.line)
    if line is None:
        return False
    return "(" in line[start.column - 1 + 3:end.column - 1]


def _text_between(context, start, end) -> str:
    parts = []
    for number in range(start.line, end.line + 1):
        line = context.source_line(start.file, number) or ""
        if number == start.line:
            line = line[start.column - 1 + 3:]
        if number == end.line:
            line = line[:end.column - 1] if number != start.line else line
        parts.append(line)
    return "\n".join(parts)
