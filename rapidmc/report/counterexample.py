"""A counterexample as text that fits on a screen: what went wrong first, then the steps.

``counterexample_lines(trace)`` writes, under a violated property:

* for a path that ends in an error (an uncaught run-time error, a wait
  forever), the headline of ``headline``;
* the initial state limited to the data the steps' lines and the property
  name, with a count of the rest;
* each step's changes, values longer than ``WIDTH`` characters shortened
  (``[[932.4,1557.5,2189.5],...]``);
* a stretch of steps that repeats the lines just before it (a retry loop,
  a FOR loop filling an array) folded into one line with the values it
  leaves behind;
* rounds of one sequence of lines that a RETRY or a GOTO closes (``rounds``)
  told between the first round and the last in one line, with what changed
  across them (``steps 19-51: 3 more rounds of lines 20-28 (ERROR handler
  RETRY) as in steps 8-18; retries 1 -> 4``);
* a run of steps the violation does not depend on (``trace_slice``: they
  write only data that no step kept, no error line and no atom reads) told
  in one line (``steps 2-18: waypoints{1..17} assigned, not read by the error``);
* a step that changes nothing on the line of the step after it (a one-line
  ``IF cond statement``: its test, then its statement) shown with that step
  (``steps 26-27``);
* of a call's new routine data, what the steps shown read (the rest counted);
  routine data that ends with a return is not listed (the ENDPROC says so);
* an input chosen by the statement of its own step without the ``at file:line:col``
  its name carries (the step's line says where).

Files are named relative to the current folder when they are under it, else
relative to the folder that holds them all, named once above the steps.

``TextOptions(full=True)`` (``check --full-trace``) prints every initial
value, every value in full and every step.  JSON and HTML always carry every
step and full values; the names are the same.
"""
from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, replace
from typing import Iterable, Optional, Sequence, Union

from ..check.trace import INITIAL, Change, Trace, TraceStep
from ..semantics.robots import ROBOT_TCP
from ..semantics.task_registers import names_errno
from .headline import headline_lines
from .rounds import Rounds, fold_rounds
from .trace_slice import (needed_steps, own_frames, reads_of, returned_calls, running_tasks,
                          scoped_forms, scoped_reads, stops_program, words_of)
from .trace_text import (INDEX, SOURCE_WIDTH, STRING_WIDTH, WAS_WIDTH, WIDTH,
                         TextOptions, array_elements, data_names, file_names, shorten,
                         shown_location, shown_value)

LOOP_STARTS = "-- loop starts here (repeats forever) --"
LONGEST_PERIOD = 40    # the longest stretch of steps looked for as a repeat
FEWEST_REPEATS = 3     # a stretch folds when it runs at least this many times in a row
NET_SHOWN = 4          # values listed after a folded stretch (then a count)
SLICED_SHOWN = 4       # data named in a line of steps left out (then a count)
FOLDED_WIDTH = 40      # each of them, at most
ELEMENTS_SHOWN = 4     # changed elements of a long array listed in a step (then a count)
ALWAYS_SHOWN = ("program", "ERRNO")


@dataclass(frozen=True)
class Folded:
    """Steps ``hidden`` that repeat the lines of steps ``first``-``last`` ``times`` more times."""

    first: int
    last: int
    times: int
    hidden: tuple[TraceStep, ...]


@dataclass(frozen=True)
class Joined:
    """Step ``step`` shown with the step ``first`` before it, on the same line, which
    changed nothing (``steps 26-27``)."""

    first: int
    step: TraceStep


@dataclass(frozen=True)
class Tested:
    """Steps ``steps``: an IF's condition and the ELSEIF conditions after it, each false,
    none changing anything (shown as the first with a count)."""

    steps: tuple[TraceStep, ...]


@dataclass(frozen=True)
class RanThrough:
    """Steps ``steps``: the whole run of a routine ``routine`` the path called and came back
    from, choosing no input and raising no error inside (shown as what it left behind)."""

    routine: str
    steps: tuple[TraceStep, ...]


@dataclass(frozen=True)
class SlicedAway:
    """Steps ``steps`` (two or more in a row) that the violation does not depend on, ``reader``
    naming what does (``the error``)."""

    steps: tuple[TraceStep, ...]
    reader: str


# --- the whole counterexample ------------------------------------------------------


