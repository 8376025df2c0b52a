"""Service routines: summed up in one coverage warning, and checked each as an entry of its
own with ``check --entry all`` (commands/entries.py), a verdict table per entry in every
output format."""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import xmlschema

from cli_capture import run_cli

ROOT = Path(__file__).resolve().parent.parent
PROGRAM = ROOT / "tests" / "entries" / "service_routines.mod"
JUNIT_SCHEMA = xmlschema.XMLSchema(str(ROOT / "tests" / "data" / "jenkins-junit.xsd"))
# the entry, the service routines, then the routine with a parameter no routine calls
# (a library routine: commands/library_entries.py)
ENTRIES = ["main", "CalibrateCamera", "TestGripper", "Unused"]


@pytest.fixture(autouse=True)
def in_the_cases_folder(monkeypatch):
    monkeypatch.chdir(PROGRAM.parent)


def test_routines_nobody_calls_are_one_warning_naming_them_all():
    code, out, err = run_cli(["check", PROGRAM.name, "--quiet"])
    assert code == 0
    assert err.count("[RMC701]") == 2
    assert "warning: 2 routines never run: CalibrateCamera, TestGripper [RMC701]" in err
    assert "note: 1 more place: service_routines.mod lines 23-25" in err
    # a routine with parameters is no service routine: its own warning, as before
    assert "routine Unused never runs" in err


def test_every_entry_gets_its_own_verdict_table():
    code, out, err = run_cli(["check", PROGRAM.name, "--entry", "all", "--quiet"])
    assert code == 1                        # CalibrateCamera divides by zero
    headings = [line for line in out.splitlines() if line.startswith("entry ")]
    assert headings == [f"entry {name}:" for name in ENTRIES]
    calibrate = out.split("entry CalibrateCamera:")[1].split("entry TestGripper:")[0]
    assert "no_runtime_error: VIOLATED" in calibrate
    assert "no_runtime_error: HOLDS" in out.split("entry CalibrateCamera:")[0]
    # coverage over every entry together: Unused is an entry too, so every line runs
    assert "[RMC701]" not in err
    assert "note: entry Unused: called once with offset the free analog input Unused_offset" \
        in err


def test_entry_all_in_json():
    code, out, _ = run_cli(["check", PROGRAM.name, "--entry", "ALL", "--format", "json", "--quiet"])
    document = json.loads(out)
    assert code == 1 and "properties" not in document
    assert [entry["entry"] for entry in document["entries"]] == ENTRIES
    verdicts = {entry["entry"]: {p["name"]: p["verdict"] for p in entry["properties"]}
                for entry in document["entries"]}
    assert verdicts["CalibrateCamera"]["no_runtime_error"] == "VIOLATED"
    assert verdicts["TestGripper"] == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    assert [w["message"] for w in document["warnings"] if w["code"] == "RMC701"] == []
    assert "entry Unused: called once with offset the free analog input Unused_offset" in [
        w["message"] for w in document["warnings"]]


def test_entry_all_in_sarif_is_a_run_per_entry():
    code, out, _ = run_cli(["check", PROGRAM.name, "--entry", "all", "--format", "sarif", "--quiet"])
    runs = json.loads(out)["runs"]
    assert code == 1
    assert [run["automationDetails"]["id"] for run in runs] == [f"entry/{n}" for n in ENTRIES]
    failed = [[r["ruleId"] for r in run["results"] if r["level"] == "error"] for run in runs]
    assert failed == [[], ["no_runtime_error"], [], []]


def test_entry_all_in_junit_is_a_valid_suite_per_entry(tmp_path):
    report = tmp_path / "report.xml"
    run_cli(["check", PROGRAM.name, "--entry", "all", "--junit", str(report), "--quiet"])
    JUNIT_SCHEMA.validate(str(report))
    root = ET.parse(report).getroot()
    suites = root.findall("testsuite")
    assert [s.get("name") for s in suites] == [
        f"{PROGRAM.name} (entry {name})" for name in ENTRIES]
    assert [s.get("failures") for s in suites] == ["0", "1", "0", "0"]
    assert root.get("tests") == "8" and root.get("failures") == "1"


def test_entry_all_writes_a_page_per_entry(tmp_path):
    page = tmp_path / "report.html"
    run_cli(["check", PROGRAM.name, "--entry", "all", "--html", str(page), "--quiet"])
    written = sorted(p.name for p in tmp_path.iterdir())
    assert written == ["report.CalibrateCamera.html", "report.TestGripper.html",
                       "report.Unused.html", "report.html"]


