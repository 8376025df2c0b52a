"""``--format codeclimate`` and baselines of ``check`` and ``lint`` (docs/ci.md).

The Code Quality report validates against the format's rules (tests/data), its fingerprints
stay the same across runs and under an edit above the findings, and a baseline hides the
findings it records, even moved by such an edit, and not a new one.
"""
from __future__ import annotations

import json
import re
import shutil
from pathlib import Path

import jsonschema
import pytest
import yaml

from cli_capture import run_cli

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "tests" / "ci"
QUALITY = jsonschema.Draft7Validator(json.loads(
    (ROOT / "tests" / "data" / "gitlab-code-quality.schema.json").read_text(encoding="utf-8")))

# Lines put above everything in the module: they move every finding down and change nothing.
EDIT_ABOVE = "  ! a note a colleague added above everything\n  ! (two lines of it)\n\n"
# A second unreachable statement, and a property the program violates too.
NEW_UNREACHABLE = ("  PROC Helper(num times)\n    RETURN;\n    TPWrite \"never\";\n  ENDPROC\n")


@pytest.fixture
def program(tmp_path, monkeypatch) -> Path:
    """The violating sample in a fresh folder, which is the working folder."""
    shutil.copy(SAMPLES / "violating" / "cell.mod", tmp_path / "cell.mod")
    shutil.copy(SAMPLES / "cell.ltl", tmp_path / "cell.ltl")
    monkeypatch.chdir(tmp_path)
    return tmp_path / "cell.mod"


def edit(program: Path, above: str = "", before_end: str = "") -> None:
    lines = program.read_text().splitlines(keepends=True)
    program.write_text(lines[0] + above + "".join(lines[1:-1]) + before_end + lines[-1])


LINT = ["lint", "cell.mod"]
CHECK = ["check", "cell.mod", "--ltl", "cell.ltl", "--quiet"]


def quality(argv: list[str]) -> tuple[int, list[dict]]:
    code, out, _ = run_cli([*argv, "--format", "codeclimate"])
    issues = json.loads(out)
    QUALITY.validate(issues)
    return code, issues


@pytest.mark.parametrize("argv, expected", [
    (LINT, {("RMC808", "minor", 9)}),
    (CHECK, {("at_most_three", "critical", 5), ("RMC701", "minor", 9)}),
])
def test_code_quality_report_validates_with_a_severity_and_place_per_finding(
        program, argv, expected):
    code, issues = quality(argv)
    assert code == 1
    assert {(i["check_name"], i["severity"], i["location"]["lines"]["begin"])
            for i in issues} == expected
    assert {i["location"]["path"] for i in issues} == {"cell.mod"}


@pytest.mark.parametrize("argv", [LINT, CHECK])
def test_fingerprints_are_stable_across_runs_and_an_edit_above(program, argv):
    _, first = quality(argv)
    _, again = quality(argv)
    edit(program, above=EDIT_ABOVE)
    _, edited = quality(argv)
    assert [i["fingerprint"] for i in first] == [i["fingerprint"] for i in again]
    assert [i["fingerprint"] for i in edited] == [i["fingerprint"] for i in first]
    assert [i["location"]["lines"]["begin"] for i in edited] != \
        [i["location"]["lines"]["begin"] for i in first]      # the findings did move


def test_equal_findings_in_one_file_get_distinct_fingerprints(program):
    edit(program, before_end=NEW_UNREACHABLE + NEW_UNREACHABLE.replace("Helper", "Helper2"))
    _, issues = quality(LINT)
    unreachable = [i for i in issues if i["check_name"] == "RMC808"]
    assert len(unreachable) == 3
    assert len({i["fingerprint"] for i in issues}) == len(issues)


@pytest.mark.parametrize("argv", [LINT, CHECK])
def test_an_input_error_is_a_blocker_issue(program, argv):
    program.write_text("MODULE Cell\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n")
    code, issues = quality(argv)
    assert code == 2
    assert [(i["severity"], i["location"]["lines"]["begin"]) for i in issues] == [("blocker", 3)]


def test_an_unknown_property_is_a_major_issue_whatever_the_bound(program):
    # (at 4 states the search has seen nParts = 4, a bad prefix: VIOLATED)
    fingerprints = set()
    for bound in ("2", "3"):
        code, issues = quality([*CHECK, "--max-states", bound])
        assert code == 3
        unknown = [i for i in issues if i["check_name"] == "at_most_three"]
        assert [i["severity"] for i in unknown] == ["major"]
        assert "UNKNOWN" in unknown[0]["description"] and bound not in unknown[0]["description"]
        fingerprints.add(unknown[0]["fingerprint"])
    assert len(fingerprints) == 1


