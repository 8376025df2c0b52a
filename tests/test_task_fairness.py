"""Weak fairness between tasks: the lassos it reports, how reports say it, when it applies.

The verdicts themselves are pinned by the hand-checked cases tests/check/tasks_fairness,
tasks_no_fairness and tasks_fairness_waiting, and held against Spot by
test_task_fairness_spot.py; here: the shape of fair counterexamples, the report,
--no-fairness, single-task programs and the --compact search.
"""
from __future__ import annotations

import contextlib
import io
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import HOLDS, UNKNOWN, VIOLATED
from rapidmc.check.fair import check_fair_property
from rapidmc.cli import main
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model.fairness import TaskFairness

CASES = Path(__file__).resolve().parent / "check"
FAIR = CASES / "tasks_fairness"
WAITING = CASES / "tasks_fairness_waiting"


def checked(folder: Path, task: str, fairness: bool = True, **options) -> api.CheckReport:
    properties = api.read_properties(str(folder / "props.ltl"))
    program = report_program(folder, task)
    return api.check(program, properties, api.CheckOptions(fairness=fairness, **options))


def outside_data(folder: Path) -> bool:
    """As `check` loads the case: ``--fixed-outside-data`` in its args keeps PERS that no
    task writes at the initial value (the waiting case needs a flag nobody sets)."""
    args = folder / "args"
    return not (args.exists() and "--fixed-outside-data" in args.read_text())


def cycle_tasks(report: api.CheckReport, name: str) -> list[str]:
    """The task of every step of the counterexample's cycle, closing step included."""
    result = report.result(name).result
    labels = [step.label for step in result.cycle[1:]] + [result.closing_label]
    return [dict(label[0])["task"] for label in labels]


def test_a_fair_counterexample_runs_every_task_that_can_go_on():
    report = checked(FAIR, "b.mod")
    assert report.verdicts["flag_stays"] == VIOLATED
    # both tasks can always go on in that loop except while the main task waits: both step
    assert set(cycle_tasks(report, "flag_stays")) == {"main task", "task 2 (b)"}
    fairness = TaskFairness(api.prepare(report_program(FAIR, "b.mod"), []).system)
    result = report.result("flag_stays").result
    assert fairness.unfair_tasks(result.cycle, result.closing_label) == []


def test_a_waiting_task_need_not_step_in_a_fair_loop():
    report = checked(WAITING, "counter.mod")
    assert report.verdicts["seen_again"] == VIOLATED
    assert set(cycle_tasks(report, "seen_again")) == {"task 2 (counter)"}
    system = api.prepare(report_program(WAITING, "counter.mod"), []).system
    fairness = TaskFairness(system)
    for step in report.result("seen_again").result.cycle:
        assert 0 in fairness.excused(step.state)      # the main task waits in every state


def report_program(folder: Path, task: str):
    return api.load_program([str(folder / "prog.mod")], add_tasks=[str(folder / task)],
                            properties=api.read_properties(str(folder / "props.ltl")),
                            outside_data=outside_data(folder))


def test_without_fairness_the_starving_loop_is_a_counterexample():
    report = checked(FAIR, "b.mod", fairness=False)
    assert report.verdicts["seen_again"] == VIOLATED
    assert set(cycle_tasks(report, "seen_again")) == {"task 2 (b)"}
    fairness = TaskFairness(api.prepare(report_program(FAIR, "b.mod"), []).system)
    result = report.result("seen_again").result
    assert fairness.unfair_tasks(result.cycle, result.closing_label) == ["main task"]


def run_json(*argv: str) -> dict:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["check", *argv, "--format", "json", "--quiet"])
    return {entry["name"]: entry for entry in json.loads(out.getvalue())["properties"]}


def test_the_json_report_names_the_tasks_assumed_fair(monkeypatch):
    monkeypatch.chdir(FAIR)
    entries = run_json("prog.mod", "--add-task", "b.mod", "--ltl", "props.ltl")
    assert entries["seen_again"]["fair_tasks"] == ["main task", "task 2 (b)"]
    assert entries["no_deadlock"]["fair_tasks"] is None          # built-in checks: plain
    plain = run_json("prog.mod", "--add-task", "b.mod", "--ltl", "props.ltl", "--no-fairness")
    assert all(entry["fair_tasks"] is None for entry in plain.values())
    single = run_json("prog.mod", "--formula", "p: G F seen")
    assert single["p"]["fair_tasks"] is None and single["p"]["verdict"] == VIOLATED


def test_the_text_report_says_fairness_was_assumed(monkeypatch, capsys):
    monkeypatch.chdir(FAIR)
    main(["check", "prog.mod", "--add-task", "b.mod", "--formula", "p: G F seen", "--quiet"])
    lines = capsys.readouterr().out.splitlines()
    at = lines.index(next(line for line in lines if line.startswith("p: HOLDS")))
    assert lines[at + 1] == "  assuming weak fairness between the tasks main task, task 2 (b)"
    main(["check", "prog.mod", "--add-task", "b.mod", "--formula", "p: G F seen", "--quiet",
          "--no-fairness"])
    assert "fairness" not in capsys.readouterr().out


