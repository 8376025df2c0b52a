"""RMC809: a PERS number used as an array index with no bound check around it.

PERS data is shared by every task that declares it and keeps its value across
restarts: another task, or last week's run, may have left any number in it.  A use is
checked when a condition around it (IF, ELSEIF, WHILE, TEST) compares the PERS, or an
earlier IF of the same routine compares it and leaves or assigns it (``checks``).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import SHARED_INDEX, Diagnostic
from .checks import checked
from .context import subexpressions
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
    for expression, site, routine, module in context.of_type(ast.Index):
        if routine is None:
            continue
        for index in expression.indices:
            for name in _pers_names(context, index, routine, module):
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
