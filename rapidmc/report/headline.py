"""The headline of a counterexample that ends in an error: the error, its line and step,
and each datum the failing line reads, with its value and where it got it (its last
assignment, the input chosen at a step, a stub's value or its initial value).

A bare ``RAISE;`` is followed back to the step that raised the error; a line in the
stubs module says so.
"""
from __future__ import annotations

import os
import re
from typing import Optional, Sequence

from ..check.trace import INITIAL, Trace, TraceStep
from ..load.stubs.module_text import is_stub_module
from ..semantics.task_registers import names_errno
from ..model.fairness import TASK_CHOICE
from .trace_slice import (read_part, running_tasks, statements_of, task_names, whole_assignments,
                          words_of)
from .trace_text import (INDEX, SOURCE_WIDTH, STRING_WIDTH, WIDTH, TextOptions, data_names,
                         datum_of, shorten, shown_location, shown_value)

INPUT_WIDTH = 40       # an input's value where it tells where a value came from
NOT_CALLED = re.compile(r"[A-Za-z][A-Za-z0-9_]*(?![A-Za-z0-9_]|\s*\()")   # no function's name


def headline_lines(trace: Trace, options: TextOptions = TextOptions()) -> list[str]:
    """For a path that ends in an error: the error, where, and the data its line reads (for
    a property's bad prefix: that every run going on from its last step violates it)."""
    if trace.cycle or not trace.ending:
        return []
    steps = list(trace.prefix)
    lines = [f"  {'violated' if trace.bad_prefix else 'error'}: {trace.ending}"]
    last = steps[-1]
    if last.transition is None or not last.transition.location:
        return lines
    width = None if options.full else SOURCE_WIDTH
    lines.append(f"    at step {last.index}, {shown_location(last.transition, options.files)}:  "
                 f"{shorten(last.transition.source, width)}")
    if is_stub_module(last.transition.file) and last.stack:
        lines.append(f"    (in {last.stack[-1].routine}, a routine of the stubs module: "
                     "its body is a stand-in for the real one)")
    raising = raising_steps(steps)
    if raising is not steps:
        first = raising[-1]
        lines.append(f"    raised at step {first.index}, "
                     f"{shown_location(first.transition, options.files)}:  "
                     f"{shorten(first.transition.source, width)}")
        if is_stub_module(first.transition.file) and first.stack:
            lines.append(f"    (in {first.stack[-1].routine}, a routine of the stubs module: "
                         "its body is a stand-in for the real one)")
    bounds_only = indexed_data(read_part(raising[-1].transition.source)) \
        if "ERR_OUTOFBND" in trace.ending and not options.full else frozenset()
    shown = [(name, value if options.full else shown_value(value, WIDTH, STRING_WIDTH), origin)
             for name, value, origin in read_data(steps, options.stub_data)
             if INDEX.sub("", name).upper() not in bounds_only]
    lines.extend(f"    {text}" for text in (_same_origin_together(shown) if not options.full
                                            else (f"{n} = {v}  ({o})" for n, v, o in shown)))
    return lines


def _same_origin_together(shown: Sequence[tuple]) -> list[str]:
    """``name = value  (origin)`` each, the data of one routine that follow each other with
    one origin told together (``Pick: slot = 0, count = 3  (set at step 4)``) on lines of at
    most about ``SOURCE_WIDTH`` characters."""
    texts, at = [], 0
    while at < len(shown):
        name, value, origin = shown[at]
        head, dot, own = name.rpartition(".")
        run, width = 1, len(head) + len(own) + len(str(value)) + len(origin) + 9
        while dot and "{" not in name and at + run < len(shown):
            other, other_value, other_origin = shown[at + run]
            width += len(other.rpartition(".")[2]) + len(str(other_value)) + 5
            if other_origin != origin or other.rpartition(".")[0] != head or "{" in other \
                    or width > SOURCE_WIDTH:
                break
            run += 1
        if run == 1:
            texts.append(f"{name} = {value}  ({origin})")
        else:
            parts = ", ".join(f"{n.rpartition('.')[2]} = {v}" for n, v, _ in shown[at:at + run])
            texts.append(f"{head}: {parts}  ({origin})")
        at += run
    return texts


INDEXING = re.compile(r"([A-Za-z][A-Za-z0-9_]*)(\s*\{)?|\{|\}")


def indexed_data(source: str) -> frozenset:
    """The data a line indexes outside any other index and names inside none, upper case
    (``WELDS1`` of ``nTemp := Welds1{i}.cpm / 6``; of ``a{b{i}}`` only ``A``; of ``IF n{1} > 0
    x := a{n{1}}`` only ``A``): of an index out of bounds the error gives their bounds, and
    their elements' values tell nothing more."""
    found, inside, depth = set(), set(), 0
    for match in INDEXING.finditer(source):
        if match.group(0) == "}":
            depth = max(depth - 1, 0)
            continue
        if match.group(1):
            if depth:
                inside.add(match.group(1).upper())
            elif match.group(2):
                found.add(match.group(1).upper())
        if match.group(0).endswith("{"):
            depth += 1
    return frozenset(found - inside)


