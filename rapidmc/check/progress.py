"""A one-line progress display on stderr for searches that take a while.

``states 123,456  transitions 456,789  depth 1,234  45,678 states/s``,
rewritten in place with ``\\r`` about twice a second once a search has run
for a second, and erased when it ends.  Silent when the stream is not a
terminal or ``quiet`` is set, so logs and pipes stay clean.

The engine calls ``update`` only at its budget checkpoints (every few
thousand states), so the display costs nothing per state.
"""
from __future__ import annotations

import sys
import time
from typing import Callable, Optional, TextIO


def progress_line(states: int, transitions: int, depth: int, seconds: float) -> str:
    """The text of one progress report."""
    rate = states / seconds if seconds > 0 else 0.0
    return (f"states {states:,}  transitions {transitions:,}  depth {depth:,}  "
            f"{rate:,.0f} states/s")


class Progress:
    """Prints ``progress_line`` to a terminal, throttled; see the module docstring."""

    def __init__(self, stream: Optional[TextIO] = None, *, quiet: bool = False,
                 delay: float = 1.0, interval: float = 0.5,
                 clock: Callable[[], float] = time.monotonic):
        self.stream = sys.stderr if stream is None else stream
        self.enabled = not quiet and _is_terminal(self.stream)
        self.delay = delay
        self.interval = interval
        self.clock = clock
        self.started = clock()
        self.next_print = self.started + delay
        self.width = 0
        self.note = ""         # appended to the line (a distributed search: per-worker balance)

    def start(self) -> None:
        """Restart the clock (one ``Progress`` may serve several searches)."""
        self.started = self.clock()
        self.next_print = self.started + self.delay

    def update(self, states: int, transitions: int, depth: int) -> None:
        if not self.enabled:
            return
        now = self.clock()
        if now < self.next_print:
            return
        self.next_print = now + self.interval
        line = progress_line(states, transitions, depth, now - self.started)
        if self.note:
            line += "  " + self.note
        padding = " " * max(self.width - len(line), 0)
        self.width = len(line)
        self.stream.write("\r" + line + padding)
        self.stream.flush()

    def finish(self) -> None:
        """Erase the line, if one was printed."""
        if self.width:
            self.stream.write("\r" + " " * self.width + "\r")
            self.stream.flush()
            self.width = 0


def _is_terminal(stream: TextIO) -> bool:
    isatty = getattr(stream, "isatty", None)
    return bool(isatty and isatty())
