"""Clocks: stop-watches for timing, (running, started at, accumulated seconds).

``run`` keeps virtual time (it advances in waits), so ClkRead gives the exact elapsed
virtual time there. When model checking, time is abstracted away (the state's clock stays
0), and how long a clock ran is the controller's decision: ClkRead is a nondeterministic
choice. A clock that never ran since it was reset (or since the start) reads 0, exactly as
on the controller. A clock that runs, or ran, reads one of 0.001 s (its resolution: a clock
that ran is assumed to have run at least that long), 1 s and 86400 s (a day), so both
branches of a comparison with a time limit between them are explored and an elapsed time
used as a divisor is never a false division by zero. ClkReset, ClkStart and ClkStop are exact.
"""
from __future__ import annotations

from .. import values
from ..expressions import Compiled
from ..instructions import Action, Instruction
from ..types import NUM
from .arguments import Arguments
from .environment_model import where
from .registry import CHOICE, compiled

RESOLUTION = 0.001
# what a clock that ran may read when model checking (seconds)
CHECKED_READINGS = tuple(values.to_num(seconds) for seconds in (RESOLUTION, 1.0, 86400.0))
SAMPLED_READINGS_TEXT = "0.001 s, 1 s or 86400 s (a clock that ran)"


def _clock_action(calls, compiler, call, entry, update) -> Instruction:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    return Action(call.span, lambda m: m.write_ref(ref(m), update(m, m.read_ref(ref(m)))))


def _elapsed(m, clock) -> float:
    running, started, accumulated = clock
    return accumulated + (m.clock - started if running else 0.0)


def _stopped(m, clock) -> tuple:
    """The clock stopped; when checking, one that ran keeps at least its resolution."""
    elapsed = _elapsed(m, clock)
    if m.chooser.check_mode and clock[0]:
        elapsed = max(elapsed, RESOLUTION)
    return (False, m.clock, elapsed)


@compiled("ClkReset(VAR clock Clock)")
def _clk_reset(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: (clock[0], m.clock, 0.0))


@compiled("ClkStart(VAR clock Clock)")
def _clk_start(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: clock if clock[0] else (True, m.clock, clock[2]))


@compiled("ClkStop(VAR clock Clock)")
def _clk_stop(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: _stopped(m, clock) if clock[0] else clock)


@compiled("num ClkRead(VAR clock Clock \\switch HighRes)",
          modelled=CHOICE)
def _clk_read(calls, compiler, call, entry) -> Compiled:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    name = f"ClkRead at {where(call.span)}"

    def read(m):
        clock = m.read_ref(ref(m))
        if m.chooser.check_mode and (clock[0] or clock[2] > 0.0):
            return m.choose(name, CHECKED_READINGS)
        return values.to_num(round(_elapsed(m, clock), 3))
    return Compiled(read, NUM)
