"""Vacuity: a property that holds because its trigger is never true is reported as such.

Data-driven on tests/check/: a case's ``vacuous`` file lists ``NAME TRIGGER``
for each property that holds vacuously (TRIGGER as rapidmc prints it); every
other property of every case must carry no vacuity claim, which pins that
the claim is never made when the trigger does occur or when the search was
bounded (``vacuity_bounded_search``).
"""
from __future__ import annotations

import doctest
from pathlib import Path

import pytest

import rapidmc.findings.vacuity as vacuity
from rapidmc import api
from rapidmc.cli import main
from rapidmc.ltl import parse_formula, to_text
from test_check_cases import _data_lines, report_of, verdict_cases

ROOT = Path(__file__).resolve().parent.parent
CASES = {case.name: case for case in verdict_cases()}


def expected_vacuous(folder: Path) -> dict[str, str]:
    return dict(line.split(maxsplit=1) for line in _data_lines(folder / "vacuous"))


@pytest.mark.parametrize("name", CASES)
def test_vacuity_claims_of_every_check_case(name, monkeypatch):
    case = CASES[name]
    code, document = report_of(case, monkeypatch)
    claims = {p["name"]: p["vacuous"] for p in document["properties"] if p["vacuous"]}
    assert claims == expected_vacuous(case.folder)
    for entry in document["properties"]:
        assert entry["vacuous"] is None or entry["verdict"] == "HOLDS"
    assert code == case.exit_code           # vacuity alone never changes the exit code


def test_the_cases_include_a_vacuous_property():
    assert any(expected_vacuous(case.folder) for case in CASES.values())


SORTER = ["check", "case_studies/sorter/sorter_a.mod", "--env", "case_studies/sorter/plant.mod",
          "--quiet", "--formula", "both: G((S_3 & S_4) -> F C_OUT)",
          "--formula", "P1: G((!C_IN & (S_1 & S_2)) -> F(S_3 & !S_4))"]


def test_sorter_text_names_the_trigger_that_never_happens(monkeypatch, capsys):
    """The plant never reports a pinion on both C1 and C2; P1's trigger does happen."""
    monkeypatch.chdir(ROOT)
    assert main(SORTER) == 0
    lines = capsys.readouterr().out.splitlines()
    both = next(line for line in lines if line.startswith("both:"))
    assert both.startswith('both: HOLDS (vacuously: "S_3 & S_4" is never true; ')
    p1 = next(line for line in lines if line.startswith("P1:"))
    assert "vacuously" not in p1 and p1.startswith("P1: HOLDS (")


def test_fail_on_vacuous_exits_1(monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    assert main([*SORTER, "--fail-on-vacuous"]) == 1
    assert main([*SORTER[:-4], "--fail-on-vacuous"]) == 0     # P1 alone: not vacuous
    capsys.readouterr()


@pytest.mark.parametrize("formula, expected", [
    ("G((!C_IN & (S_1 & S_2)) -> F(S_3 & !S_4))", ["!C_IN & (S_1 & S_2)"]),
    ("G(p -> F q) & G(r -> X s)", ["p", "r"]),
    ("G(F p -> G q)", []),                       # a temporal antecedent is no state trigger
    ("G(p -> (q -> F r))", ["p", "q"]),
    ("G F p", []),
])
def test_triggers_are_the_state_condition_antecedents(formula, expected):
    assert [to_text(t) for t in vacuity.triggers(parse_formula(formula))] == expected


def test_the_module_example_runs():
    assert doctest.testmod(vacuity).failed == 0


# --- differential: every claim and every non-claim, checked by an independent search -------

PLAIN_CASES = [case for case in CASES.values()
               if not case.extra_args and (case.folder / "props.ltl").exists()]


@pytest.mark.parametrize("case", PLAIN_CASES, ids=lambda case: case.name)
def test_a_trigger_is_reported_exactly_when_G_not_trigger_holds(case, monkeypatch):
    """For each holding property, its first trigger for which the LTL search proves
    ``G !trigger`` is the one reported as never true (and none when there is none)."""
    monkeypatch.chdir(case.folder)
    env = ["env.mod"] if (case.folder / "env.mod").exists() else []
    program = api.load_program(["prog.mod"], env=env)
    report = api.check(program, api.read_properties("props.ltl"))
    for prop in api.read_properties("props.ltl"):
        checked = report.result(prop.name)
        if checked.result.verdict != "HOLDS":
            continue
        never = None
        for number, trigger in enumerate(vacuity.triggers(prop.formula), start=1):
            absent = api.property_from_text(f"absent: G !({to_text(trigger)})", number)
            if api.check(program, [absent]).verdicts["absent"] == "HOLDS":
                never = to_text(trigger)
                break
        assert checked.vacuous == never, prop.name
