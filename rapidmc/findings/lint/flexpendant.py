"""RMC810: TPReadFK with an empty key label whose number the program waits for.

A function key whose label is empty ("" or stEmpty) is not shown on the FlexPendant:
the operator cannot press it.  A branch taken when the answer is that key's number
can never run, and a loop waiting for it never ends.
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import EMPTY_KEY, Diagnostic
from .arguments import bind_predefined
from .context import name_of
from .registry import rule

KEYS = ("TPFK1", "TPFK2", "TPFK3", "TPFK4", "TPFK5")


def _empty(expression) -> bool:
    kind = type(expression)
    return (kind is ast.StringLiteral and expression.value == "") or \
        (kind is ast.NameRef and expression.name.key == "STEMPTY")


@rule(EMPTY_KEY, "warning",
      bad="""
          MODULE M
            PROC main()
              VAR num key;
              TPReadFK key, "Start the cycle?", "Yes", stEmpty, stEmpty, stEmpty, "No";
              IF key = 2 THEN
                TPWrite "starting";
              ENDIF
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PROC main()
              VAR num key;
              TPReadFK key, "Start the cycle?", "Yes", stEmpty, stEmpty, stEmpty, "No";
              IF key = 1 THEN
                TPWrite "starting";
              ENDIF
            ENDPROC
          ENDMODULE
          """,
      why="An empty label hides the key: the answer the program compares with can never "
          "come.")
def empty_key(context):
    for site in context.calls:
        call = site.statement
        if call.name.key != "TPREADFK":
            continue
        bound = bind_predefined(call)
        answer = bound.get("TPANSWER")
        name = name_of(answer.value) if answer is not None and answer.value is not None else None
        if name is None:
            continue
        compared = _compared_numbers(context, site, name.key)
        for number, key in enumerate(KEYS, start=1):
            argument = bound.get(key)
            if argument is not None and argument.value is not None and \
                    _empty(argument.value) and number in compared:
                yield Diagnostic(
                    EMPTY_KEY, f"key {number} of TPReadFK has an empty label, so the "
                    f"operator cannot press it, but the program tests "
                    f"'{name.text} = {number}' (line {compared[number]})",
                    argument.value.span, severity="warning")


def _compared_numbers(context, call_site, key: str) -> dict[int, int]:
    """Number -> line, for each number the answer ``key`` is compared with after the call
    (up to the next TPReadFK into the same answer, in the lines of the routine)."""
    start = call_site.statement.span.line
    end = _next_read(context, call_site, key)
    found: dict[int, int] = {}
    for site in context.sites_by_routine[id(call_site.routine)]:
        statement = site.statement
        if type(statement) is ast.Test and _is(statement.subject, key) \
                and start < statement.span.line < end:
            for case in statement.cases:
                for value in case.values:
                    if type(value) is ast.NumLiteral:
                        found.setdefault(int(value.value), value.span.line)
    for expression, site, inside, module in context.of_type(ast.Binary):
        if inside is not call_site.routine or expression.op not in ("=", "<>") \
                or not start <= expression.span.line < end:
            continue
        for this, other in ((expression.left, expression.right),
                            (expression.right, expression.left)):
            if _is(this, key) and type(other) is ast.NumLiteral:
                found.setdefault(int(other.value), expression.span.line)
    return found


def _next_read(context, call_site, key: str) -> float:
    """The line of the next TPReadFK of the routine into the same answer (or infinity)."""
    for site in context.sites_by_routine[id(call_site.routine)]:
        statement = site.statement
        if type(statement) is ast.ProcedureCall and statement.name.key == "TPREADFK" \
                and statement.span.line > call_site.statement.span.line:
            answer = bind_predefined(statement).get("TPANSWER")
            if answer is not None and answer.value is not None and _is(answer.value, key):
                return statement.span.line
    return float("inf")


def _is(expression, key: str) -> bool:
    return type(expression) is ast.NameRef and expression.name.key == key
