"""From a lasso of model states to the steps a robot programmer reads.

The RAPID specifics come from a ``TraceDescriber`` the caller implements:
what every global data object, signal and robot item looks like in a
state, and where a transition is in the source, what it chose and wrote.
This module only compares consecutive states so that each step lists
only what changed (the first step lists every value once).

A describer may also say where the run is (``describe_stack``): the
call stack each step's statement executes in, for viewers that show it.

Shape of a trace: ``prefix`` steps, then ``cycle`` steps, then ``closing``
(the transition from the last cycle state back to the state of the first
cycle step).  Steps are numbered from 1 across all three.
"""
from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Hashable, Mapping, Optional, Protocol

from .fold import fold_lasso
from .transition_system import STUTTER
from .result import LassoStep, SearchResult

INITIAL = "initial"
TRANSITION = "transition"
STUCK = "stuck"
STUCK_SOURCE = "(no statement can execute: the program is stuck and stays in this state)"


@dataclass(frozen=True)
class TransitionInfo:
    """What one model transition did, in source terms."""

    file: Optional[str]
    line: Optional[int]
    source: str
    inputs: Mapping[str, str] = field(default_factory=dict)
    output: str = ""

    @property
    def location(self) -> str:
        """``file:line``, or empty when the transition has no source position."""
        if self.file is None:
            return ""
        return f"{self.file}:{self.line}" if self.line else self.file


@dataclass(frozen=True)
class CallFrame:
    """One active routine: its name, the line it is at, and its task (empty with one task)."""

    routine: str
    file: Optional[str]
    line: Optional[int]
    task: str = ""


class TraceDescriber(Protocol):
    """Printable views of model states and labels, supplied by the caller.

    Optional: ``describe_stack(state) -> tuple[CallFrame, ...]`` (outermost
    routine first); without it, steps carry an empty stack.  Optional:
    ``absent_values``, the value of a name while ``describe_state`` leaves it out.
    """

    def describe_state(self, state: Hashable) -> Mapping[str, str]: ...

    def describe_transition(self, label: Hashable) -> TransitionInfo: ...


@dataclass(frozen=True)
class Change:
    """A value that differs from the previous step; ``old`` None when it is new, ``new`` None when gone."""

    name: str
    old: Optional[str]
    new: Optional[str]


@dataclass(frozen=True)
class TraceStep:
    """One numbered step: the transition taken (unless initial) and what it changed.

    ``stack``: the call stack the step's statement executes in (the stack of
    the state before it; for the initial step, of the initial state).
    """

    index: int
    kind: str
    transition: Optional[TransitionInfo]
    changes: tuple[Change, ...]
    stack: tuple[CallFrame, ...] = ()


@dataclass(frozen=True)
class Trace:
    prefix: tuple[TraceStep, ...]
    cycle: tuple[TraceStep, ...]
    closing: Optional[TraceStep]

    @property
    def loop_start(self) -> Optional[int]:
        """The index of the first cycle step, or None for a finite path."""
        return self.cycle[0].index if self.cycle else None


def changes_between(before: Optional[Mapping[str, str]], after: Mapping[str, str],
                    absent: Mapping[str, str] = {}) -> tuple[Change, ...]:
    """Values of ``after`` that differ from ``before`` (all of them when ``before`` is None).

    ``absent``: the value a name has when a view leaves it out (a describer's
    ``absent_values``: the program's status is shown only while it is not running), so
    a name that leaves the view changes to that value instead of ceasing to exist."""
    before = before or {}
    changed = [Change(name, before.get(name), value) for name, value in after.items()
               if before.get(name) != value]
    changed.extend(Change(name, value, absent.get(name)) for name, value in before.items()
                   if name not in after)
    return tuple(changed)


def build_trace(result: SearchResult, describer: TraceDescriber) -> Trace:
    """The readable trace of a VIOLATED result's lasso, folded to its shortest spelling."""
    prefix, cycle, closing_label = fold_lasso(result.prefix, result.cycle, result.closing_label)
    views: dict[int, Mapping[str, str]] = {}

    def view(step: LassoStep) -> Mapping[str, str]:
        key = id(step.state)
        if key not in views:
            views[key] = describer.describe_state(step.state)
        return views[key]

    describe_stack = getattr(describer, "describe_stack", lambda state: ())
    steps: list[TraceStep] = []
    previous: Optional[LassoStep] = None
    for lasso_step in [*prefix, *cycle]:
        before = view(previous) if previous is not None else None
        step = _trace_step(len(steps) + 1, lasso_step.label, before, view(lasso_step), describer)
        stack = describe_stack((previous or lasso_step).state)
        steps.append(replace(step, stack=tuple(stack)))
        previous = lasso_step
    closing = None
    if cycle:
        closing = _trace_step(len(steps) + 1, closing_label, view(cycle[-1]), view(cycle[0]),
                              describer)
        closing = replace(closing, stack=tuple(describe_stack(cycle[-1].state)))
    split = len(prefix)
    return Trace(tuple(steps[:split]), tuple(steps[split:]), closing)


def _trace_step(index: int, label: Optional[Hashable], before: Optional[Mapping[str, str]],
                after: Mapping[str, str], describer: TraceDescriber) -> TraceStep:
    changes = changes_between(before, after, getattr(describer, "absent_values", {}))
    if label is None:
        return TraceStep(index, INITIAL, None, changes)
    if label is STUTTER:
        return TraceStep(index, STUCK, TransitionInfo(None, None, STUCK_SOURCE), changes)
    return TraceStep(index, TRANSITION, describer.describe_transition(label), changes)
