"""On-the-fly emptiness check of model × Büchi: Couvreur's SCC algorithm, iterative.

The search is one depth-first pass that numbers product states in the
order it discovers them and keeps, for the strongly connected components
on the current path, a stack of roots each with an "contains an accepting
state" bit.  An edge back to a live state merges the components above it;
if the merged component has an accepting state, it holds an accepting
cycle and the search stops: the property is violated.  A component whose
root is popped is complete and its states become dead (never merged
again).  Every product state is expanded exactly once, and a violation is
found as soon as the cycle's last edge is seen (unlike nested DFS, which
may need a second pass).

Memory per stored product state: four bytes in ``number`` (an array
indexed by product key: model state ids are dense, so product keys are
too), one byte in ``dead`` and, while live, one slot in ``active``.  No
Python recursion: the DFS path is a list of keys, and the successors still
to try of all its states lie on one stack of ints.

Reference: J.-M. Couvreur, "On-the-fly verification of linear temporal
logic", FM 1999; the single-acceptance-set form of Geldenhuys & Valmari.
"""
from __future__ import annotations

from array import array
from typing import Optional

from .budget import SearchBudget, stopped_in_time
from .lasso import build_bad_prefix, build_lasso
from .native import NATIVE, _native, native_search
from .product import Product
from .result import BAD_PREFIX, HOLDS, UNKNOWN, VIOLATED, SearchResult, SearchStats

UNSEEN = array("i", [-1])


def search_accepting_cycle(product: Product, budget: SearchBudget) -> SearchResult:
    """HOLDS if no accepting cycle is reachable, VIOLATED with a lasso, or UNKNOWN.

    A search that stops after seeing a state from which every run violates the property (a
    bad prefix: ``Product.universal``) is VIOLATED with that finite path, which ends in the
    words ``BAD_PREFIX``: a safety property broken by a model that never repeats a state
    afterwards (a cycle counter) has no lasso to find.  It stops at its bound, or
    ``BAD_PREFIX_GRACE`` states after it saw the bad prefix (``SearchBudget.saw_bad_prefix``),
    whichever comes first.  On a finite model every bad prefix leads on to an accepting
    cycle, which the search finds as before when it does within the grace: the verdict is
    the same either way.
    """
    search = _NativeCycleSearch(product, budget) if native_search() else \
        _CycleSearch(product, budget)
    found = None
    with stopped_in_time(budget):
        found = search.run()
    stats = search.stats()
    stats.seconds = budget.finish()
    if found is not None:
        prefix, cycle, closing = build_lasso(product, *found, search.explored())
        return SearchResult(VIOLATED, None, prefix, cycle, stats, closing)
    if budget.reason is not None:
        bad_path = search.bad_path
        if bad_path is not None:
            prefix = build_bad_prefix(product, bad_path, search.explored())
            return SearchResult(VIOLATED, None, prefix, stats=stats, ending=BAD_PREFIX)
        return SearchResult(UNKNOWN, budget.reason, stats=stats,
                            frontier=product.last_model_state())
    return SearchResult(HOLDS, stats=stats)


def initial_bad_end(product: Product, initial_keys: list[int]) -> Optional[list[int]]:
    """``[key]`` of the first initial product state that ends a bad prefix, else None: the
    search may never come back to the initial states after the first one (a model that
    keeps making new states), so they are looked at before it starts."""
    for key in initial_keys:
        if product.is_universal(key):
            return [key]
    return None


