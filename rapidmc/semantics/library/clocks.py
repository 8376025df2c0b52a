"""Clocks: (running, started at, accumulated seconds) in virtual time."""
from __future__ import annotations

from .. import values
from ..expressions import Compiled
from ..instructions import Action, Instruction
from ..types import NUM
from .arguments import Arguments
from .registry import compiled


def _clock_action(calls, compiler, call, entry, update) -> Instruction:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    return Action(call.span, lambda m: m.write_ref(ref(m), update(m, m.read_ref(ref(m)))))


def _elapsed(m, clock) -> float:
    running, started, accumulated = clock
    return accumulated + (m.clock - started if running else 0.0)


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
                         lambda m, clock: (False, m.clock, _elapsed(m, clock)))


@compiled("num ClkRead(VAR clock Clock \\switch HighRes)")
def _clk_read(calls, compiler, call, entry) -> Compiled:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    return Compiled(lambda m: values.to_num(round(_elapsed(m, m.read_ref(ref(m))), 3)), NUM)

