"""Calls of predefined routines: binding, static checks, and dispatch.

Pure routines (math, strings, …) are called through their registry
implementation.  Routines that need the program state (I/O, motion,
FlexPendant, clocks, interrupts, Present, Dim, ValToStr …) carry a
``factory`` in their registry entry (``rapidmc.semantics.library``) that
compiles each call into a closure or an instruction.
"""
from __future__ import annotations

from typing import Callable

from .. import ast
from ..diagnostics import ENV_ONLY, TYPE_MISMATCH, UNKNOWN_ROUTINE, error
from .library import registry
from .calls import REFERENCE, SIGNAL_ARG, VALUE, ParameterView, bind
from .expressions import Compiled, ExpressionCompiler, constant, with_source
from .instructions import Action, Instruction
from .machine import ABSENT
from .program import ENVIRONMENT_NAMESPACE
from .types import ANYTYPE, ArrayType


def plain(value):
    """What a registry implementation receives for an argument (None when absent)."""
    return None if value is ABSENT else value


def _argument_expression(args, key: str, position: int):
    """The expression passed for parameter ``key`` (by name, else by position)."""
    for arg in args:
        if arg.name is not None and arg.name.key == key:
            return arg.value
    positional = [a for a in args if a.kind == ast.REQUIRED and a.name is None]
    return positional[position].value if position < len(positional) else None


def _with_call_source(compiled: Compiled, impl, entry, sources: list) -> Compiled:
    """``compiled`` (a call of a predefined function) with its source when every argument
    has one: ``impl(plain(a), ...)``, switches as ``a is True`` (``argument_functions``)."""
    if any(source is None for source in sources):
        return compiled
    arguments = ", ".join(
        ("{1}({%d} is True)" if spec.is_switch else "{1}({%d})") % (i + 2)
        for i, spec in enumerate(entry.signature.parameters))
    return with_source(compiled, "{0}(" + arguments + ")", constant(impl, None),
                       constant(plain, None), *sources)


