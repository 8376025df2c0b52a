"""Breadth-first search for the shortest path to a state satisfying a predicate.

Used for the built-in safety checks ("no uncaught run-time error", "no
deadlock"): the predicate marks the bad states.  The result is VIOLATED
with the shortest path (``prefix``, empty ``cycle``) when a bad state is
reachable, HOLDS when the whole reachable state space was searched
without finding one, UNKNOWN when a bound stopped the search first.

States without successors are deadlocks; with ``deadlock_is_target`` they
count as bad states themselves (otherwise they are counted in the
statistics and the search goes on).

``observe(state, successors)``, when given, sees every state the search
expands with its labelled successors: after a HOLDS verdict (a complete
search) it has seen the whole reachable state graph, which is what
coverage and vacuity are computed from.  An observer that needs labels only
for a while (``StatesObserver``: coverage once every line has run) says so
in ``labels_wanted``, read before each state until it is false: from then on
the search steps without labels (the system's ``successor_states``, the
same states in the same order) and hands the observer the states
(``observe.states``).  Without an observer the search never builds labels
but for the path it reports.

``explored(graph)``, when given, receives that graph after a HOLDS verdict
of an exact search: every stored state with its successors' ids and the
values of the functions in ``valuations`` (``graph_store.ExploredGraph``),
for the property searches of the same system to explore without stepping
the model again.
"""
from __future__ import annotations

from array import array
from contextlib import contextmanager
from typing import Callable, Hashable, Optional, Protocol, Sequence

from .budget import DEFAULT_MAX_STATES, OutOfTime, SearchBudget, stopped_in_time
from .collector import frozen_while_searching
from .transition_system import TransitionSystem, Valuation, as_sequence, transition_label
from .progress import Progress
from .graph_store import ExploredGraph
from .hashed import hashed_reachable, visited_sets
from .native import NATIVE, _native, engine_of, state_table
from .store import unique, wider
from .result import (HOLDS, NO_AUTOMATON, UNKNOWN, VIOLATED, LassoStep,
                     SearchResult, SearchStats)

Observer = Callable[[Hashable, Sequence[tuple[Hashable, Hashable]]], None]


class _GraphSink:
    """Where ``packed_breadth_first`` hands what it buffered: the parents of new states
    and the graph's rows (starts, targets, deadlock flags, one value per kept valuation,
    interleaved as 64-bit numbers)."""

    def __init__(self, parent: array, graph: Optional[ExploredGraph]):
        self.parent = parent
        self.graph = graph

    def __call__(self, parents: bytes, starts: bytes, targets: bytes, deadlocked: bytes,
                 values: bytes) -> None:
        self.parent.frombytes(parents)
        graph = self.graph
        if graph is None:
            return
        graph.starts.frombytes(starts)
        graph.targets.frombytes(targets)
        graph.deadlocked.extend(deadlocked)
        kept = graph.valuations
        if not kept or not values:
            return
        rows = array("Q")
        rows.frombytes(values)
        width = len(kept)
        for position, valuation in enumerate(list(kept)):
            column = rows[position::width].tolist()
            known = kept[valuation]
            top = max(column, default=0)
            if type(known) is array and top >= 1 << 8 * known.itemsize:
                known = kept[valuation] = wider(known, top)
            known.extend(column)


class StatesObserver(Protocol):
    """An observer that may do without labels (see the module docstring)."""

    labels_wanted: bool           # read before each state until false (then never again)

    def __call__(self, state: Hashable,
                 successors: Sequence[tuple[Hashable, Hashable]]) -> None: ...

    def states(self, state: Hashable, targets: Sequence[Hashable]) -> None: ...


def find_reachable(system: TransitionSystem, predicate: Callable[[Hashable], bool], *,
                   max_states: Optional[int] = DEFAULT_MAX_STATES,
                   max_seconds: Optional[float] = None,
                   progress: Optional[Progress] = None,
                   deadlock_is_target: bool = False,
                   observe: Optional[Observer] = None,
                   storage: Optional[tuple] = None,
                   explored: Optional[Callable[[ExploredGraph], None]] = None,
                   valuations: Sequence[Valuation] = ()) -> SearchResult:
    """Shortest path to a state where ``predicate`` holds; see the module docstring.

    ``storage`` (``check_property``): hashed visited states, depth-first, no
    shortest path, and nothing observed (``observe`` is for complete searches).
    """
    budget = SearchBudget(max_states, max_seconds, progress)
    with frozen_while_searching():
        if storage is not None:
            return hashed_reachable(system, predicate, visited_sets(storage, 1)[0], budget)
        search = _BreadthFirst(system, predicate, budget, deadlock_is_target, observe,
                               record=None if explored is None else valuations)
        target = None
        with stopped_in_time(budget):
            target = search.run()
    stats = search.stats()
    stats.seconds = budget.finish()
    if target is not None:
        return SearchResult(VIOLATED, None, search.path_to(target), [], stats)
    if budget.reason is not None:
        stored = len(search.states)
        return SearchResult(UNKNOWN, budget.reason, stats=stats,
                            frontier=search.states[stored - 1] if stored else None)
    if search.graph is not None:
        release = getattr(search.states, "release_index", None)
        if release is not None:      # (what only interning needs; made again if asked)
            release()
        explored(search.graph)
    return SearchResult(HOLDS, stats=stats)


