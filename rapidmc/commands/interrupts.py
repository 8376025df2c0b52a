"""A first interrupt ends a check with the verdicts it reached; a second one ends it at once.

A CI job's time limit (``timeout 120 rapidmc check ...``) or an engineer's Ctrl-C used to
end the process with nothing printed, losing verdicts reached seconds before.  While a
command runs under ``stop_on_interrupt``, the first SIGINT or SIGTERM asks every search to
stop (``budget.request_stop``): the running one ends UNKNOWN at its next clock reading,
later ones at their first, and the report is written as usual, each verdict cut short
saying why.  A second signal raises ``KeyboardInterrupt`` (``rapidmc: interrupted``, exit
130).  A CPU time limit (``ulimit -t``, ``RLIMIT_CPU``) is met the same way: the kernel sends
SIGXCPU at its soft limit, and again each second until the hard limit ends the process, so
only its first counts; the report is written in the time left before the hard limit.
"""
from __future__ import annotations

import signal
from contextlib import contextmanager

from ..check import budget

SIGNALS = {signal.SIGINT: "SIGINT", signal.SIGTERM: "SIGTERM", signal.SIGXCPU: "SIGXCPU"}


@contextmanager
def stop_on_interrupt():
    """Run the block with the first interrupt asking the searches to stop."""
    def first(number, frame):
        budget.request_stop(f"interrupted by {SIGNALS.get(number, number)}")
        for known in SIGNALS:
            signal.signal(known, again if known == signal.SIGXCPU else second)

    def second(number, frame):
        raise KeyboardInterrupt

    def again(number, frame):
        pass                             # the kernel's repeat of SIGXCPU: the hard limit ends it

    try:
        previous = {known: signal.signal(known, first) for known in SIGNALS}
    except ValueError:                   # not the main thread (an editor's server): as before
        yield
        return
    try:
        yield
    finally:
        for known, handler in previous.items():
            signal.signal(known, handler)
        budget.clear_stop()