def counterexample_lines(trace: Trace, options: TextOptions = TextOptions()) -> list[str]:
    """The headline (for a path ending in an error), then the steps with the loop markers."""
    count = len(trace.prefix) + len(trace.cycle)
    if trace.cycle:
        head = (f"  counterexample: {_steps(len(trace.prefix))}, "
                f"then a loop of {_steps(len(trace.cycle))}")
    elif trace.bad_prefix:
        head = f"  counterexample: {_steps(count)}, then any run (no loop needed)"
    else:
        head = f"  counterexample: {_steps(count)}"
    if not options.full:
        trace = chosen_inputs_only(trace)
    options = replace(options, files=file_names(trace_files(trace)))
    lines = headline_lines(trace, options)
    lines.extend(f"  {line}" for line in options.files.legend())
    lines.append(head)
    head_at = len(lines) - 1
    items = _prefix_items(trace, needed_steps(trace, options.names, options.handler_starts,
                                              options.compound_exits), options)
    items = _calls_told_once(items, trace, options)
    hidden = {step.index for item in items if isinstance(item, SlicedAway) for step in item.steps}
    shown = [step for step in [*trace.prefix, *trace.cycle] if step.index not in hidden]
    read = options.names | scoped_reads(trace, shown)
    for item in _joined(items, options, trace.loop_start):
        lines.extend(_item_lines(item, options, read))
    if trace.cycle:
        lines.append("  " + LOOP_STARTS)
        for item in _joined(_folded(trace.cycle, options), options, trace.loop_start):
            lines.extend(_item_lines(item, options, read))
        lines.extend(step_lines(trace.closing, options))
        lines.append(f"  -- loop closes: back to the state of step {trace.loop_start} --")
    if not options.full and any(LEFT_OUT.search(line) for line in lines[head_at + 1:]):
        lines[head_at] += " (--full-trace shows every step and value)"
    return lines


# what a line says was left out of the text: a stretch of steps, or values counted
LEFT_OUT = re.compile(r"^    -- steps |\(\d+ more (new )?values?\b|\d+ values, none read|"
                      r"elements changed: .* and \d+ more$")


def _prefix_items(trace: Trace, needed: frozenset, options: TextOptions) -> list:
    """The prefix's steps with their repeats folded, then each run of two or more shown
    steps the violation does not need as one ``SlicedAway``."""
    folded = _folded(trace.prefix, options)
    if options.full or not (trace.cycle or trace.ending):
        return folded                          # an ending of unknown reads: all of it
    reader = "the loop or the property" if trace.cycle else \
        "the property" if trace.bad_prefix else "the error"
    items: list = []
    run: list[TraceStep] = []
    for item in [*folded, None]:
        if isinstance(item, TraceStep) and item.index not in needed:
            run.append(item)
            continue
        if isinstance(item, (Folded, Rounds)) and \
                not any(step.index in needed for step in item.hidden):
            run.extend(item.hidden)         # repeats of steps the violation does not need
            continue
        items.extend(run if len(run) < 2 else [SlicedAway(tuple(run), reader)])
        run = []
        if item is not None:
            items.append(item)
    return items


FEWEST_CALL_STEPS = 3   # a call's run told in one line from this many steps on


