"""RMC806 (data never used) and RMC807 (routines never called).

Routine data and LOCAL module data are reported whenever nothing uses them.  Global
and TASK names are reported only in a program with a ``main`` procedure (a module
linted alone may be a library for others) and never from a SYSMODULE; global PERS data
is never reported (another task may share it; TASK PERS is the task's own), nor a
routine whose name a string of the program could spell (``CallByVar``, ``%name%``), nor
a global procedure without parameters (an operator may start it by hand, "PP to routine":
``check`` sums those up, and ``check --entry all`` checks each).
"""
from __future__ import annotations

from ... import ast
from ...diagnostics import UNUSED_DATA, UNUSED_ROUTINE, Diagnostic
from .registry import rule


def _used_names(context) -> set[str]:
    """Every name the program uses as data, routine or trap (``LintContext.used_names``)."""
    return context.used_names


def _scoped_uses(context) -> dict[int, set[str]]:
    """Routine id -> the names used inside it (for routine data)."""
    uses: dict[int, set[str]] = {}
    for expression, site, routine, module in context.of_type(ast.NameRef):
        if routine is not None:
            uses.setdefault(id(routine), set()).add(expression.name.key)
    return uses


def _has_main(context) -> bool:
    return any(r.name.key == "MAIN" and r.kind == ast.PROC
               for module in context.modules for r in module.routines)


def _is_system(module: ast.Module) -> bool:
    return "SYSMODULE" in module.attributes


@rule(UNUSED_DATA, "note", default=False,
      bad="""
          MODULE M
            PROC main()
              VAR num unused_count;
              TPWrite "ready";
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PROC main()
              TPWrite "ready";
            ENDPROC
          ENDMODULE
          """,
      why="Data nobody reads or writes is noise, or the sign of a name misspelt elsewhere.")
def unused_data(context):
    used = _used_names(context)
    scoped = _scoped_uses(context)
    whole_program = _has_main(context)
    for module in context.modules:
        for routine in module.routines:
            inside = scoped.get(id(routine), set())
            for decl in routine.data:
                if decl.name.key not in inside:
                    yield _unused(decl, f"routine data '{decl.name.text}' of "
                                        f"{routine.name.text}")
        if _is_system(module):
            continue
        for decl in module.data:
            if decl.name.key in used:
                continue
            if decl.scope != ast.LOCAL and not whole_program:
                continue                 # a module alone may be a library for others
            if decl.scope == ast.GLOBAL and decl.storage == ast.PERS:
                continue                 # another task may share it
            yield _unused(decl, f"{decl.storage} '{decl.name.text}'")


def _service_routine(routine: ast.Routine) -> bool:
    """A global procedure without parameters: one the operator may start from the
    FlexPendant ("PP to routine"), as a calibration or a test move is."""
    return routine.kind == ast.PROC and not routine.local and not routine.parameters


def _unused(decl, what: str) -> Diagnostic:
    return Diagnostic(UNUSED_DATA, f"{what} is declared and never used", decl.name.span,
                      severity="note")


@rule(UNUSED_ROUTINE, "note",
      bad="""
          MODULE M
            PROC main()
              TPWrite "ready";
            ENDPROC
            LOCAL PROC old_home()
              TPWrite "home";
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PROC main()
              TPWrite "ready";
            ENDPROC
          ENDMODULE
          """,
      why="A routine nothing calls is dead code that still has to be read and maintained.")
def unused_routine(context):
    used = _used_names(context)
    whole_program = _has_main(context)
    spelled = [e.value.upper() for e, *_ in context.of_type(ast.StringLiteral) if e.value]
    for module in context.modules:
        if _is_system(module):
            continue
        for routine in module.routines:
            key = routine.name.key
            if key in used or key == "MAIN" or (not routine.local and not whole_program):
                continue
            if any(key.startswith(text) for text in spelled):
                continue
            if _service_routine(routine):
                continue                 # an operator may start it by hand
            kind = {ast.PROC: "procedure", ast.FUNC: "function", ast.TRAP: "trap"}[routine.kind]
            yield Diagnostic(UNUSED_ROUTINE, f"{kind} {routine.name.text} is never "
                             f"{'connected' if routine.kind == ast.TRAP else 'called'}",
                             routine.name.span, severity="note")