def read_data(steps: Sequence[TraceStep], stub_data: frozenset = frozenset()) -> list[tuple]:
    """(name, value, origin) of each datum the last step's line reads, in the order it names them.

    The value is the one before the last step ran: its latest change in the steps
    before or its initial value; an input chosen at a step counts as a change of
    that step.  Of a datum changed part by part, the part the line names
    (``pk.id``), else the part changed last.
    """
    steps = raising_steps(steps)
    source = steps[-1].transition.source
    words = list(dict.fromkeys(word.upper() for word in NOT_CALLED.findall(read_part(source))))
    written = source.replace(" ", "").upper()
    found = stub_results(steps)
    tasks = task_names(steps)
    running = running_tasks(steps)[-1]
    others = tasks - {running} if running else frozenset()
    for word in words:
        candidates = [candidate for candidate in
                      _latest_values(steps, word, words, stub_data, tasks)
                      if not _of_task(candidate[0], others)]
        named = [c for c in candidates if INDEX.sub("", c[0]).replace(" ", "").upper() in written
                 and "." in c[0] and datum_of(c[0], words) == data_names(c[0])[0]]
        path = _component_path(read_part(source), word)
        by_number = bool(path) and path[0].startswith("{")
        element = [c for c in candidates if by_number and
                   c[0].replace(" ", "").upper() == word + path[0].upper()]
        if named:
            found.append(named[0])
        elif element:
            found.append(element[0])           # the element the line names, by number
        elif candidates:
            # of an element read by number, what other elements' changes do not tell: the
            # latest value of the whole datum (or a component) holding it
            pool = [c for c in candidates if "{" not in c[0]] if by_number else candidates
            found.append(_part_read(pool, path, word) or candidates[0])
    return found


def _of_task(name: str, tasks: frozenset) -> bool:
    """Whether a shown name is a datum of one of ``tasks`` (``T_ROB2.count``, upper case):
    the failing line of another task cannot read it."""
    head, dot, _ = name.removeprefix("signal ").partition(".")
    return bool(dot) and head.upper() in tasks


def _datum(name: str, words: Sequence[str], tasks: frozenset) -> str:
    """``datum_of`` a shown name, its task's name left out (``T_ROB2.main.i``: I)."""
    head, dot, rest = name.partition(".")
    return datum_of(rest if dot and head.upper() in tasks else name, words)


PART = r"\s*\.\s*[A-Za-z][A-Za-z0-9_]*|\{\s*\d+\s*\}"     # a component, or an element by number


def _component_path(source: str, word: str) -> list[str]:
    """The parts the line reads of the datum ``word``: ``raw_message.head.length`` gives
    ``[".head", ".length"]``, ``table{3}.x`` ``["{3}", ".x"]`` (none when the line reads it
    whole, not by name, or by an index that is no number)."""
    match = re.search(r"\b" + re.escape(word) + f"((?:{PART})+)", source, re.IGNORECASE)
    if match is None:
        return []
    return [re.sub(r"\s", "", part) for part in re.findall(PART, match.group(1))]


def _part_read(candidates: list[tuple], path: list[str], word: str) -> Optional[tuple]:
    """Of a datum's latest values (latest first), the value of the component ``path`` the
    line reads: from the latest value that holds that component, taken down to it; the
    latest change inside it as it is; None when the line reads no path or an array element
    is in the way (the old choice stands)."""
    if not path:
        return None
    for name, value, origin in candidates:
        if "{" in name:
            return None
        parts = name.split(".")
        at = next((n for n, part in enumerate(parts) if part.upper() == word), None)
        if at is None:
            return None
        own = ["." + part for part in parts[at + 1:]]
        if [part.upper() for part in own] == [part.upper() for part in path[:len(own)]]:
            for part in path[len(own):]:
                value = {suffix.upper(): text for suffix, text in
                         getattr(value, "parts", ())}.get(part.upper())
                if value is None:
                    return None
            return (".".join(parts[:at + 1]) + "".join(path[len(own):]) if not own else
                    name + "".join(path[len(own):]), value, origin)
        if [part.upper() for part in path] == [part.upper() for part in own[:len(path)]]:
            return (name, value, origin)       # a change inside the part read
    return None


BARE_RAISE = re.compile(r"^RAISE\s*;", re.IGNORECASE)


