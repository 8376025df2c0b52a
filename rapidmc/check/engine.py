"""One call per property: ``check_property(system, buchi, valuation)``.

``buchi`` is the automaton of the NEGATED property (``rapidmc.ltl.to_buchi``
of ``!φ``): the property is violated exactly when model × automaton has a
reachable accepting cycle.

Example::

    result = check_property(system, to_buchi(parse_formula('!(G F "done")')),
                            valuation, max_states=100_000)
    result.verdict            # "HOLDS", "VIOLATED" or "UNKNOWN"
    result.prefix, result.cycle   # the counterexample lasso when VIOLATED
"""
from __future__ import annotations

from typing import Optional

from .budget import DEFAULT_MAX_STATES, SearchBudget
from .collector import frozen_while_searching
from .emptiness import search_accepting_cycle
from .graph_store import ExploredGraph, GraphStore
from .hashed import hashed_accepting_cycle, visited_sets
from .transition_system import TransitionSystem, Valuation
from .product import Product
from .progress import Progress
from .result import SearchResult
from .store import ModelStore


def check_property(system: TransitionSystem, buchi, valuation: Valuation, *,
                   max_states: Optional[int] = DEFAULT_MAX_STATES,
                   max_seconds: Optional[float] = None,
                   progress: Optional[Progress] = None,
                   storage: Optional[tuple] = None,
                   explored: Optional[ExploredGraph] = None) -> SearchResult:
    """Search model × ``buchi`` for an accepting lasso; see the module docstring.

    ``storage``: None to store every state, else ``(COMPACT,)`` or ``(BITSTATE, bytes)``
    (``hashed``: visited states remembered by hash; no violation found is UNKNOWN).
    ``explored``: the whole state graph of ``system``, as a complete search of it found
    it (``find_reachable``'s ``explored``): the model is not stepped again.
    """
    budget = SearchBudget(max_states, max_seconds, progress)
    with frozen_while_searching():
        if storage is not None:
            outer, inner = visited_sets(storage, 2)
            return hashed_accepting_cycle(system, buchi, valuation, outer, inner, budget)
        if explored is not None and explored.system is not system:
            raise ValueError("the explored graph is another system's")
        store = ModelStore(system, valuation) if explored is None else \
            GraphStore(explored, valuation)
        product = Product(store, buchi)
        return search_accepting_cycle(product, budget)
