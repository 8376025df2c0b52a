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
from typing import Callable, Hashable, Optional, Sequence

from .transition_system import Label, Valuation, labelled_successors, path_system, \
    path_transitions
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
        self.table_bytes: Optional[int] = None     # the state table's, once measured

    def __len__(self) -> int:
        return len(self.starts) - 1

    def add(self, state_id: int, state: Hashable, successor_ids: list[int]) -> None:
        """The row of ``state_id`` (the next id): its successors' ids in model order."""
        assert state_id == len(self.deadlocked), "rows are added in id order"
        self.adder()(state, successor_ids)

    def adder(self) -> Callable[[Hashable, list[int]], None]:
        """``add`` for the search's hot loop: ``add(state, successor_ids)`` appends the row of
        the next id (names bound once; the usual single valuation evaluated inline)."""
        targets, starts, deadlocked = self.targets, self.starts, self.deadlocked
        kept = self.valuations
        evaluate = self._evaluate
        only = next(iter(kept)) if len(kept) == 1 else None
        values = kept[only] if only is not None else None

        def add(state: Hashable, successor_ids: list[int]) -> None:
            nonlocal values
            if only is not None:
                value = only(state)
                try:
                    values.append(value)
                except OverflowError:
                    values = kept[only] = wider(values, value)
                    values.append(value)
            elif kept:
                evaluate(state)
            if successor_ids:
                targets.extend(successor_ids if len(successor_ids) == 1
                               else unique(successor_ids))
                deadlocked.append(0)
            else:
                targets.append(len(deadlocked))
                deadlocked.append(1)
            starts.append(len(targets))
        return add

    def _evaluate(self, state: Hashable) -> None:
        """Append each kept valuation of ``state``."""
        for valuation, values in self.valuations.items():
            value = valuation(state)
            try:
                values.append(value)
            except OverflowError:
                values = self.valuations[valuation] = wider(values, value)
                values.append(value)

    def memory_bytes(self) -> int:
        """Bytes of the state table, the rows and the valuations (the table measured once:
        it is complete before any search reads it)."""
        if self.table_bytes is None:
            self.table_bytes = self.states.memory_bytes()
        return self.table_bytes + self.rows_bytes()

    def rows_bytes(self) -> int:
        """Bytes of the rows and the valuations."""
        return len(self.deadlocked) + sum(
            len(a) * a.itemsize for a in (self.starts, self.targets)) + sum(
            valuations_bytes(values) for values in self.valuations.values())


class GraphStore:
    """An ``ExploredGraph`` with one property's valuations, as ``Product`` uses a ``ModelStore``.

    ``len`` is the number of states reached (interned, in ``ModelStore`` terms:
    the initial states and the successors of the states expanded), counted
    when asked.  Valuations the graph lacks are computed when a state is first
    reached.
    """

    def __init__(self, graph: ExploredGraph, valuation: Valuation):
        self.graph = graph
        self.system = graph.system
        self.valuation = valuation
        self.states = graph.states
        known = graph.valuations.get(valuation)
        # without kept valuations: by id, 1 once evaluated
        self._evaluated = bytearray(len(graph)) if known is None else None
        self.valuations = array(VALUATION_TYPES[0], bytes(len(graph))) if known is None \
            else known
        self.expanded = bytearray(len(graph))
        self.deadlocked: set[int] = set()

    def __len__(self) -> int:
        graph, expanded = self.graph, self.expanded
        if expanded.count(0) == 0:           # every state expanded, so every one reached
            return len(graph)
        reached = bytearray(len(graph))
        for state_id in graph.initial:
            reached[state_id] = 1
        starts, targets = graph.starts, graph.targets
        at = expanded.find(1)
        while at >= 0:
            for target_id in targets[starts[at]:starts[at + 1]]:
                reached[target_id] = 1
            at = expanded.find(1, at + 1)
        return reached.count(1)

    def initial_ids(self) -> list[int]:
        self._evaluate(self.graph.initial)
        return list(self.graph.initial)

    def successor_ids(self, state_id: int) -> Sequence[int]:
        """Distinct successor ids in model order; a deadlocked state is its own successor."""
        graph = self.graph
        ids = graph.targets[graph.starts[state_id]:graph.starts[state_id + 1]]
        self.expanded[state_id] = 1
        if graph.deadlocked[state_id]:
            self.deadlocked.add(state_id)
        if self._evaluated is not None:
            self._evaluate(ids)
        return ids

    def native_rows(self) -> Optional[tuple]:
        """The arrays a search in the compiled core reads ``successor_ids`` from (row starts,
        targets, kept valuations, the expanded flags it sets), None when the valuations
        are not all kept (then ``successor_ids`` evaluates them)."""
        graph = self.graph
        if self._evaluated is not None or type(self.valuations) is not array:
            return None
        return graph.starts, graph.targets, self.valuations, self.expanded

    def note_deadlocks_expanded(self) -> None:
        """``deadlocked`` as ``successor_ids`` would have filled it (after a native search)."""
        deadlocked, expanded = self.graph.deadlocked, self.expanded
        at = deadlocked.find(1)             # (deadlocks are few; expanded states many)
        while at >= 0:
            if expanded[at]:
                self.deadlocked.add(at)
            at = deadlocked.find(1, at + 1)

    def _evaluate(self, ids: Sequence[int]) -> None:
        """The valuations of ``ids``, unless kept with the graph or computed already."""
        evaluated = self._evaluated
        if evaluated is None:
            return
        for state_id in ids:
            if evaluated[state_id]:
                continue
            evaluated[state_id] = 1
            valuation = self.valuation(self.states[state_id])
            try:
                self.valuations[state_id] = valuation
            except OverflowError:
                self.valuations = wider(self.valuations, valuation)
                self.valuations[state_id] = valuation

    def memory_bytes(self) -> int:
        """Bytes of the graph (states, rows, valuations) and of this search's own."""
        own = len(self.expanded)
        if self._evaluated is not None:
            own += valuations_bytes(self.valuations) + len(self._evaluated)
        return self.graph.memory_bytes() + own

    def labelled_successor_ids(self, state_id: int) -> list[tuple[Label, int]]:
        """Every (label, successor id) in model order, ``STUTTER`` for a deadlock (slow path);
        on a model with a ``path_system`` its transitions into the graph's states."""
        state = self.states[state_id]
        if path_system(self.system) is not self.system:
            found = path_transitions(self.system, state,
                                     lambda target: self.states.intern(target, add=False)[0])
            self._evaluate([target_id for _, target_id in found])
            return found
        transitions = labelled_successors(self.system, state)
        ids = [self.states.intern(target, add=False)[0] for _, target in transitions]
        assert min(ids) >= 0, "a successor the explored graph does not hold"
        self._evaluate(ids)
        return [(label, target_id) for (label, _), target_id in zip(transitions, ids)]

