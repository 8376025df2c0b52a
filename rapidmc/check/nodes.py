"""Tree-compressed storage of state components: every subvalue interned once as a node.

LTSmin's tree compression (Laarman, van de Pol and Weber, SPIN 2011) for Python values.
A value is a tree: a tuple (a call stack, a frame, global data, an array, a record) or a
persistent vector is a node whose key is the ids of its children; anything else (a number,
a string, None ...) is a leaf, keyed by its type and value (a bool and a num are
different leaves even where Python finds them equal).  Each distinct node is stored
once, as a *canonical* object built from the canonical objects of its children, so
equal subtrees of different states are one object.

A value handed on unchanged from a stored state is that canonical object, found by
identity (``id``) without hashing its contents; a step that writes one element of a
512-element array builds a new tuple whose other 511 elements are still canonical, so
interning it costs 511 identity look-ups and one new leaf or record, not a deep hash of
the whole array.  Two values get the same node id exactly when their trees are equal,
so states are compared by id.

``memory_bytes`` is counted as nodes are added (each node's own object, its key and its
index entries), never by walking stored values.

The searches over one model share one node table (``shared_nodes``): the states each
rebuilds are made of the same canonical objects, so comparing a state with one an earlier
search handed over (a model's successors kept between searches) finds equal parts by
identity instead of comparing 512-element arrays element by element, and the nodes are
stored once for all the searches.
"""
from __future__ import annotations

import sys
import weakref
from operator import is_
from typing import Callable, Hashable, Optional

from pyrsistent import pvector

_PVECTOR = PVECTOR = type(pvector())
_new_tuple = tuple.__new__
# an index entry (key -> id or id(object) -> id) in a dict: a hash, a key and a value
# pointer, and the table's share of empty room (dicts stay a third to two thirds full)
ENTRY_BYTES = 3 * 8 * 2
ALIAS_LIMIT = 1 << 14        # equal non-canonical objects known by identity, at most
SHARED = 0                   # objects Python keeps once for all uses cost nothing here


_SHARED: "weakref.WeakKeyDictionary" = weakref.WeakKeyDictionary()   # model -> {kind: table}


def shared_nodes(system, kind: type) -> "NodeTable":
    """The node table of class ``kind`` that the searches over ``system`` share (a new one
    for a model that cannot be referred to weakly); it lives as long as the model."""
    try:
        tables = _SHARED.setdefault(system, {})
    except TypeError:
        return kind()
    table = tables.get(kind)
    if table is None:
        table = tables[kind] = kind()
    return table


def existing_nodes(system) -> Optional["NodeTable"]:
    """A node table the searches over ``system`` already share (the first made), or None."""
    try:
        tables = _SHARED.get(system)
    except TypeError:
        return None
    return next(iter(tables.values()), None) if tables else None


