"""SARIF 2.1.0 output, for CI systems and code-scanning views.

Each property is a rule; each VIOLATED property is a result of level
``error`` whose location is the last statement before the counterexample's
loop (for a run-time error: the statement that failed) and whose code flow
is the whole counterexample, step by step, with the inputs chosen and the
values changed as the messages of the steps.  UNKNOWN properties are
results of level ``warning``; HOLDS gives no result.  Input errors (syntax,
static, property files) become results of level ``error`` too, so a CI
pipeline reads one format whatever went wrong.
"""
from __future__ import annotations

import json
from pathlib import Path
from typing import Optional, Sequence

from .. import __version__
from ..diagnostics import Diagnostic
from .counterexample import chosen_inputs_only
from .headline import read_data
from .trace_text import WIDTH, shorten
from .ci_findings import violation_anchor
from .results import PropertyResult, deepest_text, described_formula
from ..check.result import UNKNOWN, VIOLATED
from ..check.trace import Trace, TraceDescriber, TraceStep, build_trace
from . import indented_json

SARIF_SCHEMA = "https://json.schemastore.org/sarif-2.1.0.json"


def format_sarif(results: Sequence[PropertyResult], describer: TraceDescriber,
                 exit_code: int, warnings: Sequence[Diagnostic] = ()) -> str:
    rules = [_rule(checked.name, described_formula(checked)) for checked in results]
    sarif_results = []
    for index, checked in enumerate(results):
        result = checked.result
        if result.verdict == VIOLATED:
            trace = chosen_inputs_only(build_trace(result, describer))   # inputs as in text
            sarif_results.append(_violation(index, checked, trace))
        elif result.verdict == UNKNOWN:
            sarif_results.append({
                "ruleId": checked.name, "ruleIndex": index, "level": "warning",
                "message": {"text": f"{checked.name}: UNKNOWN ({result.reason}): no violation "
                                    "found, but the search was bounded" +
                                    (f"; {deepest_text(result)}" if result.deepest else "")}})
    _assumptions(results, rules, sarif_results)
    _diagnostic_results(warnings, rules, sarif_results)
    return _document(rules, sarif_results, exit_code)


def format_sarif_entries(entries: Sequence[tuple[str, Sequence[PropertyResult], TraceDescriber]],
                         exit_code: int, warnings: Sequence[Diagnostic] = ()) -> str:
    """``check --entry all``: one run per entry routine (``automationDetails.id``
    ``entry/NAME``); the warnings of the whole check in the first run."""
    runs = []
    for number, (entry, results, describer) in enumerate(entries):
        run = json.loads(format_sarif(results, describer, exit_code,
                                      warnings if number == 0 else ()))["runs"][0]
        run["automationDetails"] = {"id": f"entry/{entry}"}
        runs.append(run)
    document = json.loads(_document([], [], exit_code))
    document["runs"] = runs
    return indented_json.dumps(document, 2) + "\n"


def _assumptions(results: Sequence[PropertyResult], rules: list, sarif_results: list) -> None:
    """What each verdict assumes (findings.assumptions): ``properties.assumes`` of the
    property's rule (every verdict; HOLDS gives no result) and of its result, if any."""
    for rule, checked in zip(rules, results):
        if checked.assumes:
            rule.setdefault("properties", {})["assumes"] = list(checked.assumes)
    for result in sarif_results:
        assumes = rules[result["ruleIndex"]].get("properties", {}).get("assumes")
        if assumes:
            result.setdefault("properties", {})["assumes"] = assumes


def format_sarif_diagnostics(diagnostics: Sequence[Diagnostic], exit_code: int) -> str:
    """Input errors as SARIF results (one rule per diagnostic code)."""
    rules: list = []
    results: list = []
    _diagnostic_results(diagnostics, rules, results)
    return _document(rules, results, exit_code)


def _diagnostic_results(diagnostics: Sequence[Diagnostic], rules: list, results: list) -> None:
    """Append a result per diagnostic (level: its severity) and a rule per new code."""
    for code in sorted({d.code.code for d in diagnostics}):
        entry = next(d.code for d in diagnostics if d.code.code == code)
        rules.append(_rule(code, entry.summary))
    indices = {rule["id"]: index for index, rule in enumerate(rules)}
    for diagnostic in diagnostics:
        result = {"ruleId": diagnostic.code.code, "ruleIndex": indices[diagnostic.code.code],
                  "level": diagnostic.severity, "message": {"text": diagnostic.message}}
        if diagnostic.span is not None and diagnostic.span.line > 0:
            span = diagnostic.span
            result["locations"] = [_location(span.file, span.line, span.column,
                                             span.end_line if span.end_line > span.line else 0)]
        if diagnostic.places:           # a finding given once per cause: its other places
            result["relatedLocations"] = [
                dict(id=number, message={"text": "the same finding"},
                     **_location(span.file, span.line, span.column,
                                 span.end_line if span.end_line > span.line else 0))
                for number, span in enumerate(diagnostic.places, start=1)]
        if diagnostic.omitted:          # the last result of a capped report counts the rest
            result["properties"] = {"errorsNotShown": diagnostic.omitted}
        if diagnostic.flow:             # a lint flow: source, the steps between, sink
            result["codeFlows"] = [{"threadFlows": [{"locations": [
                _flow_location(span, text, order)
                for order, (span, text) in enumerate(diagnostic.flow, start=1)]}]}]
        results.append(result)


