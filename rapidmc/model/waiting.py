"""Tasks that wait forever while the others go on: ``no_deadlock`` with several tasks.

With one task, the program waits forever when no step changes anything
(``RapidSystem.stuck``).  With several, one task may wait forever while the
others go on: a task whose partner never reaches its ``WaitSyncTask``, or that
waits for a flag no other task sets while a background task loops.  Such a
run is a run of the controller (weak fairness lets a task that cannot go on
wait), so the check searches for it: a fair run satisfying

    F G waits(T1)  |  F G waits(T2)  |  ...

where ``waits(T)`` holds in a state when task T is running and cannot go on
(``TaskFairness.waiting``: each of its steps would change nothing of its own, at most
the inputs the environment chose and the interrupts they queue for other tasks:
``task_waits``, the same in every model of the inputs).  A task
waiting for a free input can go on (some input value lets it), so it never
waits forever in this sense: inputs are free to come.
"""
from __future__ import annotations

from functools import reduce
from typing import Optional

from ..check import VIOLATED, Progress, SearchResult
from ..ltl import to_buchi
from ..ltl.syntax import Atom, Finally, Globally, Or
from ..semantics.state import RUNNING, State
from .fairness import TaskFairness, fair_or_plain_search


def waits_forever(system, bounds: dict, progress: Optional[Progress]) -> SearchResult:
    """A fair lasso in which some task waits forever (VIOLATED, its ``reason`` naming the
    task and where it waits), or HOLDS / UNKNOWN as the search ends."""
    fairness = TaskFairness(system)
    atoms = tuple(f"waits({name})" for name in fairness.names)
    formula = reduce(Or, [Finally(Globally(Atom(atom))) for atom in atoms])
    buchi = to_buchi(formula, backend="builtin", atoms=atoms)
    order = [atoms.index(atom) for atom in buchi.atoms]
    valuation = _waiting_valuation(fairness, order)
    result = fair_or_plain_search(system, buchi, valuation, fairness, progress,
                                  {key: value for key, value in bounds.items()
                                   if key != "explored"})
    if result.verdict == VIOLATED:
        result.reason = _reason(system, fairness, result)
    return result


def _waiting_valuation(fairness: TaskFairness, order: list[int]):
    """``fn(state) -> int``: bit i set when the task of the automaton's atom i waits."""
    remembered: dict = {}

    def valuation(state: State) -> int:
        bits = remembered.get(state)
        if bits is None:
            waiting = waiting_tasks(fairness, state)
            bits = sum(1 << position for position, task in enumerate(order) if task in waiting)
            if len(remembered) < 1 << 16:
                remembered[state] = bits
        return bits
    return valuation


def waiting_tasks(fairness: TaskFairness, state: State) -> set[int]:
    """The running tasks that cannot go on in ``state``."""
    if state.status != RUNNING:
        return set()
    return set(fairness.waiting(state))


def _reason(system, fairness: TaskFairness, result: SearchResult) -> str:
    """``T_ROB1 waits forever at FILE:LINE (...) for T_ROB2, while the others go on``."""
    states = [step.state for step in result.cycle] or [result.prefix[-1].state]
    waiting = set.intersection(*(waiting_tasks(fairness, state) for state in states))
    described = system.describe_waits(states[0], only=waiting)
    return f"{described}, while the other tasks go on" if described else \
        "a task waits forever while the others go on"

