"""Search bounds: how many states may be stored and for how long, plus progress.

Both searches (emptiness and reachability) ask ``may_store`` before storing
a new state and call ``checkpoint`` when their count reaches
``next_checkpoint``; only there is the clock read, so a bound costs one
integer comparison per state.
"""
from __future__ import annotations

import time
from typing import Optional

from .progress import Progress

DEFAULT_MAX_STATES = 1_000_000
CHECK_EVERY = 2048


class SearchBudget:
    """The bounds of one search and the clock it started with."""

    def __init__(self, max_states: Optional[int] = DEFAULT_MAX_STATES,
                 max_seconds: Optional[float] = None,
                 progress: Optional[Progress] = None):
        self.max_states = max_states if max_states is not None else float("inf")
        self.max_seconds = max_seconds
        self.progress = progress
        self.started = time.monotonic()
        self.next_checkpoint = CHECK_EVERY
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
        self.next_checkpoint = stored + CHECK_EVERY
        if self.progress is not None:
            self.progress.update(stored, transitions, depth)
        if self.max_seconds is not None and self.elapsed() >= self.max_seconds:
            self.reason = f"time limit {self.max_seconds:g} s reached"
            return False
        return True

    def elapsed(self) -> float:
        return time.monotonic() - self.started

    def finish(self) -> float:
        """Clear the progress line; the seconds the search took."""
        if self.progress is not None:
            self.progress.finish()
        return self.elapsed()
