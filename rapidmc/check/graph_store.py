"""The state graph a complete breadth-first search explored, kept for the property searches.

The run-time error search (``reachability``) expands every reachable state
of the very system the property searches then explore.  When it ends
without a target and without reaching a bound, it has seen the whole
graph: ``ExploredGraph`` keeps its state table with each state's distinct
successor ids in model order (compressed sparse rows: one ``array`` of
row starts, one of targets; a deadlocked state is its own successor, as
in ``ModelStore``), and the valuations it was asked for, computed while
each state was at hand.  ``GraphStore`` offers that graph to ``Product``
in place of a ``ModelStore``: a product search then steps the model for
nothing (and evaluates atoms only for valuations the graph lacks, on
states rebuilt from the table).

Only the ids differ from a ``ModelStore`` (the breadth-first search's
numbering instead of the product search's discovery order); the search
never looks at an id beyond identity, so verdicts, counterexamples and
every count are the same (tests/test_graph_reuse.py).  The statistics
count what this search reached: its model states are the states it
interned (initial states and successors of the states it expanded), its
deadlocks those it expanded.
"""
from __future__ import annotations

from array import array
from typing import Hashable, Sequence

from .model import Label, Valuation, labelled_successors
from .states import StateTable
from .store import VALUATION_TYPES, unique, valuations_bytes, wider


class ExploredGraph:
    """States by id (a ``StateTable``), initial ids and successor ids; see the module docstring.

    Rows are added in id order (``add``), as a breadth-first search expands its states.
    """

    def __init__(self, system, states: StateTable, valuations: Sequence[Valuation] = ()):
        self.system = system
        self.states = states
        self.initial: list[int] = []
        self.starts = array("i", [0])          # row of state i: targets[starts[i]:starts[i + 1]]
        self.targets = array("i")
        self.deadlocked = bytearray()          # by id: 1 for a state without successors
        # valuation function -> its values by id (narrowest array type that holds them)
        self.valuations: dict[Valuation, object] = {
            valuation: array(VALUATION_TYPES[0]) for valuation in valuations}

    def __len__(self) -> int:
        return len(self.starts) - 1

    def add(self, state_id: int, state: Hashable, successor_ids: list[int]) -> None:
        """The row of ``state_id`` (the next id): its successors' ids in model order."""
        assert state_id == len(self), "rows are added in id order"
        for valuation, values in self.valuations.items():
            value = valuation(state)
            try:
                values.append(value)
            except OverflowError:
                values = self.valuations[valuation] = wider(values, value)
                values.append(value)
        if successor_ids:
            self.targets.extend(unique(successor_ids))
            self.deadlocked.append(0)
        else:
            self.targets.append(state_id)
            self.deadlocked.append(1)
        self.starts.append(len(self.targets))

    def memory_bytes(self) -> int:
        """Bytes of the state table, the rows and the valuations."""
        return self.states.memory_bytes() + len(self.deadlocked) + sum(
            len(a) * a.itemsize for a in (self.starts, self.targets)) + sum(
            valuations_bytes(values) for values in self.valuations.values())


class GraphStore:
    """An ``ExploredGraph`` with one property's valuations, as ``Product`` uses a ``ModelStore``.

    ``len`` is the number of states reached so far (interned, in ``ModelStore``
    terms).  Valuations the graph lacks are computed when a state is first reached.
    """

    def __init__(self, graph: ExploredGraph, valuation: Valuation):
        self.graph = graph
        self.system = graph.system
        self.valuation = valuation
        self.states = graph.states
        known = graph.valuations.get(valuation)
        self._evaluate = known is None
        self.valuations = array(VALUATION_TYPES[0], bytes(len(graph))) if known is None \
            else known
        self.reached = bytearray(len(graph))
        self.count = 0
        self.deadlocked: set[int] = set()

    def __len__(self) -> int:
        return self.count

    def initial_ids(self) -> list[int]:
        self._reach(self.graph.initial)
        return list(self.graph.initial)

    def successor_ids(self, state_id: int) -> Sequence[int]:
        """Distinct successor ids in model order; a deadlocked state is its own successor."""
        graph = self.graph
        ids = graph.targets[graph.starts[state_id]:graph.starts[state_id + 1]]
        if graph.deadlocked[state_id]:
            self.deadlocked.add(state_id)
        reached = self.reached
        for target_id in ids:
            if not reached[target_id]:
                self._reach((target_id,))
        return ids

    def _reach(self, ids: Sequence[int]) -> None:
        """Mark ``ids`` reached, with their valuations."""
        for state_id in ids:
            if self.reached[state_id]:
                continue
            self.reached[state_id] = 1
            self.count += 1
            if not self._evaluate:
                continue
            valuation = self.valuation(self.states[state_id])
            try:
                self.valuations[state_id] = valuation
            except OverflowError:
                self.valuations = wider(self.valuations, valuation)
                self.valuations[state_id] = valuation

    def memory_bytes(self) -> int:
        """Bytes of the graph (states, rows, valuations) and of this search's own."""
        own = valuations_bytes(self.valuations) if self._evaluate else 0
        return self.graph.memory_bytes() + own + len(self.reached)

    def labelled_successor_ids(self, state_id: int) -> list[tuple[Label, int]]:
        """Every (label, successor id) in model order, ``STUTTER`` for a deadlock (slow path)."""
        transitions = labelled_successors(self.system, self.states[state_id])
        ids = [self.states.intern(target, add=False)[0] for _, target in transitions]
        assert min(ids) >= 0, "a successor the explored graph does not hold"
        self._reach(ids)
        return [(label, target_id) for (label, _), target_id in zip(transitions, ids)]