def test_lint_baseline_hides_old_findings_moved_by_an_edit_and_shows_a_new_one(program):
    code, _, err = run_cli([*LINT, "--write-baseline", "baseline.json"])
    assert code == 0 and "wrote 1 finding" in err
    edit(program, above=EDIT_ABOVE)
    code, out, err = run_cli([*LINT, "--baseline", "baseline.json"])
    assert (code, "RMC808" in out) == (0, False), out
    assert "1 finding(s) recorded in the baseline" in err

    edit(program, before_end=NEW_UNREACHABLE)
    code, issues = quality([*LINT, "--baseline", "baseline.json"])
    assert code == 1
    assert sorted((i["check_name"], i["description"]) for i in issues) == [
        ("RMC807", "procedure Helper is never called"),
        ("RMC808", "this statement is never reached: the RETURN on line 15 comes first")]


def test_check_baseline_hides_a_known_violation_and_shows_a_new_one(program):
    code, _, _ = run_cli([*CHECK, "--write-baseline", "baseline.json"])
    assert code == 0
    edit(program, above=EDIT_ABOVE)
    code, out, _ = run_cli([*CHECK, "--baseline", "baseline.json"])
    assert code == 0
    assert "at_most_three: VIOLATED" in out          # the text still shows every verdict

    new_property = ["--formula", "at_most_four: G \"nParts <= 4\""]
    code, issues = quality([*CHECK, *new_property, "--baseline", "baseline.json"])
    assert code == 1
    assert [i["check_name"] for i in issues] == ["at_most_four"]
    code, out, _ = run_cli([*CHECK, *new_property, "--baseline", "baseline.json", "--format", "sarif"])
    assert [r["ruleId"] for r in json.loads(out)["runs"][0]["results"]] == ["at_most_four"]


@pytest.mark.parametrize("text, says", [
    ("not json", "is not JSON"),
    ('{"schema": "something else"}', "is not a rapidmc baseline"),
    ('{"schema": "rapidmc-baseline/1", "command": "lint", "findings": []}', "'rapidmc lint'"),
    ('{"schema": "rapidmc-baseline/1", "command": "check", "findings": [{"rule": 1}]}',
     "malformed finding"),
    ('{"schema": "rapidmc-baseline/1", "command": "check", "findings": 3}',
     "findings are not a list"),
])
def test_a_bad_baseline_is_an_input_error(program, text, says):
    Path("baseline.json").write_text(text)
    code, _, err = run_cli([*CHECK, "--baseline", "baseline.json"])
    assert code == 2
    assert "[RMC509]" in err and says in err


def test_a_missing_baseline_is_an_input_error_before_the_search(program):
    code, out, err = run_cli([*LINT, "--baseline", "missing.json"])
    assert code == 2 and "[RMC509]" in err and "cannot read the baseline" in err


def test_the_gitlab_example_writes_the_reports_it_declares():
    text = (ROOT / "docs" / "ci.md").read_text(encoding="utf-8")
    blocks = map(yaml.safe_load, re.findall(r"```yaml\n(.*?)```", text, re.S))
    (pipeline,) = [block for block in blocks if isinstance(block, dict) and "stages" in block]
    jobs = {name: job for name, job in pipeline.items() if isinstance(job, dict) and "script" in job}
    assert set(jobs) == {"rapidmc-lint", "rapidmc-check"}
    for job in jobs.values():
        script = " ".join(job["script"])
        reports = job["artifacts"]["reports"]
        assert f"--format codeclimate > {reports['codequality']}" in script
        if "junit" in reports:
            assert f"--junit {reports['junit']}" in script
        assert job["artifacts"]["when"] == "always"


def test_a_warning_given_once_per_cause_carries_every_place(tmp_path, monkeypatch):
    """An RMC701 warning grouping several stretches (findings/unreached_causes.py) has each
    of them in the Code Quality issue, its stretch's last line as ``lines.end``: the lines
    SARIF's relatedLocations and the JSON report's places name."""
    case = ROOT / "tests" / "dead_code" / "routine_called_from_dead_code_only"
    shutil.copy(case / "prog.mod", tmp_path / "prog.mod")
    monkeypatch.chdir(tmp_path)
    argv = ["check", "prog.mod", "--quiet"]
    _, issues = quality(argv)
    _, out, _ = run_cli([*argv, "--format", "json"])
    (grouped,) = [w for w in json.loads(out)["warnings"] if w["code"] == "RMC701" and w["places"]]
    (issue,) = [i for i in issues if i["description"] == grouped["message"]]

    def lines(place: dict) -> tuple:
        return place["line"], max(place["line"], place.get("end_line") or 0)
    assert issue["location"]["path"] == "prog.mod"
    assert (issue["location"]["lines"]["begin"], issue["location"]["lines"].get(
        "end", issue["location"]["lines"]["begin"])) == lines(grouped["location"])
    assert [(o["path"], o["lines"]["begin"], o["lines"].get("end", o["lines"]["begin"]))
            for o in issue["other_locations"]] == \
        [("prog.mod", *lines(place)) for place in grouped["places"]]
    assert len(issue["other_locations"]) == 2
