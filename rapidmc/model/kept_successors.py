"""Successors kept between the searches of one program, as node ids, not as states.

The searches for a program's properties expand the same states again when the first
search did not see them all (a time or state limit, a violation found early), and the
general step (tasks, interrupts, stored inputs) is the costly part of a search; so
``RapidSystem.successors`` keeps what it found at such states for the next search.

What is kept is small: the state and each successor are stored as the node ids of
their parts (``check.nodes``: each frame, array, record, signal vector and leaf
interned once, in the node table the searches' state tables share), and each label
(choices, span, output) as the node id of its tree in a table of the labels' own (a
label is no state part: the shared table's nodes are what a distributed search encodes,
and a span has no canonical bytes); a state's entry is one ``bytes``
key and one ``bytes`` value of 4-byte ids.  Kept as the step made them, the successors
of a state with 32 transitions held each a fresh signal vector, frames and labels:
40 KB a state on a PickMaster task (2.0 GB at 21,231 states), where the node ids cost
about 1 KB.

The successors given back are rebuilt from the canonical objects: equal to the ones
the step made, of the same types (the node table tells ``1``, ``1.0`` and ``True``
apart), so what a search does with them is what it did with the step's; a state is
found again exactly when its parts' trees are equal, as the state tables find it.
"""
from __future__ import annotations

from array import array
from typing import Callable, Optional

from ..check.nodes import NodeTable, existing_nodes


class KeptSuccessors:
    """``get(state)``: the kept labelled successors of ``state`` (a new list) or None;
    ``keep(state, successors, owner)``; ``len``: the states kept."""

    def __init__(self, split: Callable, join: Callable):
        self._split, self._join = split, join
        self._nodes: Optional[NodeTable] = None     # (the owner's, when first kept)
        self._labels: Optional[NodeTable] = None    # the labels' trees, apart (same kind)
        self._kept: dict[bytes, bytes] = {}
        self._width = 0                        # parts per state

    def __reduce__(self):
        return KeptSuccessors, (self._split, self._join)     # (nothing kept travels)

    def __len__(self) -> int:
        return len(self._kept)

    def get(self, state) -> Optional[list]:
        if not self._kept:
            return None
        found = self._kept.get(self._key(state))
        if found is None:
            return None
        ids = array("I")
        ids.frombytes(found)
        width = self._width
        count = len(ids) // (width + 1)
        labels, parts = self._labels.values(ids[:count]), self._nodes.values(ids[count:])
        join = self._join
        return [(labels[index], join(parts[index * width:(index + 1) * width]))
                for index in range(count)]

    def keep(self, state, successors: list, owner) -> None:
        """Keep ``successors`` of ``state``, their nodes in the table the searches over
        ``owner`` (the system) share, or one of its own before any search made one (not
        holding the owner: it holds this).  Stored as the labels' node ids, then each
        successor's parts' ids."""
        if self._nodes is None:
            found = existing_nodes(owner)
            self._nodes = NodeTable() if found is None else found
            self._labels = type(self._nodes)()
            self._width = len(self._split(state))
        ids, split = self._nodes.ids, self._split
        found = array("I", self._labels.ids([label for label, _ in successors]))
        found.extend(ids([part for _, after in successors for part in split(after)]))
        self._kept.setdefault(self._key(state), found.tobytes())

    def _key(self, state) -> bytes:
        return array("I", self._nodes.ids(self._split(state))).tobytes()

