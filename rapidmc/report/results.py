"""Verdicts and counterexamples as text for people and JSON for scripts.

Text, one line per property and a counterexample under each violation::

    P1: HOLDS (1,234 states, 0.12 s)
    P2: VIOLATED (56 states, 0.01 s)
      formula: G "x < 3"           (a pattern's property: "pattern: ..." above it)
      counterexample: 2 steps, then a loop of 2 steps
        step 1  initial state
            x = 0
        step 2  main.mod:4  x := x + 1;
            x = 1  (was 0)
      -- loop starts here (repeats forever) --
        ...
      -- loop closes: back to the state of step 3 --
    P3: UNKNOWN (state limit 1000000 reached; 1,000,000 states, 30.1 s)

JSON follows the schema in docs/json-output.md (``SCHEMA`` names its version).
"""
from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass
from typing import Optional, Sequence

from ..diagnostics import MORE_ERRORS, Diagnostic
from ..diagnostics.error_report import omitted_count
from ..check.result import UNKNOWN, VIOLATED, SearchResult, SearchStats
from ..check.trace import INITIAL, Trace, TraceDescriber, TraceStep, build_trace
from .counterexample import chosen_inputs_only, counterexample_lines, trace_files
from .headline import read_data
from .line_width import wrapped
from .trace_text import IDENTIFIER, TextOptions, data_names, file_names
from .trace_slice import needed_steps, reads_of, with_robot
from . import indented_json

SCHEMA = "rapidmc-check/1"


@dataclass(frozen=True)
class PropertyResult:
    """The outcome of checking one named property."""

    name: str
    formula: str
    result: SearchResult
    vacuous: Optional[str] = None    # a trigger never true in any reachable state (HOLDS only)
    fair_tasks: tuple = ()           # the tasks assumed weakly fair in the search (several tasks)
    # what the verdict rests on that rapidmc assumed (findings.assumptions): sentences
    assumes: tuple = ()
    pattern: Optional[str] = None    # the specification pattern the formula translates
    # on a controller of several tasks: (atom, the tasks whose own data or places it reads)
    # per atom of the formula (no task: shared PERS data, signals, the controller's status)
    atom_tasks: tuple = ()
    # with a vacuous HOLDS: the sampled inputs it rests on ("with the socket messages tried
    # (SocketReceive at line 14)"), "" when every input's values were tried
    vacuous_inputs: str = ""


# --- text ---------------------------------------------------------------------


def format_text(results: Sequence[PropertyResult], describer: TraceDescriber,
                full: bool = False) -> str:
    """Every property's verdict line, with a counterexample under each violation.

    ``full``: every initial value, every value in full, no step folded (``--full-trace``).
    No line is longer than ``line_width.LONGEST_LINE``: a longer one goes on in the next.
    """
    lines: list[str] = []
    for checked in results:
        lines.append(verdict_line(checked))
        lines.extend(deepest_lines(checked.result))
        trace = build_trace(checked.result, describer) \
            if checked.result.verdict == VIOLATED else None
        options = text_options(checked, describer, full)
        lines.extend(assumption_lines(checked, trace_words(trace, options)
                                      if trace is not None and not full else None))
        if checked.fair_tasks:
            lines.append(f"  {fairness_text(checked.fair_tasks)}")
        stats = checked.result.stats
        if stats.deadlocks:
            lines.append(f"  note: {stats.deadlocks:,} reachable state(s) without a successor; "
                         "runs ending there repeat their last state")
        if checked.result.verdict == VIOLATED:
            if checked.pattern is not None:
                lines.append(f"  pattern: {checked.pattern}")
            lines.append(f"  formula: {checked.formula}")
            if checked.atom_tasks:
                lines.append(f"  {atoms_text(checked.atom_tasks)}")
            if checked.result.reason:
                lines.append(f"  {files_shown(checked.result.reason, trace)}")
            lines.extend(counterexample_lines(trace, options))
    return wrapped("\n".join(lines)) + "\n"


# ``T_ROB1 waits at FILE:LINE (statement)`` in a reason (``RapidDescriber.describe_waits``)
WAIT_PLACE = re.compile(r"(?<= at )(.+?)(?=:\d+ \()")


