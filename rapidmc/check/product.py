"""The synchronous product of a model with a Büchi automaton, as integer keys.

A product state (model state id ``s``, automaton state ``q``) is the single
integer ``key = s * width + q`` where ``width`` is the number of automaton
states, so the search stores plain ints.

Run semantics (the automaton reads the label of every model state,
starting with the initial one): the initial product states are ``(s0, q')``
for each edge ``initial --g--> q'`` with ``s0 |= g``; ``(s, q)`` leads to
``(s', q')`` for each model successor ``s'`` and each edge ``q --g--> q'``
with ``s' |= g``.  A product state is accepting when ``q`` is.
"""
from __future__ import annotations

from array import array
from typing import Hashable, Optional

from ..ltl.universal import universal_states
from .result import LassoStep
from .store import ModelStore

MOVES_KEPT = 1 << 12        # remembered valuations per automaton state
TABLE_LIMIT = 1 << 12       # a guard table per automaton state up to this many entries


class Product:
    """Model × automaton over a ``ModelStore``; see the module docstring."""

    def __init__(self, store: ModelStore, buchi):
        self.store = store
        self.width = max(len(buchi.edges), 1)
        self.initial_automaton_state = buchi.initial
        self.edges = [tuple((edge.positive, edge.negative, edge.target) for edge in out)
                      for out in buchi.edges]
        # per automaton state: valuation -> the distinct targets of the edges it enables
        self._moves: list[dict[int, tuple[int, ...]]] = [{} for _ in self.edges]
        self.accepting = bytearray(self.width)
        for q in buchi.accepting:
            self.accepting[q] = 1
        # automaton states from which every continuation is accepted: a product state there
        # ends a bad prefix (``ltl.universal``)
        self.universal = bytearray(self.width)
        for q in universal_states(buchi):
            self.universal[q] = 1
        # the guard tables: per automaton state, indexed by a valuation's bits that some
        # guard reads (``valuation & read``), the distinct targets (``moves``); None when
        # the guards read too many bits, to keep the tables small
        self.read = 0
        for out in self.edges:
            for positive, negative, _ in out:
                self.read |= positive | negative
        self.tables = None if self.read >= TABLE_LIMIT else \
            [self._guard_table(q) for q in range(len(self.edges))]

    def key(self, state_id: int, automaton_state: int) -> int:
        return state_id * self.width + automaton_state

    def split(self, key: int) -> tuple[int, int]:
        """(model state id, automaton state) of a product key."""
        return divmod(key, self.width)

    def is_accepting(self, key: int) -> bool:
        return bool(self.accepting[key % self.width])

    def is_universal(self, key: int) -> bool:
        """Whether every run that goes on from ``key`` violates the property."""
        return bool(self.universal[key % self.width])

    def targets(self, automaton_state: int, valuation: int) -> list[int]:
        """Automaton states reached from ``automaton_state`` reading ``valuation``, in edge order."""
        return [target for positive, negative, target in self.edges[automaton_state]
                if valuation & positive == positive and not valuation & negative]

    def moves(self, automaton_state: int, valuation: int) -> tuple[int, ...]:
        """``targets`` without repeats, remembered per valuation (up to ``MOVES_KEPT``)."""
        moves = self._moves[automaton_state]
        if len(moves) >= MOVES_KEPT:
            moves.clear()
        found = moves[valuation] = tuple(dict.fromkeys(self.targets(automaton_state, valuation)))
        return found

    def _guard_table(self, automaton_state: int) -> list[tuple[int, ...]]:
        """``moves(automaton_state, v)`` for every ``v`` up to ``read`` (equal ones shared)."""
        shared: dict[tuple[int, ...], tuple[int, ...]] = {}
        return [shared.setdefault(targets, targets) for targets in
                (tuple(dict.fromkeys(self.targets(automaton_state, valuation)))
                 for valuation in range(self.read + 1))]

    def initial_keys(self) -> list[int]:
        if not self.edges:
            return []
        keys = []
        for state_id in self.store.initial_ids():
            valuation = self.store.valuations[state_id]
            keys.extend(self.key(state_id, q)
                        for q in self.targets(self.initial_automaton_state, valuation))
        return list(dict.fromkeys(keys))

    def successor_keys(self, key: int) -> list[int]:
        """Distinct product successors of ``key`` in deterministic order (the hot path)."""
        state_id, q = divmod(key, self.width)
        return self._keys(q, self.store.successor_ids(state_id))

    def python_successor_keys(self, key: int) -> list[int]:
        """``successor_keys`` with the model stepped in Python (``native_machine``)."""
        state_id, q = divmod(key, self.width)
        return self._keys(q, self.store.python_successor_ids(state_id))

    def _keys(self, q: int, target_ids) -> list[int]:
        """The product keys of automaton state ``q`` with the model states ``target_ids``."""
        width = self.width
        if self.tables is not None:          # the guard table of ``q``: one index per target
            table, read = self.tables[q], self.read
            valuations = self.store.valuations
            keys = []
            for target_id in target_ids:
                base = target_id * width
                for target in table[valuations[target_id] & read]:
                    keys.append(base + target)
            return keys
        known = self._moves[q]
        valuations = self.store.valuations
        keys = []
        for target_id in target_ids:
            valuation = valuations[target_id]
            targets = known.get(valuation)
            if targets is None:
                targets = self.moves(q, valuation)
            base = target_id * width
            for target in targets:
                keys.append(base + target)
        return keys

    def native_successors(self) -> Optional[tuple]:
        """What the compiled core's cycle search needs to compute ``successor_keys`` itself
        (``_native.CycleSearch``): over an explored graph whose valuations are kept, with
        guard tables: ((row starts, targets, valuations, expanded flags), move starts,
        moves, read); else None (it calls ``successor_keys``)."""
        rows = getattr(self.store, "native_rows", None)
        if rows is None or self.tables is None:
            return None
        found = rows()
        if found is None:
            return None
        return (found, *self._move_arrays(), self.read)

    def native_machine(self) -> Optional[tuple]:
        """What the compiled core's cycle search needs to compute ``successor_keys`` itself
        over a packed table's step machine (``ModelStore``'s fast path, with guard
        tables): (store, ``python_successor_keys``, the index of the machine's atoms, -1
        where they are not compiled, move starts, moves, read); else None."""
        store = self.store
        if getattr(store, "_machine", None) is None or self.tables is None or \
                not isinstance(store.valuations, array):
            return None
        starts, moves = self._move_arrays()
        return store, self.python_successor_keys, store._machine_valuation, starts, moves, \
            self.read

    def _move_arrays(self) -> tuple[bytes, bytes]:
        """The guard tables as (starts, moves): the moves of (q, v) are
        moves[starts[q * (read + 1) + v] .. starts[q * (read + 1) + v + 1]]."""
        starts, moves = array("i", [0]), array("i")
        for table in self.tables:
            for targets in table:
                moves.extend(targets)
                starts.append(len(moves))
        return starts.tobytes(), moves.tobytes()

    def labelled_successor_keys(self, key: int) -> list[tuple[Hashable, int]]:
        """Every (model label, product successor), for rebuilding paths (slow path)."""
        state_id, q = divmod(key, self.width)
        result = []
        for label, target_id in self.store.labelled_successor_ids(state_id):
            valuation = self.store.valuations[target_id]
            result.extend((label, self.key(target_id, target))
                          for target in self.targets(q, valuation))
        return result

    def label_between(self, key: int, next_key: int) -> Hashable:
        """The first model label of a transition from ``key`` to ``next_key``."""
        for label, successor in self.labelled_successor_keys(key):
            if successor == next_key:
                return label
        raise AssertionError(f"no product transition {key} -> {next_key}")

    def last_model_state(self):
        """The model state stored last (None before any): where an UNKNOWN search stood
        (``SearchResult.frontier``)."""
        stored = len(self.store)
        return self.store.states[stored - 1] if stored else None

    def lasso_step(self, key: int, label: Optional[Hashable]) -> LassoStep:
        state_id, q = divmod(key, self.width)
        return LassoStep(label, self.store.states[state_id], q)
