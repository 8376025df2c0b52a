"""PERS data a wait awaits a value of that no loaded code ever writes (issue 28).

A command loop that a PC or an HMI drives clears its command and waits for the next
one::

    nCmdInput := 0;
    WaitUntil nCmdInput <> 0;

The loaded code writes only 0, so within it the wait can never end: only a client
outside the controller's programs (a PC through Robot Web Services or the PC SDK, an
HMI, a task that is not in the backup) ends it.  Reporting that wait as a deadlock is
a false alarm a cell engineer learns to ignore.  This module names such data as also
written by an outside client, so that ``outside_data`` chooses its value where a
wait reads it (as for data a task not loaded writes) and the verdicts say so under
``assumes:``.

A handshake flag polled in an endless loop is awaited the same way (held-out survey,
issue 28: seven false "never reached" warnings in one program)::

    WHILE TRUE DO
        IF newTarget = TRUE THEN
            newTarget := FALSE;
            ...
        ENDIF
        WaitTime 0.25;
    ENDWHILE

The condition of an IF or ELSEIF (or a compact IF) inside a WHILE is a poll
(``polled``): ``statements`` reads such data there as it reads a WaitUntil condition
(``OutsideData.polled_at`` names those conditions).

The rule is narrow, so that it never hides a wait the loaded code could end:

* the WaitUntil (or poll) condition is ``name op constant`` (either side; ``op`` a comparison;
  the constant a literal or a CONST: ``GlbCommandId = INST_UNKNOWN``),
  ``name`` or ``NOT name``, or such tests of one name joined by OR and AND
  (``WaitUntil nCmdMatch = 1 OR nCmdMatch = -1``), or such tests of several names joined
  by AND, each of which must hold (``WaitUntil GlbCommandId = INST_UNKNOWN AND FlagRltAck
  = TRUE``: each name's test counts alone), where ``name`` is a whole PERS data
  object of type num, dnum, bool or string, shared between tasks (a TASK PERS or a LOCAL one is the task's
  own: ``outside_data`` leaves it alone);
* every write of that data object in the loaded code is an assignment of a constant
  to the whole object (a write through a component, an element, a by-reference
  argument or of a computed value leaves the data alone: that code might write a
  value that ends the wait);
* none of the written constants ends the wait.

The data object's initial value does not count: a PERS's initial value in a backup is
the value it held when the backup was taken, not a write of the program.
"""
from __future__ import annotations

import operator
from pathlib import Path
from typing import Callable, Iterable, Optional

from .. import ast
from ..semantics.scope import CONSTANT, GLOBAL_DATA
from .shared_data import _parameter_modes, _root, walk_routine

VALUE_KEYS = frozenset({"BOOL", "NUM", "DNUM", "STRING"})
_COMPARE: dict[str, Callable] = {
    "=": operator.eq, "<>": operator.ne, "<": operator.lt, "<=": operator.le,
    ">": operator.gt, ">=": operator.ge}
_MIRRORED = {"=": "=", "<>": "<>", "<": ">", "<=": ">=", ">": "<", ">=": "<="}
UNKNOWN = object()          # a write whose value the rule cannot know
_JOINED: dict[str, Callable] = {"OR": lambda a, b: a or b, "AND": lambda a, b: a and b}


def constant_value(expr, lookup: Optional[Callable] = None) -> object:
    """The value of a literal (``-`` a number included) or, given the scope's ``lookup``,
    of a CONST of type num, string or bool (``INST_UNKNOWN``), else ``UNKNOWN``."""
    if isinstance(expr, (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral)):
        return float(expr.value) if isinstance(expr, ast.NumLiteral) else expr.value
    if isinstance(expr, ast.Unary) and expr.op == "-":
        value = constant_value(expr.operand, lookup)
        return -value + 0.0 if type(value) is float else UNKNOWN
    if lookup is not None and isinstance(expr, ast.NameRef):
        symbol = lookup(expr.name.key)
        if symbol is not None and symbol.kind == CONSTANT and \
                type(symbol.value) in (float, str, bool):
            return symbol.value
    return UNKNOWN


def _conjuncts(condition) -> list:
    """The tests a condition joins by AND at its top (each must hold for it to hold)."""
    if isinstance(condition, ast.Binary) and condition.op == "AND":
        return _conjuncts(condition.left) + _conjuncts(condition.right)
    return [condition]


def _awaited_each(condition, lookup) -> list:
    """(NameRef, test) per data object a wait condition tests, each test one the value must
    pass for the condition to hold: the condition itself when it tests one data object
    (``_awaited``), else each of the tests it joins by AND that tests one
    (``GlbCommandId = INST_UNKNOWN AND FlagRltAck = TRUE``: neither can end the wait alone,
    and a value that fails one keeps the wait going whatever the other holds)."""
    whole = _awaited(condition, lookup)
    if whole is not None:
        return [whole]
    return [found for found in (_awaited(part, lookup) for part in _conjuncts(condition))
            if found is not None]


