"""The HTML report of ``rapidmc check --html FILE``: one self-contained page.

The page holds its style, its script and its data inline and loads
nothing (its Content-Security-Policy forbids every request), so it can be
opened offline or attached to a CI run.  It shows every property's
verdict, formula and statistics, and each counterexample as a player: the
RAPID source with the current line, the call stack, the inputs chosen, the
values changed, the FlexPendant output so far, and a timeline of the
signals and changing bool/num data with the repeating loop marked.

The data is the JSON report's (``report.property_json`` and
``report.trace_json``) plus what a viewer needs beyond it: the source
lines of the program's files, each step's call stack and previous values,
and the timeline rows.  The page itself lives in ``html_page/``
(``page.html``, ``page.css``, ``page.js``).

Example::

    write_html("report.html", results, describer)
"""
from __future__ import annotations

import html as markup
import json
import re
from importlib import resources
from pathlib import Path
from typing import Mapping, Optional, Sequence

from .. import __version__
from ..diagnostics import HTML_OUTPUT, NEVER_REACHED, Diagnostic, SourceCache, error
from .results import (PropertyResult, atoms_text, error_json_of, fairness_text, property_json,
                      step_json)
from ..check.result import VIOLATED
from ..check.trace import Trace, TraceDescriber, TraceStep, build_trace

DIGITAL = "digital"
BOOL = "bool"
NUM = "num"
SIGNAL_PREFIX = "signal "
DIGITAL_VALUES = frozenset({"0", "1"})
BOOL_VALUES = frozenset({"TRUE", "FALSE"})
ASSETS = "html_page"
# Where the template takes the title, style, data and script.
SLOTS = ("<!--rapidmc:title-->", "/*rapidmc:style*/", "<!--rapidmc:data-->", "/*rapidmc:script*/")


# --- the page -----------------------------------------------------------------


def write_html(path: str, results: Sequence[PropertyResult], describer: TraceDescriber,
               warnings: Sequence[Diagnostic] = ()) -> None:
    """Write the report page to ``path``; a path that cannot be written is a diagnostic."""
    text = format_html(results, describer, warnings)
    try:
        Path(path).write_text(text, encoding="utf-8")
    except OSError as exc:
        raise html_unwritable(path, exc.strerror or str(exc)) from None


def html_unwritable(path: str, why: str):
    return error(HTML_OUTPUT, f"cannot write the HTML report '{path}': {why}")


def format_html(results: Sequence[PropertyResult], describer: TraceDescriber,
                warnings: Sequence[Diagnostic] = ()) -> str:
    """The whole page: template with the style, the script and the report data inlined."""
    data = page_data(results, describer, warnings)
    title = "rapidmc check: " + (", ".join(Path(f["name"]).name for f in data["files"]) or
                                 "report")
    values = {SLOTS[0]: markup.escape(title), SLOTS[1]: _asset("page.css"),
              SLOTS[2]: _script_json(data), SLOTS[3]: _asset("page.js")}
    # one pass, so that text put in a slot is never searched for slots itself
    pattern = "|".join(re.escape(slot) for slot in SLOTS)
    return re.sub(pattern, lambda match: values[match.group(0)], _asset("page.html"))


def _asset(name: str) -> str:
    return (resources.files(__package__) / ASSETS / name).read_text(encoding="utf-8")


def _script_json(data: dict) -> str:
    """JSON that cannot end its ``<script>`` element early (no ``<``, ``>``, ``&`` as such)."""
    text = json.dumps(data, ensure_ascii=False, separators=(",", ":"))
    return text.replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


# --- the data -----------------------------------------------------------------


