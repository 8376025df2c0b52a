"""A property's bad prefix in every report: a finite counterexample with no loop, after whose
last step every run violates the property (``check.result.BAD_PREFIX``).

The case is tests/check/ltl_safety_unbounded_counter: ``G !("gripper_open" & "moving")``
broken at step 23 (``gripper_open := TRUE;`` while moving, in cycle 3) of a loop that counts
its cycles for ever.  Text, JSON, SARIF, JUnit and ``rapidmc replay`` each say that any run
goes on after the path; the HTML page is tests/test_html_report.py's.
"""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rapidmc.check.result import BAD_PREFIX
from cli_capture import run_cli

CASE = Path(__file__).resolve().parent / "check" / "ltl_safety_unbounded_counter"
CHECK = ["check", "prog.mod", "--ltl", "props.ltl", "--max-states", "3000", "--quiet"]
NAME = "never_open_while_moving"


@pytest.fixture
def in_case(monkeypatch):
    monkeypatch.chdir(CASE)


def test_the_text_says_violated_and_any_run_and_shows_no_loop(in_case):
    code, out, _ = run_cli(CHECK)
    assert code == 1
    block = out[out.index(f"{NAME}: VIOLATED"):out.index("count_not_negative")]
    assert f"  violated: {BAD_PREFIX}\n    at step 23, prog.mod:13:  gripper_open := TRUE;" \
        in block
    assert "  counterexample: 23 steps, then any run (no loop needed)" in block
    assert "loop" not in block.replace("(no loop needed)", "")
    assert "not read by the property" in block        # the slice names what reads the data


def test_the_json_trace_is_a_prefix_whose_error_is_the_bad_prefix(in_case):
    code, out, _ = run_cli([*CHECK, "--format", "json"])
    entry = next(p for p in json.loads(out)["properties"] if p["name"] == NAME)
    trace = entry["trace"]
    assert (entry["verdict"], entry["reason"]) == ("VIOLATED", None)
    assert trace["cycle"] == [] and trace["closing"] is None and trace["loop_start"] is None
    assert len(trace["prefix"]) == 23
    assert trace["error"] == {"message": BAD_PREFIX, "step": 23, "reads": [],
                              "bad_prefix": True}
    assert trace["prefix"][-1]["changes"] == {"gripper_open": "TRUE"}


def test_a_built_in_safety_violation_is_no_bad_prefix(monkeypatch):
    monkeypatch.chdir(CASE.parent / "runtime_div_input")
    _, out, _ = run_cli(["check", "prog.mod", "--quiet", "--format", "json"])
    entry = next(p for p in json.loads(out)["properties"] if p["name"] == "no_runtime_error")
    assert entry["trace"]["error"]["bad_prefix"] is False


def test_sarif_says_any_run_goes_on(in_case):
    _, out, _ = run_cli([*CHECK, "--format", "sarif"])
    result = next(r for r in json.loads(out)["runs"][0]["results"] if r["ruleId"] == NAME)
    assert result["message"]["text"].endswith(
        f"(counterexample: 23 steps, then any run: {BAD_PREFIX})")
    assert len(result["codeFlows"][0]["threadFlows"][0]["locations"]) == 23
    assert result["locations"][0]["physicalLocation"]["region"]["startLine"] == 13


def test_junit_fails_with_the_bad_prefix(in_case, tmp_path):
    run_cli([*CHECK, "--junit", str(tmp_path / "report.xml")])
    case = next(c for c in ET.parse(tmp_path / "report.xml").iter("testcase")
                if c.get("name") == NAME)
    failure = case.find("failure")
    assert failure is not None and failure.get("type") == "VIOLATED"
    assert failure.text.startswith(f"violated: {BAD_PREFIX}\n")
    assert "counterexample: 23 steps, then any run (no loop needed)" in failure.text


def test_replay_follows_the_prefix_and_says_any_run_goes_on(in_case, tmp_path):
    _, out, _ = run_cli([*CHECK, "--format", "json"])
    saved = tmp_path / "trace.json"
    saved.write_text(out)
    code, _, err = run_cli(["replay", str(saved), "--property", NAME, "--quiet"])
    assert code == 0, err
    assert f"{NAME}: the counterexample replays: 23 steps, then any run: {BAD_PREFIX}" in err


def report_without_times(argv: list[str]) -> tuple[int, dict]:
    code, out, _ = run_cli([*argv, "--format", "json", "--quiet"])
    document = json.loads(out)
    for entry in document["properties"]:
        for measured in ("seconds", "states_per_second", "bytes_per_state"):
            entry["stats"].pop(measured)
    return code, document


ROOT = CASE.parent.parent.parent
FINITE = {
    # LTL check cases whose state space the search covers: safety properties VIOLATED by a
    # lasso, others that hold, several tasks under fairness
    **{name: ["check", "prog.mod", *extra, "--ltl", "props.ltl"] for name, extra in [
        ("loop_mod_counter", []), ("ltl_until_release", []), ("ltl_next_call", []),
        ("tasks_fairness", ["--add-task", "b.mod"])]},
    "sorter_b": ["check", str(ROOT / "case_studies/sorter/sorter_b.mod"), "--env",
                 str(ROOT / "case_studies/sorter/plant.mod"), "--ltl",
                 str(ROOT / "specs/sorter.ltl")],
}


@pytest.mark.parametrize("name", FINITE)
def test_finite_models_report_as_without_bad_prefixes(name, monkeypatch):
    """On a finite state space a bad prefix leads on to a loop the search finds: the whole
    report (verdicts, lassos, counts) is the one of the search without the automaton's
    universal states (the search before bad prefixes)."""
    monkeypatch.chdir(CASE.parent / name if (CASE.parent / name).is_dir() else ROOT)
    with_prefixes = report_without_times(FINITE[name])
    monkeypatch.setattr("rapidmc.check.product.universal_states", lambda buchi: frozenset())
    assert with_prefixes == report_without_times(FINITE[name])
    assert "VIOLATED" in {entry["verdict"] for entry in with_prefixes[1]["properties"]}
