"""A counterexample of the reduced model, re-executed on the unreduced one.

The reduced model stores states with sliced data reset and may run
several instructions per transition.  A counterexample found there is
re-executed step by step by the plain step function: each reduced
transition becomes the unreduced steps that execute the same lines with
the same choices and end in a state the projection maps onto the reduced
one.  The trace then lists every RAPID line executed and the actual value
of every sliced data object.  The loop closes onto a state equal to the
loop's first state in everything but sliced data (a cycle counter, say,
keeps counting).
"""
from __future__ import annotations

from typing import Callable, Hashable, Optional

from ...check.transition_system import STUTTER
from ...check.result import LassoStep, SearchResult
from .merging import executed_spans

Path = list[tuple[Hashable, Hashable]]


def expand_lasso(system, result: SearchResult) -> None:
    """Replace ``result``'s lasso by its unreduced counterpart (unchanged if none is found)."""
    if not system.plan.active or not result.prefix + result.cycle:
        return
    plain = system.unreduced()
    project: Callable = system.project or (lambda state: state)
    steps = result.prefix + result.cycle
    start = next((s for s in plain.initial_states() if project(s) == steps[0].state), None)
    if start is None:
        return
    expanded = [LassoStep(None, start, steps[0].automaton_state)]
    loop_start = 0
    for position, step in enumerate(steps[1:], start=1):
        path = _follow(plain, expanded[-1].state, step.label, step.state, project)
        if path is None:
            return
        expanded.extend(LassoStep(label, state, step.automaton_state) for label, state in path)
        if position == len(result.prefix):
            loop_start = len(expanded) - 1
    closing = result.closing_label
    if result.cycle:
        path = _follow(plain, expanded[-1].state, closing, result.cycle[0].state, project)
        if path is None:
            return
        automaton = result.cycle[-1].automaton_state
        expanded.extend(LassoStep(label, state, automaton) for label, state in path[:-1])
        closing = path[-1][0]
        result.prefix, result.cycle = expanded[:loop_start], expanded[loop_start:]
    else:
        result.prefix, result.cycle = expanded, []
    result.closing_label = closing


def _follow(plain, state, label, target, project: Callable) -> Optional[Path]:
    """Unreduced steps from ``state`` that make the reduced transition ``label`` to ``target``."""
    if label is None or label is STUTTER:
        return [(label, state)]
    choices, span, _ = label
    spans = list(executed_spans(span))
    choices = tuple(choices)

    def search(at, depth: int, chosen: tuple) -> Optional[Path]:
        for step_label, successor in plain.successors(at):
            step_choices, step_span, _ = step_label
            made = chosen + tuple(step_choices)
            if step_span != spans[depth] or made != choices[:len(made)]:
                continue
            if depth + 1 == len(spans):
                if made == choices and project(successor) == target:
                    return [(step_label, successor)]
                continue
            rest = search(successor, depth + 1, made)
            if rest is not None:
                return [(step_label, successor)] + rest
        return None

    return search(state, 0, ())
