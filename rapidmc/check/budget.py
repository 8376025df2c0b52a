"""Search bounds: how many states may be stored and for how long, plus progress.

Both searches (emptiness and reachability) ask ``may_store`` before storing
a new state and call ``checkpoint`` when their count reaches
``next_checkpoint``; only there is the clock read, so a bound costs one
integer comparison per state.  The distance between checkpoints adapts to
the speed of the model (a RAPID step function may be a thousand times
slower than a toy model) so that the clock is read about ten times a
second: often enough for the progress line and the time limit, rarely
enough to cost nothing.  A checkpoint also puts the objects the search has
kept so far out of the cycle collector's reach (``collector``).

Checkpoints come with new states only, so a search whose expansions find few
new states (thousands of successors that are mostly known), or one step with
thousands of successors, would run far past its time limit.  So the model's
successor generation calls ``time_check`` between two runs of a step: it
reads the clock of the running search's budget and raises ``OutOfTime`` once
its time is over; the search catches it (``stopped_in_time``) and ends
UNKNOWN at the time limit, like a checkpoint would.  The clock is injectable,
so tests count clock readings instead of timing.
"""
from __future__ import annotations

import time
from contextlib import contextmanager
from typing import Callable, Optional

from .collector import freeze_survivors
from .progress import Progress

DEFAULT_MAX_STATES = 1_000_000
FIRST_CHECKPOINT = 16
CHECKPOINT_SECONDS = 0.1
MAX_CHECKPOINT_DISTANCE = 1 << 16
BAD_PREFIX_GRACE = 10_000       # states a search goes on storing after it saw a bad prefix

# the clock of budgets made without one (tests put a counter here)
default_clock: Callable[[], float] = time.monotonic


# why every search stops now (``request_stop``: the user interrupted the check), else None
stop_requested: Optional[str] = None


def request_stop(reason: str) -> None:
    """End the running search and every later one at their next clock reading, each with
    ``reason`` as its bound (UNKNOWN): what a first interrupt does, so the verdicts already
    reached are still reported."""
    global stop_requested
    stop_requested = reason


def clear_stop() -> None:
    global stop_requested
    stop_requested = None


class OutOfTime(Exception):
    """The running search's time limit is over (raised by ``time_check``)."""


class SearchBudget:
    """The bounds of one search and the clock it started with."""

    def __init__(self, max_states: Optional[int] = DEFAULT_MAX_STATES,
                 max_seconds: Optional[float] = None,
                 progress: Optional[Progress] = None,
                 clock: Optional[Callable[[], float]] = None):
        self.max_states = max_states if max_states is not None else float("inf")
        self.max_seconds = max_seconds
        self.progress = progress
        self.clock = clock if clock is not None else default_clock
        self.started = self.clock()
        self.last_checkpoint = self.started
        self.distance = FIRST_CHECKPOINT
        self.next_checkpoint = FIRST_CHECKPOINT
        self.reason: Optional[str] = None
        if progress is not None:
            progress.start()

    def may_store(self, stored: int) -> bool:
        """False (and ``reason`` set) once ``stored`` states fill the state limit."""
        if stored < self.max_states:
            return True
        self.reason = f"state limit {self.max_states} reached"
        return False

    def saw_bad_prefix(self, stored: int) -> None:
        """A property search with ``stored`` states saw a bad prefix (``check.emptiness``):
        it goes on for at most ``BAD_PREFIX_GRACE`` more states, to find a loop (a lasso
        as before: on a finite state space one follows), then stops with the finite path
        instead of searching a model that keeps making new states to its bound."""
        self.max_states = min(self.max_states, stored + BAD_PREFIX_GRACE)

    def checkpoint(self, stored: int, transitions: int, depth: int) -> bool:
        """Report progress; False (and ``reason`` set) once the time limit is over."""
        freeze_survivors()
        now = self.clock()
        self._adapt_distance(now - self.last_checkpoint)
        self.last_checkpoint = now
        self.next_checkpoint = stored + self.distance
        if self.progress is not None:
            self.progress.update(stored, transitions, depth)
        if stop_requested is not None:
            self.reason = stop_requested
            return False
        if self.max_seconds is not None and now - self.started >= self.max_seconds:
            self.reason = f"time limit {self.max_seconds:g} s reached"
            return False
        return True

    def _adapt_distance(self, seconds: float) -> None:
        """Aim the next checkpoint ``CHECKPOINT_SECONDS`` ahead at the speed just seen."""
        states_per_second = self.distance / max(seconds, 1e-6)
        wanted = int(states_per_second * CHECKPOINT_SECONDS)
        self.distance = max(1, min(wanted, self.distance * 4, MAX_CHECKPOINT_DISTANCE))

    def over_time(self) -> bool:
        """Whether the time limit is over or a stop was requested (``reason`` set then);
        reads the clock."""
        if stop_requested is not None and self.reason is None:
            self.reason = stop_requested
        if self.max_seconds is None or self.reason is not None:
            return self.reason is not None
        if self.clock() - self.started >= self.max_seconds:
            self.reason = f"time limit {self.max_seconds:g} s reached"
        return self.reason is not None

    def elapsed(self) -> float:
        return self.clock() - self.started

    def finish(self) -> float:
        """Clear the progress line; the seconds the search took."""
        if self.progress is not None:
            self.progress.finish()
        return self.elapsed()


_running: Optional[SearchBudget] = None     # the budget of the search running its loop


def time_check() -> None:
    """Raise ``OutOfTime`` when the running search has a time limit and it is over, or a
    stop was requested: what a model's successor generation calls between two runs of a
    step."""
    budget = _running
    if budget is not None and (budget.max_seconds is not None or stop_requested is not None) \
            and budget.over_time():
        raise OutOfTime(budget.reason)


@contextmanager
def stopped_in_time(budget: SearchBudget):
    """Run a search's loop with ``budget`` as the running one (``time_check`` reads it); an
    ``OutOfTime`` from the successor generation ends the loop with the budget's ``reason``
    set (the caller's result is UNKNOWN).  Outside such a loop (a counterexample's steps
    described after the search) ``time_check`` never raises."""
    global _running
    outer, _running = _running, budget
    try:
        yield
    except OutOfTime:
        if budget.reason is None:       # another search's budget ran out: not ours
            raise
    finally:
        _running = outer
