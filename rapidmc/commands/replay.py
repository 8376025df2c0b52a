"""``rapidmc replay TRACE.json``: re-execute a counterexample saved by ``check --format json``.

The JSON report records the ``check`` command that wrote it; replay builds
the same program and transition system from it (run it from the directory
``check`` ran in) and follows the chosen property's counterexample step by
step: each step on stderr as ``check`` prints it, FlexPendant output on
stdout as ``run`` prints it.  A program that no longer follows the trace
(edited since) stops the replay with a diagnostic at the step that broke.

A property's bad prefix (a finite path after which every run violates the
property: no loop) replays to its last step and says so.

Exit codes: 0 the counterexample replays to its end (its loop closes);
2 the trace file is unusable or the program no longer follows it.
"""
from __future__ import annotations

import argparse
import json
import sys
from dataclasses import replace
from typing import Optional

from ..report.counterexample import step_lines
from ..report.line_width import wrapped
from ..check.trace import INITIAL, Change, TraceStep, TransitionInfo
from ..diagnostics import EXIT_OK, TRACE_DIVERGED, TRACE_FILE, SourceCache, UserError, error
from ..check.trace_replay import ReplayedStep, SavedStep, SavedTrace, TraceDiverged, follow
from .. import ast
from ..diagnostics.quoting import one_line, quoted

SCHEMA = "rapidmc-check/1"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("trace", metavar="TRACE.json",
                        help="a report written by 'rapidmc check --format json'")
    parser.add_argument("--property", metavar="NAME", default=None,
                        help="the violated property whose counterexample to replay "
                             "(default: the first violated one)")
    parser.add_argument("--quiet", action="store_true",
                        help="no step lines on stderr, only the FlexPendant output")


def execute(args: argparse.Namespace) -> int:
    document = _read(args.trace)
    entry = _violated_property(document, args.property, args.trace)
    model = _model(document, args.trace)
    trace = _saved_trace(entry, args.trace)
    count = 0
    try:
        for replayed in follow(model.system, model.describer, trace):
            _show(replayed, args.quiet)
            count += 1
    except TraceDiverged as exc:
        sys.stdout.flush()
        raise _diverged(entry["name"], exc) from None
    sys.stdout.flush()
    ending = (entry["trace"].get("error") or {}) if not trace.loop_start else {}
    loop = f", the loop back to step {trace.loop_start} closes" if trace.loop_start else \
        f", then any run: {ending['message']}" if ending.get("bad_prefix") else ""
    print(f"{entry['name']}: the counterexample replays: {count} steps{loop}", file=sys.stderr)
    return EXIT_OK


def _read(path: str) -> dict:
    try:
        with open(path, encoding="utf-8") as handle:
            document = json.load(handle)
    except OSError as exc:
        raise error(TRACE_FILE, f"cannot read trace file '{path}': {exc.strerror}") from None
    except (ValueError, UnicodeDecodeError) as exc:
        raise error(TRACE_FILE, f"'{path}' is not JSON: {one_line(str(exc))}") from None
    if not isinstance(document, dict) or document.get("schema") != SCHEMA:
        raise error(TRACE_FILE, f"'{path}' is not a report of 'rapidmc check --format json' "
                    f"(schema {SCHEMA})")
    return document


def _violated_property(document: dict, name: Optional[str], path: str) -> dict:
    entries = [p for p in document.get("properties") or [] if isinstance(p, dict)]
    violated = [p for p in entries if p.get("verdict") == "VIOLATED" and p.get("trace")]
    if name is None:
        if not violated:
            raise error(TRACE_FILE, f"'{path}' holds no counterexample: no property is VIOLATED")
        return violated[0]
    entry = next((p for p in entries if p.get("name") == name), None)
    if entry is None:
        names = ", ".join(quoted(p.get("name", "?")) for p in entries)
        raise error(TRACE_FILE, f"'{path}' has no property {quoted(name)} (it has {names})")
    if entry not in violated:
        raise error(TRACE_FILE, f"property {quoted(name)} is {entry.get('verdict')} in "
                    f"'{path}': it has no counterexample")
    return entry


def _model(document: dict, path: str):
    from ..cli import build_parser
    from .check import prepare_model
    command = document.get("command")
    if not (isinstance(command, list) and command and command[0] == "check"
            and all(isinstance(word, str) for word in command)):
        raise error(TRACE_FILE, f"'{path}' does not record the check command that wrote it "
                    "(reports of rapidmc check --format json do)")
    try:
        args = build_parser().parse_args(command)
        args.no_reduce = True     # a saved trace lists every instruction: replay them one by one
        return prepare_model(args)
    except UserError as exc:
        note = (f"the program is rebuilt from the check command recorded in '{path}' "
                f"({' '.join(command)}): run replay from the directory check ran in")
        raise UserError([replace(d, notes=d.notes + (note,)) for d in exc.diagnostics],
                        exc.exit_code) from None


def _saved_trace(entry: dict, path: str) -> SavedTrace:
    try:
        trace = SavedTrace.from_json(entry["trace"])
    except (KeyError, TypeError, ValueError) as exc:
        raise error(TRACE_FILE, f"the trace of {quoted(entry['name'])} in '{path}' is "
                    f"malformed ({type(exc).__name__}: {one_line(str(exc))})") from None
    if not trace.steps or trace.steps[0].kind != INITIAL:
        raise error(TRACE_FILE, f"the trace of {quoted(entry['name'])} in '{path}' does not "
                    "start with the initial state")
    return trace


def _show(replayed: ReplayedStep, quiet: bool) -> None:
    saved = replayed.saved
    if saved.output:
        sys.stdout.write(saved.output if saved.output.endswith("\n") else saved.output + "\n")
    if not quiet:
        sys.stdout.flush()
        lines = step_lines(_as_trace_step(saved))
        print(wrapped("\n".join(lines)), file=sys.stderr)


def _as_trace_step(saved: SavedStep) -> TraceStep:
    transition = None
    if saved.kind != INITIAL:
        transition = TransitionInfo(saved.file, saved.line, saved.source or "", saved.inputs, "")
    changes = tuple(Change(name, None, value) for name, value in saved.changes.items())
    return TraceStep(saved.index, saved.kind, transition, changes)


def _diverged(name: str, exc: TraceDiverged):
    step = exc.step
    span = None
    if step.file and step.line:
        text = SourceCache.line(step.file, step.line) or ""
        span = ast.Span(step.file, step.line, len(text) - len(text.lstrip()) + 1)
    expected = f"{step.where}  {step.source or ''}".rstrip()
    if step.inputs:
        expected += "  (inputs: " + ", ".join(f"{k} = {v}" for k, v in step.inputs.items()) + ")"
    notes = [f"the trace executes: {expected}"] + [f"the program can execute: {p}"
                                                   for p in exc.possible]
    return error(TRACE_DIVERGED, f"the program no longer follows the counterexample of "
                 f"{quoted(name)} at step {step.index}", span, *notes)
