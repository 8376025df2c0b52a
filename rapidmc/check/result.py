"""The outcome of a search: three-valued verdict, lasso-shaped path, statistics.

``HOLDS`` only when the search was exhaustive; a bound reached without a
violation gives ``UNKNOWN`` with the bound as ``reason`` (never ``HOLDS``).
A ``VIOLATED`` result carries a lasso: ``prefix`` leads from an initial
state to ``cycle[0]``; the successor of ``cycle[-1]`` is ``cycle[0]``,
reached by the transition labelled ``closing_label``.  Reachability
results have an empty cycle and ``closing_label`` None; their ``ending`` may
say, in words, what is wrong in the last state (an uncaught error, a wait
that never ends).  So does a property's bad prefix: an empty cycle, and
``ending`` ``BAD_PREFIX`` (every run that goes on from its last state violates
the property).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Hashable, NamedTuple, Optional

HOLDS = "HOLDS"
VIOLATED = "VIOLATED"
UNKNOWN = "UNKNOWN"

BAD_PREFIX = "every run that goes on from this step violates the property"
"""``SearchResult.ending`` of a property violated by a finite path (a bad prefix): the
automaton of its negation accepts whatever follows (``check.emptiness``)."""

NO_AUTOMATON = -1
"""``LassoStep.automaton_state`` of paths found without an automaton (reachability)."""


@dataclass
class LassoStep:
    """One state of a path and the transition label that led into it (None: initial)."""

    label: Optional[Hashable]
    state: Hashable
    automaton_state: int


@dataclass
class SearchStats:
    """What a search stored and explored, and how long it took."""

    product_states: int = 0
    model_states: int = 0
    transitions: int = 0
    max_depth: int = 0
    seconds: float = 0.0
    deadlocks: int = 0
    bytes_per_state: float = 0.0     # memory of the stored states and search structures
    engine: str = "python"           # "native" when the compiled core ran it (check.native)

    @property
    def states_per_second(self) -> float:
        return self.product_states / self.seconds if self.seconds > 0 else 0.0

    def as_dict(self) -> dict:
        return {
            "product_states": self.product_states,
            "model_states": self.model_states,
            "transitions": self.transitions,
            "max_depth": self.max_depth,
            "seconds": round(self.seconds, 3),
            "states_per_second": round(self.states_per_second),
            "deadlocks": self.deadlocks,
            "bytes_per_state": round(self.bytes_per_state),
            "engine": self.engine,
        }


class TaskPlace(NamedTuple):
    """Where a task stands in a state: its routine and the statement it runs next."""

    task: str
    routine: str                      # "" for a task that has ended
    file: str
    line: int
    statement: str                    # the source line, stripped


@dataclass
class SearchResult:
    """Verdict of one search; see the module docstring for the path shape."""

    verdict: str
    reason: Optional[str] = None
    prefix: list[LassoStep] = field(default_factory=list)
    cycle: list[LassoStep] = field(default_factory=list)
    stats: SearchStats = field(default_factory=SearchStats)
    closing_label: Optional[Hashable] = None
    ending: Optional[str] = None      # a path's last state, in words (safety violations)
    # UNKNOWN of a breadth-first search: the last state it stored (one of the deepest), until
    # the model says where its tasks stand in ``deepest``
    frontier: Optional[Hashable] = None
    deepest: tuple = ()               # (TaskPlace, ...) of ``frontier``, one per task