def files_shown(text: str, trace: Trace) -> str:
    """``text`` (a reason naming ``FILE:LINE``) with its files named as the trace's
    counterexample names them (``TASK1/PROGMOD/Rob1.mod:64``, not the absolute path); a
    task that never stepped in the trace waits in a file of its own, named the same way."""
    names = file_names(trace_files(trace))
    return WAIT_PLACE.sub(lambda found: names.shown(found.group(1)), text)


def described_formula(checked: PropertyResult) -> str:
    """The formula, after the specification pattern it translates (if any), and on a
    controller of several tasks the task of each atom: one line."""
    described = checked.formula if checked.pattern is None else \
        f"{checked.pattern} (LTL: {checked.formula})"
    if checked.atom_tasks:
        described += f" [{atoms_text(checked.atom_tasks)}]"
    return described


def atoms_text(atom_tasks: Sequence[tuple]) -> str:
    """``atoms: "seen = 1" (T_LOG), go (shared), "AtLine(T_ROB2, 9)" (T_ROB2)``."""
    return "atoms: " + ", ".join(
        f"{atom_written(atom)} ({', '.join(tasks) if tasks else 'shared'})"
        for atom, tasks in atom_tasks)


def atom_written(atom: str) -> str:
    """An atom as a formula writes it: bare when it is one name, else quoted."""
    return atom if IDENTIFIER.fullmatch(atom) else json.dumps(atom, ensure_ascii=False)


def verdict_line(checked: PropertyResult) -> str:
    """``P3: UNKNOWN (state limit 1000000 reached; 1,000,000 states, 30.1 s)``."""
    result = checked.result
    figures = statistics_text(result.stats)
    if result.verdict == UNKNOWN and result.reason:
        figures = f"{result.reason}; {figures}"
    if checked.vacuous is not None:
        figures = f"{vacuity_text(checked.vacuous, checked.vacuous_inputs)}; {figures}"
    return f"{checked.name}: {result.verdict} ({figures})"


def deepest_lines(result: SearchResult) -> list[str]:
    """Under an UNKNOWN breadth-first search, how far it came: ``  searched to depth 166;
    last state stored: T_ROB1 in r_RRC_InitVar (RRC_Control_Rob.sys:122), ...``
    (a search that stopped while every task is still in its start-up covers no
    production cycle)."""
    text = deepest_text(result)
    return [f"  {text}"] if text else []


def deepest_text(result: SearchResult) -> str:
    """``searched to depth 166; last state stored: T_ROB1 in ...`` ("" where the result
    names no deepest state)."""
    if result.verdict != UNKNOWN or not result.deepest:
        return ""
    return f"searched to depth {result.stats.max_depth:,}; last state stored: " + \
        ", ".join(place_text(place) for place in result.deepest)


def place_text(place) -> str:
    """``T_ROB1 in r_RRC_InitVar (RRC_Control_Rob.sys:122)``, ``T_LOG ended``."""
    if not place.routine:
        return f"{place.task} ended"
    return f"{place.task} in {place.routine} ({os.path.basename(place.file)}:{place.line})"


MAX_ASSUMPTIONS_SHOWN = 6


ASSUMPTION_WIDTH = 240
PLACE = re.compile(r" \([^()]*:\d+\)$")       # `` (Teaching.mod:25)`` ending an assumption


