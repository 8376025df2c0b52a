"""Data only the outside writes that a wait of the loaded code reads (issue 28).

A PC fills a mailbox and the task waits for it::

    WaitUntil stMacro{1} <> "" AND stMacro{2} <> "";
    head := StrPart(stMacro{1}, 1, 1);

Data no loaded code writes is read as a choice (``outside_data``).  If every read
chose afresh, the read after the wait could take ``""`` again, and StrPart would
raise an error no controller shows: the client wrote the command the wait saw, and
the task reads it on.  So data only the outside writes that a wait of the loaded
code reads, and that no task of the backup writes (a client's: a PC's, an HMI's), is
taken to change only while a task waits or polls for it:

* a wait's read (a WaitUntil condition, a WHILE condition, an IF polled in a loop,
  and the functions they call) takes the stored value or another of the domain, and
  stores it where the wait ends, as it does for data another party writes besides
  the loaded code (``ExpressionCompiler._outside_read_as``);
* every other read takes the stored value: the value the last wait took.

This holds for the components the waits read (``cmd.go`` of ``WaitUntil cmd.go``; an
array's elements all count as one): the others are still chosen at each read, as the
client may have filled them in any order before it set the flag the task waits for.

The verdicts say so under ``assumes:``; ``check --outside-writes-anytime`` keeps the
old reading, a choice at every read.  The reduction counts such a wait as a write of
the data by the task that waits (``model.reduction.partial_order``).

``waited_reads`` finds the waits syntactically.  A name counts only where the
statement compiler reads it as a wait does: in the arguments of a WaitUntil or the
condition of a WHILE, outside the arguments of a user function (which are compiled
with the call, apart from the wait).  Data counted here is chosen at such a read, so
no data is left at its initial value because of this module.
"""
from __future__ import annotations

from pathlib import Path
from typing import Iterable

from .. import ast
from ..semantics.scope import GLOBAL_DATA, ROUTINE
from .awaited_from_outside import polled
from .shared_data import walk_routine


def waited_reads(routines: Iterable, slots: set) -> dict:
    """Slot (of ``slots``) -> (``WaitUntil at file:line`` or ``WHILE at file:line``: the
    first wait of ``routines`` in source order that reads it; the component paths the waits
    read (upper-case component names, indices left out: ``()`` the whole object); the
    (file, line, column) of each IF polled in a loop that reads it, which then reads it as
    a wait does)."""
    first: dict = {}
    paths: dict = {}
    polls: dict = {}
    for routine in routines:
        if routine.ast is None:
            continue
        lookup = routine.scope.lookup
        for node in walk_routine(routine.ast):
            if isinstance(node, ast.ProcedureCall) and node.name.key == "WAITUNTIL":
                expressions, kind = [arg.value for arg in node.args], "WaitUntil"
            elif isinstance(node, ast.While):
                expressions, kind = [node.condition], "WHILE"
            else:
                continue
            for slot, path in _reads(expressions, lookup, slots):
                paths.setdefault(slot, set()).add(path)
                where = (node.span.file, node.span.line, node.span.column)
                if slot not in first or where < first[slot][0]:
                    first[slot] = (where, f"{kind} at {Path(node.span.file).name}:"
                                          f"{node.span.line}")
        for condition, span in polled(routine.ast):
            for slot, _ in _reads([condition], lookup, slots):
                polls.setdefault(slot, set()).add((span.file, span.line, span.column))
    return {slot: (text, _outermost(paths[slot]), frozenset(polls.get(slot, ())))
            for slot, (_, text) in first.items()}


def _reads(expressions: list, lookup, slots: set) -> set:
    """(slot, component path) of each read of data in ``slots`` that ``expressions`` make,
    outside a user function's arguments."""
    found = set()
    for expression in expressions:
        if expression is None:
            continue
        for node, parents in ast.walk(expression):
            if not isinstance(node, ast.NameRef) or any(
                    isinstance(parent, ast.FunctionCall) and _user_routine(lookup, parent)
                    for parent in parents):
                continue
            symbol = lookup(node.name.key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.slot in slots:
                found.add((symbol.slot, _path(node, parents)))
    return found


def _path(name_ref, parents: tuple) -> tuple:
    """The components a read names below the data object (``cmd.part``, ``jobs{i}.ready``:
    indices left out)."""
    path, current = [], name_ref
    for parent in reversed(parents):
        if isinstance(parent, ast.Component) and parent.base is current:
            path.append(parent.name.key)
        elif not (isinstance(parent, ast.Index) and parent.base is current):
            break
        current = parent
    return tuple(path)


def _outermost(paths: set) -> frozenset:
    """The paths no other one of ``paths`` contains (``()`` alone when the whole is read)."""
    return frozenset(path for path in paths
                     if not any(other != path and path[:len(other)] == other
                                for other in paths))


def _user_routine(lookup, call) -> bool:
    symbol = lookup(call.name.key)
    return symbol is not None and symbol.kind == ROUTINE
