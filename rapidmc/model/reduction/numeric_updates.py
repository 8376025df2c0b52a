"""Predefined numeric updates read as the assignments they are.

``Incr x``, ``Decr x``, ``Clear x`` and ``Add x, e`` change one num or
dnum variable exactly as ``x := x + 1``, ``x := x - 1``, ``x := 0`` and
``x := x + e`` do as far as the reductions care: they read and write the same data, and they fail in the same cases
(``Incr``: never, a stored value being finite; ``Add``: as
``Totality`` decides for ``x + e``).
Real programs count cycles and parts with ``Incr``, so the slicing
analysis (``relevance``) and merged steps (``merging``) look at a call
through ``as_assignment``; a call they cannot read so (a user routine of
that name, optional or named arguments, any other argument form) stays a
call, which both treat as observable.
"""
from __future__ import annotations

from typing import Callable, Optional

from ... import ast

UPDATES = {"INCR": ("+", 1), "DECR": ("-", 1), "CLEAR": (None, 0), "ADD": ("+", None)}


def as_assignment(call, lookup: Callable[[str], object]) -> Optional[ast.Assignment]:
    """The assignment that ``call`` amounts to, or None; ``lookup(key)`` resolves a name
    where the call is written (a user routine named ``Incr`` is no predefined update)."""
    if not isinstance(call, ast.ProcedureCall):
        return None
    update = UPDATES.get(call.name.key)
    if update is None or lookup(call.name.key) is not None:
        return None
    op, amount = update
    args = call.args
    if len(args) != (2 if amount is None else 1) or \
            any(arg.kind != ast.REQUIRED or arg.name is not None for arg in args):
        return None
    target = args[0].value
    if not isinstance(target_root(target), ast.NameRef):
        return None
    span = call.span
    operand = args[1].value if amount is None else ast.NumLiteral(amount, str(amount), span)
    value = operand if op is None else ast.Binary(op, target, operand, span)
    return ast.Assignment(target, value, span)


def target_root(target):
    """The data name under an assignment target's indices and components."""
    while isinstance(target, (ast.Index, ast.Component)):
        target = target.base
    return target
