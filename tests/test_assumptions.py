"""What a verdict rests on that rapidmc assumed, in every output format (issue 19).

Each case under tests/assumptions/ (see its README.md) is a ``rapidmc check`` run whose
verdicts and ``assumes:`` lines are written in ``expected``; the same assumptions must
appear in JSON (``assumes`` of each property), SARIF (``properties.assumes`` of the rule and
of the result), JUnit (``<system-out>``) and the HTML report's data.
"""
from __future__ import annotations

import json
import re
import shlex
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from cli_capture import run_cli

CASES = Path(__file__).resolve().parent / "assumptions"
VERDICT = re.compile(r"^(\S+): (HOLDS|VIOLATED|UNKNOWN)\b")


def run(folder: Path, *extra: str) -> tuple[int, str]:
    """``rapidmc check`` of the case's ``args`` (and ``extra``), from inside its folder."""
    return check_in_folder(folder, *shlex.split((folder / "args").read_text()), *extra)


def check_in_folder(folder: Path, *argv: str) -> tuple[int, str]:
    """Exit code and stdout of ``rapidmc check ARGV --quiet`` run from inside ``folder``."""
    code, out, _ = run_cli(["check", *argv, "--quiet"], cwd=folder)
    return code, out


def expected(folder: Path) -> dict[str, list[str]]:
    """Property -> the sentences of its ``assumes:`` lines, from ``expected``."""
    found: dict[str, list[str]] = {}
    current = None
    for line in (folder / "expected").read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        if line.startswith("  assumes: "):
            found[current].append(line[len("  assumes: "):])
        else:
            current = VERDICT.match(line).group(1)
            found[current] = []
    return found


def text_lines(out: str) -> list[str]:
    kept = []
    for line in out.splitlines():
        match = VERDICT.match(line)
        if match:
            kept.append(f"{match.group(1)}: {match.group(2)}")
        elif line.startswith("  assumes: "):
            kept.append(line)
    return kept


CASE_NAMES = sorted(p.name for p in CASES.iterdir() if p.is_dir())


@pytest.mark.parametrize("name", CASE_NAMES)
def test_text_shows_the_assumptions_under_each_verdict(name):
    folder = CASES / name
    _, out = run(folder)
    wanted = [line for line in (folder / "expected").read_text().splitlines()
              if line.strip() and not line.startswith("#")]
    assert text_lines(out) == wanted, out


@pytest.mark.parametrize("name", CASE_NAMES)
def test_json_sarif_junit_and_html_carry_the_same_assumptions(name, tmp_path):
    folder = CASES / name
    wanted = expected(folder)
    _, out = run(folder, "--format", "json")
    assert {p["name"]: p["assumes"] for p in json.loads(out)["properties"]} == wanted

    _, out = run(folder, "--format", "sarif")
    run_ = json.loads(out)["runs"][0]
    rules = {rule["id"]: rule.get("properties", {}).get("assumes", [])
             for rule in run_["tool"]["driver"]["rules"]}
    assert {name: rules[name] for name in wanted} == wanted
    for result in run_["results"]:
        if result["ruleId"] in wanted:
            assert result.get("properties", {}).get("assumes", []) == wanted[result["ruleId"]]

    junit, page = tmp_path / "report.xml", tmp_path / "report.html"
    run(folder, "--junit", str(junit), "--html", str(page))
    cases = {case.get("name"): case for case in ET.parse(junit).getroot().iter("testcase")}
    for prop, sentences in wanted.items():
        out_text = cases[prop].findtext("system-out") or ""
        assert [line.split(" assumes: ", 1)[1] for line in out_text.splitlines()
                if " assumes: " in line] == sentences
    html = page.read_text(encoding="utf-8")
    for sentences in wanted.values():
        for sentence in sentences:
            assert json.dumps(sentence)[1:-1] in html
