"""A counterexample of the reduced model, re-executed on the unreduced one.

The reduced model stores states with sliced data reset and may run
several instructions per transition.  A counterexample found there is
re-executed step by step by the plain step function: each reduced
transition becomes the unreduced steps that execute the same lines with
the same choices and end in a state the projection maps onto the reduced
one.  The trace then lists every RAPID line executed and the actual value
of every sliced data object.

The reduced loop may close onto a plain state that differs from the loop's
first plain state in data the projection resets (a reply string written in
the loop and dead where the loop starts holds its initial value the first
time round and the last reply after).  The loop is then followed again, up
to ``UNROLLINGS`` times, until it comes back to the plain state at the
start of one of its rounds; the rounds before that one join the prefix.
Only a loop that never closes so (a sliced cycle counter that keeps
counting) closes onto the first round's state, equal in all but the data
the projection resets.
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
        closed = _close(plain, expanded, loop_start, result, project)
        if closed is None:
            return
        expanded, loop_start, closing = closed
        result.prefix, result.cycle = expanded[:loop_start], expanded[loop_start:]
    else:
        result.prefix, result.cycle = expanded, []
    result.closing_label = closing


UNROLLINGS = 8      # further rounds of a reduced loop followed to close it on plain states


def _close(plain, expanded: list, loop_start: int, result: SearchResult,
           project: Callable) -> Optional[tuple[list, int, Hashable]]:
    """(steps, index of the loop's first step, closing label): ``expanded`` (which ends
    after the loop's last step) with the loop followed again until its closing step comes
    back to the plain state of a round's start; None when a step cannot be followed."""
    cycle = result.cycle
    rounds = {expanded[loop_start].state: loop_start}     # plain state -> its round's index
    automaton = cycle[-1].automaton_state
    first_closing = None
    for _ in range(UNROLLINGS + 1):
        path = _follow(plain, expanded[-1].state, result.closing_label, cycle[0].state, project)
        if path is None:
            return None
        if first_closing is None:
            first_closing = expanded, path
        start = rounds.get(path[-1][1])
        if start is None and len(rounds) > UNROLLINGS:
            # it closes in all but data projected away only (a counter that keeps counting)
            (expanded, path), start = first_closing, loop_start
        if start is not None:
            steps = expanded + [LassoStep(label, state, automaton) for label, state in path[:-1]]
            return steps, start, path[-1][0]
        expanded = expanded + [LassoStep(label, state, automaton) for label, state in path[:-1]]
        expanded.append(LassoStep(path[-1][0], path[-1][1], cycle[0].automaton_state))
        rounds[path[-1][1]] = len(expanded) - 1
        for step in cycle[1:]:
            path = _follow(plain, expanded[-1].state, step.label, step.state, project)
            if path is None:
                return None
            expanded.extend(LassoStep(label, state, step.automaton_state)
                            for label, state in path)
    return None


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