def test_a_backups_service_routines_are_its_main_tasks():
    """In a backup, --entry names routines of the main task: its service routine is an
    entry, the PLC task's stays a coverage warning."""
    code, out, err = run_cli(["check", "backup", "--entry", "all", "--format", "json", "--quiet"])
    document = json.loads(out)
    assert code == 0
    assert [entry["entry"] for entry in document["entries"]] == ["main", "ServicePosition"]
    assert [w["message"] for w in document["warnings"] if w["code"] == "RMC701"] == [
        "never reached under any input (routine ResetPlc never runs)"]


def test_entry_all_in_code_quality_names_the_entry_of_each_issue():
    code, out, _ = run_cli(["check", PROGRAM.name, "--entry", "all", "--format", "codeclimate",
                            "--quiet"])
    issues = json.loads(out)
    assert code == 1
    violated = [i["description"] for i in issues if i["severity"] == "critical"]
    assert violated == ["entry CalibrateCamera: no_runtime_error is violated: no reachable "
                        "uncaught run-time error"]
    assert len({i["fingerprint"] for i in issues}) == len(issues)


LIBRARY = ROOT / "tests" / "entries" / "library" / "PartLib.mod"
LIBRARY_ENTRIES = ["Ratio", "Slot", "Label", "Ready"]


@pytest.mark.parametrize("entry", [[], ["--entry", "all"]])
def test_a_library_without_main_is_checked_routine_by_routine(entry):
    """A module of FUNCs and procedures with parameters (no main): each is an entry, called
    by a driver with its arguments as free inputs; the default and --entry all agree."""
    code, out, err = run_cli(["check", str(LIBRARY), "--format", "json", "--quiet", *entry])
    document = json.loads(out)
    assert code == 1                        # Ratio divides by a width of 0
    assert [e["entry"] for e in document["entries"]] == LIBRARY_ENTRIES
    verdicts = {e["entry"]: {p["name"]: p["verdict"] for p in e["properties"]}
                for e in document["entries"]}
    assert verdicts["Ratio"]["no_runtime_error"] == "VIOLATED"
    assert all(v == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
               for name, v in verdicts.items() if name != "Ratio")
    ratio = document["entries"][0]["properties"][0]
    assert "ERR_DIVZERO" in json.dumps(ratio["trace"]) or "ERR_DIVZERO" in ratio["reason"]
    notes = [w["message"] for w in document["warnings"] if w["code"] == "RMC515"]
    # how each entry's arguments were chosen, and the routine that could not be driven
    assert "entry Label: called once with large the free digital input Label_large; name " \
        "its string's neutral value" in notes
    assert "entry Ready: called once, with no arguments" in notes
    assert "entry Reset: not checked: counter is a PERS parameter, which no driver can pass" \
        in notes
    # the width's values are stated beside the verdicts (no exact default: a divisor)
    assert any(a.startswith("input Ratio_width takes only values -1..1")
               for a in ratio["assumes"])


def test_a_library_routine_a_main_program_calls_is_no_entry(tmp_path):
    """A FUNC the program's own code calls is checked through that code, not again."""
    program = tmp_path / "prog.mod"
    program.write_text("MODULE M\n  VAR num x := 0;\n  PROC main()\n    x := Twice(2);\n"
                       "  ENDPROC\n  FUNC num Twice(num v)\n    RETURN 2 * v;\n  ENDFUNC\n"
                       "  FUNC num Half(num v)\n    RETURN v / 2;\n  ENDFUNC\nENDMODULE\n")
    code, out, _ = run_cli(["check", str(program), "--entry", "all", "--format", "json", "--quiet"])
    assert code == 0
    assert [e["entry"] for e in json.loads(out)["entries"]] == ["main", "Half"]


def test_procedures_without_main_are_each_an_entry_by_default(tmp_path):
    """Module files without main, whose procedures an operator starts by hand: each
    procedure no routine calls is an entry (as with --entry all), instead of RMC211."""
    program = tmp_path / "prog.mod"
    program.write_text("MODULE M\n  VAR num n := 0;\n  PROC rPick()\n    n := 1;\n  ENDPROC\n"
                       "  PROC rPlace()\n    n := 1 / n;\n  ENDPROC\nENDMODULE\n")
    code, out, err = run_cli(["check", str(program), "--quiet"])
    assert code == 1, err                   # rPlace divides by the 0 n starts with
    headings = [line for line in out.splitlines() if line.startswith("entry ")]
    assert headings == ["entry rPick:", "entry rPlace:"]
    # --entry names one of them as before
    code, out, _ = run_cli(["check", str(program), "--entry", "rPick", "--quiet"])
    assert code == 0 and "entry " not in out