def _calls_told_once(items: list, trace: Trace, options: TextOptions) -> list:
    """The prefix's items with each routine call the path came back from told in one
    ``RanThrough`` (the call's own step stays): where no step inside chose an input or set
    ERRNO or the program's status, the run inside followed from the state at the call, so
    what it left behind says all of it.  The outermost such call, ``FEWEST_CALL_STEPS`` or
    more steps long, and only where no item reaches out of it; not with ``options.full``
    (``trace_slice.returned_calls``: with several tasks, a call whose run no other task's
    step interrupts)."""
    if options.full or not items:
        return items
    prefix = trace.prefix
    chosen: list[tuple[int, int]] = []          # (first, last) step indexes
    for end, start in sorted(returned_calls(prefix, options.handler_starts).items(),
                             key=lambda pair: (pair[1], -pair[0])):
        inside = prefix[start:end + 1]
        first, last = inside[0].index, inside[-1].index
        if len(inside) < FEWEST_CALL_STEPS or any(a <= first and last <= b for a, b in chosen):
            continue
        if any(step.transition is None or step.transition.inputs or any(
                change.name in ALWAYS_SHOWN or names_errno(change.name)
                for change in step.changes) for step in inside):
            continue
        chosen.append((first, last))
    if not chosen:
        return items
    spans = [_index_span(item) for item in items]
    kept = [(a, b) for a, b in chosen
            if all(b < lo or hi < a or (a <= lo and hi <= b) for lo, hi in spans)]
    told: list = []
    tasks = dict(zip((step.index for step in prefix), running_tasks(prefix)))
    by_first = {step.index: step for step in prefix}
    for item, (lo, hi) in zip(items, spans):
        around = next(((a, b) for a, b in kept if a <= lo and hi <= b), None)
        if around is None:
            told.append(item)
        elif lo == around[0] or not told or not isinstance(told[-1], RanThrough) or \
                told[-1].steps[0].index != around[0]:
            steps = tuple(step for step in prefix if around[0] <= step.index <= around[1])
            task = tasks[around[0]]
            frames = own_frames(by_first[around[0]], task)
            routine = frames[-1].routine if frames else "?"
            if told and isinstance(told[-1], TraceStep):
                # the call's own step: the routine's data it makes end with the run told
                call, made = told[-1], f"{frames[-1].task}.{routine}." if task else f"{routine}."
                told[-1] = replace(call, changes=tuple(
                    change for change in call.changes if change.old is not None or
                    not change.name.upper().startswith(made.upper())))
            told.append(RanThrough(routine, steps))
    return told


def _index_span(item) -> tuple[int, int]:
    """The first and last step numbers an item of the prefix covers."""
    if isinstance(item, TraceStep):
        return item.index, item.index
    steps = item.hidden if isinstance(item, (Folded, Rounds)) else item.steps
    return steps[0].index, steps[-1].index


def ran_through_line(ran: RanThrough) -> str:
    """``-- steps 4-10: ROS_init_socket ran (no input chosen); after it: server_socket =
    <socketdev: listening> --``."""
    steps = ran.steps
    what = f"steps {steps[0].index}-{steps[-1].index}: {ran.routine} ran (no input chosen)"
    said = _outputs_written(steps)
    if said:
        what += ", " + ", ".join(said)
    return f"    -- {what}{_left_behind(steps, 'it')} --"


def _left_behind(steps: Sequence[TraceStep], them: str) -> str:
    """``; after them: n = 5, ok = TRUE and 2 more``: what a run of steps left changed."""
    net = _grouped(net_changes(steps))
    if not net:
        return ""
    more = len(net) - NET_SHOWN
    return f"; after {them}: {', '.join(net[:NET_SHOWN])}" + \
        (f" and {more} more" if more > 0 else "")


def _joined(items: list, options: TextOptions, loop_start: Optional[int]) -> list:
    """The items with each step that changed nothing, chose nothing and wrote nothing joined
    to the step after it on the same line (unless ``options.full``, or it is where the loop
    starts again)."""
    if options.full:
        return items
    items = _tests_told_once(items)
    joined: list = []
    skipped: Optional[TraceStep] = None
    for item in items:
        if skipped is not None:
            if isinstance(item, TraceStep) and _same_line(skipped, item):
                joined.append(Joined(skipped.index, item))
                skipped = None
                continue
            joined.append(skipped)
            skipped = None
        if isinstance(item, TraceStep) and item.kind != INITIAL and item.transition is not None \
                and not (item.changes or item.transition.inputs or item.transition.output) \
                and item.index != loop_start:
            skipped = item
            continue
        joined.append(item)
    if skipped is not None:
        joined.append(skipped)
    return joined


ELSEIF = re.compile(r"^ELSEIF\b", re.IGNORECASE)
FEWEST_TESTS = 3       # an IF and its ELSEIFs told in one line from this many on


def _tests_told_once(items: list) -> list:
    """The items with each run of steps that test an IF's conditions one after another
    (its IF, then ELSEIFs, or ELSEIFs alone), each changing, choosing and writing nothing,
    told as one ``Tested`` when ``FEWEST_TESTS`` or more of them are followed by another
    test of the chain (so each of those was false); the last test stays a step."""
    told: list = []
    run: list[TraceStep] = []

    def flush():
        # each test but the last was false (an ELSEIF of its chain followed it); the last
        # may have held: it stays a step of its own
        if len(run) - 1 >= FEWEST_TESTS:
            told.append(Tested(tuple(run[:-1])))
            told.append(run[-1])
        else:
            told.extend(run)
        run.clear()
    for item in items:
        if isinstance(item, TraceStep) and _a_silent_test(item) and (
                ELSEIF.match(item.transition.source) if run else True) and (
                not run or item.transition.file == run[-1].transition.file):
            if not run and not re.match(r"^(ELSE)?IF\b", item.transition.source, re.IGNORECASE):
                told.append(item)
                continue
            run.append(item)
            continue
        flush()
        told.append(item)
    flush()
    return told


