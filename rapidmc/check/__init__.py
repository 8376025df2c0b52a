"""Model checking: model × Büchi emptiness, reachability, traces and reports.

The engine sees only states, transitions and atom valuations (``model``);
RAPID enters through the ``TraceDescriber`` used when reporting.

* ``check_property(system, buchi, valuation, ...)`` — one LTL property
  (``buchi`` is the automaton of its negation) -> ``SearchResult``.
* ``find_reachable(system, predicate, ...)`` — shortest path to a bad state.
* ``format_text(results, describer)`` / ``format_json(results, describer)``
  over ``PropertyResult(name, formula, result)`` values.
"""
from .engine import check_property
from .model import STUTTER, TransitionSystem
from .progress import Progress
from .reachability import find_reachable
from .report import PropertyResult, format_json, format_text
from .result import HOLDS, UNKNOWN, VIOLATED, LassoStep, SearchResult, SearchStats
from .trace import TraceDescriber, TransitionInfo

__all__ = [
    "check_property", "find_reachable", "format_text", "format_json", "PropertyResult",
    "TransitionSystem", "STUTTER", "Progress", "HOLDS", "VIOLATED", "UNKNOWN",
    "LassoStep", "SearchResult", "SearchStats", "TraceDescriber", "TransitionInfo",
]
