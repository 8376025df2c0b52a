"""Cheap hash keys of states whose big parts are handed on unchanged from step to step.

Hashing a state hashes all its data again: with buffers of hundreds of records in
global data, that is most of the time a search spends per state outside the store.  A
step changes little: the successors of a step that writes no global data hold the very
same global-data vector as their state, and one that writes one datum holds a new vector
whose other elements are the same objects.  ``StateKeys.key`` hashes a state from the
hashes of its parts, each remembered by the identity of the part's object (kept alive
by the bounded cache, so an id is never that of a different object), and the global
data from the remembered hashes of its elements.

Equal states get equal keys (every part's key is a function of its value), so a key
that is not found means the state was not met; a key found may be another state's (a
collision): users compare the states or take the safe side.

Where the compiled core is built the remembered hashes are kept in C
(``_native.PartHashes``), whatever the engine: it computes the very numbers the Python code
does (a key decides the partial-order reduction's choices, its cycle proviso, so the
choices do not depend on it; tests/test_state_keys.py compares them).
"""
from __future__ import annotations

from typing import Hashable, Optional

from pyrsistent import pvector

from ..check.native import part_hashes

KNOWN_LIMIT = 1 << 15          # parts remembered by identity, at most (then forgotten)
_CONTAINERS = (tuple, type(pvector()))     # arrays and records (a number is hashed at once)


class StateKeys:
    """``key(state) -> int``, equal for equal states (see the module docstring).
    ``native``: remember the hashes in C (default: when the compiled core is built)."""

    def __init__(self, native: Optional[bool] = None) -> None:
        self._known: dict[int, tuple] = {}        # id(part) -> (part, its hash)
        self._stores: dict[int, tuple] = {}       # id(global data) -> (it, its key)
        # the state last keyed and its key: callers ask about one state object twice in a
        # row (a search's kept successors, the reduction's proviso)
        self._last: list = [None, 0]
        hashes = part_hashes(KNOWN_LIMIT) if native is not False else None
        if hashes is not None:
            self._part, self._store = hashes.of, hashes.of_items

    def key(self, state) -> int:
        last = self._last
        if state is last[0]:
            return last[1]
        part = self._part
        key = hash((part(state[0]), self._store(state[1]), part(state[2]), part(state[3]),
                    state[4], state[5], state[6], state[7], state[8], state[9],
                    tuple([part(stack) for stack in state[10]])))
        last[0], last[1] = state, key
        return key

    def _part(self, value: Hashable) -> int:
        found = self._known.get(id(value))
        if found is not None and found[0] is value:
            return found[1]
        known = self._known
        if len(known) >= KNOWN_LIMIT:
            known.clear()
        hashed = hash(value)
        known[id(value)] = (value, hashed)
        return hashed

    def _store(self, store) -> int:
        """The key of the global data: from its elements' remembered hashes."""
        found = self._stores.get(id(store))
        if found is not None and found[0] is store:
            return found[1]
        part = self._part
        hashed = hash(tuple([part(value) if type(value) in _CONTAINERS else hash(value)
                             for value in store]))
        stores = self._stores
        if len(stores) >= KNOWN_LIMIT:
            stores.clear()
        stores[id(store)] = (store, hashed)
        return hashed
