"""Emptiness of model × Büchi under weak fairness constraints (Tarjan's SCCs, iterative).

A weak fairness constraint (justice) holds on an infinite run when the
constrained party — a RAPID task, for ``rapidmc.model.fairness`` — takes a
step infinitely often or is infinitely often unable to go on.  On a lasso
that means: its cycle contains a step of the party or a state where the
party cannot go on.

The search numbers product states depth-first (Tarjan) and examines each
strongly connected component when it is complete.  A component answers
the question for every cycle inside it: a cycle may pass through all of
its states and edges, and a smaller cycle only loses witnesses.  So a
non-trivial component with an accepting state holds a fair accepting cycle
exactly when, for each constraint, some edge inside it is a step of the
party or some state inside it has the party unable to go on.  The cycle
reported then walks (shortest paths inside the component) from its entry
to an accepting state and on to one witness per constraint not yet met,
and back.

The fairness is given as an object with ``count`` constraints and two
methods over model states and transition labels: ``taken(state, label)``
-> the constraint a step fulfils (None: none), ``excused(state)`` -> the
constraints a state fulfils.  Only the components that could answer
(non-trivial, with an accepting state) are asked about, so the search pays
for fairness only there.  Memory is a dictionary entry per product state:
more than ``emptiness``'s arrays, the price of keeping complete components.
"""
from __future__ import annotations

from typing import Callable, Hashable, Optional, Protocol

from ..ltl.graph import pop_component
from .budget import DEFAULT_MAX_STATES, SearchBudget, stopped_in_time
from .native import engine_of
from .lasso import LabelledKey, shortest_entry, shortest_path
from .product import Product
from .progress import Progress
from .result import HOLDS, UNKNOWN, VIOLATED, SearchResult, SearchStats
from .store import ModelStore


class Fairness(Protocol):
    """Weak fairness constraints over a model; see the module docstring."""

    count: int

    def taken(self, state: Hashable, label: Hashable) -> Optional[int]: ...

    def excused(self, state: Hashable) -> frozenset: ...


EdgeWitness = tuple[int, Hashable, int]        # a step: (key, label, successor key)
StateWitness = int                             # a state: its key
Witnesses = dict[int, "EdgeWitness | StateWitness"]    # constraint -> where it is met


def search_fair_accepting_cycle(product: Product, fairness: Fairness,
                                budget: SearchBudget) -> SearchResult:
    """HOLDS if no fair accepting cycle is reachable, VIOLATED with a fair lasso, or UNKNOWN."""
    search = _ComponentSearch(product, fairness, budget)
    found = None
    with stopped_in_time(budget):
        found = search.run()
    stats = search.stats()
    stats.seconds = budget.finish()
    if found is not None:
        dfs_path, component, witnesses = found
        entry = shortest_entry(product, dfs_path, component, search.number)
        walk = fair_cycle(product, fairness.taken, search.excused_at, entry[-1][1], component,
                          witnesses)
        prefix = [product.lasso_step(key, label) for label, key in entry[:-1]]
        cycle = [product.lasso_step(key, label) for label, key in walk[:-1]]
        cycle[0].label = entry[-1][0]
        return SearchResult(VIOLATED, None, prefix, cycle, stats, walk[-1][0])
    if budget.reason is not None:
        return SearchResult(UNKNOWN, budget.reason, stats=stats,
                            frontier=product.last_model_state())
    return SearchResult(HOLDS, stats=stats)


