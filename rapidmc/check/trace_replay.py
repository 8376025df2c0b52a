"""Following a saved counterexample (``check --format json``) through the program again.

A saved trace names, for every step, the source line executed, the inputs
chosen, the FlexPendant output and the values that changed.  ``follow``
starts from the initial state whose values are those of step 1 and, for
each later step, takes the transition that matches all of that (the step
function is deterministic once the choices are fixed, so at most one
does).  When none does, the program no longer follows the trace — it was
edited since, or checked with other options — and ``TraceDiverged`` says
at which step and what the program can do instead.  The closing step must
lead back to the very state of the loop's first step.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Hashable, Iterator, Mapping, Optional

from .trace import changes_between

STUCK = "stuck"


@dataclass(frozen=True)
class SavedStep:
    """One step of a trace as ``--format json`` writes it (docs/json-output.md)."""

    index: int
    kind: str
    file: Optional[str]
    line: Optional[int]
    source: Optional[str]
    inputs: Mapping[str, str]
    changes: Mapping[str, Optional[str]]
    output: Optional[str]

    @classmethod
    def from_json(cls, step: dict) -> "SavedStep":
        location = step.get("location") or {}
        return cls(int(step["index"]), str(step["kind"]), location.get("file"),
                   location.get("line"), step.get("source"), dict(step.get("inputs") or {}),
                   dict(step.get("changes") or {}), step.get("output"))

    @property
    def where(self) -> str:
        return f"{self.file}:{self.line}" if self.file else "(no source line)"


@dataclass(frozen=True)
class SavedTrace:
    steps: tuple[SavedStep, ...]        # prefix, cycle, then the closing step
    loop_start: Optional[int]           # index of the first cycle step

    @classmethod
    def from_json(cls, trace: dict) -> "SavedTrace":
        steps = [*trace["prefix"], *trace["cycle"]]
        if trace.get("closing"):
            steps.append(trace["closing"])
        return cls(tuple(SavedStep.from_json(step) for step in steps), trace.get("loop_start"))


class TraceDiverged(Exception):
    """The program cannot take a step of the trace."""

    def __init__(self, step: SavedStep, possible: list[str]):
        self.step = step
        self.possible = possible
        super().__init__(f"step {step.index}")


@dataclass(frozen=True)
class ReplayedStep:
    saved: SavedStep
    state: Hashable


def follow(system, describer, trace: SavedTrace) -> Iterator[ReplayedStep]:
    """The states of the trace, one per step; raises ``TraceDiverged`` where it breaks."""
    first, *rest = trace.steps
    state = _initial(system, describer, first)
    yield ReplayedStep(first, state)
    states = {first.index: state}
    for step in rest:
        state = _next(system, describer, state, step)
        states[step.index] = state
        yield ReplayedStep(step, state)
    closing = trace.steps[-1]
    if trace.loop_start is not None and states.get(trace.loop_start) != state:
        raise TraceDiverged(closing, [f"the loop does not close: the state after step "
                                      f"{closing.index} is not the state of step "
                                      f"{trace.loop_start}"])


def _initial(system, describer, step: SavedStep):
    for state in system.initial_states():
        if dict(describer.describe_state(state)) == step.changes:
            return state
    raise TraceDiverged(step, ["no initial state has the values of step 1"])


def _next(system, describer, state, step: SavedStep):
    successors = system.successors(state)
    if step.kind == STUCK:
        if not successors:
            return state
        raise TraceDiverged(step, _possible(describer, successors))
    before = describer.describe_state(state)
    for label, after in successors:
        info = describer.describe_transition(label)
        if (info.file, info.line) != (step.file, step.line) or dict(info.inputs) != step.inputs:
            continue
        if (info.output or None) != step.output:
            continue
        changes = {c.name: c.new for c in changes_between(before, describer.describe_state(after),
                                                           getattr(describer, "absent_values", {}))}
        if changes == step.changes:
            return after
    raise TraceDiverged(step, _possible(describer, successors))


def _possible(describer, successors) -> list[str]:
    """What the program can do instead: each distinct statement and its inputs, in order."""
    seen: dict[str, None] = {}
    for label, _ in successors:
        info = describer.describe_transition(label)
        inputs = ", ".join(f"{name} = {value}" for name, value in info.inputs.items())
        text = f"{info.location or '(no source line)'}  {info.source}".rstrip()
        seen.setdefault(f"{text}  (inputs: {inputs})" if inputs else text, None)
    return list(seen) or ["nothing: the program has no successor state here"]
