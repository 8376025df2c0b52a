"""Which steps of a counterexample the failure depends on: a dynamic slice of the trace.

A reader of a counterexample wants the steps that lead to what went wrong.  A
step that only writes data nothing later needed reads (17 waypoints assigned
before a division by zero) can be told in one line instead of seventeen.

``needed_steps(trace, names)`` walks the trace backwards from what the
violation reads -- the failing line of a path that ends in an error, every
line of a lasso's cycle (the loop runs forever: all of it counts), and the
property's ``names`` -- and keeps:

* data dependence: a step that writes a datum a kept step (or the property)
  reads; its own line's data become read in turn;
* control dependence, over-approximated: every step whose statement decides
  where the run goes (IF, WHILE, FOR, TEST, RETURN, RAISE, waits, interrupt
  set-up ...) is kept with the data it reads, and so is the call that entered
  the routine of each kept step (its arguments may be references);
* every step that is not a plain statement: the initial state, a stuck state,
  a step with no source line, a step that changes ERRNO or the program's status,
  chooses an input, or raises an error (the next step starts an ERROR handler:
  the caller names the handlers' first lines).

A stretch the run left for the statement after it without a jump is left out whole
-- its control steps and chosen inputs too -- when no step inside it writes what a
kept step reads or changes ERRNO or the program's status: its path inside decided
nothing but its own data.  Such stretches are a routine call the run came back from,
to the statement after the call (a homing routine's checks of the robot's position
before a later index error), and an IF, FOR, WHILE or TEST the run went on from to the
statement after it (``compound_exits``: FOR loops filling arrays of positions).  A
call whose statement runs again after the return (a FUNC's value in an expression) is
kept as above: its value is read.

What a statement reads is taken from its source text (every identifier of
every statement a merged step ran), what it writes from the data the step
changed.  Both are over-approximations (an identifier is taken to name every
datum it may name), so a step left out is one whose writes nothing kept can
read: the slice is sound, not minimal.
"""
from __future__ import annotations

import re
from typing import Iterable, Mapping, Optional, Sequence

from ..check.trace import INITIAL, TRANSITION, Trace, TraceStep
from ..semantics.robots import ROBOT_TCP
from ..semantics.task_registers import names_errno
from .trace_text import IDENTIFIER, INDEX

STRING = re.compile(r'"(?:[^"]|"")*"')
COMMENT = re.compile(r"!.*$")
# the target of an assignment: a name with indexes and components (``pk{2}.id``)
ASSIGNED = re.compile(r"^\s*[A-Za-z][A-Za-z0-9_]*(\s*\{[^}]*\}|\s*\.\s*[A-Za-z][A-Za-z0-9_]*)*\s*$")

# first words of statements that decide where the run goes next (or when)
CONTROL_WORDS = frozenset("""
    IF ELSEIF ELSE ENDIF WHILE ENDWHILE FOR ENDFOR TEST CASE DEFAULT ENDTEST GOTO RETURN RAISE
    EXIT EXITCYCLE RETRY TRYNEXT STOP BREAK SYSTEMSTOPACTION ERROR UNDO BACKWARD
    WAITUNTIL WAITDI WAITDO WAITAI WAITAO WAITGI WAITGO WAITSYNCTASK WAITTESTANDSET WAITLOAD
    WAITTIME WAITWOBJ WAITROB
    CONNECT IDELETE IENABLE IDISABLE ISLEEP IWATCH ISIGNALDI ISIGNALDO ISIGNALAI ISIGNALAO
    ISIGNALGI ISIGNALGO ITIMER IPERS IERROR IRMQMESSAGE
    CALLBYVAR
""".split())
# the robot's position is read by these functions (and by atoms naming them, or AtTarget)
ROBOT_READERS = frozenset({"CROBT", "CPOS", "CJOINTT", "CTOOL", "CWOBJ", "CDIRPATH", "ATTARGET"})
ROBOT = ROBOT_TCP.upper()      # a change of T_ROB2.robot TCP writes T_ROB2 and ROBOT TCP
ALWAYS_KEPT = ("ERRNO", "program")
LABEL = re.compile(r"^\s*[A-Za-z][A-Za-z0-9_]*\s*:(?!=)")


