"""RMC809: a PERS number used as an array index with no bound check around it.

PERS data is shared by every task that declares it and keeps its value across
restarts: another task, or last week's run, may have left any number in it.  A use is
checked when a condition around it (IF, ELSEIF, WHILE, TEST) compares the PERS, or an
earlier IF of the same routine compares it and leaves or assigns it (``checks``).

A wrong value must also be plausible: the rule keeps to PERS data the program never
writes (another task, the FlexPendant or a PC does) or writes with anything but a
constant (a count ``n := n + 1``, an input ``TPReadNum n``, a routine's INOUT
argument).  A PERS the program only sets to constants holds one of them or its
initial value, which the programmer chose, in this run and in any earlier one.
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import SHARED_INDEX, Diagnostic
from .checks import checked
from .context import name_of, subexpressions
from .registry import rule

@rule(SHARED_INDEX, "warning",
      bad="""
          MODULE M
            PERS num next_slot := 1;
            VAR robtarget slots{4};
            PROC main()
              MoveL slots{next_slot}, v100, fine, tool0;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PERS num next_slot := 1;
            VAR robtarget slots{4};
            PROC main()
              IF next_slot >= 1 AND next_slot <= Dim(slots, 1) THEN
                MoveL slots{next_slot}, v100, fine, tool0;
              ENDIF
            ENDPROC
          ENDMODULE
          """,
      why="Another task sharing the PERS, or a value kept from an earlier run, can put any "
          "number there: out of range it stops the program with ERR_ARRAY_INDEX (ERR_ORDER).")
def shared_index(context):
    constant_only = _written_with_constants_only(context)
    for expression, site, routine, module in context.of_type(ast.Index):
        if routine is None:
            continue
        for index in expression.indices:
            for name in _pers_names(context, index, routine, module):
                if name.key in constant_only:
                    continue
                if site is not None and checked(context, site, name.key):
                    continue
                yield Diagnostic(
                    SHARED_INDEX, f"PERS '{name.text}' is used as an index with no bound "
                    "check: another task or an earlier run may have left any value in it",
                    name.span, severity="warning")


def _pers_names(context, index, routine, module):
    seen = set()
    for expression in subexpressions(index):
        if type(expression) is ast.NameRef and expression.name.key not in seen:
            declaration = context.declaration(expression.name.key, routine, module)
            if isinstance(declaration, ast.DataDeclaration) and declaration.storage == ast.PERS:
                seen.add(expression.name.key)
                yield expression.name


def _written_with_constants_only(context) -> set[str]:
    """The keys of the data the program writes, and only ever with a constant: a number,
    a negated number or a CONST (by assignment to the whole datum or an element)."""
    constant, other = set(), set()
    for site in context.sites:
        statement = site.statement
        if type(statement) is ast.Assignment:
            target = name_of(statement.target)
            if target is not None:
                is_constant = _is_constant(context, statement.value, site)
                (constant if is_constant else other).add(target.key)
        for expression in _written_arguments(context, site):
            target = name_of(expression)
            if target is not None:
                other.add(target.key)
    return constant - other


def _written_arguments(context, site):
    """The argument expressions of ``site`` a call may write (every one that names data)."""
    statement = site.statement
    if type(statement) is ast.ProcedureCall:
        yield from (argument.value for argument in statement.args if argument.value is not None)
    for call in context.function_calls(site):
        yield from (argument.value for argument in call.args if argument.value is not None)


def _is_constant(context, value, site) -> bool:
    kind = type(value)
    if kind is ast.NumLiteral:
        return True
    if kind is ast.Unary and value.op in ("-", "+"):
        return _is_constant(context, value.operand, site)
    if kind is ast.NameRef:
        declaration = context.declaration(value.name.key, site.routine, site.module)
        return isinstance(declaration, ast.DataDeclaration) and declaration.storage == ast.CONST
    return False
