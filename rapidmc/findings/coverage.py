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

A procedure without parameters that no routine calls is, on a real controller, most
often a service routine an operator starts by hand ("PP to routine": a calibration, a
test move).  Those that never run are summed up in one warning naming them all
(``service_routines``), instead of one warning each; ``check --entry all`` checks each
of them as an entry of its own.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Hashable, Optional, Sequence

from .. import ast
from ..ast import Span
from .dead_code import lines_after_jumps, lines_behind_absent_options
from .unreached_causes import group_by_cause
from ..diagnostics import NEVER_REACHED, Diagnostic
from ..model.reduction.merging import executed_spans
from ..semantics.instructions import Call, EndRoutine, EndUndo, LateCall
from ..semantics.library.program_control import CALLS_BY_NAME
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program

NOT_STATEMENTS = (EndRoutine, EndUndo)      # ENDPROC / end of UNDO: not a line to run
CALLED = ("PROC", "FUNC")       # routines that run only where a call of them does (not TRAPs)
ANY_INPUT = "under any input"
# an UNDO handler runs when its routine is left by EXIT, a reset or a moved program pointer
# (and inside the step of the EXIT that ends the program, where no state shows its lines)
UNDO_NOT_FOLLOWED = "with UNDO handlers not followed (one runs when EXIT, a reset or a " \
                    "moved program pointer leaves its routine)"


@dataclass(frozen=True)
class Unreached:
    """A statement, a stretch of statements up to ``last_line``, or a whole routine that no
    reachable transition executes."""

    span: Span
    routine: str
    whole_routine: bool
    last_line: int = 0            # the last line of the stretch (0: the statement's own)

    def diagnostic(self, inputs: str = ANY_INPUT) -> Diagnostic:
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

    def novel(self, successors: Sequence[tuple[Hashable, Hashable]]) -> list:
        """The successors whose step runs a line not executed yet (``check.walks``: a walk
        takes such a step first)."""
        executed, recorded = self.executed, self._recorded
        return [one for one in successors
                if any(span is not None and id(span) not in recorded
                       and (span.file, span.line) not in executed
                       for span in executed_spans(one[0][1]))]

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


def coverage_warnings(program: Program, executed: set[tuple[str, int]],
                      inputs: str = ANY_INPUT, called: Optional[frozenset] = None
                      ) -> list[Diagnostic]:
    """RMC701 warnings: the service routines that never run as one, then the rest.

    ``inputs`` says which inputs a warning holds for (``tried_inputs.qualifier``); a
    routine outside ``called`` (those a chain of calls reaches) is unreached under any
    input whatever was tried."""
    dead = _after_jumps(program)
    undo = _undo_lines(program)
    found = unreached(program, executed, {key: (value, key in undo) for key, value in dead.items()})
    service = {routine.span for routine in service_routines(program)}
    idle = [u for u in found if u.whole_routine and u.span in service]
    uncalled = [u for u in found if u.whole_routine and u not in idle
                and called is not None and u.routine not in called]
    if len(uncalled) < 2:
        uncalled = []
    only_dead_callers = _called_from_dead_code(program, dead, called)
    only_undo_callers = _called_only_where(program, lambda caller, key: key in undo)
    left = [u for u in found if u not in idle and u not in uncalled]
    warnings = group_by_cause(program, left, [
        UNDO_NOT_FOLLOWED if _within(u, dict.fromkeys(undo, True))
        or u.whole_routine and u.routine in only_undo_callers
        else ANY_INPUT if called is not None and u.routine not in called or _within(u, dead)
        or u.whole_routine and u.routine in only_dead_callers else inputs for u in left])
    if uncalled:
        warnings.append(_uncalled_routines(uncalled))
    if len(idle) > 1:
        warnings.append(_idle_service_routines(idle))
    else:
        warnings.extend(u.diagnostic() for u in idle)
    return warnings


def _after_jumps(program: Program) -> dict:
    """(file, line) -> whether it has a statement, for the statement lines of the watched
    routines: True where that statement follows a jump in its list, or lies in an ``IF
    Present(p)`` branch that no call gives ``p`` (``dead_code``)."""
    lines: dict = {}
    absent = lines_behind_absent_options([routine.ast for routine in program.routines
                                          if routine.ast is not None])
    for routine in _watched_routines(program):
        dead = lines_after_jumps(routine.ast) if routine.ast is not None else frozenset()
        for key in _statement_lines(routine):
            lines[key] = key in dead or key in absent
    return lines


def _undo_lines(program: Program) -> frozenset:
    """(file, line) of the statements of the watched routines' UNDO handlers."""
    return frozenset((node.span.file, node.span.line) for routine in _watched_routines(program)
                     if routine.ast is not None and routine.ast.undo
                     for statement in routine.ast.undo for node, _ in ast.walk(statement)
                     if getattr(node, "span", None) is not None)


def _called_from_dead_code(program: Program, dead: dict, called: Optional[frozenset]
                           ) -> frozenset:
    """The names of the procedures and functions every call of which is dead under any
    input: after a jump (``dead``), or in a routine no chain of calls reaches (outside
    ``called``) or itself called from dead code only (dtcameron's ``CloseConnection``,
    called once after ``WHILE TRUE``; a checksum function called only there).  Such a
    routine never runs whatever the inputs.  None when the program calls procedures by
    name (any may be the one) or ``called`` is unknown; a TRAP (run by an interrupt a
    CONNECT orders, wherever that is) is never counted."""
    if called is None:
        return frozenset()
    return _called_only_where(program, lambda caller, key: caller not in called
                              or dead.get(key, False), called)