def _a_silent_test(step: TraceStep) -> bool:
    transition = step.transition
    return step.kind != INITIAL and transition is not None and not (
        step.changes or transition.inputs or transition.output)


def tested_line(tested: Tested, options: TextOptions) -> str:
    """``steps 44-51  LogicZ.mod:76-98  IF A_onlySide1 = TRUE THEN  (and 7 ELSEIF tests
    after it: all false)``."""
    first, last = tested.steps[0], tested.steps[-1]
    location = shown_location(first.transition, options.files)
    source = shorten(first.transition.source, SOURCE_WIDTH)
    return (f"    steps {first.index}-{last.index}  {location}-{last.transition.line}  {source}"
            f"  (and {len(tested.steps) - 1} ELSEIF tests after it: all false)")


def _same_line(first: TraceStep, then: TraceStep) -> bool:
    a, b = first.transition, then.transition
    return b is not None and then.kind == first.kind and \
        (a.file, a.line, a.source) == (b.file, b.line, b.source)


def trace_files(trace: Trace) -> list[str]:
    """The files the trace's steps are in, in order of first use."""
    steps = [*trace.prefix, *trace.cycle, *([trace.closing] if trace.closing else [])]
    return list(dict.fromkeys(step.transition.file for step in steps
                              if step.transition is not None and step.transition.file))


def chosen_inputs_only(trace: Trace) -> Trace:
    """The trace with each input shown at the step that chose it: an input the step just
    before chose with the same value (a signal an interrupt watches is chosen at every
    step) is left out, unless the step's statement names it."""
    previous: dict = {}

    def kept(step: Optional[TraceStep]) -> Optional[TraceStep]:
        nonlocal previous
        transition = step.transition if step is not None else None
        if transition is None:
            previous = {}
            return step
        named = reads_of(step)
        inputs = {name: value for name, value in transition.inputs.items()
                  if previous.get(name) != value or name.upper() in named}
        previous = dict(transition.inputs)
        if len(inputs) == len(transition.inputs):
            return step
        return replace(step, transition=replace(transition, inputs=inputs))

    prefix = tuple(kept(step) for step in trace.prefix)
    cycle = tuple(kept(step) for step in trace.cycle)
    return replace(trace, prefix=prefix, cycle=cycle, closing=kept(trace.closing))


def _steps(count: int) -> str:
    return f"{count} step" if count == 1 else f"{count} steps"


def _folded(steps: Sequence[TraceStep], options: TextOptions) -> list:
    """The steps with each chain of rounds (``rounds``) folded, then the repeats of the
    steps between them; every step with ``options.full``."""
    if options.full:
        return list(steps)
    items: list = []
    run: list[TraceStep] = []
    for item in fold_rounds(steps):
        if isinstance(item, Rounds):
            items.extend(fold_repeats(run))
            items.append(item)
            run = []
        else:
            run.append(item)
    return items + fold_repeats(run)


def _item_lines(item: Union[TraceStep, Folded, Rounds, SlicedAway, Joined, Tested, RanThrough],
                options: TextOptions, read: frozenset) -> list[str]:
    if isinstance(item, Folded):
        return [folded_line(item)]
    if isinstance(item, Rounds):
        return [rounds_line(item, read)]
    if isinstance(item, SlicedAway):
        return [sliced_line(item)]
    if isinstance(item, Joined):
        return step_lines(item.step, options, read, first=item.first)
    if isinstance(item, Tested):
        return [tested_line(item, options)]
    if isinstance(item, RanThrough):
        return [ran_through_line(item)]
    if item.kind == INITIAL and not options.full:
        return initial_lines(item, read)
    return step_lines(item, options, read)


# --- one step ----------------------------------------------------------------------


