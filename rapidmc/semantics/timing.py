"""Virtual time: timers, delayed signal changes, and interruptible waits.

In ``run`` mode the state's clock advances only when the program waits
(WaitTime, a \\MaxTime limit, or a wait that only a timer can end);
timer interrupts and delayed signal changes (PulseDO, SetDO \\SDelay) happen
at their due times.  When model checking, time is abstracted away: the
clock stays 0, timers may fire at any step and delayed signal changes take
effect at the next step.
"""
from __future__ import annotations

from typing import Optional

from .machine import Machine

EPSILON = 1e-9


def enqueue(m: Machine, number: int) -> None:
    pending = m.interrupts.pending
    if number not in pending:
        m.interrupts = m.interrupts._replace(pending=pending + (number,))


def schedule(m: Machine, delay: float, index: int, value: float) -> None:
    """Set signal ``index`` to ``value`` after ``delay`` seconds."""
    entry = (m.clock + delay, index, float(value))
    m.interrupts = m.interrupts._replace(
        scheduled=tuple(sorted(m.interrupts.scheduled + (entry,))))


def apply_scheduled(m: Machine, until: Optional[float] = None) -> None:
    """Carry out the delayed signal changes due by ``until`` (all of them if None)."""
    remaining = []
    for due, index, value in m.interrupts.scheduled:
        if until is None or due <= until + EPSILON:
            m.io = m.io.set(index, value)
        else:
            remaining.append((due, index, value))
    m.interrupts = m.interrupts._replace(scheduled=tuple(remaining))


def fire_timers(m: Machine) -> None:
    """Enqueue every timer interrupt due at the current clock; compute its next due time."""
    table = list(m.interrupts.table)
    for i, entry in enumerate(table):
        if entry.active and entry.source and entry.source[0] == "timer":
            _, period, once = entry.source
            if entry.due <= m.clock + EPSILON:
                enqueue(m, entry.number)
                due = entry.due
                while due <= m.clock + EPSILON and period > 0:
                    due += period
                table[i] = entry._replace(due=due)
    m.interrupts = m.interrupts._replace(table=tuple(table))


def next_event(interrupts) -> Optional[float]:
    """The earliest due time of an active timer or a delayed signal change."""
    dues = [e.due for e in interrupts.table
            if e.active and e.source and e.source[0] == "timer"]
    dues.extend(due for due, _, _ in interrupts.scheduled)
    return min(dues) if dues else None


def advance_to(m: Machine, time: float) -> None:
    """Let virtual time pass up to ``time``: timers fire, delayed changes happen."""
    m.clock = max(m.clock, time)
    apply_scheduled(m, m.clock)
    fire_timers(m)