def statements_of(step: TraceStep) -> tuple[str, ...]:
    """The source text of every statement the step ran (a merged step ran several)."""
    transition = step.transition
    if transition is None:
        return ()
    return tuple(getattr(transition, "statements", ()) or (transition.source,))


def words_of(text: str) -> list[str]:
    """The identifiers of a statement, upper case, strings and comments left out."""
    return [word.upper() for word in IDENTIFIER.findall(COMMENT.sub("", STRING.sub('""', text)))]


def read_part(source: str) -> str:
    """What a line reads: of an assignment, the indexes of its target and its value."""
    target, assigns, value = source.partition(":=")
    if not assigns or not ASSIGNED.match(target):
        return source                  # no assignment (``SocketReceive s \Str:=text;``)
    return " ".join(re.findall(r"\{([^}]*)\}", target)) + " " + value


def reads_of(step: TraceStep, scoped: frozenset = frozenset()) -> frozenset:
    """What the step may read: every identifier its statements name, an assignment's target
    left out (not its indexes), and the robot's position when a statement calls a function
    that reads it.  ``scoped`` (``routine_data``): an identifier that names data of the
    routine the step runs in is that datum, ``ROUTINE.NAME``."""
    words = set()
    for text in statements_of(step):
        named = words_of(text)
        if named and named[0] not in CONTROL_WORDS and not LABEL.match(text):
            named = words_of(read_part(text))
        words.update(named)
    return with_robot(_in_scope(words, step, scoped))


def routine_data(steps: Sequence[TraceStep]) -> frozenset:
    """``ROUTINE.NAME`` of each routine datum the trace changes (``Main.i``), for a run of
    one task: a name its routine's statements use means that datum and no other (RAPID's
    routine data are seen by their routine alone).  Empty with several tasks."""
    if any(frame.task for step in steps for frame in step.stack):
        return frozenset()
    routines = {frame.routine.upper() for step in steps for frame in step.stack}
    found = set()
    for step in steps:
        for change in step.changes:
            parts = INDEX.sub("", change.name).upper().split(".")
            if len(parts) > 1 and parts[0] in routines:
                found.add(f"{parts[0]}.{parts[1]}")
    return frozenset(found)


def _in_scope(words, step: TraceStep, scoped: frozenset) -> set:
    if not scoped or not step.stack:
        return set(words)
    routine = step.stack[-1].routine.upper()
    return {f"{routine}.{word}" if f"{routine}.{word}" in scoped else word for word in words}


def with_robot(words) -> frozenset:
    """``words`` (upper case), and the robot's position when one of them reads it."""
    return frozenset(words | {ROBOT} if ROBOT_READERS.intersection(words) else words)


def writes_of(step: TraceStep, scoped: frozenset = frozenset()) -> frozenset:
    """Every identifier a changed name may be about (``main.reg1{2}``: MAIN and REG1), and
    the datum of each assignment's target (an assignment of the value it had changes
    nothing, yet the value read after it comes from it).  ``scoped`` (``routine_data``):
    a routine's datum is ``ROUTINE.NAME`` alone."""
    found = set()
    for text in statements_of(step):
        target, assigns, _ = text.partition(":=")
        if assigns and ASSIGNED.match(target):
            found.add(IDENTIFIER.match(target.strip()).group().upper())
    found = _in_scope(found, step, scoped)
    for change in step.changes:
        parts = INDEX.sub("", change.name.removeprefix("signal ")).upper().split(".")
        if len(parts) > 1 and f"{parts[0]}.{parts[1]}" in scoped:
            found.add(f"{parts[0]}.{parts[1]}")
        else:
            found.update(parts[:2])
    return frozenset(found)


