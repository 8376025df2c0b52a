"""Which parameter each argument of a call fills, for predefined and user routines."""
from __future__ import annotations

import functools
from typing import Optional

from ... import ast
from ...semantics.library import lookup_function, lookup_procedure


def predefined_signature(name: ast.Name, procedure: bool = True):
    """The registered signature of a predefined routine, or None."""
    entry = (lookup_procedure if procedure else lookup_function)(name.key)
    return entry.signature if entry is not None else None


def bind_predefined(call, procedure: bool = True) -> dict[str, ast.Argument]:
    """Parameter key -> argument for a call of a predefined routine (empty when the
    routine is not predefined or its parameter list is not known)."""
    slots = _required_slots(call.name.key, procedure)
    return _bind(call.args, slots) if slots is not None else {}


@functools.lru_cache(maxsize=None)
def _required_slots(key: str, procedure: bool) -> Optional[tuple]:
    """The keys of each positional slot of a predefined routine (a group of required
    alternatives is one slot), or None when the routine or its parameters are unknown."""
    entry = (lookup_procedure if procedure else lookup_function)(key)
    if entry is None or entry.signature.open_parameters:
        return None
    slots = []
    for spec in entry.signature.required:
        if slots and spec.alternative_group is not None \
                and spec.alternative_group == slots[-1][0]:
            slots[-1][1].append(spec.key)
        else:
            slots.append((spec.alternative_group, [spec.key]))
    return tuple(keys for _, keys in slots)


def bind_user(call, routine: ast.Routine) -> dict[str, ast.Argument]:
    """Parameter key -> argument for a call of a user routine."""
    return _bind(call.args, [[p.name.key] for p in routine.parameters if not p.optional])


def _bind(args, slots: list[list[str]]) -> dict[str, ast.Argument]:
    bound: dict[str, ast.Argument] = {}
    position = 0
    for argument in args:
        if argument.name is not None:
            bound[argument.name.key] = argument
            if argument.kind == ast.REQUIRED:
                position += 1
        elif position < len(slots):
            bound[slots[position][0]] = argument
            position += 1
    return bound


def argument_value(bound: dict, key: str) -> Optional[object]:
    argument = bound.get(key)
    return argument.value if argument is not None else None


def by_reference(call, routines: dict, procedure: bool = True):
    """The argument expressions of ``call`` that bind a parameter the routine may write
    (VAR, INOUT, PERS).  Nothing for a routine whose declaration is not loaded (in an
    encrypted module or an option): what it does is not known."""
    found = routines.get(call.name.key)
    if found is not None:
        modes = {p.name.key: p.mode.upper() for p in found[0].parameters}
        bound = bind_user(call, found[0])
    else:
        entry = (lookup_procedure if procedure else lookup_function)(call.name.key)
        if entry is None or entry.signature.open_parameters:
            return
        modes = {p.key: p.mode.upper() for p in entry.signature.parameters}
        bound = bind_predefined(call, procedure)
    keys = {id(argument): key for key, argument in bound.items()}
    for argument in call.args:
        if argument.value is not None and modes.get(keys.get(id(argument)), "IN") != "IN":
            yield argument.value
