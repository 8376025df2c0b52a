"""Every report format names the task of each atom of a property on a controller of several
tasks (tests/task_backups/qualified/backup: T_ROB1, T_ROB2, T_LOG)."""
from __future__ import annotations

import contextlib
import io
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rapidmc.cli import main

BACKUP = Path(__file__).resolve().parent / "task_backups" / "qualified" / "backup"
# seen: T_LOG's alone; go: PERS data T_ROB1 and T_ROB2 share; the place names its task
FORMULA = 'G ("seen = 0" | !go | "InRoutine(T_ROB2, \\"MoveToSlot\\")")'
ATOMS = [{"atom": "seen = 0", "tasks": ["T_LOG"]}, {"atom": "go", "tasks": []},
         {"atom": 'InRoutine(T_ROB2, "MoveToSlot")', "tasks": ["T_ROB2"]}]
ATOMS_TEXT = ('atoms: "seen = 0" (T_LOG), go (shared), '
              '"InRoutine(T_ROB2, \\"MoveToSlot\\")" (T_ROB2)')


@pytest.fixture
def run(tmp_path):
    props = tmp_path / "props.ltl"
    props.write_text(f"mixed: {FORMULA}\n")

    def check(*arguments: str) -> str:
        out = io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = main(["check", str(BACKUP), "--ltl", str(props), *arguments])
        assert code == 1, out.getvalue()
        return out.getvalue()
    return check


def test_text_names_the_task_of_each_atom_under_the_formula(run):
    assert f"  formula: {FORMULA}\n  {ATOMS_TEXT}\n" in run()


def test_json_lists_each_atom_with_its_tasks(run):
    properties = {p["name"]: p for p in json.loads(run("--format", "json"))["properties"]}
    assert properties["mixed"]["atoms"] == ATOMS
    assert properties["no_deadlock"]["atoms"] is None


def test_sarif_rule_and_result_name_the_tasks(run):
    sarif_run = json.loads(run("--format", "sarif"))["runs"][0]
    rules = {rule["id"]: rule["shortDescription"]["text"]
             for rule in sarif_run["tool"]["driver"]["rules"]}
    assert rules["mixed"] == f"{FORMULA} [{ATOMS_TEXT}]"
    [violation] = [r for r in sarif_run["results"] if r["ruleId"] == "mixed"]
    assert f"[{ATOMS_TEXT}]" in violation["message"]["text"]


def test_junit_failure_names_the_tasks(run, tmp_path):
    run("--junit", str(tmp_path / "report.xml"))
    case = ET.parse(tmp_path / "report.xml").find(".//testcase[@name='mixed']")
    assert case.find("failure").get("message") == f"{FORMULA} [{ATOMS_TEXT}]"


def test_html_page_data_names_the_tasks(run, tmp_path):
    run("--html", str(tmp_path / "report.html"))
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    data = json.loads(page.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    mixed = next(p for p in data["properties"] if p["name"] == "mixed")
    assert (mixed["atoms"], mixed["atoms_text"]) == (ATOMS, ATOMS_TEXT)
    # the timeline's rows name each task's own data as atoms do
    names = {row["name"] for row in mixed["trace"]["timeline"]}
    assert "T_LOG.seen" in names and "go" in names, names


def test_a_pattern_property_names_the_task_of_its_atoms(tmp_path):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["check", str(BACKUP), "--formula", 'pat: absence("T_ROB2.slot = 2") after(go)'])
    assert ('  pattern: absence("T_ROB2.slot = 2") after(go)\n'
            '  formula: G (go -> G !"T_ROB2.slot = 2")\n'
            '  atoms: go (shared), "T_ROB2.slot = 2" (T_ROB2)\n') in out.getvalue()
