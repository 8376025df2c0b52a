"""What the factories of state-reading routines share: bound arguments, robot state parts."""
from __future__ import annotations

from typing import Callable

from ... import ast
from ...diagnostics import UNKNOWN_NAME, UNKNOWN_ROUTINE, UNSUPPORTED, UserError, error
from ..calls import REFERENCE
from ..expressions import Compiled, constant
from ..instructions import Action, Instruction
from ..machine import ABSENT

ROBOT_TCP, ROBOT_TOOL, ROBOT_WOBJ, ROBOT_JOINTS = range(4)


class Arguments:
    """The bound arguments of one call, by parameter name."""

    def __init__(self, calls, compiler, call, entry):
        self.binders = calls.bind(compiler, entry, call.args, call.span)
        self.specs = entry.signature.parameters
        self.by_key = {spec.key: binder for spec, binder in zip(self.specs, self.binders)}

    def fn(self, key: str) -> Callable:
        return self.by_key[key.upper()][1]

    def kind(self, key: str) -> str:
        return self.by_key[key.upper()][0]

    def value(self, key: str) -> Callable:
        """fn(m) -> value of the argument (ABSENT if not given); reads through references."""
        kind, fn = self.by_key[key.upper()]
        if kind == REFERENCE:
            def deref(m):
                ref = fn(m)
                return ABSENT if ref is ABSENT else m.read_ref(ref)
            return deref
        return fn


def argument_expression(call, key: str, position: int):
    """The AST expression given for a parameter (by name or position), or None."""
    positional = [a for a in call.args if a.kind == ast.REQUIRED and a.name is None]
    for arg in call.args:
        if arg.name is not None and arg.name.key == key.upper():
            return arg.value
    if 0 <= position < len(positional):
        return positional[position].value
    return None


def no_effect(calls, compiler, call, entry) -> Instruction:
    """Factory of an instruction checked against its signature that changes nothing
    rapidmc observes (motion tuning, process settings, logs)."""
    Arguments(calls, compiler, call, entry)
    return Action(call.span, lambda m: None)


def fixed(value) -> Callable:
    """Factory of a function whose controller-dependent result is the fixed ``value``."""
    def factory(calls, compiler, call, entry) -> Compiled:
        Arguments(calls, compiler, call, entry)
        return constant(value, calls.return_type(entry))
    factory.reading = value        # input_flow bounds the size of values computed with it
    return factory


def not_modelled(reason: str) -> Callable:
    """Factory of a routine the program may call but rapidmc cannot model: the program
    loads; reaching the call stops with RMC305 saying ``reason``."""
    def factory(calls, compiler, call, entry):
        Arguments(calls, compiler, call, entry)
        return _stops(calls, call, entry, f"{call.name.text} {reason}")
    return factory


def _stops(calls, call, entry, message: str):
    """The compiled call (closure or instruction) that stops the run with RMC305."""
    def unsupported(m):
        raise error(UNSUPPORTED, message, call.span)
    if entry.signature.return_type:
        return Compiled(unsupported, calls.return_type(entry))
    return Action(call.span, unsupported)


def unknown_parameters(evidence: str) -> Callable:
    """Factory of a routine known from ABB's reference by name only (signature ``(...)``):
    the program loads whatever arguments it passes, which are neither checked nor evaluated;
    reaching the call stops with RMC305 saying that its parameter list is not known
    (``evidence`` says where the name comes from)."""
    def factory(calls, compiler, call, entry):
        for arg in call.args:
            if arg.value is not None:
                _names_are_declared(compiler, arg.value)
        return _stops(calls, call, entry, f"rapidmc knows {call.name.text} {evidence}; its "
                      "parameters and effect are not modelled")
    return factory


def _names_are_declared(compiler, expr) -> None:
    """Report an undeclared name or routine in an argument of a routine whose parameters are
    not known; whether the argument fits its (unknown) parameter cannot be checked."""
    try:
        compiler.value(expr)
    except UserError as failure:
        if any(d.code in (UNKNOWN_NAME, UNKNOWN_ROUTINE) for d in failure.diagnostics):
            raise


# The factory of the names rapidmc knows from docs/reference-names.txt only.
NAME_ONLY = unknown_parameters("from the name list of ABB's reference only "
                               "(docs/reference-names.txt)")
