"""One coverage warning per cause: the stretches of unreached code one thing keeps out.

Coverage (``coverage``) finds stretches of lines no reachable step runs, and routines
none of whose lines runs.  One dead cause often gives several of them: the arms of one
IF or TEST that the tested value never opens, the code after an endless loop and the
procedures only that code calls, the ERROR handlers no error enters.  A cell engineer
fixes (or accepts) a cause, not a stretch, so the stretches of one cause become one
warning that names the cause and lists every stretch: its first stretch is the
warning's place and the others its ``places`` (each with its last line), which every
report shows (``Diagnostic.places``).  No stretch is dropped: a warning of one stretch
keeps the message it had, and a grouped one lists the lines of each.

The cause of a stretch is read from where its first statement sits:

* after a jump that ends its statement list (``dead_code.jumps_before``): that jump;
* first in an arm of an IF, TEST, WHILE, FOR or compact IF (the compound statement ran,
  the arm did not): that statement, whose line the warning names;
* first in an ERROR handler: "no error enters the handler", one cause for all of a
  program's handlers (as ``coverage`` gives all routines no call reaches one warning),
  and likewise first in an UNDO handler (``coverage.UNDO_NOT_FOLLOWED``);
* after a statement that ran but never went on: that statement.

A routine that never runs, every call of which (at least one) lies in unreached code of
one cause, shares that cause (``CloseConnection``, called only after ``WHILE TRUE``).
Only warnings of the same wording of the inputs (``under any input`` or the inputs
tried) are grouped.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Iterable, Optional, Sequence

from .. import ast
from ..ast import Span, canonical
from ..diagnostics import NEVER_REACHED, Diagnostic, SourceCache
from ..diagnostics.quoting import quoted
from ..semantics.library.program_control import CALLS_BY_NAME
from .dead_code import jumps_before, lines_behind_absent_options

HANDLERS = ("handler",)       # the cause shared by every ERROR handler no error enters
UNDO = ("undo",)              # ... and by every UNDO handler coverage does not follow


@dataclass(frozen=True)
class Seat:
    """Where a statement sits: the compound statement whose arm it opens (None: a
    routine's body, UNDO, ERROR or backward list), which list of the routine holds it
    ("body", "error", "undo"), and the statement before it in its list (None: it comes
    first)."""

    owner: object
    part: str
    previous: object


@dataclass(frozen=True)
class Cause:
    key: tuple
    text: str                 # what keeps the code out ("the code after the RETURN at line 12")
    test: object = None       # the condition, when the code is an IF's THEN arm
    alone: bool = False       # named even for one stretch: a fact of the code (a jump,
                              # a Present branch no call opens), not of the inputs


def group_by_cause(program, found: Sequence, wording: Sequence[str]) -> list[Diagnostic]:
    """The warnings of ``found`` (``coverage.Unreached``, in source order) worded with
    ``wording`` (one per item): one per cause, at the place of its first stretch."""
    routines = [r for r in program.routines if r.ast is not None]
    seats = _seats(routines)
    jumps: dict = {}
    for routine in routines:
        jumps.update(jumps_before(routine.ast))
    absent = lines_behind_absent_options([r.ast for r in routines])
    causes = [None if item.whole_routine else
              _cause(item.span, seats, jumps, absent) or Cause(("stretch", index), "")
              for index, item in enumerate(found)]
    _same_tests_share_a_cause(causes)
    _routines_share_callers_cause(routines, found, causes)
    groups: dict = {}
    order: list = []
    for index, (item, inputs, cause) in enumerate(zip(found, wording, causes)):
        key = (inputs, cause.key) if cause is not None else ("alone", index)
        if key not in groups:
            groups[key] = []
            order.append(key)
        groups[key].append(index)
    warnings = []
    for key in order:
        members = groups[key]
        cause = causes[members[0]]
        if len(members) == 1 and cause is not None and cause.alone:
            alone = found[members[0]].diagnostic(wording[members[0]])
            warnings.append(replace(alone, message=f"{alone.message}: {cause.text}"))
        elif len(members) == 1:
            warnings.append(found[members[0]].diagnostic(wording[members[0]]))
        else:
            warnings.append(_grouped([found[i] for i in members], wording[members[0]],
                                     causes[members[0]]))
    return warnings


def _grouped(items: list, inputs: str, cause: Cause) -> Diagnostic:
    """One warning for the stretches and routines of one cause: the stretches first."""
    stretches = [u for u in items if not u.whole_routine]
    whole = [u for u in items if u.whole_routine]
    ordered = stretches + whole
    spans = [u.diagnostic(inputs).span for u in ordered]
    listed = "; ".join(_lines_of(routine, [u for u in stretches if u.routine == routine])
                       for routine in dict.fromkeys(u.routine for u in stretches))
    names = ", ".join(u.routine for u in whole)
    if not stretches:       # (the code calling them is worded otherwise: another warning)
        return Diagnostic(NEVER_REACHED, f"never reached {inputs}: routines {names}, called "
                          f"only in {cause.text or 'unreached code'}", spans[0],
                          severity="warning", places=tuple(spans[1:]))
    message = f"never reached {inputs}: {cause.text} ({listed})" if cause.text else \
        f"never reached {inputs}: {listed}"
    if whole:
        message += f" and the routine{'s' if len(whole) > 1 else ''} only that code " \
                   f"calls ({names})"
    return Diagnostic(NEVER_REACHED, message, spans[0], severity="warning",
                      places=tuple(spans[1:]))


def _lines_of(routine: str, stretches: list) -> str:
    ranges = [f"{u.span.line}-{u.last_line}" if u.last_line > u.span.line else f"{u.span.line}"
              for u in stretches]
    multiple = len(stretches) > 1 or stretches[0].last_line > stretches[0].span.line
    return f"line{'s' if multiple else ''} {', '.join(ranges)} of {routine}"


def _cause(span: Span, seats: dict, jumps: dict, absent: frozenset = frozenset()
           ) -> Optional[Cause]:
    """The cause of a stretch that starts at ``span`` (see the module docstring)."""
    key = (span.file, span.line)
    jump = jumps.get(key)
    if jump is not None:
        return Cause(("after", _where(jump)), f"the code after the {_jump_text(jump)} at line "
                                              f"{jump.span.line}", alone=True)
    seat = seats.get(key)
    if seat is None:
        return None
    option = _absent_option(seat.owner, key) if key in absent else None
    if option is not None:
        return Cause(("present", _where(seat.owner)), f"the code the IF at line "
                     f"{seat.owner.span.line} never enters, as no call passes \\{option}",
                     alone=True)
    if seat.previous is None and seat.owner is not None:
        return Cause(("arm", _where(seat.owner)), f"the code the {_compound_text(seat.owner)} at "
                                                  f"line {seat.owner.span.line} never enters",
                     _then_test(seat.owner, key))
    if seat.previous is None and seat.part == "error":
        return Cause(HANDLERS, "ERROR handlers no error enters")
    if seat.previous is None and seat.part == "undo":
        return Cause(UNDO, "UNDO handlers")
    if seat.previous is not None:
        return Cause(("after", _where(seat.previous)),
                     f"the code after line {seat.previous.span.line}, which never goes on")
    return None


def _absent_option(owner, key: tuple) -> Optional[str]:
    """The optional parameter ``p`` as written when the line ``key`` opens the arm of an
    ``IF Present(p)`` (or ELSEIF) branch of ``owner``, else None."""
    for branch in getattr(owner, "branches", ()) if isinstance(owner, ast.If) else ():
        if branch.body and (branch.body[0].span.file, branch.body[0].span.line) == key \
                and isinstance(branch.condition, ast.FunctionCall) \
                and branch.condition.name.key == "PRESENT" and branch.condition.args \
                and isinstance(branch.condition.args[0].value, ast.NameRef):
            return branch.condition.args[0].value.name.text
    return None


def _then_test(owner, key: tuple):
    """The condition of ``owner`` when the line ``key`` opens its THEN arm (an IF's first
    statement after THEN, or a compact IF's statement), else None."""
    if isinstance(owner, ast.CompactIf):
        return owner.condition
    if isinstance(owner, ast.If) and owner.branches[0].body \
            and (owner.branches[0].body[0].span.file,
                 owner.branches[0].body[0].span.line) == key:
        return owner.branches[0].condition
    return None


def _same_tests_share_a_cause(causes: list) -> None:
    """IFs of the same condition (``IF end_index < start_index THEN``, copied after each
    StrFind) whose THEN arm is all that is unreached of them share one cause: that the
    test never holds at any of them (in place, on ``causes``).  Only tests written alike
    at two places or more; an IF with other arms unreached keeps its own cause."""
    arms: dict = {}
    for cause in causes:
        if cause is not None:
            arms[cause.key] = arms.get(cause.key, 0) + 1
    shapes: dict = {}
    for index, cause in enumerate(causes):
        if cause is not None and cause.test is not None and arms[cause.key] == 1:
            shapes.setdefault(_shape(cause.test), []).append(index)
    for shape, members in shapes.items():
        if len(members) < 2:
            continue
        text = _source(causes[members[0]].test)
        shared = Cause(("test", shape), f"the code IFs testing {text} never enter"
                       if text else "the code IFs of the same test never enter")
        for index in members:
            causes[index] = shared


def _shape(node):
    """``node`` without its places: two conditions written alike have the same shape."""
    if isinstance(node, ast.Name):
        return node.key
    if isinstance(node, tuple):
        return tuple(_shape(inner) for inner in node)
    if hasattr(node, "__dataclass_fields__"):
        return (type(node).__name__,) + tuple(
            _shape(getattr(node, name)) for name in node.__dataclass_fields__
            if name != "span")
    return node


def _source(expr) -> str:
    """The condition as written, quoted (one line), or "" when its text is not at hand."""
    span = expr.span
    line = SourceCache.line(span.file, span.line)
    if line is None or span.end_line != span.line or span.end_column <= span.column:
        return ""
    return quoted(" ".join(line[span.column - 1:span.end_column - 1].split()))


def _where(node) -> tuple:
    return node.span.file, node.span.line, node.span.column


def _jump_text(statement) -> str:
    if isinstance(statement, ast.While):
        return "endless WHILE loop"
    if isinstance(statement, ast.ProcedureCall):
        return statement.name.text
    return type(statement).__name__.upper()


def _compound_text(node) -> str:
    return {ast.If: "IF", ast.CompactIf: "IF", ast.Test: "TEST", ast.While: "WHILE",
            ast.For: "FOR"}.get(type(node), "statement")


def _seats(routines) -> dict:
    """(file, line) -> the ``Seat`` of the first statement (or ELSEIF, CASE) on that line,
    for every routine."""
    seats: dict = {}
    for routine in routines:
        tree = routine.ast
        lists = [(tree.body, None, "body"), (tree.backward, None, "body"),
                 (tree.undo, None, "undo"),
                 (tree.error.body if tree.error is not None else None, None, "error")]
        while lists:
            statements, owner, part = lists.pop()
            if not statements:
                continue
            previous = None
            for statement in statements:
                _seat(seats, statement.span, Seat(owner, part, previous))
                previous = statement
                lists.extend((inner, compound, part) for inner, compound in _arms(statement))
                for arm in getattr(statement, "branches", ())[1:] + getattr(statement, "cases", ()):
                    _seat(seats, arm.span, Seat(statement, part, None))   # ELSEIF, CASE
    return seats


def _seat(seats: dict, span: Optional[Span], seat: Seat) -> None:
    if span is not None:
        seats.setdefault((span.file, span.line), seat)


def _arms(statement) -> list:
    """The statement lists ``statement`` opens, each as (list, ``statement``)."""
    if isinstance(statement, ast.If):
        lists = [branch.body for branch in statement.branches] + [statement.else_body]
    elif isinstance(statement, ast.Test):
        lists = [case.body for case in statement.cases] + [statement.default]
    elif isinstance(statement, (ast.While, ast.For)):
        lists = [statement.body]
    elif isinstance(statement, ast.CompactIf):
        lists = [(statement.statement,)]
    else:
        lists = []
    return [(inner, statement) for inner in lists]


def _routines_share_callers_cause(routines, found: Sequence, causes: list) -> None:
    """Give each routine of ``found`` that never runs the cause of the unreached code that
    holds every call of it, when that is one cause (in place, on ``causes``)."""
    if _named_at_run_time(routines):
        return
    names = [r.ast.name.key for r in routines]
    calls: dict = {}                # routine key -> (file, line) of each call
    for routine in routines:
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall, ast.Connect)):
                key = node.trap.key if isinstance(node, ast.Connect) else node.name.key
                calls.setdefault(key, []).append((node.span.file, node.span.line))
    holder = _holders(routines, found)
    by_name = {canonical(u.routine): i for i, u in enumerate(found) if u.whole_routine}
    changed = True
    while changed:
        changed = False
        for name, index in by_name.items():
            sites = calls.get(name)
            if causes[index] is not None or not sites or names.count(name) != 1:
                continue
            held = {holder.get(site) for site in sites}
            if None in held or index in held:
                continue
            shared = {causes[i].key if causes[i] is not None else None for i in held}
            if len(shared) == 1 and None not in shared:
                causes[index] = causes[next(iter(held))]
                changed = True


def _holders(routines, found: Sequence) -> dict:
    """(file, line) -> the index in ``found`` of the stretch or routine that holds it."""
    extent = {r.name: (r.ast.span, r.ast.end_span) for r in routines}
    held: dict = {}
    for index, item in enumerate(found):
        first, last = item.span.line, max(item.last_line, item.span.line)
        if item.whole_routine and item.routine in extent:
            first, last = extent[item.routine][0].line, extent[item.routine][1].line
        for line in range(first, last + 1):
            held.setdefault((item.span.file, line), index)
    return held


def _named_at_run_time(routines: Iterable) -> bool:
    """Whether some procedure is called by a name computed at run time (any may be it)."""
    return any(isinstance(node, ast.LateBindingCall) or
               (isinstance(node, ast.ProcedureCall) and node.name.key in CALLS_BY_NAME)
               for routine in routines for node, _ in ast.walk(routine.ast))