def raising_steps(steps: Sequence[TraceStep]) -> Sequence[TraceStep]:
    """The steps up to the one that raised the error a bare ``RAISE;`` passes on (the latest
    that set ERRNO); ``steps`` itself when the last step is no bare RAISE or none set it."""
    last = steps[-1].transition
    if last is None or not BARE_RAISE.match(last.source):
        return steps
    for number in range(len(steps) - 2, 0, -1):
        if any(names_errno(change.name) and change.new for change in steps[number].changes) \
                and steps[number].transition is not None:
            return steps[:number + 1]
    return steps


def stub_results(steps: Sequence[TraceStep]) -> list[tuple]:
    """(``F()``, value, origin) of each stub function the failing statement called: of the
    steps just before it that run deeper in the call stack (in the functions it called),
    those in a stubs module."""
    depth = len(steps[-1].stack)
    found = []
    for step in reversed(steps[:-1]):
        transition = step.transition
        if transition is None or len(step.stack) <= depth:
            break
        returned = re.match(r"RETURN\s+(.*?);?$", transition.source, re.IGNORECASE)
        if returned and step.stack and is_stub_module(transition.file):
            found.append((f"{step.stack[-1].routine}()", returned.group(1).strip(),
                          f"returned by the stub at {os.path.basename(transition.file)}:"
                          f"{transition.line}"))
    return found[::-1]


def _latest_values(steps: Sequence[TraceStep], word: str, words: Sequence[str],
                   stub_data: frozenset, tasks: frozenset = frozenset()) -> list[tuple]:
    """The latest values of the datum named ``word`` (one of the line's ``words``) and of its
    parts before the last step, latest first, up to the datum's own: (name, value, origin)."""
    found: dict[str, tuple] = {}
    rewritten = None        # the latest step that assigned the datum whole without changing it
    for step in reversed(steps):
        transition = step.transition
        if rewritten is None and not found and step is not steps[-1] and \
                word in whole_assignments(step) and \
                not any(_datum(change.name, words, tasks) == word for change in step.changes):
            rewritten = step.index
        if transition is not None:             # the failing step reads what it chose
            for name, value in transition.inputs.items():
                if name.upper() == word or name.upper() == word + "{*}":
                    return list(found.values()) + [(name, value, f"input chosen at step "
                                                    f"{step.index}" + _read_before(
                                                        steps, step, name, value))]
        if step is steps[-1] and step.kind != INITIAL:
            continue                           # what the failing step itself wrote
        for change in reversed(step.changes):
            if change.new is None or change.name in found or \
                    _datum(change.name, words, tasks) != word:
                continue
            if step.kind == INITIAL:
                origin = "stub value" if change.name in stub_data else "initial value"
            else:
                origin = f"set at step {step.index}" + _inputs_text(step, steps[0])
            if rewritten is not None and not found:
                origin = f"set at step {rewritten}, to the value it had"
            found[change.name] = (change.name, change.new, origin)
            if not INDEX.search(change.name) and "." not in change.name.removeprefix("signal "):
                return list(found.values())    # the whole datum: older parts are in it
    return list(found.values())


def _read_before(steps: Sequence[TraceStep], chosen: TraceStep, name: str, value) -> str:
    """``; it read 1 at step 105, line 116`` when an input read again had another value the
    time before (a value checked, then used after the signal changed).  An input the state
    keeps is chosen before every step: only a step whose statement names it read it."""
    first = steps[0]
    kept = first.kind == INITIAL and any(change.name == f"signal {name}"
                                         for change in first.changes)
    for step in reversed(steps[:steps.index(chosen)]):
        transition = step.transition
        if kept and transition is not None and name.upper() not in {
                word for text in statements_of(step) for word in words_of(text)}:
            continue
        if transition is not None and name in transition.inputs:
            before = transition.inputs[name]
            if before == value:
                return ""
            return f"; it read {before} at step {step.index}, line {transition.line}"
    return ""


def _inputs_text(step: TraceStep, first: TraceStep) -> str:
    """`` by task 2 (T_ROB2)`` when the step chose the task that steps, and `` from the
    input TPReadNum = 1`` when it chose inputs its statements may read, else nothing.  An
    input the state keeps (``signal diStart`` of the ``first`` step, the initial state) is
    chosen before every step, so it counts only where a statement of the step names it: a
    SetDO beside it does not take its value from it."""
    inputs = step.transition.inputs if step.transition is not None else {}
    if not inputs:
        return ""
    kept = {change.name[len("signal "):] for change in first.changes
            if change.name.startswith("signal ")} if first.kind == INITIAL else set()
    words = {word for text in statements_of(step) for word in words_of(text)}
    read = {name: value for name, value in inputs.items()
            if name != TASK_CHOICE and (name not in kept or name.upper() in words)}
    text = f" by {inputs[TASK_CHOICE]}" if TASK_CHOICE in inputs else ""
    if read:
        chosen = ", ".join(f"{name} = {shorten(value, INPUT_WIDTH)}"
                           for name, value in read.items())
        text += f" from the input {chosen}" if len(read) == 1 else f" from the inputs {chosen}"
    return text