def is_control(step: TraceStep, raised: bool = False) -> bool:
    """Whether the step decides the run's path (``raised``: the next step starts an ERROR
    handler, so this one raised an error), or is not a plain statement at all."""
    if step.kind != TRANSITION or step.transition is None or not step.transition.location:
        return True
    if raised or step.transition.inputs:       # an error raised, an input chosen
        return True
    if any(change.name in ALWAYS_KEPT or names_errno(change.name)
           for change in step.changes):
        return True
    for text in statements_of(step):
        words = words_of(text)
        if not words or words[0] in CONTROL_WORDS or LABEL.match(text) or text.startswith("%"):
            return True
    return False


def needed_steps(trace: Trace, names: Iterable[str] = (),
                 handler_starts: frozenset = frozenset(),
                 compound_exits: Mapping = {}) -> frozenset:
    """The indexes of the steps the violation depends on (see the module's docstring).

    One walk back over the prefix: a kept step adds what it reads and marks the calls
    that entered its routine (earlier steps, so the walk meets them later).  A kept
    assignment of a whole datum ``x := ...`` that does not read ``x`` ends the need
    for earlier writes of ``x`` -- only where the name cannot mean another datum (one
    task, no routine data or other datum of that name in the trace)."""
    steps = [*trace.prefix, *trace.cycle]
    position = {step.index: number for number, step in enumerate(steps)}
    read = set(names)
    needed = set()
    if trace.cycle:
        for step in [*trace.cycle, *([trace.closing] if trace.closing else [])]:
            read |= reads_of(step)
            if step.index in position:
                needed.add(step.index)
                needed.update(call.index for call in _entering_calls(steps, position[step.index]))
    elif trace.prefix:
        needed.add(trace.prefix[-1].index)
    single = _plain_names(steps)
    # routine data by routine (a loop counter i of one routine is not another's i), for a
    # path that ends in an error: a cycle's and a property's reads stay plain names
    scoped = routine_data(steps) if not (trace.cycle or trace.bad_prefix) else frozenset()
    prefix = steps[:len(trace.prefix)]
    left = returned_calls(prefix, handler_starts)
    for end, start in _left_compounds(prefix, compound_exits).items():
        left[end] = min(start, left.get(end, start))
    number = len(trace.prefix) - 1
    while number >= 0:
        start = left.get(number)
        if start is not None and not any(_needed_inside(step, needed, read, scoped)
                                         for step in steps[start:number + 1]):
            number = start - 1          # the whole stretch: nothing kept reads what it did
            continue
        step = steps[number]
        number -= 1
        if step.index in needed or is_control(step, _raises(steps, number + 1, handler_starts)) \
                or not read.isdisjoint(writes_of(step, scoped)):
            needed.add(step.index)
            reads = reads_of(step, scoped)
            read -= (_whole_assigned(step) & single) - reads
            read |= reads
            needed.update(call.index for call in _entering_calls(steps, number + 1))
    return frozenset(needed)


def _needed_inside(step: TraceStep, needed: set, read: set, scoped: frozenset) -> bool:
    """Whether a step inside a returned call keeps the call: it is kept already, writes
    what a kept step reads, or changes ERRNO or the program's status."""
    return step.index in needed or not read.isdisjoint(writes_of(step, scoped)) or \
        any(change.name in ALWAYS_KEPT or names_errno(change.name) for change in step.changes)


def _left_compounds(steps: Sequence[TraceStep], exits: Mapping) -> dict:
    """IF, FOR, WHILE and TEST statements the run entered and went on from to the statement
    after them (``exits``: ``RapidDescriber.compound_exits``), as {number of the last step
    inside: number of the first (the statement's own)}: every step between is the
    statement's (its lines, in the same routine) or deeper in a call, before the path's
    last step."""
    found: dict[int, int] = {}
    last = len(steps) - 1
    for number in range(last):
        step = steps[number]
        where = _place(step)
        exit_ = exits.get(where) if where is not None else None
        if exit_ is None:
            continue
        end_line, after = exit_
        depth, routine = len(step.stack), step.stack[-1].routine if step.stack else None

        def inside(other: TraceStep) -> bool:
            place = _place(other)
            return place is not None and (len(other.stack) > depth or (
                len(other.stack) == depth and other.stack[-1].routine == routine and
                place[0] == where[0] and where[1] <= place[1] <= end_line))
        if number > 0 and inside(steps[number - 1]) and len(steps[number - 1].stack) == depth:
            continue                    # a later round of a loop, not its entry
        end = number
        while end < last and inside(steps[end + 1]):
            end += 1
        if end < last and len(steps[end + 1].stack) == depth and \
                _place(steps[end + 1]) == after:
            found.setdefault(end, number)
    return found