def page_data(results: Sequence[PropertyResult], describer: TraceDescriber,
              warnings: Sequence[Diagnostic] = ()) -> dict:
    """Everything the page shows, as one JSON-ready dictionary.

    ``warnings``: coverage warnings, whose statements the source view shades.
    """
    properties = []
    located: list[str] = []
    for checked in results:
        entry = property_json(checked, describer)
        if checked.fair_tasks:
            entry["fairness"] = fairness_text(checked.fair_tasks)
        if checked.atom_tasks:
            entry["atoms_text"] = atoms_text(checked.atom_tasks)
        if checked.result.verdict == VIOLATED:
            entry["trace"] = trace_view(build_trace(checked.result, describer),
                                        frozenset(getattr(describer, "stub_data", ())))
            located.extend(s["location"]["file"] for s in entry["trace"]["steps"]
                           if s["location"])
        properties.append(entry)
    unreached = [{"file": span.file, "line": span.line,
                  "end_line": max(span.line, span.end_line), "message": w.message}
                 for w in warnings if w.span is not None and w.code is NEVER_REACHED
                 for span in (w.span, *w.places)]
    located.extend(entry["file"] for entry in unreached)
    return {"tool": f"rapidmc {__version__}", "files": source_files(describer, located),
            "properties": properties, "unreached": unreached}


def trace_view(trace: Trace, stub_data: frozenset = frozenset()) -> dict:
    """The JSON trace with every step in one list (closing last), the timeline rows, and
    the error a path ends in (as in the JSON report)."""
    steps = [*trace.prefix, *trace.cycle, *([trace.closing] if trace.closing else [])]
    return {"steps": [step_view(step) for step in steps],
            "loop_start": trace.loop_start,
            "closing": trace.closing.index if trace.closing else None,
            "timeline": timeline_rows(steps),
            "error": error_json_of(trace, stub_data)}


def step_view(step: TraceStep) -> dict:
    """A step as in the JSON report, with its previous values and its call stack."""
    view = step_json(step)
    view["was"] = {change.name: change.old for change in step.changes}
    view["stack"] = [{"routine": frame.routine, "file": frame.file, "line": frame.line,
                      "task": frame.task} for frame in step.stack]
    return view


def values_by_step(steps: Sequence[TraceStep]) -> list[dict[str, str]]:
    """The value of every item after each step (the changes accumulated)."""
    current: dict[str, str] = {}
    columns = []
    for step in steps:
        current = dict(current)
        for change in step.changes:
            if change.new is None:
                current.pop(change.name, None)
            else:
                current[change.name] = change.new
        columns.append(current)
    return columns


def timeline_rows(steps: Sequence[TraceStep]) -> list[dict]:
    """One waveform per digital signal and per bool or num item that changes, in first-seen order.

    Each row has a ``kind`` (``digital``, ``bool`` or ``num``) and one value
    per step (None where the item does not exist, e.g. a routine's data
    outside the routine).  Digital signals come first.
    """
    columns = values_by_step(steps)
    names = list(dict.fromkeys(name for column in columns for name in column))
    rows = []
    for name in names:
        values = [column.get(name) for column in columns]
        kind = row_kind(name, values)
        if kind is not None:
            rows.append({"name": name, "kind": kind, "values": values})
    rows.sort(key=lambda row: row["kind"] != DIGITAL)
    return rows


def row_kind(name: str, values: Sequence[Optional[str]]) -> Optional[str]:
    """``digital`` for a 0/1 signal; ``bool`` / ``num`` for data that changes; else None."""
    present = {value for value in values if value is not None}
    if name.startswith(SIGNAL_PREFIX) and present <= DIGITAL_VALUES:
        return DIGITAL
    if len(present) < 2:
        return None
    if present <= BOOL_VALUES:
        return BOOL
    if all(_is_number(value) for value in present):
        return NUM
    return None


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def source_files(describer: TraceDescriber, located: Sequence[str]) -> list[dict]:
    """The program's files (from the describer when it knows them) and every file a step names."""
    known: Mapping[str, Sequence[str]] = {}
    if hasattr(describer, "source_lines"):
        known = describer.source_lines()
    files = {name: list(lines) for name, lines in known.items()}
    for name in dict.fromkeys(located):
        lines = SourceCache.lines(name)
        if name not in files and lines is not None:
            files[name] = list(lines)
    return [{"name": name, "lines": lines} for name, lines in files.items()]
