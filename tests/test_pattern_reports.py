"""Specification patterns end to end: the sorting cell's P1-P3 written as patterns
(specs/sorter_patterns.ltl) give the verdicts of specs/sorter.ltl, and every report format
shows the pattern beside its LTL translation."""
from __future__ import annotations

import json
import os
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from rapidmc import api
from cli_capture import run_cli

ROOT = Path(__file__).resolve().parent.parent
SORTER = "case_studies/sorter"
P2_PATTERN = "response(!C_IN & !(S_1 & S_2), !S_3 & S_4)"
P2_FORMULA = "G (!C_IN & !(S_1 & S_2) -> F (!S_3 & S_4))"


@pytest.fixture
def at_root():
    before = os.getcwd()
    os.chdir(ROOT)
    yield
    os.chdir(before)


@pytest.mark.parametrize("program, plant", [
    ("sorter_a.mod", "plant.mod"), ("sorter_b.mod", "plant.mod"), ("sorter_c.mod", "plant.mod"),
    ("sorter_a.mod", "variants/plant_reset_on_arrival.mod"),
    ("sorter_a.mod", "variants/plant_sensors_forget.mod")])
def test_the_patterns_give_the_verdicts_of_the_ltl_properties(program, plant):
    loaded = api.load_program([str(ROOT / SORTER / program)], env=[str(ROOT / SORTER / plant)])
    by_ltl = api.check(loaded, api.read_properties(str(ROOT / "specs/sorter.ltl")))
    by_patterns = api.check(loaded, api.read_properties(str(ROOT / "specs/sorter_patterns.ltl")))
    assert by_patterns.verdicts == by_ltl.verdicts
    assert [r.pattern for r in by_patterns.results[2:]] == [
        "response(!C_IN & S_1 & S_2, S_3 & !S_4)", P2_PATTERN,
        "response((S_3 & !S_4) | (!S_3 & S_4), C_OUT) globally"]


def run(*arguments: str) -> tuple[int, str]:
    code, out, _ = run_cli(["check", f"{SORTER}/sorter_b.mod", "--env", f"{SORTER}/plant.mod",
                            "--ltl", "specs/sorter_patterns.ltl", *arguments])
    return code, out


def test_text_shows_the_pattern_above_the_formula(at_root):
    code, text = run()
    assert code == 1
    assert "P2: VIOLATED" in text
    assert f"  pattern: {P2_PATTERN}\n  formula: {P2_FORMULA}\n" in text


def test_json_carries_the_pattern_and_its_translation(at_root):
    _, text = run("--format", "json")
    properties = {p["name"]: p for p in json.loads(text)["properties"]}
    assert (properties["P2"]["pattern"], properties["P2"]["formula"]) == (P2_PATTERN, P2_FORMULA)
    assert properties["no_deadlock"]["pattern"] is None


def test_sarif_rules_and_results_name_pattern_and_formula(at_root):
    _, text = run("--format", "sarif")
    run_ = json.loads(text)["runs"][0]
    described = f"{P2_PATTERN} (LTL: {P2_FORMULA})"
    rules = {rule["id"]: rule["shortDescription"]["text"]
             for rule in run_["tool"]["driver"]["rules"]}
    assert rules["P2"] == described
    [violation] = [r for r in run_["results"] if r["ruleId"] == "P2"]
    assert violation["message"]["text"].startswith(f"P2 is violated: {described} ")


def test_junit_failure_message_names_pattern_and_formula(at_root, tmp_path):
    run("--junit", str(tmp_path / "report.xml"))
    case = ET.parse(tmp_path / "report.xml").find(".//testcase[@name='P2']")
    assert case.find("failure").get("message") == f"{P2_PATTERN} (LTL: {P2_FORMULA})"


def test_the_html_page_data_carries_the_pattern(at_root, tmp_path):
    run("--html", str(tmp_path / "report.html"))
    page = (tmp_path / "report.html").read_text(encoding="utf-8")
    data = json.loads(page.split('id="report-data">', 1)[1].split("</script>", 1)[0])
    p2 = next(p for p in data["properties"] if p["name"] == "P2")
    assert (p2["pattern"], p2["formula"]) == (P2_PATTERN, P2_FORMULA)
