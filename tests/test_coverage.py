"""Coverage: after a complete search, statements no input reaches are warnings (RMC701).

Data-driven on tests/check/: a case's ``unreached`` file lists the lines
(``13``) and stretches of lines (``13-14``: one warning) expected to be
reported, in prog.mod or, written ``reader.mod:6``, in another module of the case (a routine that never runs is reported once, at its declaration);
the places of one warning given once per cause (``findings/unreached_causes.py``) are
joined by `` + `` (``11 + 14-17``: the UNDO line and the routine only it calls);
every other case must report none.  The case studies pin
the one dead statement of sorter B, and the three output formats are
checked to carry the same warnings.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.cli import main
from rapidmc.load.message_domains import message_domains
from test_check_cases import _data_lines, report_of, verdict_cases
from test_html_report import browser  # noqa: F401  (the headless Chromium fixture)

ROOT = Path(__file__).resolve().parent.parent
CASES = {case.name: case for case in verdict_cases()}


@pytest.mark.parametrize("name", CASES)
def test_unreached_lines_of_every_check_case(name, monkeypatch):
    case = CASES[name]
    code, document = report_of(case, monkeypatch)
    # domain notes, fixed readings (ReadCfgData in the cfg_* cases) and the sink a --flows
    # counterexample reaches (tests/test_flow_marks.py) and an encrypted module left out are no
    # coverage
    warnings = [w for w in document["warnings"]
                if w["code"] not in ("RMC515", "RMC702", "RMC735", "RMC820")]
    assert all(w["code"] == "RMC701" for w in warnings)
    expected = [tuple(_stretch(place) for place in line.split(" + "))
                for line in _data_lines(case.folder / "unreached")]
    assert [tuple((one["file"], one["line"], one["end_line"]) for one in w["lines"])
            for w in warnings] == expected
    assert all(w["lines"][0]["line"] == w["location"]["line"] for w in warnings)
    assert code == case.exit_code            # warnings never change the exit code


def _stretch(text: str) -> tuple[str, int, int]:
    """``13`` (one statement's line of prog.mod), ``13-14`` (a stretch of lines) or
    ``reader.mod:6`` (a line of another module): (file, first, last)."""
    file, _, lines = text.rpartition(":")
    first, _, last = lines.partition("-")
    return file or "prog.mod", int(first), int(last or first)


def test_no_warnings_after_a_bounded_search(monkeypatch):
    """vacuity_bounded_search never runs its last statements within 5 states: no claim."""
    assert report_of(CASES["vacuity_bounded_search"], monkeypatch)[1]["warnings"] == []


def sorter(program: str, *extra: str) -> list[str]:
    return ["check", f"case_studies/sorter/{program}", "--env", "case_studies/sorter/plant.mod",
            "--ltl", "specs/sorter.ltl", "--quiet", *extra]


@pytest.mark.parametrize("program, lines", [
    ("sorter_a.mod", []),
    ("sorter_b.mod", [84]),       # SetDO c_out after a defective pinion went to C1: s4 stays 0
    ("sorter_c.mod", []),
])
def test_case_studies(program, lines, monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    main(sorter(program, "--format", "json"))
    warnings = json.loads(capsys.readouterr().out)["warnings"]
    assert [w["location"]["line"] for w in warnings] == lines


def test_text_sarif_and_json_carry_the_same_warning(monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    main(sorter("sorter_b.mod"))
    err = capsys.readouterr().err
    assert "case_studies/sorter/sorter_b.mod:84:21: warning: never reached under any input " \
           "[RMC701]" in err
    # beside the counterexample one line; --full-trace adds the source line
    assert "SetDO c_out, 1;" not in err
    main(sorter("sorter_b.mod", "--full-trace"))
    assert "SetDO c_out, 1;" in capsys.readouterr().err
    main(sorter("sorter_b.mod", "--format", "sarif"))
    (run,) = json.loads(capsys.readouterr().out)["runs"]
    (warning,) = [r for r in run["results"] if r["ruleId"] == "RMC701"]
    assert warning["level"] == "warning"
    assert run["tool"]["driver"]["rules"][warning["ruleIndex"]]["id"] == "RMC701"
    region = warning["locations"][0]["physicalLocation"]["region"]
    assert (region["startLine"], region["startColumn"]) == (84, 21)


def test_the_html_page_carries_the_unreached_statements(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    page = tmp_path / "report.html"
    main(sorter("sorter_b.mod", "--html", str(page)))
    capsys.readouterr()
    text = page.read_text()
    data = json.loads(text.split('id="report-data"', 1)[1].split(">", 1)[1].split("</script>")[0])
    assert data["unreached"] == [{"file": "case_studies/sorter/sorter_b.mod", "line": 84,
                                  "end_line": 84, "message": "never reached under any input"}]


def test_the_html_page_shades_the_unreached_line(browser, monkeypatch, capsys, tmp_path):
    from test_html_report import Page
    monkeypatch.chdir(ROOT)
    path = tmp_path / "report.html"
    main(sorter("sorter_b.mod", "--html", str(path)))
    capsys.readouterr()
    page = Page(browser, path)
    page.click('#file-tabs button[title="case_studies/sorter/sorter_b.mod"]')
    shaded = browser.execute_script(
        "return [...document.querySelectorAll('.source .file:not([hidden]) .line.unreached')]"
        ".map((line) => [Number(line.dataset.line), line.title, "
        "line.querySelector('.text').textContent.trim()])")
    assert shaded == [[84, "never reached under any input", "SetDO c_out, 1;"]]


# --- differential: each warning checked by an independent LTL search ---------------------

PLAIN_CASES = [case for case in CASES.values() if not case.extra_args]


@pytest.mark.parametrize("case", PLAIN_CASES, ids=lambda case: case.name)
def test_an_unreached_statement_is_never_about_to_run(case, monkeypatch):
    """``G !AtLine(L)`` holds for every reported line and every line of a routine reported
    as never running (``G !InRoutine(R)`` for the routine itself), and fails for every
    other statement line of the program.  Each line is its own property, searched on its
    own product; one check searches them all, as ``--ltl`` with a property per line
    would, so that the program's graph is built once rather than once per line."""
    monkeypatch.chdir(case.folder)
    env = ["env.mod"] if (case.folder / "env.mod").exists() else []
    modules = ["prog.mod", *sorted(p.name for p in case.folder.glob("*.sys"))]
    program = api.load_program(modules, env=env)
    report = api.check(program)
    routines = {r.span.line: r for r in program.routines if r.namespace == 0}
    stretches = [span for w in report.warnings if w.code.code == "RMC701"
                 for span in (w.span, *w.places)]        # (a grouped warning's places)
    lines = set().union(*map(statement_lines, routines.values()))
    reported = {w.line for w in stretches} | {line for w in stretches for line in lines
                                              if w.line <= line <= w.end_line}
    dead = set(reported)
    for line in reported & set(routines):
        dead |= statement_lines(routines[line])
    never = {}
    for number, line in enumerate(sorted(set().union(*map(statement_lines, routines.values()),
                                                    reported)), start=1):
        routine = routines.get(line)
        atom = f'"InRoutine(\\"{routine.name}\\")"' if routine else f'"AtLine({line})"'
        never[line] = api.property_from_text(f"never_{line}: G !{atom}", number)
    checked = api.check(program, never.values()).verdicts
    verdicts = {line: checked[f"never_{line}"] for line in never}
    probed = _reached_by_a_probe(program, [never[line] for line, verdict in verdicts.items()
                                           if verdict == "HOLDS" and line not in dead])
    for line, verdict in verdicts.items():
        if line in probed:
            verdict = "VIOLATED"
        assert (verdict == "HOLDS") == (line in dead), (line, verdict)


def _reached_by_a_probe(program, nevers) -> set[int]:
    """The lines of the ``never_LINE`` properties that a search offered one of the derived
    probe messages alone (as ``--socket-messages``) violates: a line reached only that way
    is no dead code either."""
    probes = [probe for domain in message_domains(program) for probe in domain.probes]
    reached: set[int] = set()
    for probe in probes:
        left = [never for never in nevers if int(never.name.split("_")[1]) not in reached]
        if not left:
            break
        # (a pair of commands' messages is offered together)
        options = api.CheckOptions(socket_messages=probe if isinstance(probe, tuple)
                                   else (probe,))
        verdicts = api.check(program, left, options).verdicts
        reached |= {int(name.split("_")[1]) for name, verdict in verdicts.items()
                    if name.startswith("never_") and verdict == "VIOLATED"}
    return reached


def statement_lines(routine) -> set[int]:
    return {i.span.line for i in routine.code if i.span is not None and
            type(i).__name__ not in ("EndRoutine", "EndUndo")}
