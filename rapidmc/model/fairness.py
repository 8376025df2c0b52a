"""Weak fairness between RAPID tasks: which task took a step, which tasks cannot go on.

A controller shares its time between its tasks, so a task that can go on
does run again: an infinite run in which a task stays able to go on and
never steps is not a run of the controller.  ``check.fair`` searches only
runs where every task steps infinitely often or is infinitely often unable
to go on.

* The task of a step is the ``task`` choice of its label (``input: task =
  ...`` in traces); when only one task is left running there is no choice,
  and the step is that task's.
* A task cannot go on in a state when the program has stopped, the task has
  ended, or it waits: each of its steps would change nothing of its own, at most
  the inputs the environment chose and the interrupts their edges queue for other
  tasks (``task_waits``, the one definition) — on the semantic successors of the
  state, before any reduction's projection.
"""
from __future__ import annotations

from typing import Hashable, Optional

from ..check import UNKNOWN, VIOLATED, Progress, SearchResult, check_property
from ..check.fair import check_fair_property
from ..check.transition_system import STUTTER
from ..semantics.state import RUNNING, State
from ..semantics.step import successors as semantic_successors
from .task_waits import TASK_CHOICE, TaskWaits, running_tasks, task_choosing

__all__ = ["TASK_CHOICE", "TaskFairness", "assumes_fairness", "fair_or_plain_search",
           "running_tasks"]


class TaskFairness:
    """The fairness constraints (one per task) of a ``RapidSystem``, for ``check.fair``."""

    def __init__(self, system):
        self.program = system.program
        self.config = system.config
        self.names = tuple(system.program.task_names)
        self.count = len(self.names)
        self.task_waits = TaskWaits(system.program, system.config)

    def taken(self, state: State, label: Hashable) -> Optional[int]:
        """The index of the task that took the step ``label`` from ``state`` (None: none)."""
        if label is STUTTER or label is None:
            return None
        return task_choosing(self.names, state, label[0])

    def excused(self, state: State) -> frozenset:
        """The tasks that cannot go on in ``state``: ended, or waiting (``task_waits``)."""
        every = frozenset(range(self.count))
        if state.status != RUNNING:
            return every
        waiting = self.task_waits.waiting(
            state, semantic_successors(self.program, state, self.config))
        return every - (frozenset(running_tasks(state)) - waiting)

    def unfair_tasks(self, steps: list, closing_label: Hashable) -> list[str]:
        """The tasks a lasso's cycle starves: able to go on in each of its states, never
        stepping (``steps``: the cycle's ``LassoStep``s).  Empty for a fair cycle, and for a
        bad prefix (no cycle): every run that goes on from its end violates the property,
        the runs fair to every task among them."""
        if not steps:
            return []
        states = [step.state for step in steps]
        labels = [step.label for step in steps[1:]] + [closing_label]
        met = {self.taken(state, label) for state, label in zip(states, labels)}
        for state in states:
            met |= self.excused(state)
        return [name for index, name in enumerate(self.names) if index not in met]


def assumes_fairness(model) -> bool:
    """Whether a prepared ``api.Model`` is searched fairly: several tasks, not --no-fairness."""
    return model.options.fairness and len(model.program.task_names) > 1


def fair_or_plain_search(system, buchi, valuation, fairness: Optional[TaskFairness],
                         progress: Optional[Progress], bounds: dict,
                         first: Optional[SearchResult] = None) -> SearchResult:
    """One property's search: fair to the tasks when ``fairness`` is given.

    Today's search runs first: fairness only removes runs, so its HOLDS stands,
    and so does a counterexample whose cycle starves no task (a safety
    property's, or any the search happens to find fair).  Only a
    counterexample that starves a task calls for the fair search
    (``check.fair``).  --compact / --bitstate searches (``bounds["storage"]``)
    cannot look for fair cycles; they never answer HOLDS anyway, and a
    counterexample of theirs that starves a task is no answer: UNKNOWN.
    ``first``: today's search's result when it ran elsewhere (on a Ray cluster).
    """
    result = first if first is not None else \
        check_property(system, buchi, valuation, progress=progress, **bounds)
    if fairness is None or result.verdict != VIOLATED:
        return result
    starved = fairness.unfair_tasks(result.cycle, result.closing_label)
    if not starved:
        return result
    if bounds.get("storage") is not None:
        return SearchResult(UNKNOWN, f"the cycle found starves {', '.join(starved)}; this "
                            "search cannot look for cycles fair to every task",
                            stats=result.stats)
    # ample sets keep the verdicts of all runs, not of the fair ones: the fair search
    # takes every interleaving
    result = check_fair_property(system.full_interleaving(), buchi, valuation, fairness,
                                 progress=progress,
                                 max_states=bounds.get("max_states"),
                                 max_seconds=bounds.get("max_seconds"))
    if result.verdict == VIOLATED and fairness.unfair_tasks(result.cycle, result.closing_label):
        raise RuntimeError("internal error: the fair search found a cycle that starves a task")
    return result
