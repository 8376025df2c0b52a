"""Distributed LTL: accepting cycles of the partitioned product by OWCTY (Černá and Pelánek;
Barnat, Brim and Černá's distributed version).

``partitioned_accepting_cycle`` answers what ``engine.check_property`` answers for one
property (HOLDS: no reachable accepting cycle; VIOLATED with a lasso; UNKNOWN at a bound),
with the product states split among ``ProductPartition`` actors by the owner of their model
state.  Nested depth-first search does not distribute (it is inherently sequential); OWCTY
needs only breadth-first spreads, each a sequence of levels like the reachability search's:

1. a breadth-first search stores every reachable product state and its edges;
2. a round keeps in the set S (at first: all of them) only the states reachable from an
   accepting state of S (REACH, which counts for each state the edges of S that enter it),
   then removes, again and again, the states no edge of S enters (ELIMINATE);
3. rounds go on until one removes nothing.  What is left is empty exactly when no accepting
   cycle is reachable: in a non-empty fixpoint, a source component of S (no edge of S enters
   it from outside) has an entering edge for each state, so it is a cycle, and a state of it
   is reachable from an accepting state of S, which must lie in it.

The lasso takes one more spread, whatever the number of accepting states in S (an accepting
state of S need not lie on a cycle itself: it may hang below one).  REGIONS goes
breadth-first through S from all accepting states of S at once: each state joins the
region of the first one that reaches it, and each accepting state x notes the first edge
of S into it and the region y that edge leaves: a path y -> ... -> x inside S.  Every
state of S is reachable from an accepting state of S, so every state joins a region, and
every accepting state, having an edge of S that enters it, notes one.  Following these
notes from x to y and on must come back to an accepting state already passed: the
notes from there on, each a path, close a cycle through accepting states.  The prefix
follows the breadth-first parents to that state.  Labels come from stepping the model
along the path here, as ``search`` does, so the lasso replays.

A complete search stores exactly the reachable product states and edges: the same product
state and transition counts as one process.  The state limit is checked after each level
of the first search (UNKNOWN, as in one process), the time limit between levels.
"""
from __future__ import annotations

from typing import Callable, Optional

from ..budget import SearchBudget
from ..product import Product
from ..result import HOLDS, UNKNOWN, VIOLATED, LassoStep, SearchResult, SearchStats
from ..transition_system import labelled_successors
from .partition import NO_PARENT, SystemSource, unlink
from .product_partition import ELIMINATE, REACH, REGIONS, initial_batch
from .search import actors_of, drop_actors, worker_failures
from .worker import CYCLES, call

ENGINE = "distributed-owcty"


def partitioned_accepting_cycle(ray, partitions: int, system, buchi, valuation,
                                property_name: str, recipe: Callable, *,
                                budget: Optional[SearchBudget] = None,
                                on_level: Optional[Callable[[list], None]] = None) -> tuple:
    """(SearchResult, per-partition figures) for the property named ``property_name``.

    ``recipe``: a picklable function that builds, in a worker's process, the prepared model
    whose ``jobs`` hold that property (``api.model_recipe``); ``system``, ``buchi`` and
    ``valuation`` are this process's, for the initial states and the lasso's labels.
    ``on_level(actors)`` is called before each level of the first search.
    """
    budget = budget if budget is not None else SearchBudget()
    actors = actors_of(ray, partitions)
    shared = ray.put(SystemSource(None, recipe))
    try:
        with worker_failures(ray):
            ray.get([call(actor, CYCLES, "start", index, partitions, shared, property_name, buchi)
                     for index, actor in enumerate(actors)])
            return _Owcty(ray, actors, system, Product(None, buchi), valuation, budget,
                          on_level).run()
    except BaseException:
        drop_actors(ray)
        raise
    finally:
        for actor in actors:
            call(actor, CYCLES, "clear")