class _CycleSearch:
    """The state of one Couvreur search (see the module docstring)."""

    def __init__(self, product: Product, budget: SearchBudget):
        self.product = product
        self.budget = budget
        self.number = array("i")              # product key -> discovery number, -1: unseen
        self.dead = bytearray()               # by number: 1 once its component is complete
        self.active = array("q")              # numbers of live states, discovery order
        self.roots = array("q")               # numbers of component roots on the path
        self.root_accepting = bytearray()     # parallel to roots
        self.transitions = 0
        self.max_depth = 0
        # the DFS path to the first state seen that ends a bad prefix (``Product.universal``)
        self.bad_path: Optional[list[int]] = None

    def stats(self) -> SearchStats:
        stored = len(self.dead)
        memory = self.product.store.memory_bytes() + sum(
            len(a) * a.itemsize for a in (self.number, self.active, self.roots)) + len(self.dead)
        return SearchStats(product_states=stored, model_states=len(self.product.store),
                           transitions=self.transitions, max_depth=self.max_depth,
                           deadlocks=len(self.product.store.deadlocked),
                           bytes_per_state=memory / stored if stored else 0.0)

    def explored(self) -> "_Explored":
        return _Explored(self.number)

    def _number_of(self, key: int) -> int:
        number = self.number
        return number[key] if key < len(number) else -1

    def run(self):
        """None when no accepting cycle was found; else (DFS path keys, component keys)."""
        initial_keys = self.product.initial_keys()
        self.bad_path = initial_bad_end(self.product, initial_keys)
        if self.bad_path is not None:
            self.budget.saw_bad_prefix(0)
        for key in initial_keys:
            if self._number_of(key) >= 0:
                continue
            if not self.budget.may_store(len(self.dead)):
                return None
            found = self._explore_from(key)
            if found is not None or self.budget.reason is not None:
                return found
        return None

    def _explore_from(self, initial_key: int):
        # One loop with local names on purpose: this is the hot path of the
        # checker, and attribute look-ups per edge would cost a third of it (and
        # a nested function for the push would turn every name it shares into a
        # slower cell variable).  The successors still to try of all states on the
        # path lie on one stack, ``pending``, each state's in reverse order above
        # those of the state below it (from ``path_starts``): no list per state,
        # which would live as long as the state stays on the path and cost
        # Python's garbage collector a look at each one in every full collection.
        # ``number`` is kept long enough for every key pushed or met as a successor.
        number, dead, active = self.number, self.dead, self.active
        roots, root_accepting = self.roots, self.root_accepting
        accepting, width = self.product.accepting, self.product.width
        # whether to look for a bad prefix's end among the successors of each state pushed:
        # noted when seen, not when pushed, since the depth-first search may never come back
        # to a successor of a model that keeps making new states (initial states: ``run``)
        universal = self.product.universal
        watching = self.bad_path is None and any(universal)
        successor_keys = self.product.successor_keys
        budget = self.budget
        max_states = budget.max_states
        path_keys: list[int] = []
        path_starts: list[int] = []
        pending: list[int] = []
        transitions, max_depth = self.transitions, self.max_depth
        if initial_key >= len(number):
            number.extend(UNSEEN * (initial_key + 1 - len(number) + len(number) // 8))
        key = initial_key          # the key to push next (-1: none)
        try:
            while True:
                if key >= 0:       # push: number it, put its successors on ``pending``
                    index = len(dead)
                    number[key] = index
                    dead.append(0)
                    active.append(index)
                    roots.append(index)
                    root_accepting.append(accepting[key % width])
                    successors = successor_keys(key)
                    path_starts.append(len(pending))
                    if successors:
                        transitions += len(successors)
                        last = max(successors)
                        if last >= len(number):
                            number.extend(UNSEEN * (last + 1 - len(number) + len(number) // 8))
                        if watching:       # the first successor that ends a bad prefix
                            for successor in successors:
                                if universal[successor % width]:
                                    self.bad_path = path_keys + [key, successor]
                                    watching = False
                                    budget.saw_bad_prefix(len(dead))
                                    max_states = budget.max_states
                                    break
                        successors.reverse()
                        pending.extend(successors)
                    path_keys.append(key)
                    if len(path_keys) > max_depth:
                        max_depth = len(path_keys)
                    key = -1
                elif not path_keys:
                    return None
                if len(pending) > path_starts[-1]:
                    successor = pending.pop()
                    index = number[successor]
                    if index < 0:
                        stored = len(dead)
                        if stored >= max_states and not budget.may_store(stored):
                            return None
                        if stored >= budget.next_checkpoint and not budget.checkpoint(
                                stored, transitions, len(path_keys)):
                            return None
                        key = successor
                    elif not dead[index]:
                        merged = 0
                        while roots[-1] > index:
                            roots.pop()
                            merged |= root_accepting.pop()
                        root_accepting[-1] |= merged
                        if root_accepting[-1]:
                            return self._violation(path_keys)
                else:
                    popped = path_keys.pop()
                    path_starts.pop()
                    index = number[popped]
                    if roots[-1] == index:
                        roots.pop()
                        root_accepting.pop()
                        while active and active[-1] >= index:
                            dead[active.pop()] = 1
        finally:
            self.transitions, self.max_depth = transitions, max_depth

    def _violation(self, path_keys: list[int]):
        """The DFS path up to the accepting component's root, and the component's keys."""
        root = self.roots[-1]
        depth = len(path_keys)
        while self.number[path_keys[depth - 1]] > root:
            depth -= 1
        component = {key for key, index in enumerate(self.number)
                     if index >= root and not self.dead[index]}
        return path_keys[:depth], component


class _Explored:
    """``key in explored``: whether the search has stored a product key."""

    def __init__(self, number: array):
        self.number = number

    def __contains__(self, key: int) -> bool:
        return key < len(self.number) and self.number[key] >= 0


class _NativeCycleSearch:
    """``_CycleSearch`` with its loop and arrays in the compiled core (``_native.CycleSearch``):
    the same states in the same order, so the same verdict, lasso and counts."""

    def __init__(self, product: Product, budget: SearchBudget):
        self.product = product
        self.budget = budget
        self.graph = product.native_successors()
        self.initial_bad_path: Optional[list[int]] = None
        self.search = _native.CycleSearch(product.successor_keys, bytes(product.accepting),
                                          product.width, budget, self.graph,
                                          bytes(product.universal),
                                          None if self.graph is not None else
                                          product.native_machine())

    @property
    def bad_path(self) -> Optional[list[int]]:
        """``_CycleSearch.bad_path``: an initial state that ends a bad prefix, else the DFS
        path to the first state the search saw that does."""
        return self.initial_bad_path or self.search.bad_path()

    def stats(self) -> SearchStats:
        counts = self.search.counts()
        stored = counts["stored"]
        memory = self.product.store.memory_bytes() + counts["bytes"]
        return SearchStats(product_states=stored, model_states=len(self.product.store),
                           transitions=counts["transitions"], max_depth=counts["max_depth"],
                           deadlocks=len(self.product.store.deadlocked),
                           bytes_per_state=memory / stored if stored else 0.0,
                           engine=NATIVE)

    def explored(self) -> "_NativeExplored":
        return _NativeExplored(self.search)

    def run(self):
        """None when no accepting cycle was found; else (DFS path keys, component keys)."""
        search = self.search
        initial_keys = self.product.initial_keys()
        self.initial_bad_path = initial_bad_end(self.product, initial_keys)
        if self.initial_bad_path is not None:
            self.budget.saw_bad_prefix(0)
        for key in initial_keys:
            if search.contains_key(key):
                continue
            if not self.budget.may_store(search.counts()["stored"]):
                return None
            found = search.explore_from(key)
            if found is not None or self.budget.reason is not None:
                return self._finished(found)
        return self._finished(None)

    def _finished(self, found):
        if self.graph is not None:        # what successor_ids would have noted on the way
            self.product.store.note_deadlocks_expanded()
        return found


class _NativeExplored:
    """``key in explored`` for a native search."""

    def __init__(self, search):
        self.contains_key = search.contains_key

    def __contains__(self, key: int) -> bool:
        return self.contains_key(key)