@pytest.mark.parametrize("fairness, verdict", [(True, UNKNOWN), (False, VIOLATED)])
def test_a_compact_search_does_not_report_a_starving_loop(fairness, verdict):
    """--compact cannot search for fair cycles: the unfair cycle it finds is no answer."""
    report = checked(FAIR, "b.mod", fairness, storage=("compact",))
    assert report.verdicts["seen_again"] == verdict
    if verdict == UNKNOWN:
        assert "starves main task" in report.result("seen_again").result.reason


def test_a_safety_property_keeps_its_verdict_with_a_fair_counterexample():
    fair, plain = checked(FAIR, "b.mod"), checked(FAIR, "b.mod", fairness=False)
    assert fair.verdicts["never_seen"] == plain.verdicts["never_seen"] == VIOLATED
    assert fair.verdicts["no_deadlock"] == plain.verdicts["no_deadlock"] == HOLDS
    fairness = TaskFairness(api.prepare(report_program(FAIR, "b.mod"), []).system)
    result = fair.result("never_seen").result
    assert fairness.unfair_tasks(result.cycle, result.closing_label) == []


def test_a_counterexample_that_starves_no_task_is_todays():
    """Today's search runs first; its lasso stands when it is fair."""
    fair, plain = checked(WAITING, "counter.mod"), checked(WAITING, "counter.mod", False)
    for name in ("seen_eventually", "seen_again"):
        ours, todays = fair.result(name).result, plain.result(name).result
        assert (ours.prefix, ours.cycle, ours.closing_label) == \
            (todays.prefix, todays.cycle, todays.closing_label)


# --- the engine's fair search on a toy model (no RAPID) ----------------------------

class TwoParties:
    """State 0 may stay (party 0) or move to 1 (party 1); 1 goes back to 0 (party 0).
    Party 1 can go on exactly in state 0.  ``p`` holds in state 1."""

    def initial_states(self):
        return (0,)

    def successors(self, state):
        return (("stay", 0), ("move", 1)) if state == 0 else (("back", 0),)


class ByLabel:
    count = 2

    def taken(self, state, label):
        return 1 if label == "move" else 0

    def excused(self, state):
        return frozenset({1}) if state == 1 else frozenset()


def toy_check(text: str, **bounds):
    buchi = to_buchi(Not(parse_formula(text)), backend="builtin")
    return check_fair_property(TwoParties(), buchi, lambda state: int(state == 1 and
                               "p" in buchi.atoms), ByLabel(), **bounds)


@pytest.mark.parametrize("text, verdict, cycle", [
    ("G F p", HOLDS, None),                   # staying in 0 forever starves party 1
    ("F G !p", VIOLATED, [0, 1]),             # fair loops pass through 1
    ("G !p", VIOLATED, [0, 1]),
])
def test_the_fair_search_on_a_toy_model(text, verdict, cycle):
    result = toy_check(text)
    assert result.verdict == verdict
    if cycle is not None:
        assert {step.state for step in result.cycle} == set(cycle)


def test_a_bounded_fair_search_is_unknown_not_holds():
    result = toy_check("G F p", max_states=1)
    assert result.verdict == UNKNOWN and "state limit 1" in result.reason


def test_the_junit_report_says_fairness_was_assumed(monkeypatch, tmp_path):
    monkeypatch.chdir(FAIR)
    report = tmp_path / "junit.xml"
    with contextlib.redirect_stdout(io.StringIO()):
        main(["check", "prog.mod", "--add-task", "b.mod", "--ltl", "props.ltl", "--quiet",
              "--junit", str(report)])
    cases = {case.get("name"): case for case in ET.parse(report).iter("testcase")}
    fair = "weak fairness between the tasks main task, task 2 (b)\n"
    assert cases["seen_again"].findtext("system-out") == f"HOLDS assuming {fair}"
    assert cases["flag_stays"].findtext("system-out") == f"VIOLATED assuming {fair}"
    assert cases["no_deadlock"].findtext("system-out") is None


def test_a_sarif_violation_names_the_tasks_assumed_fair(monkeypatch, capsys):
    monkeypatch.chdir(FAIR)
    main(["check", "prog.mod", "--add-task", "b.mod", "--ltl", "props.ltl", "--quiet",
          "--format", "sarif"])
    results = json.loads(capsys.readouterr().out)["runs"][0]["results"]
    violated = {result["ruleId"]: result for result in results if result["level"] == "error"}
    assert set(violated) == {"flag_stays", "never_seen"}
    for result in violated.values():
        assert result["properties"] == {"fairTasks": ["main task", "task 2 (b)"]}
