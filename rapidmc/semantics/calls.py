"""Binding call arguments to parameters, for predefined and user routines alike.

RAPID arguments are positional for required parameters (optionally named,
``ToPoint:=p``), named with ``\\`` for optional ones, ``\\Name`` alone for a
switch, and ``\\Name?Source`` to pass a caller's optional parameter on only
if it is present.  ``bind`` checks a call statically (unknown names,
missing or extra arguments, two members of one alternative group, types)
and returns one *binder* per parameter: a function of the machine giving
what the callee receives — a value, a reference, ``ABSENT`` or a switch flag.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Optional, Sequence

from .. import ast
from ..diagnostics import ARGUMENT, NOT_A_REFERENCE, TYPE_MISMATCH, error
from .errors import RapidError
from .expressions import Compiled, ExpressionCompiler, constant, read_signal
from .machine import ABSENT
from .scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA, SIGNAL
from .types import ANYTYPE, SEMI_VALUE, AnyType, ArrayType, RapidType, same_type

VALUE = "value"
REFERENCE = "reference"
SIGNAL_ARG = "signal"


@dataclass
class ParameterView:
    """What binding needs to know of a parameter, whoever declared it."""

    name: str
    key: str
    mode: str                       # IN, VAR, PERS, INOUT, REF
    optional: bool
    group: Optional[int]
    is_switch: bool
    types: tuple                    # accepted RapidTypes; () = anytype
    rank: int
    predefined: bool = False        # a predefined routine's parameter (PERS read by value)


def _absent(m):
    return ABSENT


def _present(m):
    return True


def bind(compiler: ExpressionCompiler, routine_name: str, params: Sequence[ParameterView],
         args: Sequence[ast.Argument], span: ast.Span,
         sources: Optional[list] = None) -> list[tuple[str, Callable]]:
    """Check a call and return ``(kind, binder)`` per parameter (kind VALUE/REFERENCE/SIGNAL_ARG).

    ``sources``, when given, receives per parameter the ``Compiled`` value the binder
    computes when it has a source (an IN argument, an absent one, a switch given), else
    None (see ``Compiled.source``)."""
    chosen: dict[int, ast.Argument] = {}
    required = [i for i, p in enumerate(params) if not p.optional]
    groups_seen: dict[int, ParameterView] = {}
    position = 0
    for arg in args:
        if arg.kind == ast.REQUIRED and arg.name is None:
            while position < len(required) and (
                    required[position] in chosen or params[required[position]].group in groups_seen):
                position += 1
            if position >= len(required):
                raise error(ARGUMENT, f"too many arguments for {routine_name} (it takes "
                            f"{len(required)} required argument(s))", arg.span)
            index = _alternative_by_type(compiler, params, required[position], arg)
            position += 1
        else:
            index = _by_name(params, arg, routine_name)
        param = params[index]
        if param.group is not None:
            other = groups_seen.get(param.group)
            if other is not None and other.key != param.key:
                raise error(ARGUMENT, f"arguments {other.name} and {param.name} of "
                            f"{routine_name} exclude each other", arg.span)
            groups_seen[param.group] = param
        if index in chosen:
            raise error(ARGUMENT, f"argument {param.name} of {routine_name} given twice", arg.span)
        chosen[index] = arg
    binders = []
    for index, param in enumerate(params):
        arg = chosen.get(index)
        if arg is None:
            if not param.optional and not _alternative_given(params, param, chosen):
                raise error(ARGUMENT, f"missing argument {param.name} in call of {routine_name}",
                            span)
            binders.append((VALUE, _absent))
            if sources is not None:
                sources.append(constant(ABSENT, None))
            continue
        kind, binder, compiled = _binder(compiler, routine_name, param, arg)
        binders.append((kind, binder))
        if sources is not None:
            sources.append(compiled)
    return binders


def _alternative_by_type(compiler, params, index: int, arg: ast.Argument) -> int:
    """The member of a required alternative group (``Signal | PersFlag``) a positional argument
    binds to: the first member, unless the argument is a named data object whose declared type
    only another member takes (a PERS bool where a search takes a signal or a bool flag)."""
    group = params[index].group
    if group is None or not isinstance(arg.value, ast.NameRef):
        return index
    symbol = compiler.scope.lookup(arg.value.name.key) or \
        compiler.linker.system_symbol(arg.value.name)
    actual = getattr(symbol, "type", None)
    if actual is None or any(same_type(actual, t) for t in params[index].types):
        return index
    for other, param in enumerate(params):
        if param.group == group and any(same_type(actual, t) for t in param.types):
            return other
    return index


def _alternative_given(params, param, chosen) -> bool:
    return param.group is not None and any(
        params[i].group == param.group for i in chosen)


def _by_name(params: Sequence[ParameterView], arg: ast.Argument, routine_name: str) -> int:
    for index, param in enumerate(params):
        if param.key == arg.name.key:
            if arg.kind != ast.REQUIRED and not param.optional:
                raise error(ARGUMENT, f"{param.name} is a required parameter of {routine_name}: "
                            f"write it without '\\'", arg.span)
            return index
    known = ", ".join(("\\" if p.optional else "") + p.name for p in params) or "none"
    raise error(ARGUMENT, f"{routine_name} has no parameter '{arg.name.text}' "
                f"(parameters: {known})", arg.span)


def _binder(compiler: ExpressionCompiler, routine_name: str, param: ParameterView,
            arg: ast.Argument) -> tuple[str, Callable, Optional[Compiled]]:
    """(kind, binder, the binder's ``Compiled`` value when it has a source, else None)."""
    if param.is_switch:
        if arg.kind == ast.CONDITIONAL:
            return VALUE, _conditional(compiler, arg, by_reference=False), None
        if arg.kind != ast.SWITCH and arg.value is not None:
            raise error(ARGUMENT, f"\\{param.name} is a switch of {routine_name} and takes no "
                        "value", arg.span)
        return VALUE, _present, constant(True, None)
    if arg.kind == ast.SWITCH:
        raise error(ARGUMENT, f"argument \\{param.name} of {routine_name} needs a value "
                    f"(\\{param.name}:=...)", arg.span)
    signal_type = _signal_type(param)
    if arg.kind == ast.CONDITIONAL:
        return (REFERENCE if param.mode != "IN" else VALUE), _conditional(
            compiler, arg, by_reference=param.mode != "IN"), None
    if signal_type is not None:
        return SIGNAL_ARG, signal_designator(compiler, arg.value, signal_type), None
    if param.mode == "PERS" and param.predefined:
        return VALUE, _persistent_value(compiler, routine_name, param, arg), None
    if param.mode == "IN":
        expected = param.types[0] if len(param.types) == 1 and not param.rank else None
        compiled = compiler.value(arg.value, _value_expectation(expected))
        _check_types(param, compiled.type, arg.value.span, routine_name)
        return VALUE, compiled.fn, compiled if compiled.source is not None else None
    return REFERENCE, _reference_binder(compiler, routine_name, param, arg), None


def _value_expectation(expected):
    if isinstance(expected, RapidType) and expected.kind == SEMI_VALUE:
        return None
    return expected


def _check_types(param: ParameterView, actual: Optional[AnyType], span, routine_name) -> None:
    if actual is None or not param.types:
        return
    if param.rank:
        if not isinstance(actual, ArrayType) or actual.rank != param.rank:
            raise error(TYPE_MISMATCH, f"argument {param.name} of {routine_name} must be an "
                        f"array of rank {param.rank}", span)
        actual = actual.element
    if not any(same_type(actual, t) for t in param.types):
        wanted = " or ".join(str(t) for t in param.types)
        raise error(TYPE_MISMATCH, f"argument {param.name} of {routine_name} must be {wanted}, "
                    f"not {actual}", span)


def _persistent_value(compiler, routine_name, param, arg) -> Callable:
    """A predefined routine's PERS parameter: the value of a persistent (tool0 counts)."""
    expr = arg.value
    root = expr
    while isinstance(root, (ast.Index, ast.Component)):
        root = root.base
    if isinstance(root, ast.NameRef):
        symbol = compiler.scope.lookup(root.name.key) or compiler.linker.system_symbol(root.name)
        storage = symbol.storage if symbol is not None else ""
        if symbol is not None and storage not in ("PERS", "INOUT", "REF") and \
                compiler.linker.options.get("strict_pers", True):
            raise error(NOT_A_REFERENCE, f"argument {param.name} of {routine_name} must be a "
                        f"persistent (PERS), not {storage or 'a value'} '{root.name.text}' "
                        "(the controller requires PERS here)", expr.span)
    expected = param.types[0] if len(param.types) == 1 and not param.rank else None
    compiled = compiler.value(expr, expected)
    _check_types(param, compiled.type, expr.span, routine_name)
    return compiled.fn


def _reference_binder(compiler, routine_name, param, arg) -> Callable:
    expr = arg.value
    try:
        ref_fn, ref_type, symbol = compiler.reference(expr, f"passed to {param.mode} "
                                                      f"parameter {param.name}")
    except Exception:
        if param.mode in ("REF",):
            compiled = compiler.value(expr)
            value_fn = compiled.fn
            return lambda m: ("value", value_fn(m))
        raise
    _check_types(param, ref_type, expr.span, routine_name)
    storage = symbol.storage if symbol is not None else ""
    if symbol is None:                     # a placeholder <VAR>: an error when executed
        return ref_fn
    if symbol.kind == LOCAL_DATA and storage in ("CONST", "FOR") or storage == "CONST":
        raise error(NOT_A_REFERENCE, f"{storage} '{expr_root_name(expr)}' cannot be passed to "
                    f"{param.mode} parameter {param.name}", expr.span)
    if param.mode == "PERS" and storage not in ("PERS", "INOUT", "REF"):
        raise error(NOT_A_REFERENCE, f"argument {param.name} of {routine_name} must be a "
                    f"persistent (PERS), not {storage or 'a value'}", expr.span)
    if param.mode == "VAR" and storage == "PERS" and symbol.kind == GLOBAL_DATA:
        raise error(NOT_A_REFERENCE, f"argument {param.name} of {routine_name} must be a "
                    f"variable (VAR), not a persistent", expr.span)
    return ref_fn


def expr_root_name(expr) -> str:
    while not isinstance(expr, ast.NameRef):
        expr = expr.base
    return expr.name.text


def _conditional(compiler: ExpressionCompiler, arg: ast.Argument, by_reference: bool) -> Callable:
    symbol = compiler.scope.lookup(arg.source.key)
    if symbol is None or symbol.kind != LOCAL_DATA or not symbol.optional:
        raise error(ARGUMENT, f"conditional argument \\{arg.name.text}?{arg.source.text} needs "
                    f"an optional parameter of this routine", arg.span)
    slot = symbol.slot
    if by_reference and not symbol.by_reference:
        def local_ref(m):
            if m.frames[-1].locals[slot] is ABSENT:
                return ABSENT
            return (len(m.frames) - 1, slot, ())
        return local_ref
    if not by_reference and symbol.by_reference:
        def deref(m):
            ref = m.frames[-1].locals[slot]
            return ABSENT if ref is ABSENT else m.read_ref(ref)
        return deref
    return lambda m: m.frames[-1].locals[slot]


def _signal_type(param: ParameterView) -> Optional[RapidType]:
    if len(param.types) >= 1:
        first = param.types[0]
        if isinstance(first, RapidType) and first.kind == SEMI_VALUE:
            return first
    return None


def signal_designator(compiler: ExpressionCompiler, expr: ast.Expr,
                      signal_type: RapidType) -> Callable:
    """Compile a signal argument to ``fn(machine) -> physical signal index``."""
    if isinstance(expr, ast.StringLiteral):
        raise error(TYPE_MISMATCH, "a signal is required here, not a string", expr.span)
    if isinstance(expr, ast.NameRef):
        symbol = compiler.scope.lookup(expr.name.key) or compiler.linker.system_symbol(expr.name)
        if symbol is None:
            symbol = compiler.linker.infer_signal(expr.name, signal_type)
        if symbol.kind == SIGNAL:
            kind = getattr(symbol.type, "signal_kind", "")
            if kind and kind != signal_type.signal_kind:
                raise error(TYPE_MISMATCH, f"'{expr.name.text}' is a {kind} signal, a "
                            f"{signal_type.name} is required", expr.span)
            index = symbol.slot
            compiler.note_io_read(index)
            compiler.linker.note_signal_named(index)
            return lambda m: index
        if not (isinstance(symbol.type, RapidType) and symbol.type.kind == SEMI_VALUE):
            raise error(TYPE_MISMATCH, f"'{expr.name.text}' is {symbol.type}, not a signal",
                        expr.span)
        if symbol.type.signal_kind != signal_type.signal_kind:
            raise error(TYPE_MISMATCH, f"'{expr.name.text}' is a {symbol.type.name}, a "
                        f"{signal_type.name} is required", expr.span)
        compiler.note_io_read()            # (a parameter, signal data: any signal)
        if symbol.kind == LOCAL_DATA and symbol.by_reference:
            # a signal parameter of this routine: its caller bound the physical index
            slot = symbol.slot
            return lambda m: m.frames[-1].locals[slot]
    else:
        compiler.note_io_read()
    ref_fn, _, _ = compiler.reference(expr, "used as a signal")

    def bound_index(m):
        index = m.read_ref(ref_fn(m))
        if index < 0:
            raise RapidError("ERR_NO_ALIASIO_DEF",
                             "the signal data is not connected to a signal (AliasIO)")
        return index
    return bound_index
