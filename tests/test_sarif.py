"""``rapidmc check --format sarif``: SARIF 2.1.0 for CI pipelines and code-scanning views."""
from __future__ import annotations

import json

from rapidmc.cli import main

SORTER = ["case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
          "--ltl", "specs/sorter.ltl", "--quiet", "--format", "sarif"]


def run(capsys, monkeypatch, *argv):
    from pathlib import Path
    monkeypatch.chdir(Path(__file__).resolve().parent.parent)
    code = main(["check", *argv])
    return code, json.loads(capsys.readouterr().out)


def test_violations_are_error_results_with_the_counterexample_as_code_flow(capsys, monkeypatch):
    code, sarif = run(capsys, monkeypatch, *SORTER)
    assert code == 1 and sarif["version"] == "2.1.0"
    (run_,) = sarif["runs"]
    rules = [rule["id"] for rule in run_["tool"]["driver"]["rules"]]
    # the properties, then the code of the coverage warning (line 84 is dead code)
    assert rules == ["no_runtime_error", "no_deadlock", "P1", "P2", "P3", "RMC701"]
    violated = {result["ruleId"]: result for result in run_["results"]
                if result["level"] == "error"}
    assert set(violated) == {"P2", "P3"}
    p2 = violated["P2"]
    assert p2["level"] == "error" and rules[p2["ruleIndex"]] == "P2"
    flow = p2["codeFlows"][0]["threadFlows"][0]["locations"]
    assert [step["executionOrder"] for step in flow] == list(range(1, len(flow) + 1))
    files = {step["location"]["physicalLocation"]["artifactLocation"]["uri"]
             for step in flow if "physicalLocation" in step["location"]}
    assert files == {"case_studies/sorter/sorter_b.mod"}
    assert any("loop starts here" in step["location"]["message"]["text"] for step in flow)
    assert any("MoveJ c1" in step["location"]["message"]["text"] for step in flow)
    assert run_["invocations"][0]["exitCode"] == 1


def test_input_errors_are_sarif_results_too(capsys, monkeypatch, tmp_path):
    bad = tmp_path / "bad.mod"
    bad.write_text("MODULE Bad\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n")
    code, sarif = run(capsys, monkeypatch, str(bad), "--formula", "p: G true",
                      "--format", "sarif")
    assert code == 2
    (result,) = sarif["runs"][0]["results"]
    assert result["ruleId"] == "RMC101" and result["level"] == "error"
    region = result["locations"][0]["physicalLocation"]["region"]
    assert region["startLine"] == 3
    assert sarif["runs"][0]["invocations"][0]["executionSuccessful"] is False