class _ComponentSearch:
    """One Tarjan search that stops at the first fair accepting component."""

    def __init__(self, product: Product, fairness: Fairness, budget: SearchBudget):
        self.product = product
        self.fairness = fairness
        self.budget = budget
        self.number: dict[int, int] = {}      # product key -> discovery number
        self.low: dict[int, int] = {}          # lowest number reachable, while on the stack
        self.stack: list[int] = []             # keys of unfinished components
        self.transitions = 0
        self.max_depth = 0
        self._excused: dict[int, frozenset] = {}   # by model state id

    def stats(self) -> SearchStats:
        return SearchStats(product_states=len(self.number), model_states=len(self.product.store),
                           transitions=self.transitions, max_depth=self.max_depth,
                           deadlocks=len(self.product.store.deadlocked),
                           engine=engine_of(getattr(self.product.store, "states", None)))

    def run(self):
        """None, or (DFS path to the component, its keys, a witness per constraint)."""
        for key in self.product.initial_keys():
            if key in self.number:
                continue
            found = self._explore_from(key)
            if found is not None or self.budget.reason is not None:
                return found
        return None

    def _explore_from(self, initial_key: int):
        number, low, stack, budget = self.number, self.low, self.stack, self.budget
        on_stack: set[int] = set()
        path: list[int] = []
        path_successors: list[list[int]] = []
        path_positions: list[int] = []

        def push(key: int) -> bool:
            stored = len(number)
            if not budget.may_store(stored):
                return False
            if stored >= budget.next_checkpoint and not budget.checkpoint(
                    stored, self.transitions, len(path)):
                return False
            number[key] = low[key] = stored
            stack.append(key)
            on_stack.add(key)
            successors = self.product.successor_keys(key)
            self.transitions += len(successors)
            path.append(key)
            path_successors.append(successors)
            path_positions.append(0)
            self.max_depth = max(self.max_depth, len(path))
            return True

        if not push(initial_key):
            return None
        while path:
            key = path[-1]
            successors, position = path_successors[-1], path_positions[-1]
            if position < len(successors):
                path_positions[-1] = position + 1
                successor = successors[position]
                if successor not in number:
                    if not push(successor):
                        return None
                elif successor in on_stack:
                    low[key] = min(low[key], number[successor])
                continue
            if low[key] == number[key]:
                component = pop_component(key, stack, on_stack)
                component.reverse()
                witnesses = self._fair_witnesses(component, successors)
                if witnesses is not None:
                    return list(path), set(component), witnesses
            path.pop()
            path_successors.pop()
            path_positions.pop()
            if path:
                low[path[-1]] = min(low[path[-1]], low[key])
        return None

    def _fair_witnesses(self, component: list[int], root_successors: list[int]):
        """A witness per constraint when the component holds a fair accepting cycle, else None."""
        product = self.product
        if len(component) == 1 and component[0] not in root_successors:
            return None                      # trivial: no cycle at all
        if not any(product.is_accepting(key) for key in component):
            return None
        members = set(component)
        witnesses: Witnesses = {}
        count = self.fairness.count
        for key in component:
            if len(witnesses) == count:
                break
            state = product.lasso_step(key, None).state
            for label, successor in product.labelled_successor_keys(key):
                if successor in members:
                    party = self.fairness.taken(state, label)
                    if party is not None and party not in witnesses:
                        witnesses[party] = (key, label, successor)
        for key in component:
            if len(witnesses) == count:
                break
            for party in self.excused_at(key):
                witnesses.setdefault(party, key)
        return witnesses if len(witnesses) == count else None

    def excused_at(self, key: int) -> frozenset:
        """The constraints the model state of product key ``key`` fulfils (asked once per state)."""
        state_id = self.product.split(key)[0]
        excused = self._excused.get(state_id)
        if excused is None:
            excused = self.fairness.excused(self.product.store.states[state_id])
            self._excused[state_id] = excused
        return excused


def fair_cycle(product: Product, taken: Callable, excused_at: Callable[[int], frozenset],
               root: int, component: set[int], witnesses: Witnesses) -> list[LabelledKey]:
    """A walk ``[(None, root), (label, key), ..., (label, root)]`` of at least one step
    inside the component through an accepting state and every constraint's witness
    (skipping those the walk already meets).  ``taken(state, label)`` and
    ``excused_at(key)`` are the fairness's, the latter by product key."""
    successors = product.labelled_successor_keys
    walk: list[LabelledKey] = [(None, root)]

    def go_to(goal) -> None:
        path = shortest_path(successors, [walk[-1][1]], goal, component, 0)
        if path is None:
            raise AssertionError("the fair component is not strongly connected")
        walk.extend(path[1:])

    def met(party: int) -> bool:
        """Whether the walk so far has a step of ``party`` or a state excusing it."""
        if any(party in excused_at(key) for _, key in walk):
            return True
        return any(taken(product.lasso_step(before, None).state, label) == party
                   for (_, before), (label, _) in zip(walk, walk[1:]))

    go_to(product.is_accepting)
    for party in sorted(witnesses):
        if met(party):
            continue
        witness = witnesses[party]
        if isinstance(witness, tuple):
            key, label, successor = witness
            go_to(lambda at: at == key)
            walk.append((label, successor))
        else:
            go_to(lambda at: at == witness)
    back = shortest_path(successors, [walk[-1][1]], lambda at: at == root, component,
                         1 if len(walk) == 1 else 0)
    if back is None:
        raise AssertionError("the fair component is not strongly connected")
    walk.extend(back[1:])
    return walk


def check_fair_property(system, buchi, valuation, fairness: Fairness, *,
                        max_states: Optional[int] = DEFAULT_MAX_STATES,
                        max_seconds: Optional[float] = None,
                        progress: Optional[Progress] = None) -> SearchResult:
    """``engine.check_property`` (exact storage) keeping only the runs fair to ``fairness``."""
    budget = SearchBudget(max_states, max_seconds, progress)
    product = Product(ModelStore(system, valuation), buchi)
    return search_fair_accepting_cycle(product, fairness, budget)
