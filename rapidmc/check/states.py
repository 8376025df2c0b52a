"""Interned model states in little memory: collapsed into component ids, in flat arrays.

A model may split its states into a few components (``split_state`` and
``join_state``; a RAPID state: call stacks, global data, signals, the
rest).  Each distinct component is stored once, in a table of its own,
and a state becomes the tuple of its component ids (SPIN's collapse
compression).  A component is itself stored as a tree of interned nodes
(``check.nodes``: each frame, array, record and scalar once, found by
identity when handed on unchanged), and known by the id of its tree: states that share their data but not their program counter
share the stored data.  The ids of the components after the first
``PRIMARY`` ones, which rarely change, are interned once more as one tail
id, and the first component's id with the tail id as one head id, so a
stored state is two ints: its head id and the id of its second component
(a RAPID state: global data, which varies most), kept as one 64-bit key.
The keys of all states lie in one ``array`` and the index from key to
state id is an open-addressing hash table in another ``array``, so a
stored state costs a few dozen bytes instead of a Python tuple, a dict
entry and an int object.  A model without ``split_state`` keeps its states whole in a dict.

``memory_bytes()`` adds up what the table holds: its arrays, and the nodes
and index entries as they were counted when added (Python sizes; objects
Python shares anyway, such as small ints, ``None`` and booleans, are not
counted).  It walks nothing stored, so asking costs nothing.
"""
from __future__ import annotations

import sys
from array import array
from typing import Hashable

from .nodes import ENTRY_BYTES, NodeTable, shared_nodes, value_bytes

EMPTY = -1
FIRST_CAPACITY = 1 << 10
HEAD_BYTES = sys.getsizeof((0, 0)) + 2 * 28   # a head's (first id, tail id) and its ints
PRIMARY = 2          # components with an id of their own; the others share one tail id
SECOND_BITS = 32     # a state's key: head id << SECOND_BITS | second component id
SECOND_MASK = (1 << SECOND_BITS) - 1


