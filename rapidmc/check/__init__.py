"""Searching: model × Büchi emptiness, reachability, lassos and traces.

The engine sees only states, transitions and atom valuations
(``transition_system``); RAPID enters through the ``TraceDescriber`` used
when a trace is built.  It imports nothing of RAPID: ``rapidmc.model``
implements its ``TransitionSystem``, ``rapidmc.report`` formats its results.

* ``check_property(system, buchi, valuation, ...)`` — one LTL property
  (``buchi`` is the automaton of its negation) -> ``SearchResult``.
* ``find_reachable(system, predicate, ...)`` — shortest path to a bad state.
"""
from .engine import check_property
from .transition_system import STUTTER, TransitionSystem
from .progress import Progress
from .reachability import find_reachable
from .result import HOLDS, UNKNOWN, VIOLATED, LassoStep, SearchResult, SearchStats
from .trace import TraceDescriber, TransitionInfo

__all__ = [
    "check_property", "find_reachable",
    "TransitionSystem", "STUTTER", "Progress", "HOLDS", "VIOLATED", "UNKNOWN",
    "LassoStep", "SearchResult", "SearchStats", "TraceDescriber", "TransitionInfo",
]
