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
  chooses an input its statement does not name (not only which task runs: an
  interrupt's edge, a wait's timeout), or raises an error (the next step starts an ERROR handler:
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
from ..model.fairness import TASK_CHOICE
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
    """What a line reads: of an assignment, the indexes of its target and its value; of a
    one-line IF that assigns (``IF n <> 0 rec.cpm := 1;``), its condition too."""
    target, assigns, value = source.partition(":=")
    if not assigns:
        return source
    condition = ""
    if not ASSIGNED.match(target) and ONE_LINE_IF.match(target):
        last = TARGET_AT_END.search(target)
        if last is not None:
            condition, target = target[:last.start()], last.group(0)
    if not ASSIGNED.match(target):
        return source                  # no assignment (``SocketReceive s \Str:=text;``)
    return condition + " ".join(re.findall(r"\{([^}]*)\}", target)) + " " + value


ONE_LINE_IF = re.compile(r"^\s*IF\b", re.IGNORECASE)
# the assigned data at the end of a one-line IF's text before ``:=``
TARGET_AT_END = re.compile(r"(?<![A-Za-z0-9_\\])[A-Za-z][A-Za-z0-9_]*"
                           r"(?:\s*\{[^{}]*\}|\s*\.\s*[A-Za-z][A-Za-z0-9_]*)*\s*$")


def reads_of(step: TraceStep, scoped: frozenset = frozenset(),
             task: Optional[str] = "") -> frozenset:
    """What the step may read: every identifier its statements name, an assignment's target
    left out (not its indexes), and the robot's position when a statement calls a function
    that reads it.  ``scoped`` (``routine_data``): an identifier that names data of the
    routine or the task (``task``, ``running_tasks``) the step runs in is that datum,
    ``ROUTINE.NAME`` or ``TASK.NAME``."""
    words = set()
    for text in statements_of(step):
        named = words_of(text)
        if named and (named[0] not in CONTROL_WORDS or named[0] == "IF") and \
                not LABEL.match(text):
            named = words_of(read_part(text))
        words.update(named)
    return frozenset(_in_scope(with_robot(words), step, scoped, task))


def routine_data(steps: Sequence[TraceStep]) -> frozenset:
    """The scoped names of the data the trace changes that a plain name could confuse:
    ``ROUTINE.NAME`` of each routine datum (``Main.i``) in a run of one task; with several
    tasks ``TASK.NAME`` of each task's own datum (``T_ROB1.count``) and ``TASK.ROUTINE.NAME``
    of its routines' data.  A name a routine's statements use means the datum of that
    routine, else of the running task, else the shared one (RAPID's routine data are seen
    by their routine alone, a task's data by its task alone; shared PERS keep plain names)."""
    tasks = task_names(steps)
    routines: dict[str, set] = {}
    for step in steps:
        for frame in step.stack:
            routines.setdefault(frame.task.upper(), set()).add(frame.routine.upper())
    found = set()
    for step in steps:
        for change in step.changes:
            parts = INDEX.sub("", change.name.removeprefix("signal ")).upper().split(".")
            if not tasks:
                if len(parts) > 1 and parts[0] in routines.get("", ()):
                    found.add(f"{parts[0]}.{parts[1]}")
            elif len(parts) > 1 and parts[0] in tasks:
                routine = len(parts) > 2 and parts[1] in routines.get(parts[0], ())
                found.add(".".join(parts[:3] if routine else parts[:2]))
    return frozenset(found)


def task_names(steps: Sequence[TraceStep]) -> frozenset:
    """The tasks the trace's call stacks name (upper case), empty for a run of one task."""
    return frozenset(frame.task.upper() for step in steps for frame in step.stack if frame.task)


def own_frames(step: TraceStep, task: Optional[str]) -> tuple:
    """The frames of ``task`` (upper case) in the step's call stack; every frame when the
    task is not known (None) or the run has one task."""
    if not task:
        return step.stack
    return tuple(frame for frame in step.stack if frame.task.upper() == task)


def running_tasks(steps: Sequence[TraceStep]) -> list[Optional[str]]:
    """The task that runs each step (upper case; "" for a run of one task): the one whose
    innermost routine is at the step's statement, or of several there, the one whose
    frames the next step finds changed; None where the trace does not tell."""
    if not task_names(steps):
        return [""] * len(steps)
    found: list[Optional[str]] = []
    for number, step in enumerate(steps):
        transition = step.transition
        at = [] if transition is None or not transition.file else \
            [frame.task.upper() for frame in _innermost(step.stack)
             if (frame.file, frame.line) == (transition.file, transition.line)]
        if len(at) > 1 and number + 1 < len(steps):
            after = steps[number + 1]
            at = [task for task in at if own_frames(step, task) != own_frames(after, task)]
        found.append(at[0] if len(at) == 1 else None)
    return found


def _innermost(stack: Sequence) -> list:
    """The innermost frame of each task in an all-tasks call stack (outermost first)."""
    last: dict[str, object] = {}
    for frame in stack:
        last[frame.task] = frame
    return list(last.values())


def _in_scope(words, step: TraceStep, scoped: frozenset, task: Optional[str] = "") -> set:
    """The scoped name of each word (``routine_data``) for a step run by ``task`` ("": one
    task; None: not known, so a word may mean any datum of its name)."""
    if not scoped:
        return set(words)
    if task is None:
        return {name for word in words for name in
                (word, *(s for s in scoped if s.endswith("." + word)))}
    frames = own_frames(step, task)
    if not frames:
        return set(words)
    routine = frames[-1].routine.upper()
    prefixes = (f"{task}.{routine}.", f"{task}.") if task else (f"{routine}.",)
    found = set()
    for word in words:
        found.add(next((prefix + word for prefix in prefixes if prefix + word in scoped), word))
    return found


def scoped_forms(name: str) -> tuple:
    """The scoped names a shown datum may be read by (``routine_data``): ``T_ROB1.MAIN.I``
    and ``T_ROB1.MAIN`` of ``T_ROB1.main.i{2}``, upper case."""
    parts = INDEX.sub("", name.removeprefix("signal ")).upper().split(".")
    return tuple(".".join(parts[:count]) for count in (2, 3) if len(parts) >= count)


def scoped_reads(trace: Trace, steps: Sequence[TraceStep]) -> frozenset:
    """What the ``steps`` of the trace read, scoped as ``needed_steps`` scopes them: routine
    and task data by their scoped names on a path that ends in an error, plain names
    otherwise."""
    every = [*trace.prefix, *trace.cycle]
    scoped = routine_data(every) if not (trace.cycle or trace.bad_prefix) else frozenset()
    tasks = dict(zip((step.index for step in every), running_tasks(every)))
    return frozenset().union(*(reads_of(step, scoped, tasks.get(step.index, ""))
                               for step in steps))


def with_robot(words) -> frozenset:
    """``words`` (upper case), and the robot's position when one of them reads it."""
    return frozenset(words | {ROBOT} if ROBOT_READERS.intersection(words) else words)


def writes_of(step: TraceStep, scoped: frozenset = frozenset(),
              task: Optional[str] = "") -> frozenset:
    """Every identifier a changed name may be about (``main.reg1{2}``: MAIN and REG1), and
    the datum of each assignment's target (an assignment of the value it had changes
    nothing, yet the value read after it comes from it).  ``scoped`` (``routine_data``):
    a routine's or task's datum is ``ROUTINE.NAME`` or ``TASK.NAME`` alone."""
    found = set()
    for text in statements_of(step):
        target, assigns, _ = text.partition(":=")
        if assigns and ASSIGNED.match(target):
            found.add(IDENTIFIER.match(target.strip()).group().upper())
    found |= _input_targets(step)
    found = _in_scope(found, step, scoped, task)
    for change in step.changes:
        parts = INDEX.sub("", change.name.removeprefix("signal ")).upper().split(".")
        named = next((".".join(parts[:count]) for count in (3, 2)
                      if len(parts) >= count and ".".join(parts[:count]) in scoped), None)
        if named is not None:
            found.add(named)
        else:
            found.update(parts[:2])
    return frozenset(found)


def is_control(step: TraceStep, raised: bool = False) -> bool:
    """Whether the step decides the run's path (``raised``: the next step starts an ERROR
    handler, so this one raised an error), or is not a plain statement at all."""
    if step.kind != TRANSITION or step.transition is None or not step.transition.location:
        return True
    if raised or any(name != TASK_CHOICE and not _named_read(name, step)
                     for name in step.transition.inputs):
        return True                 # an error raised, an input chosen (not the task to run)
    if any(change.name in ALWAYS_KEPT or names_errno(change.name)
           for change in step.changes):
        return True
    for text in statements_of(step):
        words = words_of(text)
        if not words or words[0] in CONTROL_WORDS or LABEL.match(text) or text.startswith("%"):
            return True
    return False


def _named_read(name: str, step: TraceStep) -> bool:
    """Whether the input ``name`` is a read of what the step's statements name (``pers_ip``
    passed to a call, ``SocketReceive at f.mod:9:5``'s message): a value the statement
    reads, whose effect on the run is what the step writes (``writes_of`` counts every
    datum the statement names) or the error it raises, so data dependence alone tells
    whether it counts.  A plain statement's only: a branch or a wait is control with
    whatever it reads."""
    first = IDENTIFIER.match(name)
    return first is not None and any(first.group().upper() in words_of(text)
                                     for text in statements_of(step))


CALLED = re.compile(r"[A-Za-z][A-Za-z0-9_]*(?=\s*\()")


def _input_targets(step: TraceStep) -> set:
    """The data a plain statement that chose an input it names may have written: every
    datum it names, but the instruction or routine it runs and the functions it calls.
    An input may leave a datum as it was (``TPReadNum n`` answered with n's value): the
    value read later still comes from the input."""
    transition = step.transition
    if transition is None or not any(_named_read(name, step) for name in transition.inputs):
        return set()
    found = set()
    for text in statements_of(step):
        words = words_of(text)
        if not words or words[0] in CONTROL_WORDS or LABEL.match(text):
            continue
        called = {word.upper() for word in CALLED.findall(STRING.sub('""', text))}
        found.update(word for word in words[1:] if word not in called)
    return found


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
    tasks = running_tasks(steps)
    position = {step.index: number for number, step in enumerate(steps)}
    read = set(names)
    needed = set()
    if trace.cycle:
        for step in [*trace.cycle, *([trace.closing] if trace.closing else [])]:
            read |= reads_of(step)
            if step.index in position:
                needed.add(step.index)
                needed.update(call.index for call in
                              _entering_calls(steps, position[step.index], tasks))
    elif trace.prefix:
        needed.add(trace.prefix[-1].index)
    single = _plain_names(steps)
    # data by routine and task (a loop counter i of one routine is not another's i, one
    # task's socket not another's), for a path that ends in an error: a cycle's and a
    # property's reads stay plain names
    scoped = routine_data(steps) if not (trace.cycle or trace.bad_prefix) else frozenset()
    prefix = steps[:len(trace.prefix)]
    left = returned_calls(prefix, handler_starts)
    for end, start in _left_compounds(prefix, compound_exits).items():
        left[end] = min(start, left.get(end, start))
    # with several tasks, a path ending in an uncaught error: a statement that decides only
    # the path of a task no kept step runs in decided nothing the error depends on
    active = {tasks[len(prefix) - 1]} if scoped and prefix and stops_program(prefix[-1]) \
        and tasks[len(prefix) - 1] else None
    number = len(trace.prefix) - 1
    while number >= 0:
        start = left.get(number)
        if start is not None and not any(
                _needed_inside(steps[at], needed, read, scoped, tasks[at])
                for at in range(start, number + 1)):
            number = start - 1          # the whole stretch: nothing kept reads what it did
            continue
        step, task = steps[number], tasks[number]
        number -= 1
        if step.index in needed or not read.isdisjoint(writes_of(step, scoped, task)) or (
                is_control(step, _raises(steps, number + 1, handler_starts)) and (
                    active is None or task is None or task in active or
                    any(change.name in ALWAYS_KEPT for change in step.changes))):
            if active is not None and step.kind != INITIAL:
                if task is None:
                    active = None
                else:
                    active.add(task)
            needed.add(step.index)
            reads = reads_of(step, scoped, task)
            read -= (_whole_assigned(step) & single) - reads
            read |= reads
            needed.update(call.index for call in _entering_calls(steps, number + 1, tasks))
    return frozenset(needed)


def stops_program(step: TraceStep) -> bool:
    """Whether the step stops the program with an uncaught error."""
    return any(change.name == "program" and (change.new or "").startswith("stopped: ")
               for change in step.changes)


def _needed_inside(step: TraceStep, needed: set, read: set, scoped: frozenset,
                   task: Optional[str]) -> bool:
    """Whether a step inside a returned call keeps the call: it is kept already, writes
    what a kept step reads, or changes ERRNO or the program's status."""
    return step.index in needed or not read.isdisjoint(writes_of(step, scoped, task)) or \
        any(change.name in ALWAYS_KEPT or names_errno(change.name) for change in step.changes)


def _left_compounds(steps: Sequence[TraceStep], exits: Mapping) -> dict:
    """IF, FOR, WHILE and TEST statements the run entered and went on from to the statement
    after them (``exits``: ``RapidDescriber.compound_exits``), as {number of the last step
    inside: number of the first (the statement's own)}: every step between is the
    statement's (its lines, in the same routine) or deeper in a call, before the path's
    last step.  With several tasks, every step of the stretch runs in the statement's task
    (``running_tasks``), and the statement after is that task's next step."""
    found: dict[int, int] = {}
    tasks = running_tasks(steps)
    last = len(steps) - 1
    for number in range(last):
        step, task = steps[number], tasks[number]
        where = _place(step)
        exit_ = exits.get(where) if where is not None else None
        if exit_ is None or task is None:
            continue
        end_line, after = exit_
        frames = own_frames(step, task)
        depth, routine = len(frames), frames[-1].routine if frames else None

        def inside(at: int) -> bool:
            place, own = _place(steps[at]), own_frames(steps[at], task)
            return place is not None and tasks[at] == task and (len(own) > depth or (
                len(own) == depth and own[-1].routine == routine and
                place[0] == where[0] and where[1] <= place[1] <= end_line))
        if number > 0 and inside(number - 1) and \
                len(own_frames(steps[number - 1], task)) == depth:
            continue                    # a later round of a loop, not its entry
        end = number
        while end < last and inside(end + 1):
            end += 1
        following = _next_own(tasks, end, task) if end < last else None
        if following is not None and len(own_frames(steps[following], task)) == depth and \
                _place(steps[following]) == after:
            found.setdefault(end, number)
    return found


def _next_own(tasks: Sequence[Optional[str]], number: int, task: str) -> Optional[int]:
    """The number of the next step after ``number`` that ``task`` runs, past steps of other
    tasks; None when there is none or a step whose task is not known comes first."""
    for later in range(number + 1, len(tasks)):
        if tasks[later] == task:
            return later
        if tasks[later] is None:
            return None
    return None


def _place(step: TraceStep) -> Optional[tuple]:
    transition = step.transition
    return None if transition is None or not transition.file else \
        (transition.file, transition.line)


def returned_calls(steps: Sequence[TraceStep], handler_starts: frozenset) -> dict:
    """Routine calls the run came back from, as {number of the last step inside: number of
    the first}: the step after the last one is back in the calling routine, at another
    statement than the call (not an ERROR handler's start, not the call's statement run
    again for a FUNC's value), before the path's last step.  With several tasks, the call
    and every step inside run in one task (``running_tasks``), whose own frames tell the
    depth, and the step after is that task's next (other tasks' steps may come between)."""
    found: dict[int, int] = {}
    tasks = running_tasks(steps)
    last = len(steps) - 1
    for number in range(1, last):
        task = tasks[number]
        call, first = steps[number], steps[number + 1]
        stack, entered = own_frames(call, task), own_frames(first, task)
        depth = len(stack)
        if task is None or tasks[number + 1] != task or call.transition is None or \
                first.transition is None or len(entered) != depth + 1 or \
                entered[:depth - 1] != stack[:-1]:
            continue
        end = number + 1
        while end < last and tasks[end + 1] == task and \
                len(own_frames(steps[end + 1], task)) > depth:
            end += 1
        after = _next_own(tasks, end, task) if end < last else None
        back = steps[after] if after is not None else None
        own = own_frames(back, task) if back is not None else ()
        if back is None or back.transition is None or \
                len(own) != depth or own[-1].routine != stack[-1].routine or \
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


def _entering_calls(steps: Sequence[TraceStep], number: int,
                    tasks: Sequence[Optional[str]]) -> list[TraceStep]:
    """The latest earlier steps at each caller frame's line: the calls that led here.

    With several tasks, the frames of the task that runs the step (``running_tasks``;
    every task's when that is not known, which keeps more, never less)."""
    own = steps[number].transition
    found = []
    for frame in own_frames(steps[number], tasks[number]):
        if own is not None and (frame.file, frame.line) == (own.file, own.line):
            continue
        for earlier in range(number - 1, -1, -1):
            transition = steps[earlier].transition
            if tasks[number] and tasks[earlier] not in (tasks[number], None):
                continue                # another task at that line of a shared module
            if transition is not None and transition.file == frame.file and \
                    transition.line == frame.line:
                found.append(steps[earlier])
                break
    return found
