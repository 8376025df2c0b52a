"""``check --flows`` (issue 22, part 2) keeps every other verdict: the taint marks it adds
to the state only record where input went, so each case of tests/check gives the same
verdicts with and without them, and ``no_unchecked_input`` besides."""
from __future__ import annotations

import pytest

from rapidmc import ast
from rapidmc.findings.lint.marks import instrument
from rapidmc.syntax import parse_text
from test_check_cases import report_of, verdict_cases

CASES = [case for case in verdict_cases() if "--flows" not in case.extra_args]


@pytest.mark.parametrize("case", CASES, ids=[case.name for case in CASES])
def test_flow_marks_keep_the_verdicts(case, monkeypatch):
    _, plain = report_of(case, monkeypatch)
    flowing = case.__class__(**{**case.__dict__, "extra_args": case.extra_args + ("--flows",)})
    _, marked = report_of(flowing, monkeypatch)
    before = {p["name"]: p["verdict"] for p in plain["properties"]}
    after = {p["name"]: p["verdict"] for p in marked["properties"]}
    assert after.pop("no_unchecked_input") in ("HOLDS", "VIOLATED", "UNKNOWN")
    assert after == before


def test_a_program_without_input_gets_no_marks():
    program = ast.Program(parse_text(
        "MODULE M\n  PROC main()\n    VAR num n := 1;\n    n := n + 1;\n  ENDPROC\nENDMODULE\n",
        "plain.mod"))
    marked = instrument(program)
    assert marked.sinks == ()
    assert marked.program.modules[0] == program.modules[0]
    assert [d.name.text for d in marked.program.modules[-1].data] == ["unchecked_input"]


def test_marks_and_flag_take_names_the_program_does_not_use():
    program = ast.Program(parse_text(
        "MODULE M\n  VAR num unchecked_input := 0;\n  VAR iodev f;\n  PROC main()\n"
        "    VAR num taint_h;\n    VAR num h;\n    h := ReadNum(f \\Time:=1);\n"
        "    SetAO ao_1, h;\n  ENDPROC\nENDMODULE\n", "names.mod"))
    marked = instrument(program)
    names = {d.name.key for d in marked.program.modules[-1].data}
    assert marked.flag == "unchecked_input_2" and "TAINT_H_2" in names
    assert [s.description for s in marked.sinks] == ["the output value of SetAO"]


FLOW_CASES = [case for case in verdict_cases() if "--flows" in case.extra_args]


@pytest.mark.parametrize("case", FLOW_CASES, ids=[case.name for case in FLOW_CASES])
def test_reductions_keep_the_flow_verdicts(case, monkeypatch):
    _, reduced = report_of(case, monkeypatch)
    plain = case.__class__(**{**case.__dict__, "extra_args": case.extra_args + ("--no-reduce",)})
    _, unreduced = report_of(plain, monkeypatch)
    assert {p["name"]: p["verdict"] for p in reduced["properties"]} == \
        {p["name"]: p["verdict"] for p in unreduced["properties"]} == case.verdicts


def test_a_flow_counterexample_replays(monkeypatch, tmp_path):
    """``replay`` rebuilds the marked program from the recorded command line."""
    import contextlib
    import io
    from rapidmc.cli import main
    case = next(case for case in FLOW_CASES if case.name == "flows_socket_move")
    monkeypatch.chdir(case.folder)
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        assert main(case.argv()) == 1
    trace = tmp_path / "trace.json"
    trace.write_text(out.getvalue())
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        assert main(["replay", str(trace), "--property", "no_unchecked_input", "--quiet"]) == 0
    assert "the counterexample replays" in err.getvalue()


@pytest.mark.parametrize("name, sinks", [("flows_socket_move", [14]),
                                         ("flows_socket_move_checked", [])])
def test_a_violated_flow_property_warns_at_the_sink_it_reaches(name, sinks, monkeypatch):
    """RMC820 names the move the counterexample takes unchecked input to; a range check
    before the move leaves no warning (findings.lint.marks.flow_sinks)."""
    case = next(case for case in verdict_cases() if case.name == name)
    _, document = report_of(case, monkeypatch)
    warned = [w["location"]["line"] for w in document["warnings"] if w["code"] == "RMC820"]
    assert warned == sinks
