"""From a lasso of model states to the steps a robot programmer reads.

The RAPID specifics come from a ``TraceDescriber`` the caller implements:
what every global data object, signal and robot item looks like in a
state, and where a transition is in the source, what it chose and wrote.
This module only compares consecutive states so that each step lists
only what changed (the first step lists every value once).  A value the
describer gives as a ``Composite`` (an array or record: its text and its
parts) changes per part when one part changes (or a few elements of an
array): ``waypoints{8}``, ``tool.tframe.trans``, not the whole value twice.

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
from .result import BAD_PREFIX, LassoStep, SearchResult

INITIAL = "initial"
TRANSITION = "transition"
STUCK = "stuck"
STUCK_SOURCE = "(no statement can execute: the program is stuck and stays in this state)"


@dataclass(frozen=True)
class TransitionInfo:
    """What one model transition did, in source terms.

    ``statements``: the source of every statement a transition that ran several (a merged
    step) ran, in order; empty when it ran one (``source`` is then all of it).
    """

    file: Optional[str]
    line: Optional[int]
    source: str
    inputs: Mapping[str, str] = field(default_factory=dict)
    output: str = ""
    statements: tuple[str, ...] = ()

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
    Optional: ``describe_ending_transition(label)``, the last transition of a path that
    ends in an error, at the statement that raised it (a transition that ran several
    statements is otherwise shown at its first).
    """

    def describe_state(self, state: Hashable) -> Mapping[str, str]: ...

    def describe_transition(self, label: Hashable) -> TransitionInfo: ...


class Composite(str):
    """A value's text together with its parts, for values made of parts (arrays, records).

    It compares, hashes and prints as its text; ``parts`` are ``(suffix, value)``
    pairs in order, each suffix appended to the value's name names the part
    (``{3}``, ``.trans``), each value a ``str`` or a ``Composite`` again.
    """

    parts: tuple[tuple[str, str], ...]

    def __new__(cls, text: str, parts: tuple[tuple[str, str], ...]) -> "Composite":
        made = super().__new__(cls, text)
        made.parts = parts
        return made


# an array whose elements change in at most this many places is shown per element
MOST_PARTS_SHOWN = 3


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
    """``ending``: for a path without a loop, what is wrong where it ends (the search's words)."""

    prefix: tuple[TraceStep, ...]
    cycle: tuple[TraceStep, ...]
    closing: Optional[TraceStep]
    ending: Optional[str] = None

    @property
    def loop_start(self) -> Optional[int]:
        """The index of the first cycle step, or None for a finite path."""
        return self.cycle[0].index if self.cycle else None

    @property
    def bad_prefix(self) -> bool:
        """Whether this is a property's finite counterexample: a path after whose last step
        every run violates the property (``result.BAD_PREFIX``), no loop."""
        return not self.cycle and self.ending == BAD_PREFIX


def changes_between(before: Optional[Mapping[str, str]], after: Mapping[str, str],
                    absent: Mapping[str, str] = {}) -> tuple[Change, ...]:
    """Values of ``after`` that differ from ``before`` (all of them when ``before`` is None).

    ``absent``: the value a name has when a view leaves it out (a describer's
    ``absent_values``: the program's status is shown only while it is not running), so
    a name that leaves the view changes to that value instead of ceasing to exist."""
    before = before or {}
    changed = [change for name, value in after.items() if before.get(name) != value
               for change in component_changes(name, before.get(name), value)]
    changed.extend(Change(name, value, absent.get(name)) for name, value in before.items()
                   if name not in after)
    return tuple(changed)


def component_changes(name: str, old: Optional[str], new: str) -> list[Change]:
    """The change of ``name`` from ``old`` to ``new``: per part where one part differs (or
    up to ``MOST_PARTS_SHOWN`` elements of an array), else whole.

    >>> old = Composite("[1,2,3]", (("{1}", "1"), ("{2}", "2"), ("{3}", "3")))
    >>> new = Composite("[1,5,3]", (("{1}", "1"), ("{2}", "5"), ("{3}", "3")))
    >>> component_changes("a", old, new)
    [Change(name='a{2}', old='2', new='5')]
    """
    old_parts = getattr(old, "parts", None)
    new_parts = getattr(new, "parts", None)
    if old_parts is None or new_parts is None or len(old_parts) != len(new_parts) or \
            any(a[0] != b[0] for a, b in zip(old_parts, new_parts)):
        return [Change(name, old, new)]
    differing = [(suffix, was, now) for (suffix, was), (_, now) in zip(old_parts, new_parts)
                 if was != now]
    # one part: that part; a few elements of an array (suffixes "{i}"): each of them;
    # several parts of a record, or most of an array: the whole value
    elements = all(suffix.startswith("{") for suffix, _, _ in differing)
    if len(differing) > 1 and not (elements and len(differing) <= MOST_PARTS_SHOWN and
                                   len(differing) < len(new_parts)):
        return [Change(name, old, new)]
    return [change for suffix, was, now in differing
            for change in component_changes(name + suffix, was, now)]


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
    if not cycle and result.ending not in (None, BAD_PREFIX) and steps and \
            steps[-1].kind == TRANSITION:
        ending = getattr(describer, "describe_ending_transition", None)
        if ending is not None:
            steps[-1] = replace(steps[-1], transition=ending(prefix[-1].label))
    return Trace(tuple(steps[:split]), tuple(steps[split:]), closing,
                 None if cycle else result.ending)


def _trace_step(index: int, label: Optional[Hashable], before: Optional[Mapping[str, str]],
                after: Mapping[str, str], describer: TraceDescriber) -> TraceStep:
    changes = changes_between(before, after, getattr(describer, "absent_values", {}))
    if label is None:
        return TraceStep(index, INITIAL, None, changes)
    if label is STUTTER:
        return TraceStep(index, STUCK, TransitionInfo(None, None, STUCK_SOURCE), changes)
    return TraceStep(index, TRANSITION, describer.describe_transition(label), changes)