def _called_only_where(program: Program, where, eligible: Optional[frozenset] = None
                       ) -> frozenset:
    """The names of the procedures and functions (of ``eligible``, when given) that some
    call reaches and every call of which is ``where(calling routine's name, (file, line))``
    or in a routine so found; none when a procedure may be called by a name computed at
    run time, or a name is twice (LOCAL routines of several modules).  Calls are read in
    every routine, the environment model's too (a call there is no dead code)."""
    if _calls_by_name(program) or any(
            isinstance(node, ast.LateBindingCall) for routine in program.routines
            if routine.ast is not None for node, _ in ast.walk(routine.ast)):
        return frozenset()
    sites: dict = {}                 # routine key -> [(calling routine's name, file, line)]
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall, ast.Connect)):
                key = node.trap.key if isinstance(node, ast.Connect) else node.name.key
                sites.setdefault(key, []).append(
                    (None if routine.namespace == ENVIRONMENT_NAMESPACE else routine.name,
                     node.span.file, node.span.line))
    procedures = {routine.key: routine.name for routine in _watched_routines(program)
                  if routine.kind in CALLED}
    if len(procedures) != len({r.name for r in _watched_routines(program)
                               if r.kind in CALLED}):
        return frozenset()
    found: set = set()
    changed = True
    while changed:
        changed = False
        for key, name in procedures.items():
            if name in found or (eligible is not None and name not in eligible) \
                    or not sites.get(key):
                continue
            if all(caller is not None and (caller in found or where(caller, (file, line)))
                   for caller, file, line in sites[key]):
                found.add(name)
                changed = True
    return frozenset(found)


def _within(found: Unreached, dead: dict) -> bool:
    """Whether every statement line of a stretch follows a jump (dead under any input)."""
    if found.whole_routine:
        return False
    span = found.span
    keys = [(span.file, line) for line in range(span.line, max(found.last_line, span.line) + 1)
            if (span.file, line) in dead]
    return bool(keys) and all(dead[key] for key in keys)


def _uncalled_routines(uncalled: list[Unreached]) -> Diagnostic:
    """Routines no chain of calls reaches, as one warning: dead code whatever the inputs,
    a fact of the call graph (each is a place of the warning), not of the inputs tried."""
    names = ", ".join(u.routine for u in uncalled)
    return Diagnostic(
        NEVER_REACHED, f"never reached {ANY_INPUT}: {len(uncalled)} routines no call "
        f"reaches ({names})", uncalled[0].span, severity="warning",
        places=tuple(u.span for u in uncalled[1:]),
        notes=("no chain of calls from an entry routine or a TRAP leads to them; 'rapidmc "
               "lint' (unused-routine, RMC807) names each that nothing calls",))


def _idle_service_routines(idle: list[Unreached]) -> Diagnostic:
    names = ", ".join(u.routine for u in idle)
    return Diagnostic(
        NEVER_REACHED, f"{len(idle)} routines never run: {names}", idle[0].span,
        severity="warning", places=tuple(u.span for u in idle[1:]),
        notes=("no routine calls them and they take no parameters: an operator may start "
               "them by hand (PP to routine); 'check --entry all' checks each as an entry",))


def service_routines(program: Program) -> list:
    """The procedures without parameters that no routine calls (by name or as a
    late-bound call's candidate) and that are no task's entry, in program order; none
    when the program calls a procedure named by a string (CallByVar, MoveLSync ...: any
    procedure without parameters may be the one)."""
    if _calls_by_name(program):
        return []
    called = {program.entry, *program.task_entries}
    for routine in program.routines:
        for instruction in routine.code:
            if isinstance(instruction, Call):
                called.add(instruction.routine.index)
            elif isinstance(instruction, LateCall):
                called.update(candidate.index for candidate, _ in
                              instruction.candidates.values())
    return [routine for routine in _watched_routines(program)
            if routine.kind == "PROC" and not routine.parameters
            and routine.index not in called]


def _calls_by_name(program: Program) -> bool:
    return any(isinstance(node, ast.ProcedureCall) and node.name.key in CALLS_BY_NAME
               for routine in program.routines if routine.ast is not None
               for node, _ in ast.walk(routine.ast))


def unreached(program: Program, executed: set[tuple[str, int]],
              regions: Optional[dict] = None) -> list[Unreached]:
    """The program's statements on lines never executed, in source order, one per stretch;
    given ``regions`` ((file, line) -> a value), a stretch also ends where the value
    changes (``coverage_warnings``: the lines after a jump, an UNDO handler: the code after
    an endless loop is not the loop's last unreached arm)."""
    found: list[Unreached] = []
    for routine in _watched_routines(program):
        lines = _statement_lines(routine)
        missed = [span for key, span in lines.items() if key not in executed]
        if lines and len(missed) == len(lines):
            found.append(Unreached(routine.span, routine.name, True))
        else:
            found.extend(_stretches(routine.name, lines, executed, regions or {}))
    return sorted(found, key=lambda u: (u.span.file, u.span.line, u.span.column))


def _stretches(routine: str, lines: dict[tuple[str, int], Span],
               executed: set[tuple[str, int]], regions: dict) -> list[Unreached]:
    """The unreached statement lines of a routine, runs without a reached line between them
    and all of one region (``unreached``)."""
    stretches: list[Unreached] = []
    first: Optional[Span] = None
    last_line = 0
    for key in sorted(lines):
        span = lines[key]
        if key in executed or (first is not None and (
                span.file != first.file or
                regions.get(key) != regions.get((first.file, first.line)))):
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
