"""Model states interned into integer ids, with their valuations and successors.

The engine stores each model state once (``states[id]``, a ``StateTable``
that keeps states collapsed into component ids) and works with ids from
then on; product bookkeeping is integers only.
Valuations are computed once per model state.  Successor ids are cached
for recently expanded states, because the emptiness search expands the
same model state once per automaton state it is paired with, often in
quick succession (and the model's step function is the expensive part).
Where few states are paired with more than one automaton state (a safety
property that holds: each once), the cache costs more than it saves, so
it is reviewed every ``CACHE_TRIAL`` expansions: with fewer than one hit
in ``CACHE_WORTH`` it is dropped for ``CACHE_REST`` expansions, then tried
again.  (The cache changes no result: the ids of a state's successors are
the same however often they are computed.)
The states last found new are kept as the model handed them over (up to
``FRESH_STATES``): the depth-first search expands most of them soon after,
and then needs not rebuild them from their components.
"""
from __future__ import annotations

import sys
from itertools import islice
from typing import Hashable, Sequence

from array import array

from .transition_system import (Label, TransitionSystem, Valuation, as_sequence,
                                labelled_successors, path_system, path_transitions)
from .native import state_table

SUCCESSOR_CACHE_SIZE = 1 << 16
CACHE_TRIAL = 1 << 12        # expansions with the successor cache, then a review
CACHE_WORTH = 8              # kept while at least one expansion in this many hits it
CACHE_REST = 1 << 15         # expansions without it when it did not pay
FRESH_STATES = 1 << 13
VALUATION_TYPES = ("B", "H", "I", "Q")     # array types for up to 8, 16, 32, 64 atoms