def _place(step: TraceStep) -> Optional[tuple]:
    transition = step.transition
    return None if transition is None or not transition.file else \
        (transition.file, transition.line)


def returned_calls(steps: Sequence[TraceStep], handler_starts: frozenset) -> dict:
    """Routine calls the run came back from, as {number of the last step inside: number of
    the first}: the step after the last one is back in the calling routine, at another
    statement than the call (not an ERROR handler's start, not the call's statement run
    again for a FUNC's value), before the path's last step.  One task only (the stack of
    a run with several tasks holds every task's frames)."""
    if any(frame.task for step in steps for frame in step.stack):
        return {}
    found: dict[int, int] = {}
    last = len(steps) - 1
    for number in range(1, last):
        call, first = steps[number], steps[number + 1]
        depth = len(call.stack)
        if call.transition is None or first.transition is None or \
                len(first.stack) != depth + 1 or first.stack[:depth - 1] != call.stack[:-1]:
            continue
        end = number + 1
        while end < last and len(steps[end + 1].stack) > depth:
            end += 1
        back = steps[end + 1] if end < last else None
        if back is None or back.transition is None or len(back.stack) != depth or \
                back.stack[-1].routine != call.stack[-1].routine or \
                (back.transition.file, back.transition.line) == \
                (call.transition.file, call.transition.line) or \
                (back.transition.file, back.transition.line) in handler_starts:
            continue
        found.setdefault(end, number + 1)
    return found


def _raises(steps: Sequence[TraceStep], number: int, handler_starts: frozenset) -> bool:
    """Whether the step after ``steps[number]`` is the first statement of an ERROR handler."""
    if number + 1 >= len(steps) or steps[number + 1].transition is None:
        return False
    following = steps[number + 1].transition
    return (following.file, following.line) in handler_starts


def whole_assignments(step: TraceStep) -> set:
    """The data the step's assignments ``x := ...`` write whole, upper case."""
    found = set()
    for text in statements_of(step):
        target, assigns, _ = text.partition(":=")
        if assigns and IDENTIFIER.fullmatch(target.strip()):
            found.add(target.strip().upper())
    return found


def _whole_assigned(step: TraceStep) -> set:
    """The datum the step's one statement, an assignment ``x := ...``, writes whole and the
    step shows changed (so ``x`` names that datum); none for any other step."""
    if len(statements_of(step)) != 1:
        return set()
    return {name for name in whole_assignments(step)
            if any(change.name.upper() == name for change in step.changes)}


def _plain_names(steps: Sequence[TraceStep]) -> set:
    """The names that can mean only one datum here: changed under that one plain name in
    the trace, and no task but the first runs (a further task's data has the same names)."""
    if any(frame.task for step in steps for frame in step.stack):
        return set()
    spellings: dict[str, set] = {}
    for step in steps:
        for change in step.changes:
            name = change.name.removeprefix("signal ")
            for part in INDEX.sub("", name).split(".")[:2]:
                spellings.setdefault(part.upper(), set()).add(INDEX.sub("", name).upper())
    return {word for word, names in spellings.items() if names == {word}}


def _entering_calls(steps: Sequence[TraceStep], number: int) -> list[TraceStep]:
    """The latest earlier steps at each caller frame's line: the calls that led here.

    With several tasks the stack holds every task's frames; the calls of the other tasks
    are taken too (more kept, never less)."""
    own = steps[number].transition
    found = []
    for frame in steps[number].stack:
        if own is not None and (frame.file, frame.line) == (own.file, own.line):
            continue
        for earlier in range(number - 1, -1, -1):
            transition = steps[earlier].transition
            if transition is not None and transition.file == frame.file and \
                    transition.line == frame.line:
                found.append(steps[earlier])
                break
    return found