class PredefinedCalls:
    """Compiles calls of predefined functions and procedures for one linker."""

    def __init__(self, linker):
        self.linker = linker
        self._views: dict[str, list[ParameterView]] = {}

    # --------------------------------------------------------------- signatures
    def views(self, entry) -> list[ParameterView]:
        key = entry.signature.kind + entry.key
        cached = self._views.get(key)
        if cached is None:
            cached = []
            for spec in entry.signature.parameters:
                types = tuple(t for t in (self.linker.builtin_types.get(n.upper())
                                          for n in spec.accepted_types) if t is not None)
                if types and types[0] is ANYTYPE:
                    types = ()
                cached.append(ParameterView(spec.name, spec.key, spec.mode, spec.optional,
                                            spec.alternative_group, spec.is_switch, types,
                                            spec.array_rank, predefined=True))
            self._views[key] = cached
        return cached

    def return_type(self, entry):
        name = entry.signature.return_type
        return self.linker.builtin_types.get(name.upper()) if name else None

    def _check_environment(self, compiler: ExpressionCompiler, name: ast.Name, span) -> None:
        from .library.environment_model import ENVIRONMENT_ONLY
        if name.key in ENVIRONMENT_ONLY:
            routine = compiler.routine
            in_environment = routine is not None and routine.namespace == ENVIRONMENT_NAMESPACE
            if not in_environment:
                raise error(ENV_ONLY, f"{name.text} is a model-only routine, allowed only in "
                            "environment modules (--env)", span)

    # ---------------------------------------------------------------- functions
    def predefined_function(self, compiler: ExpressionCompiler, expr: ast.FunctionCall) -> Compiled:
        entry = registry.lookup_function(expr.name.key)
        if entry is None:
            if registry.lookup_procedure(expr.name.key) is not None:
                raise error(TYPE_MISMATCH, f"'{expr.name.text}' is a procedure: call it as a "
                            "statement, not in an expression", expr.span)
            raise error(UNKNOWN_ROUTINE, f"unknown function '{expr.name.text}'", expr.span,
                        subject=expr.name.key)
        self._check_environment(compiler, expr.name, expr.span)
        compiler._no_variables(expr)
        if entry.special:
            return entry.factory(self, compiler, expr, entry)
        sources: list = []
        binders = bind(compiler, entry.signature.name, self.views(entry), expr.args, expr.span,
                       sources)
        impl = self.implementation(compiler, entry, expr.args)
        fns = self.argument_functions(entry, binders)
        return_type = self.return_type(entry)
        if len(fns) == 1:
            only = fns[0]
            compiled = Compiled(lambda m: impl(plain(only(m))), return_type)
        elif len(fns) == 2:
            first, second = fns
            compiled = Compiled(lambda m: impl(plain(first(m)), plain(second(m))), return_type)
        else:
            compiled = Compiled(lambda m: impl(*[plain(fn(m)) for fn in fns]), return_type)
        return _with_call_source(compiled, impl, entry, sources)

    def argument_functions(self, entry, binders) -> list:
        """Per parameter: fn(m) -> the Python value a registry implementation receives."""
        fns = []
        for spec, (_, fn) in zip(entry.signature.parameters, binders):
            if spec.is_switch:
                fns.append(lambda m, fn=fn: fn(m) is True)
            else:
                fns.append(fn)
        return fns

    def implementation(self, compiler, entry, args):
        """The implementation for the static type of the call's first ``anynum`` argument."""
        for position, spec in enumerate(entry.signature.parameters):
            if spec.type_name != "anynum":
                continue
            expr = _argument_expression(args, spec.key, position)
            if expr is None:
                break
            if spec.by_reference:
                _, arg_type, _ = compiler.reference(expr, "passed")
            else:
                arg_type = compiler.value(expr).type
            if arg_type is not None and getattr(arg_type, "key", "") == "DNUM":
                return entry.implementation("dnum")
            break
        return entry.impl

    def bind(self, compiler, entry, args, span, sources=None):
        return bind(compiler, entry.signature.name, self.views(entry), args, span, sources)

    # --------------------------------------------------------------- procedures
    def predefined_procedure(self, compiler: ExpressionCompiler, statement: ast.ProcedureCall,
                             routine_compiler) -> Instruction:
        entry = registry.lookup_procedure(statement.name.key)
        if entry is None:
            if registry.lookup_function(statement.name.key) is not None:
                raise error(TYPE_MISMATCH, f"'{statement.name.text}' is a function: use its "
                            "value in an expression (a function call is not a statement)",
                            statement.span)
            raise error(UNKNOWN_ROUTINE, f"unknown procedure '{statement.name.text}'",
                        statement.span, subject=statement.name.key)
        self._check_environment(compiler, statement.name, statement.span)
        if entry.special:
            return entry.factory(self, compiler, statement, entry)
        binders = bind(compiler, entry.signature.name, self.views(entry), statement.args,
                       statement.span)
        impl = self.implementation(compiler, entry, statement.args)
        return Action(statement.span, self._pure_procedure(entry, impl, binders))

    def _pure_procedure(self, entry, impl, binders) -> Callable:
        names = [spec.name for spec in entry.signature.parameters]
        kinds = [kind for kind, _ in binders]
        fns = self.argument_functions(entry, binders)

        def call(m):
            refs = {}
            args = []
            for name, kind, fn in zip(names, kinds, fns):
                value = fn(m)
                if kind == REFERENCE and value is not ABSENT:
                    refs[name] = value
                    value = m.read_ref(value)
                args.append(plain(value))
            changes = impl(*args)
            if changes:
                for name, new in changes.items():
                    m.write_ref(refs[name], new)
        return call

    def connect(self, compiler: ExpressionCompiler, statement: ast.Connect) -> Instruction:
        from .library.interrupts import connect
        return connect(self, compiler, statement)
