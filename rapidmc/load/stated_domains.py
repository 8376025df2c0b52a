"""Domains of free analog and group inputs that no exact default covers, stated as assumptions.

``input_domains`` derives a default that loses no behaviour when every use of
an input's value can be placed; a value that goes into arithmetic reaching a
condition (``Abs(AOutput(ao) - AInput(ai)) < limit``, a camera's position
clamped and moved to, a PLC's line number stored in a PERS) has none.  Such
programs are among the most common on real controllers (issue 28: two whole
backups and three held-out programs stopped at RMC502), and a safety engineer
expects the check to go on with the values the program itself singles out and
to say so, as a test plan would:

* the numbers the input, or any data computed from it, is compared with in the
  code or in a property's atom (``=`` ``<>`` ``<`` ``<=`` ``>`` ``>=`` with a
  literal or CONST num, TEST CASE values, WaitAI/WaitGI values): for a group input each number, its
  integer neighbours and 0; for an analog input each number, one value
  between neighbours, one beyond each end, and 0 (what an unconnected input
  reads);
* the signal's configured range from the I/O configuration (``-MinLog`` and
  ``-MaxLog`` of an analog signal, the device map's width of a group signal):
  its ends are values too, and nothing beyond them is taken.

"Data computed from it" is followed by name: the target of an assignment
whose value mentions the input or such data, and the parameter a call passes
it to.  The domain is named beside every verdict under ``assumes:`` (a HOLDS
covers those values only) and as an RMC515 note; ``--input-domain`` gives
others, and ``--exact-input-domains`` refuses instead (RMC502).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from .. import ast
from ..semantics.configured_signals import COMPARISONS
from ..semantics.program import Program, Signal
from .call_graph import TaskRoutines

READERS = frozenset({"GINPUT", "AINPUT"})
WAITS = frozenset({"WAITGI", "WAITAI"})


@dataclass(frozen=True)
class Range:
    """A signal's configured logical range (None where the configuration gives no end)."""

    low: Optional[float] = None
    high: Optional[float] = None


def configured_range(program: Program, signal: Signal) -> Range:
    """The range EIO.cfg gives the signal: ``-MinLog``/``-MaxLog`` of an analog input,
    0..2^width-1 of a group input."""
    for configured in program.options.get("configured_signals", ()):
        if configured.name.upper() != signal.key:
            continue
        if signal.kind == "GI" and getattr(configured, "width", None):
            return Range(0.0, float(2 ** configured.width - 1))
        return Range(getattr(configured, "low", None), getattr(configured, "high", None))
    return Range(0.0, None) if signal.kind == "GI" else Range()


def carriers(program: Program, signal: Signal, aliases: frozenset) -> frozenset:
    """Upper-case names that hold the input's value or data computed from it: the signal,
    the signal data ``aliases`` bound to it, and by name every datum assigned from (or
    parameter passed) an expression that mentions one of them, to a fixed point."""
    names = {signal.key} | set(aliases)
    routines = TaskRoutines(program.routines)
    changed = True
    while changed:
        changed = False
        for routine in routines.routines:         # every task's (each has its own main)
            for node, _ in ast.walk(routine.ast):
                for target in _receivers(node, names, routines, routine):
                    if target not in names:
                        names.add(target)
                        changed = True
    return frozenset(names)


def _receivers(node, names: set, routines: TaskRoutines, caller) -> list:
    """The names ``node`` (in ``caller``) stores a value mentioning ``names`` into."""
    if isinstance(node, ast.Assignment) and mentions(node.value, names):
        path = _path(node.target)
        return [path] if path is not None else []
    routine = routines.called(caller, node.name.key) \
        if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) else None
    if routine is not None:
        parameters = [p.name.key for p in routine.ast.parameters if not p.optional]
        passed = [arg for arg in node.args if arg.value is not None and mentions(arg.value, names)]
        found = []
        for position, arg in enumerate(node.args):
            if arg not in passed:
                continue
            if arg.name is not None:
                found.append(arg.name.key)
            elif position < len(parameters):
                found.append(parameters[position])
        return found
    return []


def _path(target) -> Optional[str]:
    """``POSCAM.X`` for ``posCAM.x`` (components kept apart, so that a camera's x and y
    are compared with their own numbers), ``TABLE`` for ``table{i}``."""
    if isinstance(target, ast.Component):
        base = _path(target.base)
        return f"{base}.{target.name.key}" if base is not None else None
    if isinstance(target, ast.Index):
        return _path(target.base)
    return target.name.key if isinstance(target, ast.NameRef) else None


def mentions(expr, names) -> bool:
    """Whether ``expr`` reads one of ``names`` (paths of ``_path``): a whole datum that
    holds one of them, or a component of one."""
    return any(isinstance(node, (ast.NameRef, ast.Component)) and _path(node) in names
               for node, _ in ast.walk(expr))


def roots(names: frozenset) -> frozenset:
    """The data names of ``names`` (``POSCAM`` of ``POSCAM.X``)."""
    return frozenset(name.split(".", 1)[0] for name in names)


def compared_constants(program: Program, names: frozenset, number_value,
                       atoms: tuple = (), atom_scope=None) -> set:
    """The numbers an expression mentioning ``names`` is compared with anywhere in the code
    or in a property's atom (``atoms``, read in ``atom_scope``); ``number_value(expr,
    scope)``: the num a literal or CONST denotes, else None."""
    numbers: set = set()
    for routine in program.routines:
        if routine.ast is not None:
            numbers |= _constants_in(routine.ast, routine.scope, names, number_value)
    for expr in atoms:
        numbers |= _constants_in(expr, atom_scope, names, number_value)
    return numbers


def _constants_in(root, scope, names: frozenset, number_value) -> set:
    numbers: set = set()
    for node, _ in ast.walk(root):
        if isinstance(node, ast.Binary) and node.op in COMPARISONS:
            for side, other in ((node.left, node.right), (node.right, node.left)):
                value = number_value(other, scope)
                if value is not None and mentions(side, names):
                    numbers.add(value)
        elif isinstance(node, ast.Test) and mentions(node.subject, names):
            values = (number_value(v, scope) for case in node.cases for v in case.values)
            numbers.update(v for v in values if v is not None)
        elif isinstance(node, ast.ProcedureCall) and node.name.key in WAITS:
            values = [arg.value for arg in node.args
                      if arg.kind == ast.REQUIRED and arg.name is None]
            if len(values) == 2 and mentions(values[0], names):
                value = number_value(values[1], scope)
                if value is not None:
                    numbers.add(value)
    return numbers
