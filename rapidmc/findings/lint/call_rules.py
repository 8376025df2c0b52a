"""RMC802 (tool, work object or load not PERS) and RMC803 (optional argument's case):
what a call passes, checked against the parameter it fills."""
from __future__ import annotations

import functools

from ... import ast
from ...diagnostics import OPTIONAL_CASE, TOOL_NOT_PERS, Diagnostic
from .arguments import bind_predefined, predefined_signature
from .context import name_of
from .registry import rule

_PERSISTENT_TYPES = ("tooldata", "wobjdata", "loaddata")


def call_sites(context):
    """(call, is a procedure call, routine, module) of every call in the program."""
    for site in context.calls:
        yield site.statement, True, site.routine, site.module
    for call, site, routine, module in context.of_type(ast.FunctionCall):
        yield call, False, routine, module


@rule(TOOL_NOT_PERS, "error",
      bad="""
          MODULE M
            VAR tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
            PROC main()
              MoveL Offs(CRobT(), 0, 0, 10), v100, fine, gripper;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
            PROC main()
              MoveL Offs(CRobT(), 0, 0, 10), v100, fine, gripper;
            ENDPROC
          ENDMODULE
          """,
      why="A move instruction's Tool, WObj and TLoad are PERS parameters: RobotStudio's "
          "virtual controller accepts a VAR or CONST there, a real controller's program "
          "check does not (K-RAPID paper, Table 5).")
def tool_not_pers(context):
    for call, is_procedure, routine, module in call_sites(context):
        parameters = _persistent_parameters(call.name.key, is_procedure)
        if not parameters:
            continue
        bound = bind_predefined(call, is_procedure)
        for spec in parameters:
            argument = bound.get(spec.key)
            if argument is None or argument.value is None:
                continue
            name = name_of(argument.value)
            declaration = name and context.declaration(name.key, routine, module)
            storage = _storage(declaration)
            if storage is not None and storage != "PERS":
                yield Diagnostic(
                    TOOL_NOT_PERS, f"{spec.type_name} '{name.text}' given to {call.name.text} "
                    f"\\{spec.name} is {storage}: a real controller requires PERS",
                    argument.value.span, severity="error",
                    notes=(f"declared at {declaration.span}",))


@functools.lru_cache(maxsize=None)
def _persistent_parameters(key: str, procedure: bool) -> tuple:
    """The PERS tooldata, wobjdata and loaddata parameters of a predefined routine."""
    signature = predefined_signature(ast.Name.of(key), procedure)
    if signature is None or signature.open_parameters:
        return ()
    return tuple(spec for spec in signature.parameters
                 if spec.mode == "PERS" and spec.type_name in _PERSISTENT_TYPES)


def _storage(declaration):
    if isinstance(declaration, ast.DataDeclaration):
        return declaration.storage
    if isinstance(declaration, ast.Parameter) and declaration.mode in ("IN", "VAR"):
        return "an IN parameter" if declaration.mode == "IN" else "a VAR parameter"
    return None


@rule(OPTIONAL_CASE, "note", default=False,
      bad="""
          MODULE M
            PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
            PERS wobjdata table := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
            PROC main()
              MoveL Offs(CRobT(), 0, 0, 10), v100, fine, gripper \\wobj:=table;
            ENDPROC
          ENDMODULE
          """,
      good="""
          MODULE M
            PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
            PERS wobjdata table := [FALSE, TRUE, "", [[0, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
            PROC main()
              MoveL Offs(CRobT(), 0, 0, 10), v100, fine, gripper \\WObj:=table;
            ENDPROC
          ENDMODULE
          """,
      why="Optional arguments are matched to parameters without regard to case by the "
          "controller, so the program runs; the manual spells them as declared, and tools "
          "that compare names exactly (the K-RAPID semantics, editors, other checkers) do "
          "not match them (K-RAPID, Table 5).  A note: real programs spell \\InPos and "
          "\\WObj every way.")
def optional_case(context):
    for call, is_procedure, routine, module in call_sites(context):
        named = [a for a in call.args if a.kind != ast.REQUIRED and a.name is not None]
        if not named:
            continue
        declared = _declared_names(context, call, is_procedure)
        for argument in named:
            spelling = declared.get(argument.name.key)
            if spelling is not None and spelling != argument.name.text:
                yield Diagnostic(
                    OPTIONAL_CASE, f"optional argument '\\{argument.name.text}' of "
                    f"{call.name.text} is declared '\\{spelling}'", argument.name.span,
                    severity="note")


def _declared_names(context, call, is_procedure) -> dict[str, str]:
    entry = context.routines.get(call.name.key)
    if entry is not None:
        return {p.name.key: p.name.text for p in entry[0].parameters if p.optional}
    return _predefined_optional_names(call.name.key, is_procedure)


@functools.lru_cache(maxsize=None)
def _predefined_optional_names(key: str, is_procedure: bool) -> dict[str, str]:
    signature = predefined_signature(ast.Name.of(key), is_procedure)
    if signature is None:
        return {}
    return {spec.key: spec.name for spec in signature.parameters if spec.optional}