class ModelStore:
    """Interning of model states: ``intern(state) -> id``; see the module docstring."""

    def __init__(self, system: TransitionSystem, valuation: Valuation,
                 keep_new: int = FRESH_STATES):
        self.system = system
        self.valuation = valuation
        self.states = state_table(system, packed=True)
        self._known = None if self.states.collapsed else self.states.known_ids.get
        # a packed table's step machine (``model.packed``): successors as ids, in C
        self._machine = getattr(self.states, "successor_ids", None)
        self._machine_valuation = self.states.valuation_index(valuation) \
            if self._machine is not None else -1
        self.valuations = array(VALUATION_TYPES[0])    # the narrowest that holds them
        self.deadlocked: set[int] = set()
        self._successor_cache: dict[int, tuple[int, ...]] = {}
        self._caching = True                 # whether successors are cached now
        self._hits = 0                       # cache hits since the last review
        self._expansions = 0                 # successors computed
        self._review_at = CACHE_TRIAL        # ... when the cache is reviewed next
        self._fresh: dict[int, Hashable] = {}     # id -> new state, not expanded yet
        self._keep_new = keep_new                  # at most that many (0: none)
        # the target states of a state's transitions (labels are not needed here)
        self._targets = getattr(system, "successor_states", None) or \
            (lambda state: [target for _, target in as_sequence(system.successors(state))])

    def __len__(self) -> int:
        return len(self.states)

    def intern(self, state: Hashable) -> int:
        """The id of ``state``, storing it (and its valuation) when new."""
        if self._known is not None:         # states kept whole: one dict look-up
            known = self._known(state)
            if known is not None:
                return known
        state_id, new = self.states.intern(state)
        if new:
            self._added(state_id, state)
        return state_id

    def _added(self, state_id: int, state: Hashable, valuation: int | None = None) -> None:
        """Book-keeping for a state just stored: its valuation (computed unless given);
        kept as handed over."""
        if valuation is None:
            valuation = self.valuation(state)
        self._append_valuation(valuation)
        if not self._keep_new:
            return
        fresh = self._fresh
        if len(fresh) >= self._keep_new:      # keep the newer half: expanded soonest
            fresh = self._fresh = dict(islice(fresh.items(), len(fresh) // 2 + 1, None))
        fresh[state_id] = state

    def initial_ids(self) -> list[int]:
        return unique([self.intern(state) for state in self.system.initial_states()])

    def successor_ids(self, state_id: int) -> tuple[int, ...]:
        """Distinct successor ids in model order; a deadlocked state is its own successor."""
        cache = self._successor_cache
        if self._caching:
            cached = cache.get(state_id)
            if cached is not None:
                self._hits += 1
                return cached
        if self._machine is not None:
            stepped = self._machine(state_id, self._machine_valuation)
            if stepped is not None:
                return self._machine_stepped(state_id, *stepped)
        return self.python_successor_ids(state_id)

    def python_successor_ids(self, state_id: int) -> tuple[int, ...]:
        """``successor_ids`` by the model's Python step (where the step machine leaves the
        state to it)."""
        state = self._fresh.pop(state_id, None)
        if state is None:
            state = self.states[state_id]
        successors = self._targets(state)
        if not successors:
            self.deadlocked.add(state_id)
            result: tuple[int, ...] = (state_id,)
        else:
            # ``_added`` written out for the usual new state (the hot path)
            table_intern, valuation, valuations = self.states.intern, self.valuation, \
                self.valuations
            fresh, keep = self._fresh, self._keep_new
            limit = 1 << 8 * valuations.itemsize if type(valuations) is array else 0
            ids = []
            for target in successors:
                target_id, new = table_intern(target)
                if new:
                    bits = valuation(target)
                    if bits < limit and len(fresh) < keep:
                        valuations.append(bits)
                        fresh[target_id] = target
                    else:
                        self._added(target_id, target, bits)
                        fresh, valuations = self._fresh, self.valuations
                        limit = 1 << 8 * valuations.itemsize if type(valuations) is array \
                            else 0
                ids.append(target_id)
            result = distinct(ids)
        return self._expanded(state_id, result)

    def _machine_stepped(self, state_id: int, ids: list[int], bits) -> tuple[int, ...]:
        """``successor_ids`` from the step machine's ids and the new states' valuations
        (None where its atoms gave up, or all of them when they are not compiled)."""
        valuations = self.valuations
        if bits and type(valuations) is array and None not in bits:
            try:        # (the usual: the machine valued every new state; it fits the array)
                valuations.extend(array(valuations.typecode, bits))
            except OverflowError:
                pass
            else:
                return self._expanded(state_id, distinct(ids))
        first_new = len(self.valuations)
        new_ids = range(first_new, len(self.states))
        if bits is None:
            bits = [None] * len(new_ids)
        for new_id, value in zip(new_ids, bits):
            self._append_valuation(self.valuation_of(new_id) if value is None else value)
        return self._expanded(state_id, distinct(ids))

    # The compiled cycle search steps the machine itself (``Product.native_machine``):
    # it hands over the valuations of the states the machine added, asks for the table
    # with this store's states selected, and for the valuation of a state the machine's
    # atoms gave up on.
    def machine_table(self):
        return self.states.machine_table()

    def add_valuations(self, packed: bytes) -> None:
        """The valuations of the next states, as unsigned 64-bit numbers."""
        added = array("Q")
        added.frombytes(packed)
        if type(self.valuations) is array:
            try:
                self.valuations.extend(array(self.valuations.typecode, added))
                return
            except OverflowError:               # (one needs a wider array)
                pass
        for value in added:
            self._append_valuation(value)

    def valuation_of(self, state_id: int) -> int:
        return self.valuation(self.states[state_id])

    def _append_valuation(self, value: int) -> None:
        try:
            self.valuations.append(value)
        except OverflowError:
            self.valuations = wider(self.valuations, value)
            self.valuations.append(value)

    def _expanded(self, state_id: int, result: tuple[int, ...]) -> tuple[int, ...]:
        """Book-keeping after a state's successors were found: the cache and its review."""
        cache = self._successor_cache
        if self._caching:
            if len(cache) >= SUCCESSOR_CACHE_SIZE:
                # Start afresh rather than evict one by one: deleting the oldest
                # entry of a dict makes each later next(iter(dict)) slower.
                cache.clear()
            cache[state_id] = result
        self._expansions += 1
        if self._expansions >= self._review_at:
            self._review_cache()
        return result

    def _review_cache(self) -> None:
        """Keep the successor cache, drop it, or try it again (see the module docstring)."""
        if not self._caching:
            self._caching, self._hits = True, 0
            self._review_at = self._expansions + CACHE_TRIAL
        elif self._hits * CACHE_WORTH < CACHE_TRIAL:
            self._caching = False
            self._successor_cache.clear()
            self._review_at = self._expansions + CACHE_REST
        else:
            self._hits = 0
            self._review_at = self._expansions + CACHE_TRIAL

    def memory_bytes(self) -> int:
        """Bytes of the stored states and their valuations (the successor cache excluded)."""
        return self.states.memory_bytes() + valuations_bytes(self.valuations)

    def labelled_successor_ids(self, state_id: int) -> list[tuple[Label, int]]:
        """Every (label, successor id) in model order, ``STUTTER`` for a deadlock (slow path);
        on a model with a ``path_system`` its transitions into stored states."""
        state = self.states[state_id]
        if path_system(self.system) is not self.system:
            return path_transitions(self.system, state, self.stored_id)
        transitions: Sequence = labelled_successors(self.system, state)
        return [(label, self.intern(target)) for label, target in transitions]

    def stored_id(self, state: Hashable) -> int:
        """The id of ``state``, -1 when it is not stored (nothing is added)."""
        return self.states.intern(state, add=False)[0]


def valuations_bytes(valuations) -> int:
    """Bytes of valuations kept in an array (or, beyond 64 atoms, a list of ints)."""
    if isinstance(valuations, list):        # an int object and a slot per state
        return sum(sys.getsizeof(v) + 8 for v in valuations)
    return len(valuations) * valuations.itemsize


def wider(valuations, valuation: int):
    """``valuations`` in the narrowest array type that also holds ``valuation`` (a list
    of Python ints beyond 64 atoms)."""
    for typecode in VALUATION_TYPES:
        if valuation < 1 << 8 * array(typecode).itemsize:
            return array(typecode, valuations)
    return list(valuations)


def distinct(ids: list[int]) -> tuple[int, ...]:
    """``ids`` without repeats, as a tuple, first occurrences kept in order."""
    if len(ids) == 1 or len(ids) == 2 and ids[0] != ids[1]:
        return tuple(ids)
    return tuple(dict.fromkeys(ids))


def unique(items: list[int]) -> list[int]:
    """``items`` without repeats, first occurrences kept in order."""
    if len(items) < 2 or len(items) == 2 and items[0] != items[1]:
        return items
    return list(dict.fromkeys(items))
