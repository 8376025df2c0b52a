"""Text and JSON reports over a toy robot cell, compared with golden output.

The cell reads a count (1 or 2) from the FlexPendant, sets do1, writes
"done", resets do1 and starts again.  Seconds and rates vary from run to
run, so they are normalised before comparison.
"""
from __future__ import annotations

import json
import re

from rapidmc.check import TransitionInfo, check_property, find_reachable
from rapidmc.report.results import PropertyResult, format_json, format_text
from test_engine_models import NOT_ALWAYS_P, NOT_INFINITELY_OFTEN_P


class Cell:
    """State (pc, x, do1); labels (line, source, inputs, output)."""

    def initial_states(self):
        return ((0, 0, 0),)

    def successors(self, state):
        pc, x, do1 = state
        if pc == 0:
            return tuple(((11, 'TPReadNum x, "How many?";', (("x", str(n)),), ""), (1, n, do1))
                         for n in (1, 2))
        if pc == 1:
            return (((12, "SetDO do1, 1;", (), ""), (2, x, 1)),)
        if pc == 2:
            return (((13, 'TPWrite "done";', (), "done"), (3, x, do1)),)
        return (((14, "SetDO do1, 0;", (), ""), (0, x, 0)),)


class CellDescriber:
    def describe_state(self, state):
        _, x, do1 = state
        return {"x": str(x), "do1": str(do1)}

    def describe_transition(self, label):
        line, source, inputs, output = label
        return TransitionInfo("cell.mod", line, source, dict(inputs), output)


def cell_results():
    cell = Cell()
    x_is_2 = lambda state: int(state[1] == 2)  # noqa: E731
    return [
        PropertyResult("P1", 'G "do1 = 0 | do1 = 1"',
                       check_property(cell, NOT_ALWAYS_P, lambda state: int(state[2] in (0, 1)))),
        PropertyResult("P2", 'G F "x = 2"', check_property(cell, NOT_INFINITELY_OFTEN_P, x_is_2)),
        PropertyResult("P3", 'G F "x = 2"',
                       check_property(cell, NOT_INFINITELY_OFTEN_P, x_is_2, max_states=2)),
        PropertyResult("never-done", 'no TPWrite', find_reachable(cell, lambda state: state[0] == 3)),
    ]


GOLDEN_TEXT = '''\
P1: HOLDS (9 states, <t> s)
P2: VIOLATED (9 states, <t> s)
  formula: G F "x = 2"
  counterexample: 1 step, then a loop of 4 steps
    step 1  initial state
        x = 0
        do1 = 0
  -- loop starts here (repeats forever) --
    step 2  cell.mod:11  TPReadNum x, "How many?";
        input: x = 1
        x = 1  (was 0)
    step 3  cell.mod:12  SetDO do1, 1;
        do1 = 1  (was 0)
    step 4  cell.mod:13  TPWrite "done";
    step 5  cell.mod:14  SetDO do1, 0;
        do1 = 0  (was 1)
    step 6  cell.mod:11  TPReadNum x, "How many?";
        input: x = 1
  -- loop closes: back to the state of step 2 --
P3: UNKNOWN (state limit 2 reached; 2 states, <t> s)
never-done: VIOLATED (6 states, <t> s)
  formula: no TPWrite
  counterexample: 4 steps
    step 1  initial state
        x = 0
        do1 = 0
    step 2  cell.mod:11  TPReadNum x, "How many?";
        input: x = 1
        x = 1  (was 0)
    step 3  cell.mod:12  SetDO do1, 1;
        do1 = 1  (was 0)
    step 4  cell.mod:13  TPWrite "done";
'''


def normalise_seconds(text: str) -> str:
    return re.sub(r"\d[\d,]*\.\d+ s\)", "<t> s)", text)


def test_text_report_matches_golden():
    assert normalise_seconds(format_text(cell_results(), CellDescriber())) == GOLDEN_TEXT


