"""Shortening a lasso as the programmer sees it: model states only.

The search finds a lasso in the product with the automaton, so the same
model loop may appear once in the prefix (automaton still waiting) and
again as the cycle (automaton accepting).  Without the automaton states,
``prefix · cycle^ω`` is one infinite sequence of model states, and any
lasso spelling the same sequence is an equally valid counterexample.
``fold_lasso`` finds a shorter spelling:

* roll the loop back while the last prefix state equals the last cycle
  state (``p q | r q`` becomes ``p | q r``);
* cut a cycle that repeats itself (``a b a b`` becomes ``a b``).

Labels move with the transitions they name, so every step is still a
real model transition.  The automaton states are dropped (set to the
``NO_AUTOMATON`` marker): they no longer describe a run.
"""
from __future__ import annotations

from dataclasses import replace
from typing import Hashable, Optional

from .result import NO_AUTOMATON, LassoStep

Lasso = tuple[list[LassoStep], list[LassoStep], Optional[Hashable]]


def fold_lasso(prefix: list[LassoStep], cycle: list[LassoStep], closing: Optional[Hashable]) -> Lasso:
    """The shortest lasso found by rolling back and de-repeating; see the module docstring."""
    prefix = [replace(step, automaton_state=NO_AUTOMATON) for step in prefix]
    cycle = [replace(step, automaton_state=NO_AUTOMATON) for step in cycle]
    if not cycle:
        return prefix, cycle, closing
    while prefix and prefix[-1].state == cycle[-1].state:
        closing = cycle[-1].label
        cycle = [prefix.pop()] + cycle[:-1]
    period = _period(cycle)
    if period < len(cycle):
        closing = cycle[period].label
        cycle = cycle[:period]
    return prefix, cycle, closing


def _period(cycle: list[LassoStep]) -> int:
    """The least p dividing len(cycle) such that the states repeat with period p."""
    states = [step.state for step in cycle]
    size = len(states)
    for period in range(1, size):
        if size % period == 0 and all(states[i] == states[i - period] for i in range(period, size)):
            return period
    return size