class _Owcty:
    def __init__(self, ray, actors, system, product: Product, valuation, budget, on_level):
        self.ray, self.actors, self.system = ray, actors, system
        self.product, self.valuation = product, valuation
        self.budget, self.on_level = budget, on_level
        self.count = len(actors)
        self.depth = 0

    def run(self) -> tuple:
        if not self._reach_all():
            return self._result(UNKNOWN)
        size = sum(self.ray.get([call(actor, CYCLES, "size") for actor in self.actors]))
        while size:
            self.ray.get([call(actor, CYCLES, "reset") for actor in self.actors])
            if not self._spread(REACH):
                return self._result(UNKNOWN)
            self.ray.get([call(actor, CYCLES, "restrict") for actor in self.actors])
            if not self._spread(ELIMINATE):
                return self._result(UNKNOWN)
            left = sum(self.ray.get([call(actor, CYCLES, "size") for actor in self.actors]))
            if left == size:
                break
            size = left
        if not size:
            return self._result(HOLDS)
        return self._result(VIOLATED, self._lasso())

    # --- the breadth-first search of the product -----------------------------------

    def _reach_all(self) -> bool:
        """Store every reachable product state and edge; False at a bound."""
        ray, count, actors = self.ray, self.count, self.actors
        batch = initial_batch(self.system, self.product, self.valuation)
        received = [call(actor, CYCLES, "receive", [-1], batch, returns=count + 1)
                    for actor in actors]
        while True:
            figures = ray.get([refs[count] for refs in received])
            stored, new = sum(f[0] for f in figures), sum(f[1] for f in figures)
            if new and stored > self.budget.max_states:
                self.budget.reason = f"state limit {self.budget.max_states} reached"
                return False
            if new and self.on_level is not None:
                self.on_level(actors)
            expanded = [call(actor, CYCLES, "expand", *[refs[index] for refs in received],
                             returns=count + 1) for index, actor in enumerate(actors)]
            if new:       # (queued before waiting here, as in ``search``)
                senders = list(range(count))
                received = [call(actor, CYCLES, "receive", senders,
                                 *[refs[target] for refs in expanded], returns=count + 1)
                            for target, actor in enumerate(actors)]
            self.transitions = sum(ray.get([refs[count] for refs in expanded]))
            if new == 0:
                return True
            self.depth += 1
            if not self.budget.checkpoint(stored, self.transitions, self.depth):
                return False

    def _spread(self, mode: str) -> bool:
        """Run one spread (``product_partition``) to its end; False at the time limit."""
        ray, count, actors = self.ray, self.count, self.actors
        sent = [call(actor, CYCLES, "propagate", mode, returns=count + 1) for actor in actors]
        while True:
            if not any(ray.get([refs[count] for refs in sent])):
                return True
            if self.budget.max_seconds is not None and \
                    self.budget.elapsed() >= self.budget.max_seconds:
                self.budget.reason = f"time limit {self.budget.max_seconds:g} s reached"
                return False
            sent = [call(actor, CYCLES, "propagate", mode, *[refs[target] for refs in sent],
                         returns=count + 1) for target, actor in enumerate(actors)]

    # --- the lasso -----------------------------------------------------------------------

    def _lasso(self) -> Optional[tuple]:
        """(prefix, cycle, closing label) through an accepting state of S (module
        docstring); None at the time limit."""
        ray, actors = self.ray, self.actors
        ray.get([call(actor, CYCLES, "begin_regions") for actor in actors])
        if not self._spread(REGIONS):
            return None
        notes = {}          # accepting state -> (region the edge leaves, the edge's state)
        for entries in ray.get([call(actor, CYCLES, "entries") for actor in actors]):
            for target, region, before in entries:
                notes[target] = (region, before)
        at, passed = min(notes), set()
        while at not in passed:
            passed.add(at)
            at = notes[at][0]
        return self._path_through(at, notes)

    def _path_through(self, first: int, notes: dict) -> tuple:
        """The lasso through the accepting state ``first`` (a link) whose ``notes`` lead
        back to it: its cycle gathered backwards, region by region."""
        ray, actors = self.ray, self.actors
        backwards, target = [], first
        while True:
            region, at = notes[target]
            while True:                             # from the edge's state up to its region
                backwards.append(unlink(at))
                if at == region:
                    break
                at = ray.get(call(actors[unlink(at)[0]], CYCLES, "region_back", unlink(at)[1]))
            target = region
            if target == first:
                break
        loop = backwards[::-1]                      # ``first``, then forwards
        partition, source = unlink(first)
        prefix = []
        at, parent = (partition, source), None
        while True:
            state, q, parent = ray.get(call(actors[at[0]], CYCLES, "step_back", at[1]))
            prefix.append((state, q))
            if parent == NO_PARENT:
                break
            at = unlink(parent)
        prefix.reverse()
        cycle = [ray.get(call(actors[p], CYCLES, "step_back", i))[:2] for p, i in loop]
        steps = self._labelled(prefix + cycle[1:] + cycle[:1])
        entry = len(prefix) - 1
        cycle_steps = steps[entry:entry + len(cycle)]
        closing_label = steps[entry + len(cycle)].label
        return steps[:entry], cycle_steps, closing_label

    def _labelled(self, path: list) -> list[LassoStep]:
        """LassoSteps along ``path`` ((state, automaton state) pairs), each step's label the
        first model transition between them that the automaton follows."""
        steps = [LassoStep(None, path[0][0], path[0][1])]
        for (state, q), (after, q_after) in zip(path, path[1:]):
            label = next(label for label, target in labelled_successors(self.system, state)
                         if target == after and
                         q_after in self.product.targets(q, self.valuation(after)))
            steps.append(LassoStep(label, after, q_after))
        return steps

    def _result(self, verdict: str, lasso=None) -> tuple:
        figures = self.ray.get([call(actor, CYCLES, "figures") for actor in self.actors])
        stored = sum(f["states"] for f in figures)
        memory = sum(f["bytes"] for f in figures)
        stats = SearchStats(product_states=stored,
                            model_states=sum(f["model_states"] for f in figures),
                            transitions=sum(f["transitions"] for f in figures),
                            max_depth=self.depth,
                            bytes_per_state=memory / stored if stored else 0.0, engine=ENGINE)
        stats.seconds = self.budget.finish()
        if verdict == UNKNOWN:
            return SearchResult(UNKNOWN, self.budget.reason, stats=stats), figures
        if verdict == HOLDS:
            return SearchResult(HOLDS, stats=stats), figures
        if lasso is None:                          # (the time limit, while building it)
            return SearchResult(UNKNOWN, self.budget.reason, stats=stats), figures
        prefix, cycle, closing = lasso
        return SearchResult(VIOLATED, None, prefix, cycle, stats, closing), figures
