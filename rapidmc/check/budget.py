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
"""
from __future__ import annotations

import time
from typing import Optional

from .collector import freeze_survivors
from .progress import Progress

DEFAULT_MAX_STATES = 1_000_000
FIRST_CHECKPOINT = 16
CHECKPOINT_SECONDS = 0.1
MAX_CHECKPOINT_DISTANCE = 1 << 16


class SearchBudget:
    """The bounds of one search and the clock it started with."""

    def __init__(self, max_states: Optional[int] = DEFAULT_MAX_STATES,
                 max_seconds: Optional[float] = None,
                 progress: Optional[Progress] = None):
        self.max_states = max_states if max_states is not None else float("inf")
        self.max_seconds = max_seconds
        self.progress = progress
        self.started = time.monotonic()
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

    def checkpoint(self, stored: int, transitions: int, depth: int) -> bool:
        """Report progress; False (and ``reason`` set) once the time limit is over."""
        freeze_survivors()
        now = time.monotonic()
        self._adapt_distance(now - self.last_checkpoint)
        self.last_checkpoint = now
        self.next_checkpoint = stored + self.distance
        if self.progress is not None:
            self.progress.update(stored, transitions, depth)
        if self.max_seconds is not None and now - self.started >= self.max_seconds:
            self.reason = f"time limit {self.max_seconds:g} s reached"
            return False
        return True

    def _adapt_distance(self, seconds: float) -> None:
        """Aim the next checkpoint ``CHECKPOINT_SECONDS`` ahead at the speed just seen."""
        states_per_second = self.distance / max(seconds, 1e-6)
        wanted = int(states_per_second * CHECKPOINT_SECONDS)
        self.distance = max(1, min(wanted, self.distance * 4, MAX_CHECKPOINT_DISTANCE))

    def elapsed(self) -> float:
        return time.monotonic() - self.started

    def finish(self) -> float:
        """Clear the progress line; the seconds the search took."""
        if self.progress is not None:
            self.progress.finish()
        return self.elapsed()
