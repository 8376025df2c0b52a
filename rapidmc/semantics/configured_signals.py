"""Configured I/O signals: names a program uses as signals without declaring them.

Real controller programs use the signals of the I/O configuration (EIO.cfg)
by name: ``SetDO doGripper, 1;``, ``IF diPartPresent = 1 THEN``.  They are
not declared in RAPID.  Before compiling, the linker walks every routine
and takes each undeclared name passed to a signal parameter of a predefined
routine (SetDO, WaitDI, DInput, ISignalDI, ...) as a configured signal of
that parameter's kind; the name can then also be read in expressions, in
any order.  An undeclared name compared with a number is a configured signal
too, of the kind its prefix says (``TEST giRecipe CASE 1:``, ``IF aiLevel > 2.5``) or
a ``_Gi``-style suffix (``Suck_Gi``); without either, only a name tested for equality
with 0 or 1 is one (a digital input, ``IF sensorPart = 1``).  A name with such a prefix
or suffix read as the whole value of an assignment (``nType := Type_Gi;``) is one too.
A name the program writes is never one: signals are not values RAPID can assign (AliasIO
and the Set/Reset instructions change them), so ``partReady := 0; ... IF partReady = 1``
and ``Incr nCycle; IF nCycle = 1`` read missing data.  Names passed to a ``mecunit`` parameter are
mechanical units of the motion configuration (``ActUnit CNV1``).
"""
from __future__ import annotations

import re
from typing import Iterable, Iterator, Optional

from .. import ast
from .library import registry

# Parameters of type anytype that take a signal: (routine key, parameter key).
SIGNAL_ALIASES = {("ALIASIO", "TOSIGNAL")}

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
    for node in _nodes(modules):
        yield from _call_uses(node)


def compared_names(modules: Iterable[ast.Module]) -> Iterator[tuple[ast.Name, str]]:
    """(name, kind) for each bare name compared with a number: ``IF diPart = 1 THEN``.

    Controller programs read configured signals by name without ever passing
    them to an I/O routine.  The kind follows the usual name prefix (di, do,
    gi, go, ai, ao: ``diPart``, ``DI_PART``, ``DI1``); a name without one is
    taken as a digital input.  The linker only asks about undeclared names.
    A name the program writes anywhere is data, not a signal, and is not yielded.
    """
    assigned = written_names(modules)
    for name, kind in _compared_uses(modules):
        if name.key not in assigned:
            yield name, kind


def written_names(modules: Iterable[ast.Module]) -> set[str]:
    """The names whose data (whole, an element or a component) some ``:=`` assigns, and
    the bare names passed to a parameter of a predefined routine that writes a value
    (``Incr nCycle``, ``TPReadNum nAnswer``, ``GetDataVal "x", ao_Act``: VAR, INOUT or
    PERS, of a type that is no signal's, AliasIO's ToSignal excepted)."""
    found = set()
    for node in _nodes(modules):
        if isinstance(node, ast.Assignment):
            root = node.target
            while isinstance(root, (ast.Index, ast.Component)):
                root = root.base
            if isinstance(root, ast.NameRef):
                found.add(root.name.key)
        for name, spec in _argument_specs(node):
            if spec.mode in ("VAR", "INOUT", "PERS") and spec.type_name.lower() not in \
                    SIGNAL_KINDS and (node.name.key, spec.key) not in SIGNAL_ALIASES:
                found.add(name.key)
    return found


def _compared_uses(modules: Iterable[ast.Module]) -> Iterator[tuple[ast.Name, str]]:
    for node in _nodes(modules):
        if isinstance(node, ast.Assignment) and isinstance(node.value, ast.NameRef) \
                and _SIGNAL_NAME.search(node.value.name.text) is not None:
            # ``PalletTypeNo := PalletTypeNo_Gi;`` reads a signal named as one
            yield node.value.name, kind_from_prefix(node.value.name.text)
        elif isinstance(node, ast.Binary) and node.op in COMPARISONS:
            for name_side, other in ((node.left, node.right), (node.right, node.left)):
                if isinstance(name_side, ast.NameRef) and _is_number(other):
                    kind = _compared_kind(name_side.name.text, (other,),
                                          digital=node.op in ("=", "<>"))
                    if kind is not None:
                        yield name_side.name, kind
        elif isinstance(node, ast.Test) and isinstance(node.subject, ast.NameRef) \
                and node.cases and all(_is_number(v) for case in node.cases for v in case.values):
            # ``TEST giRecipe CASE 1: ... CASE 2: ...`` compares the name with numbers too
            kind = _compared_kind(node.subject.name.text,
                                  [v for case in node.cases for v in case.values], digital=True)
            if kind is not None:
                yield node.subject.name, kind