def _flow_location(span, text: str, order: int) -> dict:
    location: dict = {"message": {"text": text}}
    location.update(_location(span.file, span.line, span.column))
    return {"location": location, "executionOrder": order, "nestingLevel": 0}


def _document(rules: list, results: list, exit_code: int) -> str:
    document = {
        "$schema": SARIF_SCHEMA,
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "rapidmc", "version": __version__, "rules": rules}},
            "results": results,
            "invocations": [{"executionSuccessful": exit_code in (0, 1, 3),
                             "exitCode": exit_code}],
        }],
    }
    return indented_json.dumps(document, 2) + "\n"


def _rule(name: str, description: str) -> dict:
    return {"id": name, "name": name, "shortDescription": {"text": description}}


def _violation(index: int, checked: PropertyResult, trace: Trace) -> dict:
    steps = [*trace.prefix, *trace.cycle]
    anchor = violation_anchor(trace)
    result = {
        "ruleId": checked.name, "ruleIndex": index, "level": "error",
        "message": {"text": f"{checked.name} is violated: {described_formula(checked)} "
                            f"({_shape(trace)})"},
        "codeFlows": [{"threadFlows": [{"locations": [
            _flow_step(step, order, trace.loop_start) for order, step in
            enumerate(steps, start=1)]}]}],
    }
    if anchor is not None:
        result["locations"] = [_location(anchor.transition.file, anchor.transition.line)]
    if checked.fair_tasks:            # the counterexample lets every task that can go on run
        result["properties"] = {"fairTasks": list(checked.fair_tasks)}
    return result


def _shape(trace: Trace) -> str:
    """``counterexample: 3 steps, then a loop of 2 steps``, or for a path ending in an error
    ``counterexample: 5 steps to uncaught ERR_DIVZERO: division by zero, reading n = 0``, or
    for a property's bad prefix ``counterexample: 5 steps, then any run: every run ...``."""
    if trace.cycle or not trace.ending:
        return f"counterexample: {len(trace.prefix)} steps, then a loop of " \
               f"{len(trace.cycle)} steps"
    read = read_data(trace.prefix) if trace.prefix[-1].transition is not None else []
    reads = ", ".join(f"{name} = {shorten(value, WIDTH)} ({origin})"
                      for name, value, origin in read)
    if trace.bad_prefix:
        return f"counterexample: {len(trace.prefix)} steps, then any run: {trace.ending}" + \
            (f"; step {trace.prefix[-1].index} reads {reads}" if reads else "")
    return f"counterexample: {len(trace.prefix)} steps to {trace.ending}" + \
        (f", reading {reads}" if reads else "")


def _flow_step(step: TraceStep, order: int, loop_start: Optional[int]) -> dict:
    transition = step.transition
    parts = []
    if loop_start is not None and step.index == loop_start:
        parts.append("loop starts here (repeats forever)")
    if transition is not None and transition.source:
        parts.append(transition.source)
    if transition is not None and transition.inputs:
        parts.append("inputs: " + ", ".join(f"{k} = {v}" for k, v in transition.inputs.items()))
    if step.changes:                  # values shortened as in the text report
        parts.append("changes: " + ", ".join(
            f"{c.name} = {shorten(c.new, WIDTH)}" if c.new is not None
            else f"{c.name} (no longer exists)" for c in step.changes))
    location: dict = {"message": {"text": "; ".join(parts) or f"step {step.index}"}}
    if transition is not None and transition.file:
        location.update(_location(transition.file, transition.line))
    return {"location": location, "executionOrder": order, "nestingLevel": 0}


def _location(file: str, line: Optional[int], column: Optional[int] = None,
              end_line: int = 0) -> dict:
    region = {"startLine": line or 1}
    if column:
        region["startColumn"] = column
    if end_line:                      # a stretch of unreached lines
        region["endLine"] = end_line
    return {"physicalLocation": {"artifactLocation": {"uri": Path(file).as_posix()},
                                 "region": region}}
