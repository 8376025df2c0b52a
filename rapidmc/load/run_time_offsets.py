"""Starts of ``UnpackRawBytes`` computed at run time: a message of several sub-messages.

A driver that reads one message holding several sub-messages keeps an index into it
(``VAR num i := 1``) and moves it on by each sub-message's length (``i := i +
ROS_MSG_LENGTH_JOINT``) before it reads the next header at ``i`` (pac48's
``ROS_receive_msg_all_data``).  ``load.message_domains`` places fields at literal starts;
such a start is known only along a walk over the sub-messages.

``walked_starts`` gives, for a start written ``i`` or ``i + k`` (``i - k``), where ``i`` is
a local ``VAR num`` of its routine declared with a number and only ever moved on by
positive numbers (``i := i + n``, ``Incr i``, ``Add i, n``), the values the start takes
over the first ``SEQUENCE`` sub-messages: level 0 is the first sub-message's, level 1 the
one after it, and so on, each level every previous value moved on by each increase.  Any
other write of ``i`` (a FOR over it, an assignment of another form, an argument a routine
may change) gives None: the start stays unknown, as it was.  Bounded: at most
``MAX_INCREASES`` distinct increases, starts beyond ``rawbytes.MAX_BYTES`` dropped.
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics import rawbytes
from .input_domains import number_value

SEQUENCE = 2            # sub-messages a walk covers after the first: levels 0..SEQUENCE
MAX_INCREASES = 8       # distinct amounts the index moves on by
# instructions that only read an index passed to them (positional, not a VAR argument)
READERS = {"UNPACKRAWBYTES", "PACKRAWBYTES", "COPYRAWBYTES", "TPWRITE", "WRITE", "ERRWRITE"}


def walked_starts(expr, routine: ast.Routine, scope) -> Optional[tuple]:
    """The values of ``expr`` (``i``, ``i + k``, ``i - k``) per level of the walk, as a
    tuple of frozensets (level 0 first), or None when ``expr`` is no such start."""
    split = _index_and_shift(expr, scope)
    if split is None or routine is None:
        return None
    key, shift = split
    first = _declared_number(routine, key, scope)
    increases = _increases(routine, key, scope)
    if first is None or increases is None:
        return None
    levels = [frozenset({first})]
    for _ in range(SEQUENCE):
        levels.append(frozenset(v + n for v in levels[-1] for n in increases
                                if v + n <= rawbytes.MAX_BYTES))
    return tuple(frozenset(int(v + shift) for v in level if 1 <= v + shift) for level in levels)


def _index_and_shift(expr, scope) -> Optional[tuple]:
    """(the index's name key, k) for ``i``, ``i + k``, ``k + i``, ``i - k``."""
    if isinstance(expr, ast.NameRef):
        return expr.name.key, 0.0
    if not (isinstance(expr, ast.Binary) and expr.op in ("+", "-")):
        return None
    for name, other, sign in ((expr.left, expr.right, 1 if expr.op == "+" else -1),
                              (expr.right, expr.left, 1 if expr.op == "+" else None)):
        if not isinstance(name, ast.NameRef) or sign is None \
                or (isinstance(other, ast.NameRef) and scope is None):
            continue
        number = number_value(other, scope)
        if number is not None and number == int(number):
            return name.name.key, sign * number
    return None


def _declared_number(routine: ast.Routine, key: str, scope) -> Optional[float]:
    """The whole number a local ``VAR num key := n`` of ``routine`` starts at."""
    for declaration in routine.data:
        if declaration.name.key == key:
            if declaration.storage != "VAR" or declaration.dims \
                    or declaration.type.name.key != "NUM" or declaration.init is None:
                return None
            value = number_value(declaration.init, scope)
            return value if value is not None and value == int(value) else None
    return None


def _increases(routine: ast.Routine, key: str, scope) -> Optional[frozenset]:
    """The positive whole amounts every write of ``key`` in ``routine`` adds to it, or
    None when some write is of another form."""
    found = set()
    for node, _ in ast.walk(routine):
        amount = _written(node, key, scope)
        if amount is None:
            continue
        if amount is False or amount <= 0 or amount != int(amount):
            return None
        found.add(amount)
    return frozenset(found) if 0 < len(found) <= MAX_INCREASES else None


def _written(node, key: str, scope):
    """What ``node`` adds to ``key`` when it writes it (a number), False when it writes or
    may write it otherwise, None when it does not."""
    if isinstance(node, ast.For):
        return False if node.variable.key == key else None
    if isinstance(node, ast.Assignment):
        target = node.target
        while isinstance(target, (ast.Index, ast.Component)):
            target = target.base
        if not (isinstance(target, ast.NameRef) and target.name.key == key):
            return None
        split = _index_and_shift(node.value, scope) \
            if isinstance(node.value, ast.Binary) and node.value.op == "+" else None
        return split[1] if split is not None and split[0] == key else False
    if not isinstance(node, ast.ProcedureCall):
        return None
    passed = [a for a in node.args
              if isinstance(a.value, ast.NameRef) and a.value.name.key == key]
    if not passed:
        return None
    if node.name.key == "INCR" and len(node.args) == 1:
        return 1.0
    if node.name.key == "ADD" and len(node.args) == 2 and node.args[0] is passed[0]:
        amount = number_value(node.args[1].value, scope)
        return amount if amount is not None else False
    positional = [a for a in node.args if a.kind == ast.REQUIRED and a.name is None]
    target = positional[2] if node.name.key == "UNPACKRAWBYTES" and len(positional) > 2 \
        else None
    if node.name.key in READERS and all(a.name is None and a is not target for a in passed):
        return None
    return False
