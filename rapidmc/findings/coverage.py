"""Coverage: the statements of a program that no input sequence reaches.

"No input" means every value the check offered each input; where an input was
offered a sample only (``tried_inputs``), the warning says so and names it.

Shown the whole reachable state graph (``StatementWatch`` is an observer
for ``find_reachable``), the statements executed by some transition are
known (a merged step names every instruction it ran); every other statement of the program — the environment model
excepted — is dead code under every input the check considered.  A routine
none of whose statements runs gets one warning at its declaration instead
of one per line, and the other unreached statements of a routine one
warning per stretch of lines with no reached statement between them
(``lines 12-40``).  Only meaningful after a complete search: the caller
asks for ``unreached`` only then.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Hashable, Optional, Sequence

from ..ast import Span
from ..diagnostics import NEVER_REACHED, Diagnostic
from ..model.reduction.merging import executed_spans
from ..semantics.instructions import EndRoutine, EndUndo
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program

NOT_STATEMENTS = (EndRoutine, EndUndo)      # ENDPROC / end of UNDO: not a line to run


@dataclass(frozen=True)
class Unreached:
    """A statement, a stretch of statements up to ``last_line``, or a whole routine that no
    reachable transition executes."""

    span: Span
    routine: str
    whole_routine: bool
    last_line: int = 0            # the last line of the stretch (0: the statement's own)

    def diagnostic(self, inputs: str = "under any input") -> Diagnostic:
        """The warning; ``inputs`` says which inputs it holds for (``tried_inputs.qualifier``)."""
        message = f"never reached {inputs}"
        span = self.span
        if self.whole_routine:
            message += f" (routine {self.routine} never runs)"
        elif self.last_line > span.line:
            message = f"lines {span.line}-{self.last_line} of {self.routine} are never " \
                      f"reached {inputs}"
            span = Span(span.file, span.line, span.column, self.last_line, 0)
        return Diagnostic(NEVER_REACHED, message, span, severity="warning")


SPANS_KEPT = 1 << 12


class StatementWatch:
    """Observer of a breadth-first search: the source lines its transitions execute.

    A step's spans are mostly the compiled instructions' own objects, met again
    in state after state: each one recorded is remembered by identity (and kept
    alive, so that its id names it), up to ``SPANS_KEPT``, and skipped after.

    Given the ``program``, the watch knows the lines ``unreached`` asks about:
    once every one of them has run (``saturated``), no further line can change
    the coverage warnings, and the search may step without labels.
    """

    def __init__(self, program: Optional[Program] = None):
        self.executed: set[tuple[str, int]] = set()
        self._recorded: dict[int, object] = {}    # id(span) -> span, its line in executed
        # the lines unreached() reports on (None: not known, never saturated)
        self._asked = None if program is None else frozenset(
            key for routine in _watched_routines(program) for key in _statement_lines(routine))
        self.saturated = self._asked == frozenset()

    def clear(self) -> None:
        """Forget every line executed (before watching another search)."""
        self.executed.clear()
        self._recorded.clear()
        self.saturated = self._asked == frozenset()

    def __call__(self, state: Hashable, successors: Sequence[tuple[Hashable, Hashable]]) -> None:
        self.note_spans([one for (_, span, _), _ in successors for one in executed_spans(span)])

    def note_spans(self, spans: Sequence) -> None:
        """Mark the lines of ``spans`` executed (a search that runs steps without labels
        names the instructions it ran)."""
        executed, recorded = self.executed, self._recorded
        before = len(executed)
        for one in spans:
            if one is None or id(one) in recorded:
                continue
            executed.add((one.file, one.line))
            if len(recorded) >= SPANS_KEPT:
                recorded.clear()
            recorded[id(one)] = one
        if len(executed) != before and self._asked is not None:
            self.saturated = self._asked <= executed


def unreached(program: Program, executed: set[tuple[str, int]]) -> list[Unreached]:
    """The program's statements on lines never executed, in source order, one per stretch."""
    found: list[Unreached] = []
    for routine in _watched_routines(program):
        lines = _statement_lines(routine)
        missed = [span for key, span in lines.items() if key not in executed]
        if lines and len(missed) == len(lines):
            found.append(Unreached(routine.span, routine.name, True))
        else:
            found.extend(_stretches(routine.name, lines, executed))
    return sorted(found, key=lambda u: (u.span.file, u.span.line, u.span.column))


def _stretches(routine: str, lines: dict[tuple[str, int], Span],
               executed: set[tuple[str, int]]) -> list[Unreached]:
    """The unreached statement lines of a routine, runs without a reached line between them."""
    stretches: list[Unreached] = []
    first: Optional[Span] = None
    last_line = 0
    for key in sorted(lines):
        span = lines[key]
        if key in executed or (first is not None and span.file != first.file):
            if first is not None:
                stretches.append(Unreached(first, routine, False, last_line))
            first = None
        if key not in executed:
            first = first or span
            last_line = span.line
    if first is not None:
        stretches.append(Unreached(first, routine, False, last_line))
    return stretches


def _watched_routines(program: Program) -> list:
    """The routines whose statements coverage reports on: all but the environment's."""
    return [routine for routine in program.routines
            if routine.namespace != ENVIRONMENT_NAMESPACE]


def _statement_lines(routine) -> dict[tuple[str, int], Span]:
    """(file, line) -> the first statement span on that line, for every line with code."""
    lines: dict[tuple[str, int], Span] = {}
    for instruction in routine.code:
        span = instruction.span
        if span is None or isinstance(instruction, NOT_STATEMENTS):
            continue
        key = (span.file, span.line)
        if key not in lines or span.column < lines[key].column:
            lines[key] = span
    return lines
