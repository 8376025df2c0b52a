"""JUnit XML output, the test report format CI servers (Jenkins, GitLab, Azure) read.

One ``<testsuite>`` per run, named after the program (``check --entry all``: one per
entry routine); one ``<testcase>`` per property (the built-in checks included):

* HOLDS — a passed test case;
* VIOLATED — a ``<failure>`` whose ``message`` is the formula (after the
  specification pattern it translates, if any) and whose
  text is the counterexample as ``rapidmc check`` prints it;
* UNKNOWN — ``<skipped>`` with the reason the search stopped;
* a property that holds vacuously says so in its ``<system-out>``, and so
  does one checked assuming weak fairness between tasks; and
  coverage warnings are listed in the suite's ``<system-out>``.

Input errors (syntax, static errors, malformed properties) become one test
case ``input`` with an ``<error>`` per diagnostic, so that a CI job shows
why nothing was checked.  The document follows the JUnit schema Jenkins
reads (tests/data/jenkins-junit.xsd); element order is the schema's.
"""
from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from typing import Sequence

from ..diagnostics import Diagnostic, render
from .counterexample import counterexample_lines
from .results import (PropertyResult, deepest_text, described_formula, fairness_text,
                      text_options, vacuity_text)
from ..check.result import UNKNOWN, VIOLATED
from ..check.trace import TraceDescriber, build_trace

INPUT_CASE = "input"
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def format_junit(results: Sequence[PropertyResult], describer: TraceDescriber,
                 suite_name: str, class_name: str, warnings: Sequence[Diagnostic] = ()) -> str:
    """The JUnit document for the verdicts of one ``check`` run."""
    return _document(_verdict_suite(results, describer, suite_name, class_name, warnings))


def format_junit_entries(entries: Sequence[tuple[str, Sequence[PropertyResult], TraceDescriber]],
                         suite_name: str, class_name: str,
                         warnings: Sequence[Diagnostic] = ()) -> str:
    """The JUnit document of ``check --entry all``: a suite per entry routine, named
    ``PROGRAM (entry NAME)``; the warnings of the whole check in the first suite."""
    return _document(*(
        _verdict_suite(results, describer, f"{suite_name} (entry {entry})", class_name,
                       warnings if number == 0 else ())
        for number, (entry, results, describer) in enumerate(entries)))


def _verdict_suite(results, describer, suite_name, class_name, warnings) -> ET.Element:
    suite = _suite(suite_name)
    for checked in results:
        _property_case(suite, checked, describer, class_name)
    if warnings:
        ET.SubElement(suite, "system-out").text = "\n".join(render(w) for w in warnings) + "\n"
    return suite


def format_junit_diagnostics(diagnostics: Sequence[Diagnostic], suite_name: str,
                             class_name: str) -> str:
    """The JUnit document of a run that stopped on input errors."""
    suite = _suite(suite_name)
    case = _case(suite, INPUT_CASE, class_name, 0.0)
    for diagnostic in diagnostics:
        error = ET.SubElement(case, "error", message=diagnostic.message,
                              type=diagnostic.code.code)
        error.text = render(diagnostic)
    return _document(suite)


def _suite(name: str) -> ET.Element:
    return ET.Element("testsuite", name=name)


def _case(suite: ET.Element, name: str, class_name: str, seconds: float) -> ET.Element:
    return ET.SubElement(suite, "testcase", name=name, classname=class_name,
                         time=_seconds(seconds))


def _property_case(suite: ET.Element, checked: PropertyResult, describer: TraceDescriber,
                   class_name: str) -> None:
    result = checked.result
    case = _case(suite, checked.name, class_name, result.stats.seconds)
    if result.verdict == UNKNOWN:
        skipped = ET.SubElement(case, "skipped")
        skipped.text = f"UNKNOWN: {result.reason}: no violation found, but the search was bounded"
        if result.deepest:
            skipped.text += f" ({deepest_text(result)})"
    elif result.verdict == VIOLATED:
        failure = ET.SubElement(case, "failure", message=described_formula(checked),
                                type=VIOLATED)
        lines = counterexample_lines(build_trace(result, describer),
                                     text_options(checked, describer))
        failure.text = "\n".join(line[2:] for line in lines) + "\n"
    notes = []
    if checked.fair_tasks:
        notes.append(f"{result.verdict} {fairness_text(checked.fair_tasks)}")
    if checked.vacuous is not None:
        notes.append(f"HOLDS {vacuity_text(checked.vacuous, checked.vacuous_inputs)}")
    notes.extend(f"{result.verdict} assumes: {text}" for text in checked.assumes)
    if notes:
        ET.SubElement(case, "system-out").text = "".join(note + "\n" for note in notes)


def _document(*suites: ET.Element) -> str:
    totals = {"tests": 0, "failures": 0, "errors": 0, "seconds": 0.0}
    for suite in suites:
        cases = suite.findall("testcase")
        counts = {"tests": len(cases),
                  "failures": sum(case.find("failure") is not None for case in cases),
                  "errors": sum(len(case.findall("error")) > 0 for case in cases),
                  "skipped": sum(case.find("skipped") is not None for case in cases)}
        for key, value in counts.items():
            suite.set(key, str(value))
        seconds = sum(float(case.get("time")) for case in cases)
        suite.set("time", _seconds(seconds))
        for key in ("tests", "failures", "errors"):
            totals[key] += counts[key]
        totals["seconds"] += seconds
    root = ET.Element("testsuites", name="rapidmc", tests=str(totals["tests"]),
                      failures=str(totals["failures"]), errors=str(totals["errors"]),
                      time=_seconds(totals["seconds"]))
    root.extend(suites)
    for element in root.iter():
        _clean(element)
    ET.indent(root)
    return ET.tostring(root, encoding="unicode", xml_declaration=True) + "\n"


def _clean(element: ET.Element) -> None:
    """Characters XML 1.0 cannot hold (RAPID strings may carry any byte) written as \\xNN."""
    if element.text:
        element.text = _xml_safe(element.text)
    for key, value in element.attrib.items():
        element.set(key, _xml_safe(value))


def _xml_safe(text: str) -> str:
    return _NOT_XML.sub(lambda match: f"\\x{ord(match.group()):02x}", text)


def _seconds(seconds: float) -> str:
    return f"{seconds:.3f}"
