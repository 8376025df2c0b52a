"""Service routines: summed up in one coverage warning, and checked each as an entry of its
own with ``check --entry all`` (commands/entries.py), a verdict table per entry in every
output format."""
from __future__ import annotations

import contextlib
import io
import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import xmlschema

from rapidmc.cli import main

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = ROOT / "tests" / "entries" / "service_routines.mod"
JUNIT_SCHEMA = xmlschema.XMLSchema(str(ROOT / "tests" / "data" / "jenkins-junit.xsd"))
ENTRIES = ["main", "CalibrateCamera", "TestGripper"]


def run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue(), err.getvalue()


@pytest.fixture(autouse=True)
def in_the_cases_folder(monkeypatch):
    monkeypatch.chdir(PROGRAM.parent)


def test_routines_nobody_calls_are_one_warning_naming_them_all():
    code, out, err = run(["check", PROGRAM.name, "--quiet"])
    assert code == 0
    assert err.count("[RMC701]") == 2
    assert "warning: 2 routines never run: CalibrateCamera, TestGripper [RMC701]" in err
    assert "note: 1 more place: service_routines.mod line 23" in err
    # a routine with parameters is no service routine: its own warning, as before
    assert "routine Unused never runs" in err


def test_every_entry_gets_its_own_verdict_table():
    code, out, err = run(["check", PROGRAM.name, "--entry", "all", "--quiet"])
    assert code == 1                        # CalibrateCamera divides by zero
    headings = [line for line in out.splitlines() if line.startswith("entry ")]
    assert headings == [f"entry {name}:" for name in ENTRIES]
    calibrate = out.split("entry CalibrateCamera:")[1].split("entry TestGripper:")[0]
    assert "no_runtime_error: VIOLATED" in calibrate
    assert "no_runtime_error: HOLDS" in out.split("entry CalibrateCamera:")[0]
    # coverage over every entry together: only the routine no entry runs is left
    assert err.count("[RMC701]") == 1 and "routine Unused never runs" in err


def test_entry_all_in_json():
    code, out, _ = run(["check", PROGRAM.name, "--entry", "ALL", "--format", "json", "--quiet"])
    document = json.loads(out)
    assert code == 1 and "properties" not in document
    assert [entry["entry"] for entry in document["entries"]] == ENTRIES
    verdicts = {entry["entry"]: {p["name"]: p["verdict"] for p in entry["properties"]}
                for entry in document["entries"]}
    assert verdicts["CalibrateCamera"]["no_runtime_error"] == "VIOLATED"
    assert verdicts["TestGripper"] == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    assert [w["message"] for w in document["warnings"]] == [
        "never reached under any input (routine Unused never runs)"]


def test_entry_all_in_sarif_is_a_run_per_entry():
    code, out, _ = run(["check", PROGRAM.name, "--entry", "all", "--format", "sarif", "--quiet"])
    runs = json.loads(out)["runs"]
    assert code == 1
    assert [run["automationDetails"]["id"] for run in runs] == [f"entry/{n}" for n in ENTRIES]
    failed = [[r["ruleId"] for r in run["results"] if r["level"] == "error"] for run in runs]
    assert failed == [[], ["no_runtime_error"], []]


def test_entry_all_in_junit_is_a_valid_suite_per_entry(tmp_path):
    report = tmp_path / "report.xml"
    run(["check", PROGRAM.name, "--entry", "all", "--junit", str(report), "--quiet"])
    JUNIT_SCHEMA.validate(str(report))
    root = ET.parse(report).getroot()
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == [
        f"{PROGRAM.name} (entry {name})" for name in ENTRIES]
    assert [s.get("failures") for s in suites] == ["0", "1", "0"]
    assert root.get("tests") == "6" and root.get("failures") == "1"


def test_entry_all_writes_a_page_per_entry(tmp_path):
    page = tmp_path / "report.html"
    run(["check", PROGRAM.name, "--entry", "all", "--html", str(page), "--quiet"])
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == ["report.CalibrateCamera.html", "report.TestGripper.html", "report.html"]


def test_a_backups_service_routines_are_its_main_tasks():
    """In a backup, --entry names routines of the main task: its service routine is an
    entry, the PLC task's stays a coverage warning."""
    code, out, err = run(["check", "backup", "--entry", "all", "--format", "json", "--quiet"])
    document = json.loads(out)
    assert code == 0
    assert [entry["entry"] for entry in document["entries"]] == ["main", "ServicePosition"]
    assert [w["message"] for w in document["warnings"] if w["code"] == "RMC701"] == [
        "never reached under any input (routine ResetPlc never runs)"]


def test_entry_all_in_code_quality_names_the_entry_of_each_issue():
    code, out, _ = run(["check", PROGRAM.name, "--entry", "all", "--format", "codeclimate",
                        "--quiet"])
    issues = json.loads(out)
    assert code == 1
    violated = [i["description"] for i in issues if i["severity"] == "critical"]
    assert violated == ["entry CalibrateCamera: no_runtime_error is violated: no reachable "
                        "uncaught run-time error"]
    assert len({i["fingerprint"] for i in issues}) == len(issues)