def step_lines(step: TraceStep, options: TextOptions = TextOptions(),
               read: Optional[frozenset] = None, first: Optional[int] = None) -> list[str]:
    """One step: number, location and source, then inputs, output and changed values.

    Unless ``options.full``: routine data that ends (a return, the program stopping) is
    not listed, and when the names the shown steps ``read`` are given, a call's new
    routine data only where they read it (the rest counted).  ``first``: the number of
    the step joined to this one (``steps 26-27``)."""
    transition = step.transition
    width = None if options.full else SOURCE_WIDTH
    if step.kind == INITIAL:
        head = "initial state"
    else:
        source = shorten(transition.source, width)
        location = shown_location(transition, options.files)
        head = f"{location}  {source}" if location else source
    number = f"steps {first}-{step.index}" if first is not None else f"step {step.index}"
    lines = [f"    {number}  {head}".rstrip()]
    if transition is not None:
        lines.extend(f"        input: {_input_name(name, transition, options)} = "
                     f"{shorten(value, None if options.full else WIDTH)}"
                     for name, value in transition.inputs.items())
        if transition.output and (options.full or not _told_by_source(transition)):
            output = json.dumps(transition.output, ensure_ascii=False)
            lines.append(f"        output: {shorten(output, width)}")
    changes = step.changes
    unread = 0
    if not options.full:
        changes = tuple(change for change in changes if change.new is not None)
        if stops_program(step) and "SOCKETCLOSE" not in words_of(transition.source):
            changes = tuple(change for change in changes if not CLOSED.match(change.new))
        if read is not None and step.kind != INITIAL:
            kept = tuple(change for change in changes
                         if change.old is not None or _new_data_read(change.name, read))
            unread, changes = len(changes) - len(kept), kept
    if options.full or step.kind == INITIAL:
        lines.extend(f"        {change_text(change, options.full)}" for change in changes)
    else:
        lines.extend(f"        {text}" for text in _new_data_together(changes))
    if unread:
        lines.append(f"        ({unread} more new {'value' if unread == 1 else 'values'} the "
                     "trace does not read)")
    return lines


def _new_data_together(changes: Sequence[Change]) -> list[str]:
    """The changes' texts, a call's new routine data told together after its routine's name
    (``Pick: slot = 0, count = 3``, lines of at most ``SOURCE_WIDTH`` characters), where
    the routine holds two or more; every other change on a line of its own."""
    routines: dict = {}
    for change in changes:
        head, dot, _ = change.name.rpartition(".")
        if change.old is None and dot and "{" not in change.name:
            routines.setdefault(head, []).append(change)
    texts, told = [], set()
    for change in changes:
        head = change.name.rpartition(".")[0]
        together = routines.get(head, ())
        if len(together) < 2 or change not in together:
            texts.append(change_text(change))
            continue
        if head in told:
            continue
        told.add(head)
        line = f"{head}:"
        for member in together:
            part = change_text(member)[len(head) + 1:]
            if len(line) + len(part) + 2 > SOURCE_WIDTH and line != f"{head}:":
                texts.append(line.rstrip(","))
                line = f"{head}:"
            line += f" {part},"
        texts.append(line.rstrip(","))
    return texts


def _told_by_source(transition) -> bool:
    """Whether the step's output is the text of string literals its line shows
    (``TPWrite "Ready";``, a TPReadFK's prompt): each line written is one literal."""
    literals = {text.replace('""', '"') for text in STRING_LITERAL.findall(transition.source)}
    return all(line in literals for line in transition.output.rstrip("\n").split("\n"))


STRING_LITERAL = re.compile(r'"((?:[^"]|"")*)"')
# a socket as the controller leaves it when the program stops (not listed at that step)
CLOSED = re.compile(r"^<socketdev: closed")


def _input_name(name: str, transition, options: TextOptions) -> str:
    """An input's name, without the ``at file:line:col`` of the step's own line (unless
    ``options.full``)."""
    if options.full or not transition.file:
        return name
    own = f" at {os.path.basename(transition.file)}:{transition.line}:"
    at = name.rfind(own)
    if at > 0 and name[at + len(own):].isdigit():
        return name[:at]
    return name


