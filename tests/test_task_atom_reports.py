"""Every report format names the task of each atom of a property on a controller of several
tasks (tests/task_backups/qualified/backup: T_ROB1, T_ROB2, T_LOG), robot atoms included
(tests/task_backups/robots/backup: T_ROB1 and T_ROB2 each move their own robot)."""
from __future__ import annotations

import contextlib
import io
import json
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import NamedTuple

import pytest

from rapidmc.cli import main

BACKUPS = Path(__file__).resolve().parent / "task_backups"
BACKUP = BACKUPS / "qualified" / "backup"


class Case(NamedTuple):
    backup: Path
    formula: str
    atoms: list
    atoms_text: str
    named: set             # names the HTML page's steps change (each task's own named as atoms do)


CASES = {
    # seen: T_LOG's alone; go: PERS data T_ROB1 and T_ROB2 share; the place names its task
    "data_and_places": Case(
        BACKUP, 'G ("seen = 0" | !go | "InRoutine(T_ROB2, \\"MoveToSlot\\")")',
        [{"atom": "seen = 0", "tasks": ["T_LOG"]}, {"atom": "go", "tasks": []},
         {"atom": 'InRoutine(T_ROB2, "MoveToSlot")', "tasks": ["T_ROB2"]}],
        'atoms: "seen = 0" (T_LOG), go (shared), '
        '"InRoutine(T_ROB2, \\"MoveToSlot\\")" (T_ROB2)', {"T_LOG.seen", "go"}),
    # each robot atom reads the robot of the task it names
    "robots": Case(
        BACKUPS / "robots" / "backup", 'G !("AtTarget(T_ROB1, p10)" & "CPos(T_ROB2).x > 1000")',
        [{"atom": "AtTarget(T_ROB1, p10)", "tasks": ["T_ROB1"]},
         {"atom": "CPos(T_ROB2).x > 1000", "tasks": ["T_ROB2"]}],
        'atoms: "AtTarget(T_ROB1, p10)" (T_ROB1), "CPos(T_ROB2).x > 1000" (T_ROB2)',
        {"T_ROB1.robot TCP", "T_ROB2.robot TCP"}),
}


@pytest.fixture(params=sorted(CASES))
def case(request) -> Case:
    return CASES[request.param]


@pytest.fixture
def run(tmp_path, case):
    props = tmp_path / "props.ltl"
    props.write_text(f"mixed: {case.formula}\n")

    def check(*arguments: str) -> str:
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = main(["check", str(case.backup), "--ltl", str(props), *arguments])
        assert code == 1, out.getvalue()
        return out.getvalue()
    return check


def test_text_names_the_task_of_each_atom_under_the_formula(run, case):
    assert f"  formula: {case.formula}\n  {case.atoms_text}\n" in run()


def test_json_lists_each_atom_with_its_tasks(run, case):
    properties = {p["name"]: p for p in json.loads(run("--format", "json"))["properties"]}
    assert properties["mixed"]["atoms"] == case.atoms
    assert properties["no_deadlock"]["atoms"] is None


def test_sarif_rule_and_result_name_the_tasks(run, case):
    sarif_run = json.loads(run("--format", "sarif"))["runs"][0]
    rules = {rule["id"]: rule["shortDescription"]["text"]
             for rule in sarif_run["tool"]["driver"]["rules"]}
    assert rules["mixed"] == f"{case.formula} [{case.atoms_text}]"
    [violation] = [r for r in sarif_run["results"] if r["ruleId"] == "mixed"]
    assert f"[{case.atoms_text}]" in violation["message"]["text"]


def test_junit_failure_names_the_tasks(run, case, tmp_path):
    run("--junit", str(tmp_path / "report.xml"))
    testcase = ET.parse(tmp_path / "report.xml").find(".//testcase[@name='mixed']")
    assert testcase.find("failure").get("message") == f"{case.formula} [{case.atoms_text}]"


def test_html_page_data_names_the_tasks(run, case, tmp_path):
    run("--html", str(tmp_path / "report.html"))
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    data = json.loads(page.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    mixed = next(p for p in data["properties"] if p["name"] == "mixed")
    assert (mixed["atoms"], mixed["atoms_text"]) == (case.atoms, case.atoms_text)
    names = {name for step in mixed["trace"]["steps"] for name in step["changes"]}
    assert case.named <= names, names


def test_a_pattern_property_names_the_task_of_its_atoms(tmp_path):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["check", str(BACKUP), "--formula", 'pat: absence("T_ROB2.slot = 2") after(go)'])
    assert ('  pattern: absence("T_ROB2.slot = 2") after(go)\n'
            '  formula: G (go -> G !"T_ROB2.slot = 2")\n'
            '  atoms: go (shared), "T_ROB2.slot = 2" (T_ROB2)\n') in out.getvalue()