def _awaited(condition, lookup=None) -> Optional[tuple]:
    """(the NameRef a wait condition tests, the test a value must pass to end it); the
    tests of one data object joined by OR or AND (``nCmdMatch=1 OR nCmdMatch=-1``) are one
    test."""
    if isinstance(condition, ast.Binary) and condition.op in _JOINED:
        left, right = _awaited(condition.left, lookup), _awaited(condition.right, lookup)
        if left is None or right is None or left[0].name.key != right[0].name.key:
            return None
        join = _JOINED[condition.op]
        return left[0], (lambda v, a=left[1], b=right[1], j=join: j(a(v), b(v)))
    if isinstance(condition, ast.NameRef):
        return condition, lambda v: v is True
    if isinstance(condition, ast.Unary) and condition.op == "NOT" \
            and isinstance(condition.operand, ast.NameRef):
        return condition.operand, lambda v: v is False
    if isinstance(condition, ast.Binary) and condition.op in _COMPARE:
        for side, other, op in ((condition.left, condition.right, condition.op),
                                (condition.right, condition.left, _MIRRORED[condition.op])):
            value = constant_value(other, lookup)
            if isinstance(side, ast.NameRef) and value is not UNKNOWN:
                compare = _COMPARE[op]
                return side, (lambda v, c=value, f=compare: _safe(f, v, c))
    return None


def _safe(compare: Callable, value, constant) -> bool:
    try:
        return bool(compare(value, constant))
    except TypeError:                   # a value of another type: it does not end the wait
        return False


def awaited_from_outside(program, routines: Iterable) -> dict:
    """Slot -> (``WaitUntil at file:line`` or ``poll at file:line``: a wait of ``routines`` that awaits
    a value of the PERS data object in that slot that no write of the loaded code gives; the
    constants the loaded code writes to it; the (file, line, column) of every poll of it)."""
    routines = [r for r in routines if r.ast is not None]
    waits: dict = {}                    # slot -> [(test, span, kind)]
    polls: dict = {}                    # slot -> {(file, line, column)} of its polls
    writes: dict = {}                   # slot -> values written, UNKNOWN among them
    for routine in routines:
        lookup = routine.scope.lookup
        for condition, span in polled(routine.ast):
            for name_ref, test in _awaited_each(condition, lookup):
                slot = _global_slot(lookup, name_ref)
                if slot is not None:
                    waits.setdefault(slot, []).append((test, span, "poll"))
                    polls.setdefault(slot, set()).add((span.file, span.line, span.column))
        for node in walk_routine(routine.ast):
            if isinstance(node, ast.ProcedureCall) and node.name.key == "WAITUNTIL" \
                    and node.args and node.args[0].value is not None:
                for name_ref, test in _awaited_each(node.args[0].value, lookup):
                    slot = _global_slot(lookup, name_ref)
                    if slot is not None:
                        waits.setdefault(slot, []).append((test, node.span, "WaitUntil"))
            elif isinstance(node, (ast.Assignment, ast.Connect)):
                slot = _global_slot(lookup, _root(node.target))
                if slot is not None:
                    whole = isinstance(node, ast.Assignment) \
                        and isinstance(node.target, ast.NameRef)
                    writes.setdefault(slot, []).append(
                        constant_value(node.value, lookup) if whole else UNKNOWN)
            elif isinstance(node, ast.LateBindingCall):
                for arg in node.args:
                    slot = _global_slot(lookup, _root(arg.value))
                    if slot is not None:
                        writes.setdefault(slot, []).append(UNKNOWN)
            elif isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                for arg, mode in zip(node.args, _parameter_modes(program, lookup, node)):
                    slot = _global_slot(lookup, _root(arg.value))
                    if slot is not None and mode != "IN":
                        writes.setdefault(slot, []).append(UNKNOWN)
    data = {d.slot: d for d in program.globals}
    found = {}
    for slot, tests in sorted(waits.items()):
        declared = data.get(slot)
        values = writes.get(slot)
        if declared is None or declared.storage != "PERS" or not values \
                or getattr(declared.type, "key", None) not in VALUE_KEYS \
                or any(v is UNKNOWN for v in values):
            continue
        for test, span, kind in sorted(tests, key=lambda t: (t[1].file, t[1].line, t[1].column)):
            if not any(test(v) for v in values):
                found[slot] = (f"{kind} at {Path(span.file).name}:{span.line}", frozenset(values),
                               frozenset(polls.get(slot, ())))
                break
    return found


def polled(routine: ast.Routine):
    """(condition, span) of each IF, ELSEIF and compact IF inside a WHILE of the routine:
    a test the loop repeats, as a wait does."""
    for node, parents in ast.walk(routine):
        if not any(isinstance(p, ast.While) for p in parents):
            continue
        if isinstance(node, ast.If):
            for branch in node.branches:
                yield branch.condition, branch.span
        elif isinstance(node, ast.CompactIf):
            yield node.condition, node.span


def _global_slot(lookup, name_ref) -> Optional[int]:
    if name_ref is None:
        return None
    symbol = lookup(name_ref.name.key)
    return symbol.slot if symbol is not None and symbol.kind == GLOBAL_DATA else None