def _new_data_read(name: str, read: frozenset) -> bool:
    """Whether the steps shown read a call's new datum ``routine.name`` (by its own name:
    the call's line names the routine, not its data)."""
    names = data_names(name)
    own = names[1:] if len(names) > 1 else names
    return name in ALWAYS_SHOWN or names_errno(name) or not read.isdisjoint(own) or \
        not read.isdisjoint(scoped_forms(name))


def change_text(change: Change, full: bool = False) -> str:
    """``x = 1  (was 0)``; values shortened unless ``full``, a long array written whole
    with a few elements changed shown by those elements."""
    if full:
        def value(text: str, _: int) -> str:
            return text
    else:
        def value(text: str, width: int) -> str:
            return shown_value(text, width, STRING_WIDTH)
    if change.new is None:
        if change.old is None:
            return f"{change.name} (no longer exists)"
        return f"{change.name} (no longer exists; was {value(change.old, WAS_WIDTH)})"
    if change.old is None:
        return f"{change.name} = {value(change.new, WIDTH)}"
    elements = None if full else changed_elements(change)
    if elements is not None:
        return elements
    return f"{change.name} = {value(change.new, WIDTH)}  (was {value(change.old, WAS_WIDTH)})"


def changed_elements(change: Change) -> Optional[str]:
    """``table: 4 of 120 elements changed: {5} = 7 (was 5), {40} = 7 (was 40), ...``: an
    array too long to show whole, written with fewer than half of its elements changed;
    None for any other change."""
    old, new = array_elements(change.old or ""), array_elements(change.new or "")
    if not old or len(change.new) <= WIDTH or [s for s, _ in old] != [s for s, _ in new]:
        return None
    differing = [(suffix, was, now) for (suffix, was), (_, now) in zip(old, new) if was != now]
    if not differing or 2 * len(differing) >= len(new):
        return None
    listed = ", ".join(f"{suffix} = {shown_value(now, FOLDED_WIDTH, FOLDED_WIDTH)} "
                       f"(was {shown_value(was, FOLDED_WIDTH, FOLDED_WIDTH)})"
                       for suffix, was, now in differing[:ELEMENTS_SHOWN])
    more = len(differing) - ELEMENTS_SHOWN
    return (f"{change.name}: {len(differing)} of {len(new)} elements changed: {listed}"
            + (f" and {more} more" if more > 0 else ""))


def initial_lines(step: TraceStep, read: frozenset) -> list[str]:
    """The initial state: the values of the data the trace reads, and a count of the rest."""
    shown = [change for change in step.changes
             if change.name in ALWAYS_SHOWN or names_errno(change.name) or
             not read.isdisjoint(data_names(change.name) + scoped_forms(change.name))]
    rest = len(step.changes) - len(shown)
    if rest and not shown:
        return [f"    step {step.index}  initial state ({rest} {'value' if rest == 1 else 'values'}"
                ", none read by the trace)"]
    lines = [f"    step {step.index}  initial state"]
    lines.extend(f"        {change_text(change)}" for change in shown)
    if rest:
        lines.append(f"        ({rest} more {'value' if rest == 1 else 'values'} the trace "
                     "does not read)")
    return lines


# --- folding repeated steps --------------------------------------------------------


def fold_repeats(steps: Sequence[TraceStep]) -> list[Union[TraceStep, Folded]]:
    """The steps, with each stretch that runs the same lines as the one before it folded.

    A stretch of up to ``LONGEST_PERIOD`` steps repeated at least
    ``FEWEST_REPEATS`` times in a row (same lines, inputs, output, and the same
    data changed, elements of an array counted as one) is shown once; the
    repeats become one ``Folded`` item.
    """
    shapes = [_shape(step) for step in steps]
    items: list[Union[TraceStep, Folded]] = []
    start = 0
    while start < len(steps):
        period, times = _repeat_at(shapes, start)
        if times < FEWEST_REPEATS:
            items.append(steps[start])
            start += 1
            continue
        items.extend(steps[start:start + period])
        hidden = tuple(steps[start + period:start + times * period])
        items.append(Folded(steps[start].index, steps[start + period - 1].index,
                            times - 1, hidden))
        start += times * period
    return items


def _shape(step: TraceStep) -> tuple:
    transition = step.transition
    where = (transition.file, transition.line, transition.source,
             tuple(transition.inputs.items()), transition.output) if transition else None
    return (step.kind, where, tuple(INDEX.sub("{}", change.name) for change in step.changes))


