"""Counterexample text that fits on a screen, compared with golden output (issue 19).

Each folder tests/counterexamples/<case>/ is one ``rapidmc check`` run from inside the
folder: ``prog.mod`` and every other ``.mod`` file of the folder (a module written by
``rapidmc stubs``, say), the options of ``args`` (one line, shell quoting), and
``expected``: the text report, stdout then stderr, with seconds written ``<t>``; where
the folder holds ``expected-full``, that is the report with ``--full-trace``.
Regenerate an expectation only after reading the new text: these files are the spec of
what a reader sees.

Every case is also checked for what must hold of any report: no line over 300
characters (``--full-trace`` too), no Python spelling of a value (``None``, ``b'...'``,
``(0.0, ...)``), the same counterexample in JSON with full values, and a JSON trace that
replays.  A case whose JSON trace does not replay because of a checker bug carries a file
``replay-xfail`` saying what the bug is; its replay runs as ``xfail(strict=True)``.
"""
from __future__ import annotations

import json
import re
import shlex
from pathlib import Path

import pytest

from rapidmc.api import check, load_program
from rapidmc.cli import main
from rapidmc.report.counterexample import chosen_inputs_only, counterexample_lines
from rapidmc.report.results import text_options
from rapidmc.report.trace_slice import needed_steps
from cli_capture import run_cli

CASES_DIR = Path(__file__).resolve().parent / "counterexamples"
CASES = sorted(path.name for path in CASES_DIR.iterdir() if (path / "prog.mod").exists())
SECONDS = re.compile(r"\d+\.\d+ s\)")
LONGEST_LINE = 300
PYTHON_SPELLINGS = re.compile(r"\bNone\b|\bb'|\(\d+\.\d+, |\bTrue\b|\bFalse\b")


def command(case: str, *extra: str) -> list[str]:
    folder = CASES_DIR / case
    files = ["prog.mod"] + sorted(p.name for p in folder.glob("*.mod") if p.name != "prog.mod")
    args_file = folder / "args"
    options = shlex.split(args_file.read_text()) if args_file.exists() else []
    return ["check", *files, "--quiet", *options, *extra]


def run(case: str, monkeypatch, *extra: str) -> tuple[int, str, str]:
    monkeypatch.chdir(CASES_DIR / case)
    return run_cli(command(case, *extra))


@pytest.mark.parametrize("case", CASES)
def test_text_report_is_the_expected_one(case, monkeypatch):
    code, out, err = run(case, monkeypatch)
    assert code == 1
    text = SECONDS.sub("<t> s)", out + err)
    assert text == (CASES_DIR / case / "expected").read_text()


@pytest.mark.parametrize("case", [case for case in CASES
                                  if (CASES_DIR / case / "expected-full").exists()])
def test_full_text_report_is_the_expected_one(case, monkeypatch):
    _, out, err = run(case, monkeypatch, "--full-trace")
    text = SECONDS.sub("<t> s)", out + err)
    assert text == (CASES_DIR / case / "expected-full").read_text()


# the step numbers a line of the text names: a step (``step 7``, ``steps 26-27``), a stretch
# told in one line (``-- steps 9-20 ...``), and of a fold the steps it repeats
SHOWN_STEP = re.compile(r"^    steps? (\d+)(?:-(\d+))?  ")
TOLD_STEPS = re.compile(r"^    -- steps (\d+)-(\d+)(?::| repeat)")
FOLD_MODEL = re.compile(r"(?:repeat steps|as in steps) (\d+)-(\d+)")


@pytest.mark.parametrize("case", [case for case in CASES
                                  if not (CASES_DIR / case / "args").exists()])
def test_folded_text_names_every_step_the_error_depends_on(case):
    # each step of the dynamic slice is shown, or lies in a fold (repeats, rounds) whose
    # shown model steps run its line, or in a call told by what it left behind; a line of
    # steps left out holds none of them
    folder = CASES_DIR / case
    files = [str(folder / "prog.mod")] + sorted(str(p) for p in folder.glob("*.mod")
                                               if p.name != "prog.mod")
    report = check(load_program(files))
    for checked in report.results:
        if checked.result.verdict != "VIOLATED":
            continue
        trace = report.trace(checked.name)
        options = text_options(checked, report.describer)
        # (the text leaves out an input the step before chose with the same value)
        needed = needed_steps(chosen_inputs_only(trace), options.names,
                              options.handler_starts, options.compound_exits)
        places = {step.index: (step.transition.file, step.transition.line)
                  for step in [*trace.prefix, *trace.cycle] if step.transition is not None}
        shown, ran, folds = set(), set(), []
        for line in counterexample_lines(trace, options):
            if SHOWN_STEP.match(line):
                low, high = SHOWN_STEP.match(line).groups()
                shown.update(range(int(low), int(high or low) + 1))
            elif TOLD_STEPS.match(line):
                span = range(int(TOLD_STEPS.match(line)[1]), int(TOLD_STEPS.match(line)[2]) + 1)
                model = FOLD_MODEL.search(line)
                if model:
                    folds.append((span, {places.get(n) for n in
                                         range(int(model[1]), int(model[2]) + 1)}))
                elif " ran (no input chosen)" in line:
                    ran.update(span)
                else:
                    assert needed.isdisjoint(span), (line, sorted(needed))
        for index in needed - shown - ran:
            assert any(index in span and places.get(index) in lines for span, lines in folds), \
                (case, index, sorted(needed))


