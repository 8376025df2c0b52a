"""RMC809: a PERS number used as an array index with no bound check around it.

PERS data is shared by every task that declares it and keeps its value across
restarts: another task, or last week's run, may have left any number in it.  A use is
checked when a condition around it (IF, ELSEIF, WHILE, TEST) compares the PERS, or an
earlier IF of the same routine compares it and leaves or assigns it (``checks``).

A wrong value must also be plausible: the rule keeps to PERS data that the program, or
another task of the controller (``lint_tasks``), *changes*: writes with anything but a
constant (a count ``n := n + 1``, an input ``TPReadNum n``, a routine's INOUT argument).
A PERS that the loaded code only sets to constants, or never writes, holds one of those
constants or its initial value, which the programmer chose, in this run and in any
earlier one (a configuration value such as a robot or channel number).  A call of a
routine whose declaration is not loaded (an encrypted module, an option) is no evidence
of a write.
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import SHARED_INDEX, Diagnostic
from .arguments import by_reference
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
              next_slot := next_slot + 1;
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
              next_slot := next_slot + 1;
            ENDPROC
          ENDMODULE
          """,
      why="Another task sharing the PERS, or a value kept from an earlier run, can put any "
          "number there: out of range it stops the program with ERR_ARRAY_INDEX (ERR_ORDER).")
def shared_index(context):
    changed = changed_data(context) | context.other_tasks_change
    for expression, site, routine, module in context.of_type(ast.Index):
        if routine is None:
            continue
        for index in expression.indices:
            for name in _pers_names(context, index, routine, module):
                if name.key not in changed:
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


def changed_data(context) -> frozenset:
    """The keys of the data the program writes with anything but a constant (a number, a
    negated number or a CONST), by assignment to the whole datum or a part, or as a call's
    argument (which the routine may write)."""
    changed = set()
    for site in context.sites:
        statement = site.statement
        if type(statement) is ast.Assignment:
            target = name_of(statement.target)
            if target is not None and not _is_constant(context, statement.value, site):
                changed.add(target.key)
        for expression in _written_arguments(context, site):
            target = name_of(expression)
            if target is not None:
                changed.add(target.key)
    return frozenset(changed)


def _written_arguments(context, site):
    """The argument expressions of ``site``'s calls that the routine may write."""
    statement = site.statement
    if type(statement) is ast.ProcedureCall:
        yield from by_reference(statement, context.routines)
    for call in context.function_calls(site):
        yield from by_reference(call, context.routines, procedure=False)


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
