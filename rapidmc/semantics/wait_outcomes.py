"""A WaitUntil's reads of outside data judged per outcome of the comparisons (issue 28).

A wait's read of PERS data another party writes (``ExpressionCompiler._outside_read_as``)
takes the stored value or any other of the data's domain, and the wait keeps what it took
only where its condition holds (``library.waits._kept_where_it_ends``).  The taeyangshim
head waits for three arms at once::

    WaitUntil stReact = ["Ready", "Ready", "Ready"];

and each element took each of 14 values: 2,744 transitions from one waiting state, all
but one back to that state.  Where such a read is compared with a constant, each value
component it chooses (a leaf: the read itself, or a component or element of a whole
read) now first chooses the *class* of its value, the values that give the comparison one
outcome (for ``=`` and ``<>``: the constant's value, and every other), and takes the class's
first value in the read's order (the stored value first).  The comparison gives the same
outcome for every value of a class, so:

* where the condition is false, the wait keeps nothing it read, and every value of the
  class would have led to the same "still waiting" state: one is enough;
* where the condition holds, the wait keeps what it read, so each leaf whose class has
  more than one value then chooses among them (``settle``), unless a later read of the
  same condition wrote that leaf again (the last write is what stays).

The wait above now makes 8 tries (each element "Ready" or not) and keeps one state per
outcome; a wait that ends for many values (``stReact{1} <> "Busy"``) still keeps each
value it ends with.  Reads whose value goes anywhere but into a comparison with a
constant choose as before (``WaitRead`` is only what the comparison needs).
"""
from __future__ import annotations

from typing import Callable, Optional

from .errors import RapidError
from .machine import read_at, replace_at

CLASS_ORDERS_KEPT = 256     # orders of a leaf's classes one read remembers (per stored value)


class WaitRead:
    """What a wait's read of outside data chooses: ``ref(m)`` the reference it reads and
    writes; ``leaves``: (positions in the value read, the choice's name, the values it may
    take, ``order(current)`` those values in the order tried, whether the wait keeps what
    it takes)."""

    __slots__ = ("ref", "leaves")

    def __init__(self, ref: Callable, leaves: list):
        self.ref = ref
        self.leaves = leaves


def note_writes(pending: Optional[list], ref: tuple, leaves) -> None:
    """Note, for ``settle``, that a read of the condition wrote these leaves' values."""
    if pending is not None:
        space, index, path = ref
        for positions in leaves:
            pending.append(((space, index, path + positions), None))


def by_outcome(read: WaitRead, compare: Callable, constant, flipped: bool,
               pending: list) -> Optional[Callable]:
    """``fn(m)``: ``read`` where each leaf takes one value per class of ``compare`` with
    the matching part of ``constant`` (on its right, or left where ``flipped``); None where
    the classes cannot be told at compile time (the comparison fails on some value)."""
    leaves = []
    for positions, name, domain, order, keeps in read.leaves:
        try:
            target = read_at(constant, positions)
            if positions:        # a part of a whole value: its own value or not
                outcome = lambda value, target=target: value == target   # noqa: E731
            elif flipped:
                outcome = lambda value, target=target: compare(target, value)  # noqa: E731
            else:
                outcome = lambda value, target=target: compare(value, target)  # noqa: E731
            outcomes = {value: outcome(value) for value in domain}
        except (RapidError, TypeError, IndexError):
            return None
        leaves.append((positions, name, order, keeps, outcomes, {}))
    ref_fn = read.ref

    def chosen(m):
        ref = ref_fn(m)
        value = old = keep = m.read_ref(ref)
        space, index, path = ref
        for positions, name, order, keeps, outcomes, known in leaves:
            current = read_at(keep, positions)
            classes = known.get(current)
            if classes is None:
                classes = _classes(order(current), outcomes)
                if len(known) < CLASS_ORDERS_KEPT:
                    known[current] = classes
            taken = m.choose(name, tuple(classes))
            if keeps:
                if taken != current:
                    keep = replace_at(keep, positions, taken)
                members = classes[taken]
                pending.append(((space, index, path + positions),
                                (name, members) if len(members) > 1 else None))
            if taken != read_at(value, positions):
                value = replace_at(value, positions, taken)
        if keep is not old:
            m.write_ref(ref, keep)
        return value
    return chosen


def _classes(values: tuple, outcomes: dict) -> dict:
    """First value of each class -> the class's values, in ``values``' order."""
    firsts: dict = {}
    members: dict = {}
    for value in values:
        outcome = outcomes.get(value, (value,))    # (a value no class knows: its own)
        first = firsts.setdefault(outcome, value)
        members.setdefault(first, []).append(value)
    return {first: tuple(values) for first, values in members.items()}


def settle(m, pending: list) -> None:
    """The condition held: each leaf it kept the first value of a class for chooses among
    the class's values, unless a later read wrote it again."""
    for i, (address, choice) in enumerate(pending):
        if choice is None or any(later == address for later, _ in pending[i + 1:]):
            continue
        name, members = choice
        taken = m.choose(name, members)
        if taken != members[0]:
            m.write_ref(address, taken)