class StateTable:
    """``intern(state) -> (id, new)``, ``table[id] -> state``; see the module docstring."""

    node_table = NodeTable        # (the native engine's table interns its nodes in C)

    def __init__(self, system):
        split = getattr(system, "split_state", None)
        # components are stored as the ids of their trees of interned nodes (check.nodes),
        # in the table every search over this model shares
        self._nodes = shared_nodes(system, self.node_table)
        self._split = self._nodes.splitter(split) if split is not None else None
        self._join = self._nodes.joiner(system.join_state) if split is not None else None
        self._whole: dict[Hashable, int] = {}
        self._whole_states: list[Hashable] = []
        self._whole_bytes = 0                  # the whole states' own bytes, counted as added
        self._components: list[dict] = []
        self._values: list[list] = []
        # the parts after PRIMARY (their node ids) -> tail id: one look-up, in C for the
        # native table (``_native.c``'s ``tail_id``), where the successors of a state
        # alternate between tails (stored inputs: each successor's own signals)
        self._tails: dict[tuple, int] = {}
        self._tail_values: list[tuple] = []
        self._tail_parts: list[tuple] = []     # by tail id: the stored parts themselves
        self._last_tail: tuple | None = None  # the tail parts last looked up, their id,
        self._last_tail_id = EMPTY             # and their heads
        self._last_heads: dict[int, int] = {}
        self._heads: list[dict[int, int]] = []  # by tail id: first component id -> head id
        self._head_values: list[tuple] = []    # by head id: (first component id, tail id)
        self._keys = array("q")                # per state: head id << 32 | second component id
        self._slots = array("i", [EMPTY]) * FIRST_CAPACITY
        self._mask = FIRST_CAPACITY - 1
        self._count = 0

    def __len__(self) -> int:
        return self._count

    @property
    def collapsed(self) -> bool:
        return self._split is not None

    @property
    def known_ids(self) -> dict:
        """state -> id for states kept whole (empty when states are collapsed)."""
        return self._whole

    # --------------------------------------------------------------- lookups
    def intern(self, state: Hashable, add: bool = True) -> tuple[int, bool]:
        """The id of ``state`` and whether it was new (id -1 when new and not ``add``).

        (Whole states are looked up here, without a further call: it runs twice per
        explored transition; collapsed ones go on in ``intern_parts``, which the workers of
        a distributed search also call with the parts they were sent.)"""
        split = self._split
        if split is None:
            state_id = self._whole.get(state)
            if state_id is not None:
                return state_id, False
            if not add:
                return EMPTY, True
            state_id = self._whole[state] = len(self._whole_states)
            self._whole_states.append(state)
            self._whole_bytes += value_bytes(state) + ENTRY_BYTES
            self._count += 1
            return state_id, True
        return self.intern_parts(split(state), add)

    def intern_parts(self, parts: tuple, add: bool = True) -> tuple[int, bool]:
        """``intern`` of the state whose split parts have these node ids (``parts_of``)."""
        components = self._components
        if not components:
            self._start(len(parts))
            components = self._components
        part = parts[0]
        first = components[0].get(part)
        if first is None:
            first = self._add_component(0, part)
        part = parts[1]
        second = components[1].get(part)
        if second is None:
            second = self._add_component(1, part)
        tail = parts[PRIMARY:]
        # the rarely changing parts are most often those of the state interned last
        # (compared element by element: the very same objects compare at once)
        if tail == self._last_tail:
            heads = self._last_heads
        else:
            heads = self._heads[self._tail_id(tail)]
        head = heads.get(first)
        if head is None:
            head = heads[first] = len(self._head_values)
            self._head_values.append((first, self._last_tail_id))
        key = head << SECOND_BITS | second
        slots, keys, mask = self._slots, self._keys, self._mask
        position = hash((head, second)) & mask
        while True:
            state_id = slots[position]
            if state_id == EMPTY:
                break
            if keys[state_id] == key:
                return state_id, False
            position = (position + 1) & mask
        if not add:
            return EMPTY, True
        state_id = self._count
        slots[position] = state_id
        keys.append(key)
        self._count += 1
        if self._count * 2 > len(slots):
            self._grow()
        return state_id, True

    def parts_of(self, state: Hashable) -> tuple:
        """The node ids of the state's split parts (collapsed tables only): equal states,
        equal ids, in this process."""
        return self._split(state)

    @property
    def nodes(self):
        """The node table the parts' trees are interned in (collapsed tables only)."""
        return self._nodes

    def intern_rows(self, rows: bytes, width: int) -> tuple[bytes, bytes]:
        """``intern_parts`` of states given as ``width`` node ids each (uint32, end to
        end): their ids (int64) and whether each was new (a byte each), as bytes (the
        native table does this in one C call)."""
        flat = array("I")
        flat.frombytes(rows)
        ids, news = array("q"), bytearray()
        intern = self.intern_parts
        numbers = iter(flat)
        for parts in zip(*[numbers] * width):     # (the rows as tuples, ``width`` at a time)
            state_id, new = intern(parts)
            ids.append(state_id)
            news.append(new)
        return ids.tobytes(), bytes(news)

    def __getitem__(self, state_id: int) -> Hashable:
        if self._split is None:
            return self._whole_states[state_id]
        key = self._keys[state_id]
        first, tail_id = self._head_values[key >> SECOND_BITS]
        values = self._values
        return self._join((values[0][first], values[1][key & SECOND_MASK]) +
                          self._tail_parts[tail_id])

    # -------------------------------------------------------------- internals
    def _start(self, width: int) -> None:
        self._components = [{} for _ in range(width)]
        self._values = [[] for _ in range(width)]

    def _add_component(self, index: int, part: int) -> int:
        """The id of a component (the node id of its tree) not stored yet."""
        values = self._values[index]
        part_id = self._components[index][part] = len(values)
        values.append(part)
        return part_id

    def _tail_id(self, tail: tuple) -> int:
        """The id of the components after PRIMARY, together (remembered as the last tail,
        with its heads); its components are stored when it is new."""
        tail_id = self._tails.get(tail)
        if tail_id is None:
            ids = []
            for index, part in enumerate(tail, PRIMARY):
                part_id = self._components[index].get(part)
                if part_id is None:
                    part_id = self._add_component(index, part)
                ids.append(part_id)
            tail = tuple(tail)
            tail_id = self._tails[tail] = len(self._tail_values)
            self._tail_values.append(tuple(ids))
            self._heads.append({})
            self._tail_parts.append(tail)
        self._last_tail, self._last_tail_id = tail, tail_id
        self._last_heads = self._heads[tail_id]
        return tail_id

    def _grow(self) -> None:
        slots = array("i", [EMPTY]) * (len(self._slots) * 2)
        mask = len(slots) - 1
        for state_id, key in enumerate(self._keys):
            position = hash((key >> SECOND_BITS, key & SECOND_MASK)) & mask
            while slots[position] != EMPTY:
                position = (position + 1) & mask
            slots[position] = state_id
        self._slots, self._mask = slots, mask

    # ----------------------------------------------------------------- memory
    def memory_bytes(self) -> int:
        """Bytes the table holds: its arrays, and the rest as counted while it was filled
        (nothing stored is walked)."""
        if self._split is None:
            return sys.getsizeof(self._whole) + sys.getsizeof(self._whole_states) + \
                self._whole_bytes
        heads = len(self._head_values)
        return (self._keys.buffer_info()[1] * self._keys.itemsize +
                self._slots.buffer_info()[1] * self._slots.itemsize +
                sys.getsizeof(self._head_values) + heads * (HEAD_BYTES + ENTRY_BYTES) +
                self.component_bytes())

    def component_bytes(self) -> int:
        """Bytes of the stored components (their node trees) and the tables that index them."""
        width = len(self._components)
        tails = len(self._tail_values)
        tables = sum(sys.getsizeof(t) + sys.getsizeof(v)
                     for t, v in zip(self._components, self._values)) + \
            sys.getsizeof(self._tails) + sys.getsizeof(self._tail_parts) + \
            sys.getsizeof(self._heads) + sys.getsizeof(self._tail_values) + \
            tails * (2 * sys.getsizeof((0,) * (width - PRIMARY)) + sys.getsizeof({}))
        return tables + self._nodes.memory_bytes()