def _repeat_at(shapes: list, start: int) -> tuple[int, int]:
    """The period and count of the longest run of repeats starting at ``start`` (count 1: none)."""
    best = (1, 1)
    for period in range(1, min(LONGEST_PERIOD, (len(shapes) - start) // 2) + 1):
        block = shapes[start:start + period]
        times = 1
        while shapes[start + times * period:start + (times + 1) * period] == block:
            times += 1
        if times >= FEWEST_REPEATS and times * period > best[0] * best[1]:
            best = (period, times)
    return best


def folded_line(folded: Folded) -> str:
    """``-- steps 9-20 repeat steps 6-8 4 more times; after them: n = 5, ok = TRUE --``."""
    hidden = folded.hidden
    what = f"steps {hidden[0].index}-{hidden[-1].index} repeat steps {folded.first}-" \
           f"{folded.last} {folded.times} more {'time' if folded.times == 1 else 'times'}"
    return f"    -- {what}{_left_behind(hidden, 'them')} --"


def rounds_line(rounds: Rounds, read: frozenset = frozenset()) -> str:
    """``-- steps 19-51: 3 more rounds of lines 20-28 (ERROR handler RETRY) as in steps 8-18;
    retries 1 -> 4, resets 1 -> 4, 3 FlexPendant lines written --``: what changed across
    the rounds, the data the shown steps ``read`` first."""
    hidden = rounds.hidden
    kind = "ERROR handler RETRY" if rounds.jump == "RETRY" else rounds.jump
    lines = "line" if rounds.lines[0] == rounds.lines[1] else "lines"
    span = str(rounds.lines[0]) if lines == "line" else f"{rounds.lines[0]}-{rounds.lines[1]}"
    what = f"steps {hidden[0].index}-{hidden[-1].index}: {rounds.times} more " \
           f"{'round' if rounds.times == 1 else 'rounds'} of {lines} {span} ({kind}) as in " \
           f"steps {rounds.first}-{rounds.last}"
    changed = [f"retries {rounds.retries[0]} -> {rounds.retries[1]}"] if rounds.retries else []
    net = sorted(net_changes(hidden), key=lambda change: read.isdisjoint(
        data_names(change.name) + scoped_forms(change.name)))
    across = _grouped(net, arrow=True)
    more = len(across) - NET_SHOWN
    changed.extend(across[:NET_SHOWN] + ([f"{more} more values"] if more > 0 else []))
    changed.extend(_outputs_written(hidden))
    return f"    -- {what}{'; ' + ', '.join(changed) if changed else ''} --"


def _grouped(changes: list[Change], arrow: bool = False) -> list[str]:
    """``n = 5`` (``arrow``: ``n 1 -> 5``, from the value before), and for several elements
    of one array ``waypoints{2} to waypoints{12} (11 values)``: what a folded stretch leaves
    behind, one entry per datum."""
    groups: dict[str, list[Change]] = {}
    for change in changes:
        groups.setdefault(INDEX.sub("{}", change.name), []).append(change)
    entries = []
    for members in groups.values():
        if len(members) == 1 and arrow and members[0].old is not None:
            entries.append(f"{members[0].name} {shorten(members[0].old, FOLDED_WIDTH)} -> "
                           f"{shorten(members[0].new, FOLDED_WIDTH)}")
        elif len(members) == 1:
            entries.append(f"{members[0].name} = {shorten(members[0].new, FOLDED_WIDTH)}")
        else:
            entries.append(f"{members[0].name} to {members[-1].name} "
                           f"({len(members)} values)")
    return entries


def net_changes(steps: Iterable[TraceStep]) -> list[Change]:
    """What a run of steps changed in all: each name's first old and last new value."""
    first_old: dict[str, Optional[str]] = {}
    last_new: dict[str, Optional[str]] = {}
    for step in steps:
        for change in step.changes:
            first_old.setdefault(change.name, change.old)
            last_new[change.name] = change.new
    return [Change(name, first_old[name], new) for name, new in last_new.items()
            if new != first_old[name] and new is not None]


# --- steps the violation does not depend on ---------------------------------------


def sliced_line(sliced: SlicedAway) -> str:
    """``-- steps 2-18: waypoints{1..17} assigned, not read by the error --``."""
    steps = sliced.steps
    changes = [change for step in steps for change in step.changes]
    names = list(dict.fromkeys(change.name for change in changes if change.new is not None))
    # a routine's datum is ``Routine.name`` (``TASK.Routine.name`` with several tasks)
    ended = list(dict.fromkeys(change.name.split(".")[-2] for change in changes
                               if change.new is None and "." in change.name))
    # a routine that returned in the stretch took its own data with it
    names = [name for name in names if not set(name.split(".")[:-1]) & set(ended)]
    robots = [name for name in names if name.endswith(ROBOT_TCP)]
    routines = {frame.routine for step in steps for frame in step.stack}
    # the cell's data first, the routines' own (``HomeReturn.nActPos``) after them
    names = sorted((name for name in names if name not in robots),
                   key=lambda name: name.split(".")[0] in routines)
    entries = _name_ranges(names)
    what = []
    tasks = list(dict.fromkeys(task for task in running_tasks(steps) if task))
    if len(tasks) > 1:
        # several tasks ran: which ones, and how many of their values changed
        shown = {frame.task.upper(): frame.task for step in steps for frame in step.stack}
        ran = [shown.get(task, task) for task in tasks]
        what.append(", ".join(ran[:-1]) + f" and {ran[-1]} ran")
        if names:
            what.append(f"{len(names)} {'value' if len(names) == 1 else 'values'} assigned")
    elif entries:
        more = len(entries) - SLICED_SHOWN
        what.append(", ".join(entries[:SLICED_SHOWN]) + (f" and {more} more" if more > 0
                                                        else "") + " assigned")
    if ended:
        what.append(f"{', '.join(ended)} returned" if len(ended) <= 2 else
                    f"{len(ended)} routines returned")
    if robots:
        what.append("the robot moved" if len(robots) == 1 else "the robots moved")
    what.extend(_outputs_written(steps))
    if not what:                 # (what nothing changed, nothing can read)
        return f"    -- steps {steps[0].index}-{steps[-1].index}: nothing changed --"
    return f"    -- steps {steps[0].index}-{steps[-1].index}: {', '.join(what)}, not read by " \
           f"{sliced.reader} --"


# Where a step's output line went: the library marks socket messages and file lines
# (semantics/library/sockets.py, files.py); the rest is FlexPendant text.
OUTPUT_KINDS = (("[socket] ", "socket message", "socket messages", "sent"),
                ("[file ", "file line", "file lines", "written"))


def _outputs_written(steps: Sequence[TraceStep]) -> list[str]:
    """``2 FlexPendant lines written``, ``1 socket message sent``: counted by kind."""
    counts = {"FlexPendant": 0, **{prefix: 0 for prefix, *_ in OUTPUT_KINDS}}
    for step in steps:
        output = step.transition.output if step.transition else ""
        for line in output.splitlines():
            kind = next((prefix for prefix, *_ in OUTPUT_KINDS if line.startswith(prefix)),
                        "FlexPendant")
            counts[kind] += 1
    said = []
    if counts["FlexPendant"]:
        number = counts["FlexPendant"]
        said.append(f"{number} FlexPendant {'line' if number == 1 else 'lines'} written")
    for prefix, one, many, verb in OUTPUT_KINDS:
        if counts[prefix]:
            said.append(f"{counts[prefix]} {one if counts[prefix] == 1 else many} {verb}")
    return said


def _name_ranges(names: Sequence[str]) -> list[str]:
    """Names with the elements of one array put together: ``k{1..3}``, ``reg{2,5}``."""
    groups: dict[str, list[str]] = {}
    for name in names:
        groups.setdefault(INDEX.sub("{}", name), []).append(name)
    entries = []
    for shape, members in groups.items():
        numbers = [_single_index(name) for name in members]
        if len(members) == 1 or shape.count("{}") != 1 or None in numbers:
            entries.extend(members)
            continue
        ordered = sorted(set(numbers))
        head, tail = shape.split("{}", 1)
        if ordered == list(range(ordered[0], ordered[-1] + 1)):
            entries.append(f"{head}{{{ordered[0]}..{ordered[-1]}}}{tail}")
        else:
            entries.append(f"{head}{{{','.join(map(str, ordered))}}}{tail}")
    return entries


def _single_index(name: str) -> Optional[int]:
    found = INDEX.findall(name)
    text = found[0][1:-1] if len(found) == 1 else ""
    return int(text) if text.isdigit() else None


