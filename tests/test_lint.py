"""``rapidmc lint`` (issue 22, parts 1 and 2): rules, configuration, reports, flows.

The rules' own examples are linted (the bad one gives the rule's finding, the good one
none); the cases of tests/lint/ carry their expected findings as ``! expect: RMCnnn``
comments on the offending lines (tests/lint/README.md).
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from rapidmc import ast
from rapidmc.diagnostics import REGISTRY
from rapidmc.findings.lint import RULES, lint_program
from rapidmc.findings.lint import documentation as lint_doc
from rapidmc.findings.lint.config import LintConfig, make_config
from rapidmc.syntax import parse_file, parse_text
from cli_capture import run_cli

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
CASES = sorted((ROOT / "tests" / "lint").glob("*.mod"))
EXPECT = re.compile(r"!\s*expect:\s*(RMC\d{3}(?:\s*,\s*RMC\d{3})*)")


EVERY_RULE = LintConfig(select=("RMC8",))      # opt-in rules too


def lint_text(text: str, name: str = "case.mod", config=EVERY_RULE):
    return lint_program(ast.Program(parse_text(text, name)), config)


# --- the registry ------------------------------------------------------------------

@pytest.mark.parametrize("code", sorted(RULES))
def test_bad_example_gives_the_finding_and_the_good_one_none(code):
    rule = RULES[code]
    bad = [f.code.code for f in lint_text(rule.bad, f"{code}_bad.mod")]
    good = [f.code.code for f in lint_text(rule.good, f"{code}_good.mod")]
    assert code in bad
    assert code not in good


def test_rules_are_registered_diagnostic_codes_of_their_range():
    for code, rule in RULES.items():
        assert REGISTRY[code] is rule.code
        assert re.fullmatch(r"RMC8[0-4]\d", code)
        assert rule.severity in ("error", "warning", "note")


def test_the_rules_page_is_generated_from_the_registry():
    assert lint_doc.DOC.read_text(encoding="utf-8") == lint_doc.document(), \
        "docs/lint.md is out of date: run python -m rapidmc.findings.lint.documentation"


# --- the data cases ----------------------------------------------------------------

def expected_findings(path: Path) -> list[tuple[int, str]]:
    found = []
    for number, line in enumerate(path.read_text(encoding="latin-1").splitlines(), start=1):
        match = EXPECT.search(line)
        if match:
            found += [(number, code.strip()) for code in match.group(1).split(",")]
    return sorted(found)


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_lint_case(path):
    """Every expected finding is found, at its own line or as another place of a finding
    given once per cause."""
    findings = lint_program(ast.Program(parse_file(str(path))), EVERY_RULE)
    found = [(span.line, f.code.code) for f in findings for span in (f.span, *f.places)]
    assert sorted(found) == expected_findings(path)


# --- the command -------------------------------------------------------------------

def test_sorter_a_reports_the_not_chain_on_line_73(monkeypatch):
    monkeypatch.chdir(ROOT)
    code, out, _ = run_cli(["lint", "case_studies/sorter/sorter_a.mod"])
    assert code == 1
    assert "case_studies/sorter/sorter_a.mod:73:34: warning: NOT negates" in out
    assert out.rstrip().endswith("1 file, 97 lines: 1 finding (1 warning)")


def test_select_ignore_and_severity_decide_findings_and_exit_code(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    case = str(ROOT / "tests" / "lint" / "unused.mod")
    assert run_cli(["lint", case, "--select", "RMC801"])[0] == 0
    code, out, _ = run_cli(["lint", case, "--select", "unused-data,unused-routine"])
    assert code == 0 and "4 findings (4 notes)" in out          # notes stay below warning
    assert run_cli(["lint", case, "--severity", "note"])[0] == 1
    code, out, _ = run_cli(["lint", case, "--ignore", "RMC806"])
    assert "RMC806" not in out and "RMC807" in out
    code, out, _ = run_cli(["lint", str(ROOT / "tests" / "lint" / "tool_not_pers.mod"),
                            "--severity", "error"])
    assert code == 1 and "error:" in out


def test_opt_in_rules_run_only_when_selected(monkeypatch):
    """RMC803 and RMC806 were judged mostly noise on public code (docs/lint.md): off unless
    a select names them (their code, a prefix of it, or their name)."""
    monkeypatch.chdir(ROOT)
    case = "tests/lint/unused.mod"
    assert "RMC806" not in run_cli(["lint", case])[1]
    assert run_cli(["lint", case, "--select", "unused-data"])[1].count("[RMC806]") == 3
    assert run_cli(["lint", case, "--select", "RMC8"])[1].count("[RMC806]") == 3
    assert not RULES["RMC806"].default and not RULES["RMC803"].default


def test_unknown_rule_or_bad_configuration_is_an_input_error(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    case = str(ROOT / "tests" / "lint" / "unused.mod")
    code, _, err = run_cli(["lint", case, "--select", "RMC999"])
    assert code == 2 and "[RMC840]" in err
    (tmp_path / "pyproject.toml").write_text('[tool.rapidmc.lint]\nseverity = "loud"\n')
    code, _, err = run_cli(["lint", case])
    assert code == 2 and "severity 'loud'" in err and "[RMC840]" in err


def test_pyproject_configuration_is_read_from_the_current_folder_upward(monkeypatch, tmp_path):
    (tmp_path / "pyproject.toml").write_text(
        '[tool.rapidmc.lint]\nignore = ["not-chain"]\nseverities = { RMC807 = "error" }\n')
    inner = tmp_path / "cell"
    inner.mkdir()
    monkeypatch.chdir(inner)
    code, out, _ = run_cli(["lint", str(ROOT / "tests" / "lint" / "unused.mod")])
    assert code == 1 and "error: procedure Forgotten is never called [RMC807]" in out
    code, out, _ = run_cli(["lint", str(ROOT / "case_studies" / "sorter" / "sorter_a.mod")])
    assert code == 0 and "no findings" in out
    code, out, _ = run_cli(["lint", str(ROOT / "case_studies" / "sorter" / "sorter_a.mod"),
                            "--select", "RMC801"])
    # --select replaces the file's select; the file's ignore list still applies
    assert code == 0 and "RMC801" not in out


def test_make_config_merges_file_and_command_line():
    config = make_config({"select": ["RMC80"], "ignore": ["RMC806"]}, "pyproject.toml",
                         ignore=("RMC807",))
    assert config.enabled("RMC801") and not config.enabled("RMC806")
    assert not config.enabled("RMC807") and not config.enabled("RMC820")
    assert LintConfig().enabled("RMC820")


@pytest.mark.parametrize("path", CASES, ids=[p.stem for p in CASES])
def test_no_two_findings_say_the_same_thing(path):
    """One finding per cause: no code and message twice in a report."""
    findings = lint_program(ast.Program(parse_file(str(path))), EVERY_RULE)
    said = [(f.code.code, f.message) for f in findings]
    assert len(said) == len(set(said))


def test_a_repeated_finding_is_one_finding_with_its_places(monkeypatch):
    monkeypatch.chdir(ROOT)
    code, out, _ = run_cli(["lint", "tests/lint/shared_index.mod", "--select", "RMC809"])
    assert code == 1
    assert out.count("PERS 'count' is used as an index") == 1
    assert "note: 1 more place: tests/lint/shared_index.mod line 36" in out
    assert out.rstrip().endswith("3 findings (3 warnings)")


def test_a_shared_index_another_task_changes_is_found_in_a_backup(monkeypatch, tmp_path):
    """RMC809 in a task that only reads a PERS index: found when another task of the backup
    changes it (lint_tasks), not when every task leaves it to its initial value."""
    reader = ("MODULE Reader\n  PERS num slot := 1;\n  VAR robtarget places{4};\n"
              "  PROC main()\n    MoveL places{slot}, v100, fine, tool0;\n  ENDPROC\nENDMODULE\n")
    writer = ("MODULE Writer\n  PERS num slot := 1;\n  PROC main()\n    {}\n  ENDPROC\n"
              "ENDMODULE\n")
    monkeypatch.chdir(tmp_path)
    found = {}
    for change in ("Incr slot;", "slot := 2;"):
        backup = tmp_path / change[:4]
        for task, text in (("T_ROB1", reader), ("T_PLC", writer.format(change))):
            folder = backup / "RAPID" / task / "PROGMOD"
            folder.mkdir(parents=True)
            (folder / f"{task}.mod").write_text(text)
        (backup / "BACKINFO").mkdir()
        (backup / "BACKINFO" / "backinfo.txt").write_text(
            ">>SYSTEM_ID:\ncell\n>>PRODUCTS_ID:\n>>TASK1: (T_ROB1,,)\n>>TASK2: (T_PLC,,)\n")
        code, out, err = run_cli(["lint", str(backup), "--select", "RMC809", "--task", "T_ROB1"])
        found[change] = (code, out.count("[RMC809]"))
    assert found == {"Incr slot;": (1, 1), "slot := 2;": (0, 0)}


def test_json_and_sarif_reports(monkeypatch):
    monkeypatch.chdir(ROOT)
    case = "tests/lint/flows.mod"
    code, out, _ = run_cli(["lint", case, "--format", "json"])
    document = json.loads(out)
    assert code == document["exit_code"] == 1
    flows = [f for f in document["findings"] if f["code"] == "RMC820"]
    # The socket read of line 15 reaches two late-bound calls (lines 16, 17): one finding.
    assert len(flows) == 5 and document["summary"]["warning"] == 5
    first = flows[0]
    assert first["location"]["line"] == 16 and first["flow"][0]["line"] == 15
    assert first["flow"][-1]["line"] == 16
    assert [p["line"] for p in first["places"]] == [17]
    assert all(f["places"] == [] for f in flows[1:])
    code, out, _ = run_cli(["lint", case, "--format", "sarif"])
    sarif = json.loads(out)
    results = sarif["runs"][0]["results"]
    assert len(results) == 5 and all(r["level"] == "warning" for r in results)
    steps = results[0]["codeFlows"][0]["threadFlows"][0]["locations"]
    assert [s["location"]["physicalLocation"]["region"]["startLine"] for s in steps] == [15, 16]
    related = results[0]["relatedLocations"]
    assert [r["physicalLocation"]["region"]["startLine"] for r in related] == [17]


def test_a_syntax_error_is_reported_not_linted(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.mod").write_text("MODULE Bad\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n")
    code, out, err = run_cli(["lint", "bad.mod"])
    assert code == 2 and "bad.mod:3" in err and "[RMC101]" in err and out == ""


@pytest.mark.parametrize("form", ["json", "sarif"])
def test_a_syntax_error_is_a_finding_of_a_machine_readable_report(tmp_path, monkeypatch, form):
    # a CI step uploads the report whatever the exit code: it must be a report, not nothing
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.mod").write_text("MODULE Bad\n  PROC main()\n    x := ;\n  ENDPROC\nENDMODULE\n")
    code, out, err = run_cli(["lint", "bad.mod", "--format", form])
    assert code == 2 and "[RMC101]" in err
    document = json.loads(out)
    if form == "json":
        assert document["exit_code"] == 2
        assert [(f["code"], f["location"]["line"]) for f in document["findings"]] == [("RMC101", 3)]
    else:
        [result] = document["runs"][0]["results"]
        assert (result["ruleId"], result["level"]) == ("RMC101", "error")
        assert result["locations"][0]["physicalLocation"]["region"]["startLine"] == 3


def test_a_backup_is_linted_task_by_task(monkeypatch, tmp_path):
    monkeypatch.chdir(tmp_path)
    for task, text in (("T_ROB1", "MODULE Main\n  PROC main()\n    VAR bool a;\n"
                        "    a := a AND NOT a AND a;\n  ENDPROC\nENDMODULE\n"),
                       ("T_BG", "MODULE Watch\n  PERS num n := 0;\n  PROC main()\n"
                        "    WHILE TRUE DO\n      n := n + 1;\n    ENDWHILE\n  ENDPROC\n"
                        "ENDMODULE\n")):
        folder = tmp_path / "backup" / "RAPID" / task / "PROGMOD"
        folder.mkdir(parents=True)
        (folder / f"{task}.mod").write_text(text)
    code, out, _ = run_cli(["lint", "backup"])
    assert code == 1 and "[RMC801]" in out and "[RMC805]" in out
    code, out, _ = run_cli(["lint", "backup", "--task", "T_BG"])
    assert "[RMC801]" not in out and "[RMC805]" in out


# --- flows ---------------------------------------------------------------------------

SOCKET_MOVE = (ROOT / "tests" / "check" / "flows_socket_move" / "prog.mod").read_text()


def test_socket_to_move_finding_names_both_lines():
    findings = [f for f in lint_text(SOCKET_MOVE, "socket.mod") if f.code.code == "RMC820"]
    assert len(findings) == 1
    finding = findings[0]
    assert finding.span.line == 14
    assert "line 11: SocketReceive reads message" in finding.message
    # the sink's line is the finding's own place (its other sinks, if any, are places)
    assert "reaches the target of MoveL" in finding.message
    assert [span.line for span, _ in finding.flow] == [11, 12, 13, 14]


def test_a_range_check_before_the_move_silences_the_flow():
    checked = (ROOT / "tests" / "check" / "flows_socket_move_checked" / "prog.mod").read_text()
    assert not [f for f in lint_text(checked, "checked.mod") if f.code.code == "RMC820"]


REALWORLD = sorted({path.parent for pattern in ("*.mod", "*.sys")
                    for path in (ROOT / "tests" / "realworld").rglob(pattern)})


@pytest.mark.parametrize("folder", REALWORLD + [ROOT / "tests" / "lint"],
                         ids=[str(f.relative_to(ROOT)) for f in REALWORLD] + ["tests/lint"])
def test_revisiting_only_what_changed_finds_every_taint(folder):
    """The taint analysis visits again only the statements that name data tainted in the
    round before; visiting every statement every round finds the same taint."""
    from rapidmc.findings.lint.context import LintContext
    from rapidmc.findings.lint.flows import TaintAnalysis
    for path in sorted(folder.glob("*.*")):
        if path.suffix.lower() not in (".mod", ".sys"):
            continue
        context = LintContext(ast.Program(parse_file(str(path))))
        fast, every = TaintAnalysis(context), TaintAnalysis(context, every_round_everything=True)
        assert set(fast.tainted) == set(every.tainted), path
        assert set(fast.returns) == set(every.returns), path
