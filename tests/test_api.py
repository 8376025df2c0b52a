"""``rapidmc.api``: the example of docs/api.md runs, and the API gives what the command gives.

The documented example is executed as it stands (its test functions are
collected from the Markdown and called), and the API's verdicts, traces and
warnings are compared with ``rapidmc check --format json`` on the case
studies and the hand-checked cases.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.report.results import property_json
from rapidmc.diagnostics import UserError
from test_check_cases import run_check, verdict_cases

ROOT = Path(__file__).resolve().parent.parent
DOC = ROOT / "docs" / "api.md"


def documented_tests() -> dict:
    """The test functions defined by the python blocks of docs/api.md."""
    namespace: dict = {}
    for block in re.findall(r"```python\n(.*?)```", DOC.read_text(), re.S):
        exec(compile(block, str(DOC), "exec"), namespace)
    return {name: fn for name, fn in namespace.items() if name.startswith("test_")}


@pytest.mark.parametrize("name", sorted(documented_tests()))
def test_the_documented_example_runs(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    documented_tests()[name]()


def test_the_documentation_has_an_example():
    assert len(documented_tests()) >= 2


def test_most_cases_are_compared():
    assert len(PLAIN_CASES) >= 30


PLAIN_CASES = [case for case in verdict_cases()
               if not case.extra_args and (case.folder / "props.ltl").exists()]


@pytest.mark.parametrize("case", PLAIN_CASES, ids=lambda case: case.name)
def test_the_api_reports_what_the_command_reports(case, monkeypatch):
    """Same verdicts, traces and warnings through the command line (the run other modules
    share) and through the API."""
    document = json.loads(run_check(case, monkeypatch)[1])         # (in the case's folder)
    env = ["env.mod"] if (case.folder / "env.mod").exists() else []
    report = api.check(api.load_program(["prog.mod"], env=env), api.read_properties("props.ltl"))
    through_api = [property_json(r, report.describer) for r in report.results]
    for entry in [*through_api, *document["properties"]]:
        entry["stats"].pop("seconds"), entry["stats"].pop("states_per_second")
    assert through_api == document["properties"]
    assert [(w.span.line, w.code.code) for w in report.warnings] == \
        [(w["location"]["line"], w["code"]) for w in document["warnings"]]


def test_bad_input_raises_user_error_with_the_diagnostics(tmp_path):
    program = tmp_path / "bad.mod"
    program.write_text("MODULE Bad\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n")
    with pytest.raises(UserError) as raised:
        api.load_program([str(program)])
    assert raised.value.exit_code == 2
    assert raised.value.diagnostics[0].code.code == "RMC101"


def test_trace_of_a_holding_property_is_refused(monkeypatch):
    monkeypatch.chdir(ROOT)
    program = api.load_program(["case_studies/door/door_safe.mod"],
                               env=["case_studies/door/plant.mod"])
    report = api.check(program, api.read_properties("specs/door.ltl"))
    assert set(report.verdicts.values()) == {"HOLDS"}
    with pytest.raises(ValueError, match="D1 is HOLDS"):
        report.trace("D1")