def assumption_lines(checked: PropertyResult, read: Optional[frozenset] = None) -> list[str]:
    """``  assumes: stub GripOpen is empty (Missing.mod:12)``, one line each, at most
    ``MAX_ASSUMPTIONS_SHOWN`` and a count of the rest, each within about
    ``ASSUMPTION_WIDTH`` characters (JSON lists them all, in full).

    Under a counterexample (``read``: the names its steps use, ``trace_words``) the
    assumptions about what it uses come first, and of the others only as many are shown
    as make ``MAX_ASSUMPTIONS_SHOWN_BESIDE_TRACE`` in all (the rest counted)."""
    assumes = merged_assumptions(checked.assumes)
    limit = MAX_ASSUMPTIONS_SHOWN
    about = 0
    if read is not None:
        used = [text for text in assumes if assumption_subject(text) in read]
        assumes = used + [text for text in assumes if assumption_subject(text) not in read]
        about = len(used)
        limit = min(MAX_ASSUMPTIONS_SHOWN, max(about, MAX_ASSUMPTIONS_SHOWN_BESIDE_TRACE))
    rest = len(assumes) - limit
    first_cut = next((n for n, text in enumerate(assumes[:limit])
                      if len(text) > ASSUMPTION_WIDTH), None)
    # where the whole texts are is told once: on the count of the rest, else the first cut
    shown = [f"  assumes: {short_assumption(text, pointer=n == first_cut and rest <= 0)}"
             for n, text in enumerate(assumes[:limit])]
    if rest > 0:
        others = " on what this counterexample does not use" if about <= limit and \
            read is not None else ""
        whole = ", each whole" if first_cut is not None else ""
        shown.append(f"  assumes: ... and {rest} more{others} (--format json lists them all"
                     f"{whole})")
    return shown


MAX_ASSUMPTIONS_SHOWN_BESIDE_TRACE = 3
QUOTED = re.compile(r'"(?:[^"]|"")*"')


def merged_assumptions(texts: Sequence[str]) -> list[str]:
    """The assumptions with those that differ only in the one string they quote told in
    one (``CRobT reads the calling task's robot for \\TaskName:="T_ROB1", "T_ROB2", which
    names no loaded task``), at the place of the first."""
    groups: dict[tuple, list[str]] = {}
    for text in dict.fromkeys(texts):          # (the same text twice is told once)
        quoted = QUOTED.findall(text)
        key = (True, QUOTED.sub('""', text)) if len(quoted) == 1 else (False, text)
        groups.setdefault(key, []).append(text)
    merged = []
    for (one_string, key), members in groups.items():
        if len(members) == 1 or not one_string:
            merged.extend(members)
            continue
        strings = ", ".join(dict.fromkeys(QUOTED.search(text).group(0) for text in members))
        merged.append(key.replace('""', strings, 1))
    return _merged_by_number(merged)


NUMBER = re.compile(r"\d+")


NUMBERS_LISTED = 3


def _merged_by_number(texts: Sequence[str]) -> list[str]:
    """The assumptions with those that differ only in their numbers (the line of each
    AliasIO) told once, with the numbers that tell the others apart after the first's:
    ``... at HandDriver.sys:1092 (and 1094, 1096) is taken ...``, at most
    ``NUMBERS_LISTED`` of them and a count of the rest (``(and 1094, 1096, 1098 and 20
    more)``)."""
    groups: dict[str, list[str]] = {}
    for text in texts:
        groups.setdefault(NUMBER.sub("#", text), []).append(text)
    merged = []
    for members in groups.values():
        if len(members) == 1:
            merged.append(members[0])
            continue
        numbers = [NUMBER.findall(text) for text in members]
        at = next(n for n in range(len(numbers[0]))
                  if len({found[n] for found in numbers}) > 1)
        others = list(dict.fromkeys(found[at] for found in numbers[1:]))
        listed = ", ".join(others[:NUMBERS_LISTED]) + (
            f" and {len(others) - NUMBERS_LISTED} more" if len(others) > NUMBERS_LISTED else "")
        first = list(NUMBER.finditer(members[0]))[at]
        merged.append(f"{members[0][:first.end()]} (and {listed}){members[0][first.end():]}")
    return merged
SUBJECT = re.compile(r"^(?:PERS |stub |the )?([A-Za-z][A-Za-z0-9_]*)")


def assumption_subject(text: str) -> str:
    """What an assumption is about, upper case: the PERS, the stub or the routine it names
    first (``PERS nRunningStep is written outside ...``: NRUNNINGSTEP; ``CRobT reads ...``:
    CROBT)."""
    found = SUBJECT.match(text)
    return found.group(1).upper() if found else ""


def trace_words(trace: Trace, options: TextOptions) -> frozenset:
    """The names a counterexample uses: every identifier of the statements of the steps
    the violation depends on (``trace_slice``) and of the data they change, upper case."""
    words = set(options.names)
    needed = needed_steps(trace, options.names, options.handler_starts, options.compound_exits)
    for step in [*trace.prefix, *trace.cycle, *([trace.closing] if trace.closing else [])]:
        if step.index not in needed and step is not trace.closing:
            continue
        words.update(reads_of(step))
        if step.kind != INITIAL:           # (the initial state holds every datum)
            for change in step.changes:
                words.update(data_names(change.name))
    return frozenset(words)