@pytest.mark.parametrize("case", CASES)
def test_text_report_is_short_and_speaks_rapid(case, monkeypatch):
    for extra in ((), ("--full-trace",)):
        _, out, err = run(case, monkeypatch, *extra)
        assert max(map(len, (out + err).splitlines())) <= LONGEST_LINE
        assert not PYTHON_SPELLINGS.search(out + err), PYTHON_SPELLINGS.search(out + err)


def replay_marks(case: str) -> list:
    """``xfail(strict=True)`` for a case whose ``replay-xfail`` names the bug, else none."""
    reason = CASES_DIR / case / "replay-xfail"
    return [pytest.mark.xfail(strict=True, reason=reason.read_text().strip())] \
        if reason.exists() else []


@pytest.mark.parametrize("case", [pytest.param(case, marks=replay_marks(case)) for case in CASES])
def test_json_has_full_values_and_replays(case, monkeypatch, tmp_path, capsys):
    code, out, _ = run(case, monkeypatch, "--format", "json")
    document = json.loads(out)
    violated = [p for p in document["properties"] if p["verdict"] == "VIOLATED"]
    assert violated
    for entry in violated:
        steps = entry["trace"]["prefix"] + entry["trace"]["cycle"]
        values = [v for step in steps for v in step["changes"].values() if v is not None]
        assert not any(v.endswith("...]") or v.endswith('..."') for v in values)
        assert not any(PYTHON_SPELLINGS.search(v) for v in values)
    saved = tmp_path / "trace.json"
    saved.write_text(out)
    for entry in violated:
        assert main(["replay", str(saved), "--property", entry["name"], "--quiet"]) == 0
    capsys.readouterr()


def test_full_trace_shows_every_initial_value_and_step(monkeypatch):
    _, short, _ = run("array_loop", monkeypatch)
    _, full, _ = run("array_loop", monkeypatch, "--full-trace")
    assert "repeat steps" in short and "repeat steps" not in full
    assert "(--full-trace shows every step and value)" in short and "spare = [0,0," in full
    assert "--full-trace" not in full
    assert full.count("    step ") == 27 and "...]" not in full


@pytest.mark.parametrize("case", CASES)
def test_both_engines_write_the_same_report(case, monkeypatch):
    _, native_out, native_err = run(case, monkeypatch)
    _, python_out, python_err = run(case, monkeypatch, "--engine", "python")
    assert SECONDS.sub("<t> s)", python_out + python_err) == \
        SECONDS.sub("<t> s)", native_out + native_err)


def test_files_given_by_absolute_path_are_shown_relative_to_the_current_folder(monkeypatch):
    # the steps, the headline and the warnings name tests/counterexamples/<case>/prog.mod
    # as counterexamples/many_unreached/prog.mod from tests/, never by its absolute path
    monkeypatch.chdir(CASES_DIR.parent)
    program = CASES_DIR / "many_unreached" / "prog.mod"
    _, out, err = run_cli(["check", program, "--quiet"])
    text = out + err
    assert str(CASES_DIR) not in text
    assert "counterexamples/many_unreached/prog.mod:" in out
    assert err.startswith("counterexamples/many_unreached/prog.mod:")


def test_a_program_given_by_absolute_path_outside_the_current_folder_reads_by_file_name(
        monkeypatch, tmp_path):
    # the program by its absolute path, the stubs module in the current folder (no common
    # folder but the root): every step and the headline say prog.mod:N, and each folder is
    # named once
    monkeypatch.chdir(tmp_path)
    case = CASES_DIR / "stub_reraise"
    (tmp_path / "Missing.mod").write_text((case / "Missing.mod").read_text())
    text = run_cli(["check", case / "prog.mod", "Missing.mod", "--quiet"]).out
    assert text.count(str(case)) == 1
    assert f"  (files in {case}: prog.mod; in {tmp_path}: Missing.mod)" in text
    assert "    at step 6, prog.mod:13:  RAISE;" in text
    assert "    step 4  Missing.mod:7  RETURN 0;" in text


def test_unreached_code_beside_a_counterexample_is_one_line_each_then_a_count(
        monkeypatch, tmp_path):
    # seven branches never taken and an error: beside the counterexample five RMC701 lines
    # without their source, then a count; --full-trace prints each with its source line
    branches = "".join(f"        IF mode = {n} THEN\n            total := {n};\n        ENDIF\n"
                       for n in range(2, 9))
    (tmp_path / "prog.mod").write_text(
        "MODULE Branches\n    VAR num mode := 1;\n    VAR num total := 0;\n"
        f"    PROC main()\n{branches}        total := 1 / total;\n    ENDPROC\nENDMODULE\n")
    monkeypatch.chdir(tmp_path)
    for extra, shown in (((), 5), (("--full-trace",), 7)):
        code, _, err = run_cli(["check", "prog.mod", "--quiet", *extra])
        assert code == 1
        lines = err.splitlines()
        assert sum(line.endswith("[RMC701]") for line in lines) == shown
        assert ("                total := 2;" in lines) == bool(extra)
        assert (lines[-1] == "rapidmc: and 2 more unreached-code warnings [RMC701] (--full-trace, "
                "--format json or --html shows each)") != bool(extra)