def test_verdict_line_formats_large_figures():
    result = check_property(Cell(), NOT_INFINITELY_OFTEN_P, lambda state: 0, max_states=2)
    result.stats.product_states = 1_000_000
    result.stats.seconds = 30.14
    result.reason = "state limit 1000000 reached"
    line = format_text([PropertyResult("P3", "G F p", result)], CellDescriber())
    assert line == "P3: UNKNOWN (state limit 1000000 reached; 1,000,000 states, 30.1 s)\n"


def test_deadlock_note_and_stuck_step():
    class Stops(Cell):
        def successors(self, state):
            return () if state[0] == 2 else super().successors(state)

    result = check_property(Stops(), NOT_ALWAYS_P, lambda state: int(state[0] != 2))
    text = format_text([PropertyResult("P", "G pc != 2", result)], CellDescriber())
    assert "note: 1 reachable state(s) without a successor" in text
    assert text.splitlines()[-2].startswith("    step 4  (no statement can execute")
    assert "loop closes: back to the state of step 3" in text


# --- JSON ---------------------------------------------------------------------------

STEP_KEYS = ["index", "kind", "location", "source", "inputs", "changes", "output"]
STATS_KEYS = ["product_states", "model_states", "transitions", "max_depth", "seconds",
              "states_per_second", "deadlocks", "bytes_per_state", "engine"]


def test_json_follows_the_documented_schema():
    document = json.loads(format_json(cell_results(), CellDescriber()))
    assert list(document) == ["schema", "command", "properties", "warnings", "errors",
                            "errors_not_shown"]
    assert document["schema"] == "rapidmc-check/1" and document["warnings"] == []
    properties = document["properties"]
    assert [p["verdict"] for p in properties] == ["HOLDS", "VIOLATED", "UNKNOWN", "VIOLATED"]
    for entry in properties:
        assert list(entry) == ["name", "formula", "verdict", "reason", "stats", "trace",
                               "vacuous", "vacuous_inputs", "fair_tasks", "assumes",
                               "pattern", "atoms", "deepest_state"]
        assert entry["fair_tasks"] is None        # one task: no fairness assumed
        assert entry["atoms"] is None             # one task: atoms belong to no task
        assert list(entry["stats"]) == STATS_KEYS
        assert (entry["trace"] is None) == (entry["verdict"] != "VIOLATED")
    assert properties[2]["reason"] == "state limit 2 reached"
    trace = properties[1]["trace"]
    assert list(trace) == ["prefix", "cycle", "closing", "loop_start", "error"]
    assert trace["error"] is None                 # a loop: no error ends it
    steps = trace["prefix"] + trace["cycle"] + [trace["closing"]]
    assert all(list(step) == STEP_KEYS for step in steps)
    assert [step["index"] for step in steps] == [1, 2, 3, 4, 5, 6]
    assert trace["loop_start"] == 2


def test_json_steps_carry_location_inputs_changes_output():
    trace = json.loads(format_json(cell_results(), CellDescriber()))["properties"][1]["trace"]
    initial, read = trace["prefix"][0], trace["cycle"][0]
    assert initial == {"index": 1, "kind": "initial", "location": None, "source": None,
                       "inputs": {}, "changes": {"x": "0", "do1": "0"}, "output": None}
    assert read == {"index": 2, "kind": "transition",
                    "location": {"file": "cell.mod", "line": 11},
                    "source": 'TPReadNum x, "How many?";', "inputs": {"x": "1"},
                    "changes": {"x": "1"}, "output": None}
    assert trace["cycle"][2]["output"] == "done" and trace["cycle"][2]["changes"] == {}


def test_reachability_trace_has_no_cycle_in_json():
    trace = json.loads(format_json(cell_results(), CellDescriber()))["properties"][3]["trace"]
    assert trace["cycle"] == [] and trace["closing"] is None and trace["loop_start"] is None
    assert len(trace["prefix"]) == 4


def test_json_is_stable_apart_from_timing():
    def without_timing(text):
        document = json.loads(text)
        for entry in document["properties"]:
            entry["stats"]["seconds"] = entry["stats"]["states_per_second"] = 0
        return document

    first = format_json(cell_results(), CellDescriber())
    second = format_json(cell_results(), CellDescriber())
    assert without_timing(first) == without_timing(second)
