"""Rounds of one sequence of source lines that a jump back closes: an ERROR handler's RETRY
rounds, a reconnect loop made of a GOTO.

A run that ends in ERR_EXCRTYMAX goes round an ERROR handler again and again: the statement
raises, the handler closes the socket and connects again, RETRY runs the statement again.
The rounds run the same lines, yet they need not change the same data (the first round sets
a flag that the later ones set to the value it has already), so the repeats that
``counterexample.fold_repeats`` looks for (the same data changed) do not find them, or find
them out of step with the rounds.

``fold_rounds(steps)`` finds each chain of ``FEWEST_ROUNDS`` or more rounds in a row.  A
round is the steps after one run of a jump (a RETRY, or a statement with a GOTO, whose next
step is on another line: the jump's target), up to and including the jump's next run, each
round running the same statements (file, line, source text, routines on the call stack) with
the same inputs chosen (but the first round, which may choose inputs the later rounds do
not choose again: a reading that stays the same for the run).  The first round and the
last one stay steps, so the reader sees the round in full and the state the error starts
from; the rounds between become one ``Rounds`` item, which the text tells in one line with
what changed across them.

The fold is the text's only: JSON, HTML and ``rapidmc replay`` keep every step, and so does
``--full-trace``.

    >>> fold_rounds([])
    []
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional, Sequence, Union

from ..check.trace import TraceStep
from .trace_slice import statements_of, words_of

FEWEST_ROUNDS = 3      # a chain folds from this many rounds on: the first, one folded, the last
LONGEST_ROUND = 80     # the most steps a round may have
RETRY = "RETRY"


@dataclass(frozen=True)
class Rounds:
    """Steps ``hidden``: ``times`` more rounds of the statements steps ``first``-``last`` ran
    (``lines``: the first and last line of the round in the jump's routine), each closed by
    ``jump`` (``RETRY``, ``GOTO again``); ``retries``: for RETRY rounds, how many times the
    RETRY had run in the chain after the first round and after the hidden ones."""

    first: int
    last: int
    times: int
    hidden: tuple[TraceStep, ...]
    jump: str
    lines: tuple[int, int]
    retries: Optional[tuple[int, int]] = None


def fold_rounds(steps: Sequence[TraceStep]) -> list[Union[TraceStep, Rounds]]:
    """The steps, with the rounds between the first and the last of each chain as one
    ``Rounds`` (see the module's docstring)."""
    keys = [_key(step) for step in steps]
    items: list[Union[TraceStep, Rounds]] = []
    done = 0                                    # steps before this are in ``items``
    at = 0
    while at < len(steps):
        chain = _chain_at(steps, keys, at, done) if _jumps_back(steps, at) else None
        if chain is None:
            at += 1
            continue
        start, period, count = chain
        shown_last = start + (count - 1) * period        # the last round's first step
        items.extend(steps[done:start + period])
        items.append(_rounds(steps, start, period, count))
        items.extend(steps[shown_last:start + count * period])
        done = at = start + count * period
    items.extend(steps[done:])
    return items


def _chain_at(steps: Sequence[TraceStep], keys: list, jump: int,
              floor: int) -> Optional[tuple[int, int, int]]:
    """(first step, round length, rounds) of the chain whose rounds the jump at ``jump``
    closes, the shortest rounds first; None when no chain of ``FEWEST_ROUNDS`` rounds is
    there.  Rounds before the jump's are counted back to ``floor``."""
    for again in range(jump + 1, min(jump + LONGEST_ROUND, len(steps) - 1) + 1):
        if keys[again] != keys[jump]:
            continue
        period = again - jump
        block = keys[jump + 1:again + 1]
        after = 1
        while keys[jump + 1 + after * period:jump + 1 + (after + 1) * period] == block:
            after += 1
        before = 0
        while jump + 1 - (before + 1) * period >= floor and \
                keys[jump + 1 - (before + 1) * period:jump + 1 - before * period] == block:
            before += 1
        # the first round may choose inputs the later ones do not choose again (a reading
        # that stays the same for the run): it is shown step by step
        start = jump + 1 - (before + 1) * period
        if start >= floor and [_without_inputs(key) for key in keys[start:start + period]] \
                == [_without_inputs(key) for key in block]:
            before += 1
        if before + after >= FEWEST_ROUNDS:
            return jump + 1 - before * period, period, before + after
    return None


def _rounds(steps: Sequence[TraceStep], start: int, period: int, count: int) -> Rounds:
    """The ``Rounds`` of a chain: the rounds between its first and its last."""
    first_round = steps[start:start + period]
    jump = first_round[-1]
    text = words_of(statements_of(jump)[-1]) if statements_of(jump) else []
    if RETRY in text[:1]:
        label, retries = RETRY, (1, count - 1)
    else:
        target = text[text.index("GOTO") + 1:text.index("GOTO") + 2] if "GOTO" in text else []
        label, retries = " ".join(["GOTO", *(_label(jump, target) if target else [])]), None
    return Rounds(first_round[0].index, jump.index, count - 2,
                  tuple(steps[start + period:start + (count - 1) * period]), label,
                  _lines(first_round, jump), retries)


def _label(jump: TraceStep, target: list[str]) -> list[str]:
    """The GOTO's label as the source spells it (``words_of`` gives it upper case)."""
    source = statements_of(jump)[-1]
    at = source.upper().rfind(target[0])
    return [source[at:at + len(target[0])]]


def _lines(round_steps: Sequence[TraceStep], jump: TraceStep) -> tuple[int, int]:
    """The first and last line the round runs in the jump's file and routine."""
    depth, file = len(jump.stack), jump.transition.file
    lines = [step.transition.line for step in round_steps
             if step.transition is not None and step.transition.file == file and
             step.transition.line is not None and len(step.stack) == depth]
    return min(lines), max(lines)


def _jumps_back(steps: Sequence[TraceStep], at: int) -> bool:
    """Whether the step at ``at`` runs a RETRY, or a statement with a GOTO, and the next
    step is on another line (the jump was taken: a one-line ``IF ... GOTO`` tests first)."""
    step = steps[at]
    if at + 1 >= len(steps) or step.transition is None or not statements_of(step):
        return False
    words = words_of(statements_of(step)[-1])
    if not (words[:1] == [RETRY] or "GOTO" in words):
        return False
    following = steps[at + 1].transition
    return following is not None and \
        (following.file, following.line) != (step.transition.file, step.transition.line)


def _without_inputs(key: tuple) -> tuple:
    kind, where, stack = key
    return kind, where[:3] if where is not None else None, stack


def _key(step: TraceStep) -> tuple:
    """What two steps of two rounds share: the statement, its place, the call stack and
    the inputs chosen (not the data changed, nor the text written)."""
    transition = step.transition
    where = (transition.file, transition.line, transition.source,
             tuple(transition.inputs.items())) if transition is not None else None
    return step.kind, where, tuple((frame.task, frame.routine) for frame in step.stack)
