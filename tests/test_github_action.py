"""The GitHub Action (action.yml) and the workflow example of docs/ci.md.

The metadata validates against SchemaStore's schema of action metadata, and the example
workflow against its schema of workflows (both vendored in tests/data, sources in its README).
The step that runs rapidmc is run here as GitHub runs it, by bash with the inputs in its
environment: it writes the SARIF report, the HTML report and the exit code to GITHUB_OUTPUT.
"""
from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import jsonschema
import pytest
import yaml

ROOT = Path(__file__).resolve().parent.parent
DATA = ROOT / "tests" / "data"
SAMPLES = ROOT / "tests" / "ci"
ACTION = yaml.safe_load((ROOT / "action.yml").read_text(encoding="utf-8"))


def schema(name: str) -> dict:
    return json.loads((DATA / name).read_text(encoding="utf-8"))


def test_the_action_metadata_validates_against_its_schema():
    jsonschema.Draft7Validator(schema("github-action.schema.json")).validate(ACTION)
    assert ACTION["runs"]["using"] == "composite"


def test_the_schema_refuses_metadata_it_should():
    """The vendored schema is a real check: a composite step without a shell is refused."""
    broken = json.loads(json.dumps(ACTION))
    del broken["runs"]["steps"][1]["shell"]
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft7Validator(schema("github-action.schema.json")).validate(broken)


def test_every_input_and_step_the_action_names_is_declared():
    text = (ROOT / "action.yml").read_text(encoding="utf-8")
    assert set(re.findall(r"inputs\.([\w-]+)", text)) <= set(ACTION["inputs"])
    step_ids = {step.get("id") for step in ACTION["runs"]["steps"]}
    assert set(re.findall(r"steps\.([\w-]+)\.outputs", text)) <= step_ids


def workflow_examples() -> list[dict]:
    text = (ROOT / "docs" / "ci.md").read_text(encoding="utf-8")
    blocks = [yaml.safe_load(block) for block in re.findall(r"```yaml\n(.*?)```", text, re.S)]
    workflows = [block for block in blocks if isinstance(block, dict) and "jobs" in block]
    for workflow in workflows:       # YAML 1.1 (PyYAML) reads the key `on` as true
        workflow["on"] = workflow.pop(True)
    return workflows


def test_the_workflow_example_validates_and_uses_the_action():
    (workflow,) = workflow_examples()
    jsonschema.Draft7Validator(schema("github-workflow.schema.json")).validate(workflow)
    used = [step for job in workflow["jobs"].values() for step in job["steps"]
            if "rapidmc" in step.get("uses", "")]
    assert {step["with"]["command"] for step in used} == {"check", "lint"}
    assert all(set(step["with"]) <= set(ACTION["inputs"]) for step in used)
    assert workflow["permissions"]["security-events"] == "write"


def run_step(tmp_path: Path, which: str, command: str, args: str) -> tuple[int, dict]:
    """The action's 'Run rapidmc' step in ``tmp_path`` with a copy of a sample program:
    (the step's exit status, the outputs it wrote)."""
    (step,) = [s for s in ACTION["runs"]["steps"] if s.get("id") == "rapidmc"]
    shutil.copy(SAMPLES / which / "cell.mod", tmp_path / "cell.mod")
    shutil.copy(SAMPLES / "cell.ltl", tmp_path / "cell.ltl")
    outputs = tmp_path / "github_output"
    environment = dict(os.environ, GITHUB_OUTPUT=str(outputs), RAPIDMC_COMMAND=command,
                       RAPIDMC_ARGS=args, RAPIDMC_SARIF="report.sarif",
                       RAPIDMC_HTML="report.html",
                       PATH=f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}")
    assert set(step["env"]) <= set(environment)
    done = subprocess.run(["bash", "-e", "-c", step["run"]], cwd=tmp_path, env=environment,
                          capture_output=True, text=True, timeout=300)
    written = dict(line.split("=", 1) for line in outputs.read_text().splitlines())
    return done.returncode, written


@pytest.mark.skipif(shutil.which("bash") is None, reason="bash is not installed")
def test_the_run_step_writes_sarif_html_and_the_exit_code_of_a_violation(tmp_path):
    status, outputs = run_step(tmp_path, "violating", "check", "cell.mod --ltl 'cell.ltl'")
    assert status == 0 and outputs["exit-code"] == "1"
    sarif = json.loads((tmp_path / "report.sarif").read_text())
    assert [r["ruleId"] for r in sarif["runs"][0]["results"] if r["level"] == "error"] == \
        ["at_most_three"]
    assert "at_most_three" in (tmp_path / "report.html").read_text()


@pytest.mark.skipif(shutil.which("bash") is None, reason="bash is not installed")
@pytest.mark.parametrize("which, code", [("clean", "0"), ("violating", "1")])
def test_the_run_step_lints(tmp_path, which, code):
    status, outputs = run_step(tmp_path, which, "lint", "*.mod")
    assert status == 0 and outputs["exit-code"] == code
    results = json.loads((tmp_path / "report.sarif").read_text())["runs"][0]["results"]
    assert [r["ruleId"] for r in results] == ([] if code == "0" else ["RMC808"])
    assert not (tmp_path / "report.html").exists()
