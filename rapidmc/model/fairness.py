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
* A task that can go on but may also take a step that changes nothing at all (its
  ``WaitDI diGo, 1`` with ``diGo`` at 0) is excused where it may (``idling``): the
  model drops such a step where another task goes on, and the run that puts it back
  at each turn is fair to the task and differs from the lasso only by repeated
  states.  The report then says where the task stands (``idle_only``).
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
        """The tasks a run through ``state`` is fair to without their stepping there:
        those that cannot go on (ended, or waiting: ``waiting``) and those that may take a
        step that changes nothing at all (``idling``)."""
        every = frozenset(range(self.count))
        if state.status != RUNNING:
            return every
        able = frozenset(running_tasks(state)) - self.waiting(state)
        return every - (able - self.idling(state, able))

    def waiting(self, state: State) -> frozenset:
        """The running tasks that cannot go on in the running ``state`` (``task_waits``):
        ``waits(T)`` of ``no_deadlock``."""
        return self.task_waits.waiting(
            state, semantic_successors(self.program, state, self.config))

    def idling(self, state: State, tasks: frozenset) -> frozenset:
        """Those of ``tasks`` that have a step from ``state`` back to ``state``: a task
        at ``WaitDI diGo, 1`` whose step with ``diGo = 0`` changes nothing.  The model
        drops such a step where another task can go on (``idle_steps_dropped``), so a
        lasso never shows it; yet the task may take it at every turn, the environment
        keeping ``diGo`` at 0 for ever, and the run with those steps put back, fair to
        it, differs from the lasso only by repeated states (stuttering).  Without this,
        the fair search would take the step that goes on as the task's only step and
        answer ``F done`` HOLDS."""
        if not tasks:
            return frozenset()
        kept = semantic_successors(self.program, state, self.config.with_idle_steps())
        idle = {task_choosing(self.names, state, transition.label)
                for transition in kept if transition.state == state}
        return tasks & idle

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

    def idle_only(self, steps: list, closing_label: Hashable) -> dict:
        """The tasks a lasso's cycle is fair to only through steps that change nothing
        (``idling``): running in each of its states, never stepping, never waiting.
        Task -> a state of the cycle where it may take such a step."""
        states = [step.state for step in steps]
        if not states or any(state.status != RUNNING for state in states):
            return {}
        labels = [step.label for step in steps[1:]] + [closing_label]
        quiet = frozenset(range(self.count)) - \
            {self.taken(state, label) for state, label in zip(states, labels)}
        for state in states:
            quiet &= frozenset(running_tasks(state)) - self.waiting(state)
        found: dict = {}
        for state in states:
            for task in sorted(self.idling(state, quiet - found.keys())):
                found[task] = state
        return found


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
        return _idle_tasks_said(system, fairness, result)
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
    return _idle_tasks_said(system, fairness, result) if result.verdict == VIOLATED else result


def _idle_tasks_said(system, fairness: TaskFairness, result: SearchResult) -> SearchResult:
    """``result`` (VIOLATED) with a ``reason`` naming where each task the cycle is fair to
    only through steps that change nothing stands (``TaskFairness.idle_only``): the
    loop shows no step of it, and the reader must learn why the run is still fair to
    it."""
    if result.reason is not None or result.cycle is None:
        return result
    idle = fairness.idle_only(result.cycle, result.closing_label)
    parts = []
    for task, state in idle.items():
        described = system.describe_waits(state, only={task})
        if described:
            parts.append(described.removeprefix("waits forever: "))
    if parts:
        result.reason = (f"in the loop, {'; '.join(parts)}: its steps there change nothing "
                         "(what it waits for may never come), while the other tasks go on")
    return result
