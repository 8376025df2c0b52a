"""Configured I/O signals: names a program uses as signals without declaring them.

Real controller programs use the signals of the I/O configuration (EIO.cfg)
by name: ``SetDO doGripper, 1;``, ``IF diPartPresent = 1 THEN``.  They are
not declared in RAPID.  Before compiling, the linker walks every routine
and takes each undeclared name passed to a signal parameter of a predefined
routine (SetDO, WaitDI, DInput, ISignalDI, ...) as a configured signal of
that parameter's kind; the name can then also be read in expressions, in
any order.
"""
from __future__ import annotations

from typing import Iterable, Iterator

from .. import ast
from .builtins import registry

SIGNAL_KINDS = {"signaldi": "DI", "signaldo": "DO", "signalai": "AI", "signalao": "AO",
                "signalgi": "GI", "signalgo": "GO"}


def declared_names(modules: Iterable[ast.Module]) -> set[str]:
    """Every data, parameter and routine name declared anywhere in the modules."""
    names: set[str] = set()
    for module in modules:
        names.update(d.name.key for d in module.data)
        for routine in module.routines:
            names.add(routine.name.key)
            names.update(p.name.key for p in routine.parameters)
            names.update(d.name.key for d in routine.data)
            names.update(_for_variables(routine.body))
    return names


def signal_uses(modules: Iterable[ast.Module]) -> Iterator[tuple[ast.Name, str]]:
    """(name, kind) for each bare name passed to a signal parameter of a predefined routine."""
    for module in modules:
        for routine in module.routines:
            sections = [routine.body, routine.backward or (), routine.undo or (),
                        routine.error.body if routine.error else ()]
            for statements in sections:
                for node in _walk_statements(statements):
                    yield from _call_uses(node)


def _call_uses(node) -> Iterator[tuple[ast.Name, str]]:
    if isinstance(node, ast.ProcedureCall):
        entry = registry.lookup_procedure(node.name.key)
    elif isinstance(node, ast.FunctionCall):
        entry = registry.lookup_function(node.name.key)
    else:
        return
    if entry is None:
        return
    parameters = entry.signature.parameters
    required = [p for p in parameters if not p.optional]
    position = 0
    for arg in node.args:
        if arg.kind == ast.REQUIRED and arg.name is None:
            spec = required[position] if position < len(required) else None
            position += 1
        else:
            spec = entry.signature.parameter(arg.name.key) if arg.name else None
        if spec is None or not isinstance(arg.value, ast.NameRef):
            continue
        kind = SIGNAL_KINDS.get(spec.type_name.lower())
        if kind is not None:
            yield arg.value.name, kind


def _for_variables(statements) -> Iterator[str]:
    for node in _walk_statements(statements):
        if isinstance(node, ast.For):
            yield node.variable.key


def _walk_statements(statements) -> Iterator[object]:
    for statement in statements:
        yield statement
        yield from _walk_expressions_of(statement)
        for child in _child_blocks(statement):
            yield from _walk_statements(child)


def _child_blocks(statement):
    if isinstance(statement, ast.If):
        for branch in statement.branches:
            yield branch.body
        if statement.else_body:
            yield statement.else_body
    elif isinstance(statement, (ast.For, ast.While)):
        yield statement.body
    elif isinstance(statement, ast.Test):
        for case in statement.cases:
            yield case.body
        if statement.default:
            yield statement.default
    elif isinstance(statement, ast.CompactIf):
        yield (statement.statement,)


def _walk_expressions_of(statement) -> Iterator[object]:
    for field in ("value", "target", "condition", "subject", "start", "stop", "step", "name_expr"):
        expr = getattr(statement, field, None)
        if expr is not None and not isinstance(expr, (str, ast.Name)):
            yield from _walk_expression(expr)
    for arg in getattr(statement, "args", ()) or ():
        if arg.value is not None:
            yield from _walk_expression(arg.value)
    for branch in getattr(statement, "branches", ()) or ():
        yield from _walk_expression(branch.condition)


def _walk_expression(expr) -> Iterator[object]:
    yield expr
    if isinstance(expr, ast.FunctionCall):
        for arg in expr.args:
            if arg.value is not None:
                yield from _walk_expression(arg.value)
    for field in ("base", "operand", "left", "right"):
        child = getattr(expr, field, None)
        if child is not None:
            yield from _walk_expression(child)
    for child in getattr(expr, "indices", ()) or getattr(expr, "items", ()) or ():
        yield from _walk_expression(child)
