"""The states of a system in breadth-first order, for tests that compare something in each."""
from __future__ import annotations

from collections import deque
from typing import Iterator


def breadth_first(system, limit: int) -> Iterator[tuple]:
    """(state, its labelled successors) for each state ``system`` reaches, up to ``limit``
    states, breadth first."""
    seen: set = set()
    pending = deque(system.initial_states())
    while pending and len(seen) < limit:
        state = pending.popleft()
        if state in seen:
            continue
        seen.add(state)
        successors = system.successors(state)
        pending.extend(after for _, after in successors)
        yield state, successors
