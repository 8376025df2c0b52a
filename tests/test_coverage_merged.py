"""Coverage and vacuity read off a search with merged steps equal those of one without.

The run-time error search that coverage (RMC701) and vacuity watch runs
with merged steps, whose transitions name every instruction they ran; a
search with one instruction per transition must find the same unreached
lines and the same never-true triggers.  Differential, on the generated
programs of tests/reduction_programs.py (X-free properties, so steps merge),
the check cases and the case studies.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from reduction_programs import properties, random_program
from test_check_cases import run_check, verdict_cases
from cli_capture import run_cli

ROOT = Path(__file__).resolve().parent.parent
CHECK_CASES = [case for case in verdict_cases() if (case.folder / "props.ltl").is_file()]


def explored_facts(argv: list[str]) -> tuple[list, dict, int]:
    """(unreached lines, vacuous trigger per property, states of the run-time error search)."""
    # the last options count
    return facts_of(run_cli(["check", *argv, "--format", "json", "--quiet"]).out)


def facts_of(stdout: str) -> tuple[list, dict, int]:
    """``explored_facts`` of a JSON report."""
    document = json.loads(stdout)
    lines = [(w["location"]["file"], w["location"]["line"]) for w in document["warnings"]
             if w["code"] == "RMC701"]
    vacuous = {p["name"]: p.get("vacuous") for p in document["properties"]}
    runtime = document["properties"][0]
    assert runtime["name"] == "no_runtime_error"
    return lines, vacuous, runtime["stats"]["product_states"]


def assert_same_facts(argv: list[str], merged_report: str | None = None) -> bool:
    """Merged and unmerged searches agree; True when steps were really merged.  The merged
    search's report may be given (``argv``'s own, run elsewhere)."""
    merged = explored_facts(argv) if merged_report is None else facts_of(merged_report)
    plain = explored_facts(argv + ["--no-merge"])
    assert merged[0] == plain[0], "unreached lines differ"
    assert merged[1] == plain[1], "vacuous triggers differ"
    return merged[2] < plain[2]


def test_generated_programs_have_the_same_coverage_and_vacuity(tmp_path):
    merged_somewhere = 0
    for seed in range(0, 60, 2):                 # even seeds: X-free, so steps merge
        program = tmp_path / f"prog{seed}.mod"
        program.write_text(random_program(seed))
        spec = tmp_path / f"props{seed}.ltl"
        spec.write_text("\n".join(properties(seed, with_next=False)) + "\n")
        # each of these programs' searches ends within 600 states, merged or not, but for
        # seed 52's, which no bound up to 20,000 completes: bounded, it reports no coverage
        # nor vacuity to compare, so a bound of 2,000 loses no comparison
        merged_somewhere += assert_same_facts(
            [str(program), "--ltl", str(spec), "--max-states", "2000"])
    assert merged_somewhere >= 20                # the comparison is not between equal searches


@pytest.mark.parametrize("case", CHECK_CASES, ids=lambda case: case.folder.name)
def test_check_cases_have_the_same_coverage_and_vacuity(case, monkeypatch):
    _, merged_report, _ = run_check(case, monkeypatch)     # (in the case's folder)
    assert_same_facts(case.argv()[1:], merged_report)


@pytest.mark.parametrize("program", ["sorter_a.mod", "sorter_b.mod", "sorter_c.mod"])
def test_case_studies_have_the_same_coverage_and_vacuity(program):
    sorter = ROOT / "case_studies" / "sorter"
    assert_same_facts([str(sorter / program), "--env", str(sorter / "plant.mod"),
                       "--ltl", str(ROOT / "specs" / "sorter.ltl")])
