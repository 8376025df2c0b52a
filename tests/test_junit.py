"""``rapidmc check --junit FILE``: JUnit XML that validates against the schema Jenkins reads.

Data-driven on the hand-checked cases under tests/check/: every case's
report validates against tests/data/jenkins-junit.xsd, and each test case
says what the expected verdict says (HOLDS passed, VIOLATED a failure
whose message is the formula, UNKNOWN skipped); a case that expects an
input error gets one ``<error>`` carrying that diagnostic code.
"""
from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import xmlschema

from rapidmc.report.junit import format_junit_diagnostics
from rapidmc.cli import main
from rapidmc.diagnostics import SYNTAX, Diagnostic
from test_check_cases import CASES_DIR, load_case

ROOT = Path(__file__).resolve().parent.parent
SCHEMA = xmlschema.XMLSchema(str(ROOT / "tests" / "data" / "jenkins-junit.xsd"))
CASES = sorted(folder.name for folder in CASES_DIR.iterdir() if (folder / "expected").exists())


def junit_report(monkeypatch, capsys, folder: Path, argv: list[str], tmp_path) -> ET.Element:
    """Run ``rapidmc`` in ``folder`` with --junit; the validated report's <testsuite>."""
    report = tmp_path / "report.xml"
    monkeypatch.chdir(folder)
    main([*argv, "--junit", str(report)])
    capsys.readouterr()
    SCHEMA.validate(str(report))
    (suite,) = ET.parse(report).getroot()
    return suite


def outcome(case: ET.Element) -> str:
    if case.find("failure") is not None:
        return "VIOLATED"
    if case.find("skipped") is not None:
        return "UNKNOWN"
    return "ERROR" if case.find("error") is not None else "HOLDS"


@pytest.mark.parametrize("name", CASES)
def test_every_check_case_gives_a_valid_report_with_its_verdicts(name, monkeypatch, capsys,
                                                                 tmp_path):
    case = load_case(CASES_DIR / name)
    if case.xfail:
        pytest.skip(case.xfail)
    suite = junit_report(monkeypatch, capsys, case.folder, case.argv(), tmp_path)
    cases = suite.findall("testcase")
    assert suite.get("tests") == str(len(cases))
    if case.error is not None:
        (input_case,) = cases
        assert input_case.get("name") == "input"
        assert [e.get("type") for e in input_case.findall("error")][0] == case.error.code
        return
    assert {c.get("name"): outcome(c) for c in cases} == case.verdicts
    assert suite.get("failures") == str(list(case.verdicts.values()).count("VIOLATED"))
    assert suite.get("skipped") == str(list(case.verdicts.values()).count("UNKNOWN"))


def test_a_failure_carries_the_formula_and_the_counterexample(monkeypatch, capsys, tmp_path):
    suite = junit_report(monkeypatch, capsys, ROOT,
                         ["check", "case_studies/sorter/sorter_b.mod", "--env",
                          "case_studies/sorter/plant.mod", "--ltl", "specs/sorter.ltl",
                          "--quiet"], tmp_path)
    assert suite.get("name") == "case_studies/sorter/sorter_b.mod"
    failures = {c.get("name"): c.find("failure") for c in suite.findall("testcase")
                if c.find("failure") is not None}
    assert set(failures) == {"P2", "P3"}
    p2 = failures["P2"]
    assert p2.get("message") == "G((!C_IN & !(S_1 & S_2)) -> F(!S_3 & S_4))"
    assert p2.text.startswith("counterexample: ")
    assert "-- loop starts here (repeats forever) --" in p2.text
    assert "sorter_b.mod:" in p2.text


def test_an_unknown_verdict_is_skipped_with_the_bound_as_reason(monkeypatch, capsys, tmp_path):
    suite = junit_report(monkeypatch, capsys, CASES_DIR / "max_states_unknown",
                         load_case(CASES_DIR / "max_states_unknown").argv(), tmp_path)
    skipped = [c.find("skipped").text for c in suite.findall("testcase")
               if c.find("skipped") is not None]
    assert skipped and all("state limit" in text for text in skipped)


def test_characters_xml_cannot_hold_are_written_as_escapes():
    diagnostic = Diagnostic(SYNTAX, "odd byte \x07 in the text")
    text = format_junit_diagnostics([diagnostic], "prog.mod", "prog")
    SCHEMA.validate(ET.fromstring(text.split("\n", 1)[1]))
    (error,) = ET.fromstring(text.split("\n", 1)[1]).iter("error")
    assert error.get("message") == "odd byte \\x07 in the text"
    assert error.get("type") == "RMC101"


def test_an_unwritable_report_file_is_a_diagnostic(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    code = main(["check", "case_studies/hello/hello.mod", "--formula", "p: G true", "--quiet",
                 "--junit", str(tmp_path / "missing" / "report.xml")])
    assert code == 2
    err = capsys.readouterr().err
    assert "cannot write the JUnit report" in err and "[RMC506]" in err


def test_vacuity_and_coverage_warnings_are_in_system_out(monkeypatch, capsys, tmp_path):
    case = load_case(CASES_DIR / "vacuity_trigger_never")
    suite = junit_report(monkeypatch, capsys, case.folder, case.argv(), tmp_path)
    outputs = {c.get("name"): c.findtext("system-out") for c in suite.findall("testcase")}
    assert outputs["served_after_request"] == 'HOLDS vacuously: "request" is never true\n'
    assert outputs["wraps"] is None
    assert "prog.mod:12:17: warning: never reached under any input [RMC701]" in \
        suite.findtext("system-out")


@pytest.mark.parametrize("argv", [
    ["check", "case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
     "--quiet", "--junit", "{missing}/report.xml"],
    ["graph", "case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
     "--quiet", "-o", "{missing}/states.graphml"],
    ["check", "case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
     "--quiet", "--junit", "{folder}"],
])
def test_an_unwritable_report_is_refused_before_the_search(argv, monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    argv = [a.format(missing=tmp_path / "missing", folder=tmp_path) for a in argv]
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert "[RMC506]" in err
    assert "HOLDS" not in out and "states:" not in out          # no search ran