def short_assumption(text: str, pointer: bool = True) -> str:
    """An assumption over ``ASSUMPTION_WIDTH`` characters (the values of every component of
    a record written from outside) cut after a ``;`` with ``...``, its place kept:
    ``PERS Welds1 ... take Welds1.cpm: 0; ... (Teaching.mod:25)``; ``pointer``: with
    ``(--format json lists it whole)`` after the ``...``."""
    if len(text) <= ASSUMPTION_WIDTH:
        return text
    place = PLACE.search(text)
    body = text[:place.start()] if place else text
    cut = body.rfind("; ", 0, ASSUMPTION_WIDTH)
    if cut <= 0:
        cut = body.rfind(" ", 0, ASSUMPTION_WIDTH) - 1     # at a word's end
    return (body[:cut + 1] if cut > 0 else body[:ASSUMPTION_WIDTH]) + " ..." + \
        (" (--format json lists it whole)" if pointer else "") + \
        (place.group(0) if place else "")


def text_options(checked: PropertyResult, describer: TraceDescriber,
                 full: bool = False) -> TextOptions:
    """How ``checked``'s counterexample is written: the names its formula uses are shown."""
    names = with_robot({word.upper() for word in IDENTIFIER.findall(checked.formula)})
    return TextOptions(full, names, frozenset(getattr(describer, "stub_data", ())),
                       handler_starts=frozenset(getattr(describer, "handler_starts", ())),
                       compound_exits=getattr(describer, "compound_exits", {}))


def vacuity_text(trigger: str, inputs: str = "") -> str:
    """``vacuously: "!C_IN & S_1" is never true`` (``inputs``: ``with the socket messages
    tried (SocketReceive at line 14)`` when that is what it rests on)."""
    return f"vacuously: {json.dumps(trigger, ensure_ascii=False)} is never true" \
        + (f" {inputs}" if inputs else "")


def fairness_text(tasks: Sequence[str]) -> str:
    """``assuming weak fairness between the tasks main task, task 2 (feeder)``."""
    return f"assuming weak fairness between the tasks {', '.join(tasks)}"


def statistics_text(stats: SearchStats) -> str:
    states = stats.product_states
    return f"{states:,} {'state' if states == 1 else 'states'}, {seconds_text(stats.seconds)}"


def seconds_text(seconds: float) -> str:
    return f"{seconds:.2f} s" if seconds < 10 else f"{seconds:,.1f} s"


# --- JSON ---------------------------------------------------------------------


def format_json(results: Sequence[PropertyResult], describer: Optional[TraceDescriber],
                warnings: Sequence[Diagnostic] = (), command: Optional[Sequence[str]] = None,
                errors: Sequence[Diagnostic] = ()) -> str:
    """The JSON document of docs/json-output.md, indented, keys in schema order.

    ``errors`` are the input errors that stopped ``check`` before any search (then
    ``results`` is empty); a capped report's count of the rest is ``errors_not_shown``.
    """
    document = {"schema": SCHEMA,
                "command": list(command) if command is not None else None,
                "properties": [property_json(checked, describer) for checked in results],
                "warnings": [warning_json(warning) for warning in warnings],
                "errors": [error_json(e) for e in errors if e.code != MORE_ERRORS],
                "errors_not_shown": omitted_count(errors)}
    return indented_json.dumps(document, 2) + "\n"


def format_json_entries(entries: Sequence[tuple[str, Sequence[PropertyResult], Optional[TraceDescriber]]],
                        warnings: Sequence[Diagnostic] = (),
                        command: Optional[Sequence[str]] = None) -> str:
    """The JSON document of ``check --entry all``: ``entries``, one per entry routine with
    its ``properties``, in place of ``properties``; the warnings of the whole check."""
    document = {"schema": SCHEMA,
                "command": list(command) if command is not None else None,
                "entries": [{"entry": entry,
                             "properties": [property_json(checked, describer)
                                            for checked in results]}
                            for entry, results, describer in entries],
                "warnings": [warning_json(warning) for warning in warnings],
                "errors": [], "errors_not_shown": 0}
    return indented_json.dumps(document, 2) + "\n"