def _compared_kind(name: str, numbers, digital: bool) -> Optional[str]:
    """The signal kind of a name compared with ``numbers``, or None when it is no signal.

    A signal prefix decides.  Without one the name is a digital input only when it is
    tested for equality with 0 or 1: ``nThickness <= 2.9`` or ``TEST nStation CASE 3:``
    reads a number of the program, which is missing, not an I/O signal.
    """
    if _SIGNAL_NAME.search(name) is not None:
        return kind_from_prefix(name)
    if digital and all(_number_value(n) in (0, 1) for n in numbers):
        return "DI"
    return None


COMPARISONS = ("=", "<>", "<", "<=", ">", ">=")
_PREFIX = re.compile(r"^(?:(di|do|gi|go|ai|ao)(?=[A-Z_0-9])|(DI|DO|GI|GO|AI|AO)(?=[_0-9]))")
# Some integrators put the kind last: ``PalletTypeNo_Gi``, ``CatchSuckNo_Go`` (survey round 8).
_SUFFIX = re.compile(r"_((?i:di|do|gi|go|ai|ao))$")
_SIGNAL_NAME = re.compile(f"{_PREFIX.pattern}|{_SUFFIX.pattern}")


def kind_from_prefix(name: str) -> str:
    """The signal kind a name's prefix (or ``_Gi``-style suffix) suggests: ``doLamp`` -> DO,
    ``Count_Gi`` -> GI; DI without either."""
    match = _PREFIX.match(name)
    if match is not None:
        return (match.group(1) or match.group(2)).upper()
    match = _SUFFIX.search(name)
    return match.group(1).upper() if match is not None else "DI"


def _is_number(expr) -> bool:
    if isinstance(expr, ast.Unary) and expr.op in ("-", "+"):
        expr = expr.operand
    return isinstance(expr, ast.NumLiteral)


def _number_value(expr):
    """The value of a number literal, sign included (``_is_number`` holds)."""
    if isinstance(expr, ast.Unary):
        value = _number_value(expr.operand)
        return -value if expr.op == "-" else value
    return expr.value


def _nodes(modules: Iterable[ast.Module]) -> Iterator[object]:
    for module in modules:
        for routine in module.routines:
            yield from walk_routine(routine)


def walk_routine(routine: ast.Routine) -> Iterator[object]:
    """Every statement and expression of a routine: its body, and its backward, UNDO and
    ERROR handlers (code that runs as much as the body does)."""
    sections = [routine.body, routine.backward or (), routine.undo or (),
                routine.error.body if routine.error else ()]
    for statements in sections:
        yield from _walk_statements(statements)


def unit_uses(modules: Iterable[ast.Module]) -> Iterator[ast.Name]:
    """Each bare name passed to a ``mecunit`` parameter of a predefined routine.

    Mechanical units other than the robots are named in the motion configuration
    (MOC.cfg): a conveyor ``CNV1`` for ActUnit and WaitWObj, a positioner ``STN1``,
    YuMi's arms ``ROB_L`` and ``ROB_R`` for EGMSetupUC.  Like signals, programs use
    them by name without declaring them.
    """
    for node in _nodes(modules):
        for name, type_name in _argument_uses(node):
            if type_name == "mecunit":
                yield name


def _call_uses(node) -> Iterator[tuple[ast.Name, str]]:
    for name, type_name in _argument_uses(node):
        kind = SIGNAL_KINDS.get(type_name)
        if kind is not None:
            yield name, kind


def _argument_uses(node) -> Iterator[tuple[ast.Name, str]]:
    """(name, parameter type in lower case) for each bare name argument of a predefined call."""
    for name, spec in _argument_specs(node):
        yield name, spec.type_name.lower()


def _argument_specs(node) -> Iterator[tuple[ast.Name, object]]:
    """(name, parameter spec) for each bare name argument of a predefined call."""
    if isinstance(node, ast.ProcedureCall):
        entry = registry.lookup_procedure(node.name.key)
    elif isinstance(node, ast.FunctionCall):
        entry = registry.lookup_function(node.name.key)
    else:
        return
    if entry is None:
        return
    for arg, spec in registry.matched_parameters(node.args, entry.signature.parameters):
        if spec is not None and isinstance(arg.value, ast.NameRef):
            yield arg.value.name, spec


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
    for case in getattr(statement, "cases", ()) or ():      # TEST's CASE values read too
        for value in case.values:
            yield from _walk_expression(value)


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