def _packed_predicate(predicate, system, table) -> int:
    """How the packed loop tests its predicate: 1 the program failed (the state's context
    says), 2 several tasks stuck (the step machine's step says where it takes it:
    ``PackedStateTable._stuck``), 0 Python's ``predicate_holds``."""
    if predicate == getattr(system, "failed", None):
        return 1
    if predicate == getattr(system, "stuck", None) and getattr(table, "tasks", 1) > 1:
        return 2
    return 0


class _BreadthFirst:
    """States by id, each with the id of the state it was first reached from."""

    def __init__(self, system, predicate, budget: SearchBudget, deadlock_is_target: bool,
                 observe: Optional[Observer] = None,
                 record: Optional[Sequence[Valuation]] = None):
        self.system = system
        self.observe = observe
        self.predicate = predicate
        self.budget = budget
        self.deadlock_is_target = deadlock_is_target
        self.states = state_table(system, packed=True)
        self.graph = ExploredGraph(system, self.states, record) if record is not None else None
        self.parent = array("i")          # by id; -1 for initial states
        self.depth = array("i")
        self.deepest = -1                 # the last state's depth, stored by the native loop
        self.transitions = 0
        self.deadlocks = 0

    def stats(self) -> SearchStats:
        depth = max(max(self.depth, default=-1), self.deepest) + 1
        stored = len(self.states)
        table = self.states.memory_bytes()
        memory = table + len(self.parent) * self.parent.itemsize + \
            len(self.depth) * self.depth.itemsize
        if self.graph is not None:                # the rows kept for the property searches
            self.graph.table_bytes = table
            memory += self.graph.rows_bytes()
        return SearchStats(product_states=stored, model_states=stored,
                           transitions=self.transitions, max_depth=depth,
                           deadlocks=self.deadlocks,
                           bytes_per_state=memory / stored if stored else 0.0,
                           engine=engine_of(self.states))

    def _store(self, state: Hashable, parent: int) -> tuple[int, bool]:
        """The state's id and whether it is new; id -1 when new and the budget is spent."""
        stored = len(self.states)
        room = stored < self.budget.max_states
        state_id, new = self.states.intern(state, add=room)
        if not new:
            return state_id, False
        if not room:
            self.budget.may_store(stored)     # sets the reason: the state limit is reached
            return -1, True
        self.parent.append(parent)
        self.depth.append(self.depth[parent] + 1 if parent >= 0 else 0)
        if stored >= self.budget.next_checkpoint:
            self.budget.checkpoint(stored, self.transitions, self.depth[stored])
        return stored, True

    def run(self) -> Optional[int]:
        """The id of the first bad state found, in breadth-first order."""
        for state in self.system.initial_states():
            state_id, new = self._store(state, -1)
            if new and state_id >= 0 and self.predicate(state):
                return state_id
            if self.graph is not None and state_id >= 0:
                self.graph.initial.append(state_id)
        if self.graph is not None:
            self.graph.initial = unique(self.graph.initial)
        return self._expand_all()

    def _expand_all(self) -> Optional[int]:
        """Expand the stored states in id order (the hot path: one loop, local names).

        Each state is rebuilt from the table, not kept as the model handed it over:
        the rebuilt state's parts are the table's own objects, which the step
        function's caches recognise, and that saves what the rebuilding costs."""
        table, intern = self.states, self.states.intern
        successors_of, observe, predicate = self.system.successors, self.observe, self.predicate
        # without labels: when nobody looks at them, or while the observer does without
        targets_of = getattr(self.system, "successor_states", None)
        unlabelled = targets_of is not None and (observe is None or hasattr(observe, "states")
                                                 and not observe.labels_wanted)
        labelled_while = targets_of is not None and hasattr(observe, "states") and not unlabelled
        parent, depth, budget = self.parent, self.depth, self.budget
        max_states = budget.max_states
        record = self.graph.adder() if self.graph is not None else None
        stored = len(table)
        frontier = 0
        native = engine_of(table) == NATIVE
        # a packed table's loop also serves an observer that wants labels for a while (it
        # names the lines its steps ran: ``note_spans``); it keeps valuations of 64 atoms
        # at most
        is_packed = hasattr(table, "python_successors")
        packed = native and is_packed and \
            (unlabelled or labelled_while and hasattr(observe, "note_spans")) and \
            all(getattr(valuation, "atom_count", 0) <= 64 for valuation in
                (self.graph.valuations if self.graph is not None else ()))
        while frontier < stored and budget.reason is None:
            if packed:                    # the same loop in the compiled core from here on
                return self._expand_packed(frontier, labels_wanted=not unlabelled)
            if unlabelled and native and not is_packed:
                return self._expand_natively(frontier, record)
            state = table[frontier]
            if unlabelled:
                successors = targets_of(state)
                if observe is not None:
                    observe.states(state, successors)
            else:
                labelled = as_sequence(successors_of(state))
                if observe is not None:
                    observe(state, labelled)
                    if labelled_while and not observe.labels_wanted:
                        unlabelled = True
                successors = [successor for _, successor in labelled]
            self.transitions += len(successors)
            if not successors:
                self.deadlocks += 1
                if self.deadlock_is_target:
                    return frontier
            ids = []
            for successor in successors:
                successor_id, new = intern(successor, stored < max_states)
                if new:
                    if successor_id < 0:
                        budget.may_store(stored)     # sets the reason: the state limit
                        return None
                    parent.append(frontier)
                    depth.append(depth[frontier] + 1)
                    stored += 1
                    if successor_id >= budget.next_checkpoint:
                        budget.checkpoint(successor_id, self.transitions, depth[successor_id])
                    if predicate(successor):
                        return successor_id
                    if budget.reason is not None:
                        return None
                ids.append(successor_id)
            if record is not None:
                record(state, ids)
            frontier += 1
        return None

    def _expand_natively(self, frontier: int, record) -> Optional[int]:
        """``_expand_all``'s unlabelled loop from ``frontier`` on, in the compiled core
        (``_native.breadth_first``): the same states, ids, calls and counts; the depths of
        the states it stores are not kept (they grow level by level: only the last one's)."""
        observe = self.observe.states if self.observe is not None else None
        with self._counts_kept_when_stopped():
            target, self.transitions, self.deadlocks, self.deepest = _native.breadth_first(
                self.states, frontier, self.system.successor_states, observe, self.predicate,
                self.parent, self.depth, self.budget, record, self.deadlock_is_target,
                self.transitions, self.deadlocks)
        return target if target >= 0 else None

    @contextmanager
    def _counts_kept_when_stopped(self):
        """A compiled loop stopped at the time limit inside a Python step (``OutOfTime``)
        returns nothing: its counts so far are those it left on the budget
        (``keep_counts``, _common.h), so an UNKNOWN reports the transitions and depth it
        reached."""
        try:
            yield
        except OutOfTime:
            counts = getattr(self.budget, "stopped_counts", None)
            if counts is not None:
                self.transitions, self.deadlocks, self.deepest = counts
            raise

    def _expand_packed(self, frontier: int, labels_wanted: bool) -> Optional[int]:
        """``_expand_all``'s loop over a packed table (``model.packed``) in the compiled core:
        the successors of the states its step machine takes, the run-time error predicate,
        the rows of the graph and their valuations, and the observer's stuck check and
        trigger atoms are computed there; Python is called for the rest (the Python step,
        with labels for the observer while it wants them: ``labels_wanted``)."""
        observe, graph = self.observe, self.graph
        table = self.states.machine_table()      # (a check's shared table: this search's)
        table.predicate = self.predicate
        table.observer = observe
        watch = getattr(observe, "packed_watch", None)
        triggers, seen = watch() if watch is not None else (None, None)
        kept = list(graph.valuations) if graph is not None else []
        table.valuations_kept = kept
        indices = [table.valuation_index(valuation) for valuation in kept]
        trigger_index = table.valuation_index(triggers) if seen is not None else -1
        depth_now = self.depth[frontier]
        level_end = frontier + 1
        while level_end < len(self.depth) and self.depth[level_end] <= depth_now:
            level_end += 1
        sink = _GraphSink(self.parent, graph)
        with self._counts_kept_when_stopped(), self._table_released(table):
            target, self.transitions, self.deadlocks, self.deepest, bits = \
                _native.packed_breadth_first(
                    table, frontier, table.python_successors,
                    table.observe if observe is not None else None,
                    watch is not None and (seen is None or trigger_index >= 0), trigger_index,
                    _packed_predicate(self.predicate, self.system, table),
                    self.deadlock_is_target, graph is not None, self.budget, sink, indices,
                    self.transitions, self.deadlocks, depth_now, level_end,
                    len(graph.targets) if graph is not None else 0, labels_wanted)
        if seen is not None:
            seen.update(bits)
        return target if target >= 0 else None

    @staticmethod
    @contextmanager
    def _table_released(table):
        """The packed table forgets this search's predicate and observer when its loop
        ends, however it ends."""
        try:
            yield
        finally:
            table.predicate = table.observer = None

    def path_to(self, state_id: int) -> list[LassoStep]:
        """The steps from an initial state to ``state_id`` with their labels."""
        ids = []
        while state_id >= 0:
            ids.append(state_id)
            state_id = self.parent[state_id]
        ids.reverse()
        steps = [LassoStep(None, self.states[ids[0]], NO_AUTOMATON)]
        for previous, current in zip(ids, ids[1:]):
            target = self.states[current]
            label = transition_label(self.system, self.states[previous], target)
            steps.append(LassoStep(label, target, NO_AUTOMATON))
        return steps
