"""Interned model states in little memory: collapsed into component ids, in flat arrays.

A model may split its states into a few components (``split_state`` and
``join_state``; a RAPID state: call stacks, global data, signals, the
rest).  Each distinct component is stored once, in a table of its own,
and a state becomes the fixed-width tuple of its component ids (SPIN's
collapse compression): states that share their data but not their
program counter share the stored data.  The ids of all states lie in one
``array`` (``width`` ints per state) and the index from key to state id is
an open-addressing hash table in another ``array``, so a stored state
costs a few dozen bytes instead of a Python tuple, a dict entry and an
int object.  A model without ``split_state`` keeps its states whole in a
dict.

``memory_bytes()`` adds up what the table holds (arrays, component
tables and the components themselves, estimated from their Python sizes).
"""
from __future__ import annotations

import sys
from array import array
from typing import Hashable

EMPTY = -1
FIRST_CAPACITY = 1 << 10


class StateTable:
    """``intern(state) -> (id, new)``, ``table[id] -> state``; see the module docstring."""

    def __init__(self, system):
        self._split = getattr(system, "split_state", None)
        self._join = getattr(system, "join_state", None)
        self._whole: dict[Hashable, int] = {}
        self._whole_states: list[Hashable] = []
        self._width = 0
        self._components: list[dict] = []
        self._values: list[list] = []
        self._component_bytes = 0
        self._ids = array("i")                 # width component ids per state
        self._slots = array("i", [EMPTY]) * FIRST_CAPACITY
        self._count = 0

    def __len__(self) -> int:
        return self._count

    # --------------------------------------------------------------- lookups
    def intern(self, state: Hashable, add: bool = True) -> tuple[int, bool]:
        """The id of ``state`` and whether it was new (id -1 when new and not ``add``)."""
        if self._split is None:
            state_id = self._whole.get(state)
            if state_id is not None:
                return state_id, False
            if not add:
                return EMPTY, True
            state_id = self._whole[state] = len(self._whole_states)
            self._whole_states.append(state)
            self._count += 1
            return state_id, True
        key = self._component_ids(self._split(state))
        return self._find_or_add(key, add)

    def __getitem__(self, state_id: int) -> Hashable:
        if self._split is None:
            return self._whole_states[state_id]
        width = self._width
        base = state_id * width
        ids = self._ids
        return self._join(tuple(self._values[i][ids[base + i]] for i in range(width)))

    # -------------------------------------------------------------- internals
    def _component_ids(self, parts: tuple) -> tuple:
        if not self._width:
            self._width = len(parts)
            self._components = [{} for _ in parts]
            self._values = [[] for _ in parts]
        ids = []
        for table, values, part in zip(self._components, self._values, parts):
            part_id = table.get(part)
            if part_id is None:
                part_id = table[part] = len(values)
                values.append(part)
                self._component_bytes += _size(part)
            ids.append(part_id)
        return tuple(ids)

    def _find_or_add(self, key: tuple, add: bool) -> tuple[int, bool]:
        slots, ids, width = self._slots, self._ids, self._width
        mask = len(slots) - 1
        position = hash(key) & mask
        while True:
            state_id = slots[position]
            if state_id == EMPTY:
                break
            base = state_id * width
            if tuple(ids[base:base + width]) == key:
                return state_id, False
            position = (position + 1) & mask
        if not add:
            return EMPTY, True
        state_id = self._count
        slots[position] = state_id
        ids.extend(key)
        self._count += 1
        if self._count * 2 > len(slots):
            self._grow()
        return state_id, True

    def _grow(self) -> None:
        slots = array("i", [EMPTY]) * (len(self._slots) * 2)
        mask = len(slots) - 1
        ids, width = self._ids, self._width
        for state_id in range(self._count):
            base = state_id * width
            position = hash(tuple(ids[base:base + width])) & mask
            while slots[position] != EMPTY:
                position = (position + 1) & mask
            slots[position] = state_id
        self._slots = slots

    # ----------------------------------------------------------------- memory
    def memory_bytes(self) -> int:
        """Bytes the table holds (components estimated from their Python sizes)."""
        if self._split is None:
            return sys.getsizeof(self._whole) + sys.getsizeof(self._whole_states) + \
                sum(_size(state) for state in self._whole_states)
        tables = sum(sys.getsizeof(t) + sys.getsizeof(v)
                     for t, v in zip(self._components, self._values))
        return (self._ids.buffer_info()[1] * self._ids.itemsize +
                self._slots.buffer_info()[1] * self._slots.itemsize +
                tables + self._component_bytes)


def _size(value, seen: set | None = None) -> int:
    """Python bytes of ``value`` and what it holds (shared parts counted once per call)."""
    seen = set() if seen is None else seen
    if id(value) in seen:
        return 0
    seen.add(id(value))
    size = sys.getsizeof(value)
    if isinstance(value, (str, bytes, int, float, bool)) or value is None:
        return size
    try:
        items = list(value) if not isinstance(value, dict) else list(value.items())
    except TypeError:
        return size
    if not isinstance(value, (tuple, list, dict)):
        size += 8 * len(items)                 # a persistent vector's node slots
    return size + sum(_size(item, seen) for item in items)