class NodeTable:
    """``node(value) -> id`` and ``value(id) -> canonical object``; see the module
    docstring."""

    def __init__(self) -> None:
        self._canonical: list = []                 # node id -> canonical object
        self._by_identity: dict[int, int] = {}     # id(canonical object) -> node id
        self._by_key: dict[Hashable, int] = {}     # children ids or (type, leaf) -> node id
        self._aliases: dict[int, tuple] = {}       # id(equal object) -> (it, node id)
        self._bytes = 0

    def __len__(self) -> int:
        return len(self._canonical)

    def value(self, node_id: int):
        return self._canonical[node_id]

    def node(self, value) -> int:
        """The id of ``value``'s tree (its nodes added when new)."""
        node_id = self._by_identity.get(id(value))
        if node_id is not None:
            return node_id
        return self._node_of_other(value)

    def _node_of_other(self, value) -> int:
        """``node`` of a value that is no canonical object (the search's hot path: each
        explored transition interns its successor's parts)."""
        kind = type(value)
        if kind is not tuple and kind is not _PVECTOR and not isinstance(value, tuple):
            # a leaf: found by its value (cheaper than remembering the object)
            key = (kind, value)
            node_id = self._by_key.get(key)
            return node_id if node_id is not None else self._add(key, kind, value, None)
        aliases = self._aliases
        alias = aliases.get(id(value))
        if alias is not None:
            return alias[1]        # (the cache keeps ``value`` alive: the id is still its own)
        # children handed on unchanged are canonical objects: their ids in one pass
        # at C speed (a canonical object lives as long as the table, so its id is
        # no other object's); the others recursively
        children = tuple(map(self._by_identity.get, map(id, value)))
        if None in children:
            other = self._node_of_other
            children = tuple([known if known is not None else other(child)
                              for known, child in zip(children, value)])
        key = children if kind is tuple else (kind, children)
        node_id = self._by_key.get(key)
        if node_id is None:
            return self._add(key, kind, value, children)
        # an equal object met again (a program's initial value a reset writes back, a
        # constant): known by identity from now on (``_alias``, inlined: most explored
        # transitions lead to a state met before and end here)
        if len(aliases) >= ALIAS_LIMIT:
            aliases.clear()
        aliases[id(value)] = (value, node_id)
        return node_id

    def _alias(self, value, node_id: int) -> None:
        """Know ``value``, equal to node ``node_id``'s canonical object but not it, by
        identity while the bounded cache keeps it alive."""
        aliases = self._aliases
        if len(aliases) >= ALIAS_LIMIT:
            aliases.clear()
        aliases[id(value)] = (value, node_id)

    def _add(self, key: Hashable, kind: type, value, children) -> int:
        canonical = self._canonical
        if children is None:
            made = value
        elif kind is not _PVECTOR and all(map(is_, map(canonical.__getitem__, children), value)):
            made = value          # (a program's initial value stays the object it hands on)
        else:
            parts = [canonical[child] for child in children]
            made = pvector(parts) if kind is _PVECTOR else _new_tuple(kind, parts)
        node_id = self._by_key[key] = len(canonical)
        canonical.append(made)
        self._by_identity[id(made)] = node_id
        if made is not value:
            # the state that holds ``value`` hands it on to its successors: found by
            # identity there, not walked again
            self._alias(value, node_id)
        self._bytes += _own_bytes(made, children) + 2 * ENTRY_BYTES + 8
        if children is not None:
            self._bytes += sys.getsizeof(key)      # the key holds the children's ids
        return node_id

    def ids(self, values) -> tuple:
        """The node id of each of ``values``."""
        # the values handed on unchanged (most of a successor's parts) are canonical
        # objects: their ids in one pass at C speed, as for a node's children
        known = tuple(map(self._by_identity.get, map(id, values)))
        if None not in known:
            return known
        other = self._node_of_other
        return tuple([node_id if node_id is not None else other(value)
                      for node_id, value in zip(known, values)])

    def values(self, ids) -> tuple:
        """The canonical object of each node id."""
        canonical = self._canonical
        return tuple([canonical[node_id] for node_id in ids])

    def splitter(self, split: Callable[[Hashable], tuple]) -> Callable[[Hashable], tuple]:
        """``split`` giving the node ids of the parts instead of the parts."""
        ids = self.ids
        return lambda state: ids(split(state))

    def joiner(self, join: Callable[[tuple], Hashable]) -> Callable[[tuple], Hashable]:
        """``join`` taking the node ids of the parts (a state of canonical objects)."""
        values = self.values
        return lambda ids: join(values(ids))

    def memory_bytes(self) -> int:
        """Bytes of the nodes and their indexes (counted as they were added), and of the
        bounded alias cache."""
        return self._bytes + sys.getsizeof(self._aliases)


def has_children(value) -> bool:
    """Whether ``value`` is a container node (a tuple, a tuple subclass, a persistent
    vector: ``NodeTable.node``'s test), not a leaf."""
    kind = type(value)
    return kind is tuple or kind is _PVECTOR or isinstance(value, tuple)


def _own_bytes(made, children) -> int:
    """Bytes of a node's own object (its children are nodes of their own)."""
    if children is None:
        if made is None or type(made) is bool or type(made) is int and -5 <= made <= 256:
            return SHARED
        return sys.getsizeof(made)
    if type(made) is _PVECTOR:
        return sys.getsizeof(made) + 8 * len(children)   # the vector's node slots
    return sys.getsizeof(made)



def value_bytes(value, seen: set | None = None) -> int:
    """Python bytes of ``value`` and what it holds (shared parts counted once per call):
    for values stored whole, counted once when they are added."""
    if value is None or type(value) is bool or type(value) is int and -5 <= value <= 256:
        return SHARED
    seen = set() if seen is None else seen
    if id(value) in seen:
        return 0
    seen.add(id(value))
    size = sys.getsizeof(value)
    if isinstance(value, (str, bytes, int, float)):
        return size
    try:
        items = list(value) if not isinstance(value, dict) else list(value.items())
    except TypeError:
        return size
    if not isinstance(value, (tuple, list, dict)):
        size += 8 * len(items)                 # a persistent vector's node slots
    return size + sum(value_bytes(item, seen) for item in items)
