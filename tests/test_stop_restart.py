"""Stop and Break pause the program; the operator may restart it at the next instruction
(docs/semantics.md, "Stop and Break"): the counterexample shows the restart, ``run`` reads
the operator's restart from stdin, and several tasks keep the behaviours of both readings."""
from __future__ import annotations

import io

import pytest

from rapidmc.cli import main

PROGRAM = """MODULE S
  VAR num x := 0;
  PROC main()
    TPWrite "before";
    Break;
    TPWrite "after";
    x := 1 / x;
  ENDPROC
ENDMODULE
"""

TASKS_MAIN = """MODULE M
  PERS num shared := 0;
  PROC main()
    Stop;
    shared := 7;
  ENDPROC
ENDMODULE
"""


def _cli(tmp_path, capsys, monkeypatch, args, stdin="", text=PROGRAM):
    program = tmp_path / "s.mod"
    program.write_text(text)
    monkeypatch.setattr("sys.stdin", io.StringIO(stdin))
    code = main([args[0], str(program)] + args[1:])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_the_counterexample_shows_the_stop_and_the_operators_restart(tmp_path, capsys,
                                                                      monkeypatch):
    code, out, _ = _cli(tmp_path, capsys, monkeypatch, ["check"])
    assert code == 1
    assert "s.mod:5  Break;" in out
    assert "program = stopped by Stop/Break (the operator may restart it)" in out
    assert "(the program continues after the Stop)" in out
    assert "input: operator = restarts the program (Start)" in out
    assert "program = running  (was stopped by Stop/Break (the operator may restart it))" in out
    assert "no longer exists" not in out
    assert "no_runtime_error: VIOLATED" in out and "no_deadlock: HOLDS" in out


def test_replay_shows_the_restart_as_the_program_running_again(tmp_path, capsys, monkeypatch):
    code, report, _ = _cli(tmp_path, capsys, monkeypatch, ["check", "--format", "json"])
    assert code == 1
    saved = tmp_path / "trace.json"
    saved.write_text(report)
    assert main(["replay", str(saved)]) == 0
    err = capsys.readouterr().err
    assert "(the program continues after the Stop)" in err
    assert "program = running" in err and "None" not in err


def test_run_pauses_at_break_and_a_line_of_stdin_restarts_it(tmp_path, capsys, monkeypatch):
    code, out, err = _cli(tmp_path, capsys, monkeypatch, ["run"], stdin="\n")
    assert code == 1 and out == "before\nafter\n"
    assert "stopped (Stop/Break) before" in err and "s.mod:6" in err
    assert "ERR_DIVZERO" in err


def test_run_at_the_end_of_stdin_leaves_the_program_stopped(tmp_path, capsys, monkeypatch):
    code, out, err = _cli(tmp_path, capsys, monkeypatch, ["run"], stdin="")
    assert code == 0 and out == "before\n"
    assert "ERR_DIVZERO" not in err


def test_run_no_restart_ends_at_the_stop_without_reading_stdin(tmp_path, capsys, monkeypatch):
    code, out, err = _cli(tmp_path, capsys, monkeypatch, ["run", "--no-restart"], stdin="\n")
    assert code == 0 and out == "before\n" and err == ""


def test_run_stays_stopped_from_the_interpreter_api():
    from rapidmc.commands.console import run_program
    from rapidmc.semantics.link import build
    from rapidmc.semantics.state import STOPPED
    from rapidmc.syntax import load_program
    import tempfile, pathlib
    with tempfile.TemporaryDirectory() as folder:
        path = pathlib.Path(folder) / "s.mod"
        path.write_text(PROGRAM)
        program = build(load_program([str(path)]))
        result = run_program(program, {}, io.StringIO("\n"), io.StringIO())
    assert result.state.status == STOPPED


# --- reductions and fast paths keep the verdicts of programs with Stop ------------------

def program_with_stop(seed: int) -> str:
    """A generated program whose loop may stop (on a free input) before its first
    statement and, every other seed, after its last."""
    from reduction_programs import random_program
    text = random_program(seed)
    text = text.replace("    WHILE TRUE DO\n", "    WHILE TRUE DO\n      IF in0 = 1 Stop;\n", 1)
    if seed % 2:
        text = text.replace("    ENDWHILE\n", "      IF in1 = 1 AND a = 0 Break;\n    ENDWHILE\n", 1)
    return text


@pytest.mark.parametrize("seed", range(12))
def test_programs_with_stop_keep_their_verdicts_when_reduced(tmp_path, seed):
    from reduction_programs import properties
    from test_reduction import assert_same_verdicts, check_json
    program = tmp_path / "prog.mod"
    program.write_text(program_with_stop(seed))
    spec = tmp_path / "props.ltl"
    props = properties(seed, with_next=seed % 2 == 1) + ['stopped: G ("Stopped()" -> F "a = 0")']
    spec.write_text("\n".join(props) + "\n")
    argv = [str(program), "--ltl", str(spec), "--max-states", "20000"]
    reduced = check_json(argv)
    assert_same_verdicts(reduced, check_json(argv + ["--no-reduce"]))
    assert reduced["no_runtime_error"] != "UNKNOWN"


@pytest.mark.parametrize("reductions", ["reduced", "plain"])
@pytest.mark.parametrize("seed", range(6))
def test_programs_with_stop_check_alike_on_the_fast_paths(tmp_path, seed, reductions):
    from rapidmc.model.reduction import ALL, NONE
    from reduction_programs import properties
    from test_fast_search import assert_same_checks
    from test_plain_step import formulas, load
    program = load(tmp_path, program_with_stop(seed))
    assert_same_checks(program, formulas(*properties(seed, with_next=seed % 2 == 1),
                                         'stopped: F "Stopped()"'),
                       ALL if reductions == "reduced" else NONE)