def format_json_errors(errors: Sequence[Diagnostic], command: Optional[Sequence[str]]) -> str:
    """The document of a ``check`` that stopped at input errors: no property, only errors."""
    return format_json((), None, (), command, errors)


def property_json(checked: PropertyResult, describer: TraceDescriber) -> dict:
    result = checked.result
    trace = None
    if result.verdict == VIOLATED:
        trace = trace_json(build_trace(result, describer),
                           frozenset(getattr(describer, "stub_data", ())))
    return {"name": checked.name, "formula": checked.formula, "verdict": result.verdict,
            "reason": result.reason, "stats": result.stats.as_dict(), "trace": trace,
            "vacuous": checked.vacuous,
            "vacuous_inputs": checked.vacuous_inputs or None,
            "fair_tasks": list(checked.fair_tasks) if checked.fair_tasks else None,
            "assumes": list(checked.assumes),
            "pattern": checked.pattern,
            "atoms": [{"atom": atom, "tasks": list(tasks)} for atom, tasks in checked.atom_tasks]
            if checked.atom_tasks else None,
            "deepest_state": [place._asdict() for place in result.deepest]
            if result.deepest else None}


def warning_json(warning: Diagnostic) -> dict:
    """A warning; its ``end_line`` is the last line of a stretch of unreached lines.  A
    finding given once per cause lists its other places; ``lines`` gives every place
    (its own first) as file and first and last line, so that a reader counting unreached
    lines need not join the two."""
    span = warning.span
    location = None
    if span:
        location = {"file": span.file, "line": span.line, "column": span.column,
                    "end_line": max(span.end_line, span.line)}
    places = [{"file": place.file, "line": place.line, "column": place.column,
               "end_line": max(place.end_line, place.line)} for place in warning.places]
    return {"code": warning.code.code, "message": warning.message, "location": location,
            "places": places,
            "lines": [{"file": one["file"], "line": one["line"], "end_line": one["end_line"]}
                      for one in ([location] if location else []) + places]}


def error_json(diagnostic: Diagnostic) -> dict:
    """An input error: code, severity, message, place (null for errors of no file) and notes."""
    span = diagnostic.span
    location = None
    if span is not None and span.line > 0:
        location = {"file": span.file, "line": span.line, "column": span.column,
                    "end_line": span.end_line, "end_column": span.end_column}
    return {"code": diagnostic.code.code, "severity": diagnostic.severity,
            "message": diagnostic.message, "location": location,
            "notes": list(diagnostic.notes)}


def trace_json(trace: Trace, stub_data: frozenset = frozenset()) -> dict:
    return {"prefix": [step_json(step) for step in trace.prefix],
            "cycle": [step_json(step) for step in trace.cycle],
            "closing": step_json(trace.closing) if trace.closing else None,
            "loop_start": trace.loop_start,
            "error": error_json_of(trace, stub_data)}


def error_json_of(trace: Trace, stub_data: frozenset = frozenset()) -> Optional[dict]:
    """The headline of a path that ends in an error, values in full; None for a loop."""
    if trace.cycle or not trace.ending:
        return None
    trace = chosen_inputs_only(trace)          # origins as the text report names them
    last = trace.prefix[-1]
    reads = [{"name": name, "value": value, "origin": origin}
             for name, value, origin in read_data(trace.prefix, stub_data)] \
        if last.transition is not None and last.transition.location else []
    return {"message": trace.ending, "step": last.index, "reads": reads,
            "bad_prefix": trace.bad_prefix}


def step_json(step: TraceStep) -> dict:
    transition = step.transition
    location = None
    if transition is not None and transition.file is not None:
        location = {"file": transition.file, "line": transition.line}
    return {"index": step.index, "kind": step.kind, "location": location,
            "source": transition.source if transition else None,
            "inputs": dict(transition.inputs) if transition else {},
            "changes": {change.name: change.new for change in step.changes},
            "output": transition.output if transition and transition.output else None}
