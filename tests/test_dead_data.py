"""Dead data (model/reduction/liveness.py) forgets only what is never read again.

Three checks, on the hand-checked cases (tests/check/) and on generated programs whose
data dies around calls, FOR loops in called routines, ERROR handlers with RETRY and
TRYNEXT and user functions (tests/dead_data_programs.py):

* **The projection commutes with the step.**  For every state ``s`` the plain program
  reaches, the reduced model's successors of ``project(s)`` are the projections of the
  plain successors of ``s``, with the same labels (merged steps off: they are checked
  by the other tests).  Then the stored states are exactly the classes of the program's
  own states, every verdict is the plain search's, and every counterexample can be
  rebuilt on the plain program.  A value forgotten while something still reads it gives
  another successor; one forgotten in one state and kept in the next (main's globals
  while a called routine runs, once forgotten before the call: ``socket_split_fields``)
  gives a successor that is not a projection.
* **Verdicts** with every reduction, with ``--no-dead`` and with ``--no-reduce`` agree.
* **Every counterexample replays** (``rapidmc replay``) on the generated programs; those
  of the check cases replay in tests/test_replay_command.py.
"""
from __future__ import annotations

import contextlib
import io
import json
from collections import Counter
from pathlib import Path

import pytest

from rapidmc.cli import build_parser, main
from rapidmc.commands.check import prepare_model

from dead_data_programs import dead_data_program, dead_data_properties
from reached_states import breadth_first
from test_check_cases import verdict_cases
from test_reduction import DEAD_DATA_PATHS
from cli_capture import run_cli

REACHED_STATES = 3000      # plain states compared per program (breadth first)
SEEDS = range(30)


def commuting_failures(argv: list[str], limit: int = REACHED_STATES,
                       compared_label=lambda label: label) -> tuple[int, list]:
    """(plain states compared, the states whose reduced successors are not the projections
    of the plain ones) for the program of ``check`` arguments ``argv``; ``compared_label``:
    the part of each transition's label that must be the same."""
    args = build_parser().parse_args(["check", *argv, "--no-merge", "--no-por"])
    system = prepare_model(args).system
    project = system.project
    if project is None:
        return 0, []
    failures = []
    compared = 0
    for state, successors in breadth_first(system.unreduced(), limit):
        compared += 1
        projected = Counter((compared_label(label), project(after))
                            for label, after in successors)
        if projected != Counter((compared_label(label), after)
                                for label, after in system.successors(project(state))):
            failures.append(state)
    return compared, failures


def check_report(argv: list[str]) -> dict:
    return json.loads(run_cli(["check", *argv, "--format", "json", "--quiet"]).out)


def verdicts(report: dict) -> dict[str, str]:
    return {entry["name"]: entry["verdict"] for entry in report["properties"]}


def replays(path: Path, name: str) -> tuple[int, str]:
    err = io.StringIO()
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(err):
        code = main(["replay", str(path), "--property", name, "--quiet"])
    return code, err.getvalue()


def generated(tmp_path: Path, seed: int, moves_and_trap: bool = False) -> list[str]:
    program, spec = tmp_path / "prog.mod", tmp_path / "props.ltl"
    program.write_text(dead_data_program(seed, moves_and_trap))
    spec.write_text("\n".join(dead_data_properties(seed)) + "\n")
    return [str(program), "--ltl", str(spec), "--max-states", "20000"]


# --- the projection commutes with the step --------------------------------------------

CASES = {case.name: case for case in verdict_cases()}


@pytest.mark.parametrize("name", sorted(CASES))
def test_check_cases_project_as_the_program_steps(name, monkeypatch):
    case = CASES[name]
    monkeypatch.chdir(case.folder)
    argv = [word for word in case.argv()[1:] if word not in ("--format", "json", "--quiet")]
    compared, failures = commuting_failures(argv)
    assert not failures, f"{len(failures)} of {compared} states, first: {failures[0]}"


@pytest.mark.parametrize("moves_and_trap", [False, True])
@pytest.mark.parametrize("seed", SEEDS)
def test_generated_programs_project_as_the_program_steps(tmp_path, seed, moves_and_trap):
    compared, failures = commuting_failures(generated(tmp_path, seed, moves_and_trap))
    assert compared > 0
    assert not failures, f"{len(failures)} of {compared} states, first: {failures[0]}"


# --- verdicts and counterexamples -------------------------------------------------------

@pytest.mark.parametrize("moves_and_trap", [False, True])
@pytest.mark.parametrize("seed", SEEDS)
def test_generated_programs_keep_their_verdicts_and_counterexamples_replay(tmp_path, seed,
                                                                           moves_and_trap):
    verdicts_agree_and_replay(tmp_path, generated(tmp_path, seed, moves_and_trap), "--no-dead")


def verdicts_agree_and_replay(tmp_path: Path, argv: list[str], unreduced: str) -> None:
    """The verdicts of ``argv`` are found, and are the same with the switch ``unreduced``,
    with ``--no-reduce`` and on the Python engine; every counterexample replays."""
    report = check_report(argv)
    reduced = verdicts(report)
    assert "UNKNOWN" not in reduced.values(), reduced
    assert verdicts(check_report(argv + [unreduced])) == reduced
    assert verdicts(check_report(argv + ["--no-reduce"])) == reduced
    assert verdicts(check_report(argv + ["--engine", "python"])) == reduced
    path = tmp_path / "report.json"
    path.write_text(json.dumps(report))
    for name, verdict in reduced.items():
        if verdict == "VIOLATED":
            code, err = replays(path, name)
            assert code == 0, err


@pytest.mark.parametrize("name", sorted(CASES))
def test_check_cases_keep_their_verdicts_without_dead_data(name, monkeypatch):
    case = CASES[name]
    monkeypatch.chdir(case.folder)
    argv = [word for word in case.argv()[1:] if word not in ("--format", "json", "--quiet")]
    if prepare_model(build_parser().parse_args(["check", *argv])).plan.projection is None:
        pytest.skip("nothing is sliced or dead: both searches are the same")
    reduced = verdicts(check_report(argv))
    assert reduced == case.verdicts
    assert verdicts(check_report(argv + ["--no-dead"])) == reduced


# --- what the analysis finds dead -------------------------------------------------------

CHECK_DIR = Path(__file__).resolve().parent / "check"


def dead_globals_by_line(text: str, tmp_path: Path, atoms: set[str]) -> dict[int, set[str]]:
    """Line -> the globals dead before each instruction of main on that line (together)."""
    from rapidmc import api
    from rapidmc.model.reduction.liveness import DeadData
    path = tmp_path / "prog.mod"
    path.write_text(text)
    program = api.load_program([str(path)], [])
    dead = DeadData(program, atoms)
    names = {data.slot: data.name for data in program.globals}
    by_line: dict[int, set[str]] = {}
    for instruction, slots in zip(program.routines[program.entry].code, dead.globals):
        if instruction.span is not None:
            by_line.setdefault(instruction.span.line, set()).update(names[s] for s in slots)
    return by_line


SERVER = (CHECK_DIR / "dead_data_request_string" / "prog.mod").read_text()
RECEIVE_LINE = next(number for number, line in enumerate(SERVER.splitlines(), start=1)
                    if "SocketReceive" in line and "\\Str" in line)


def test_a_request_is_dead_until_the_next_receive_writes_it_whole(tmp_path):
    # the handler RETRYs the receive: the old request is never read again
    dead = dead_globals_by_line(SERVER, tmp_path, {"SERVED"})
    assert "request" in dead[RECEIVE_LINE]
    assert "reply" in dead[RECEIVE_LINE]


def test_a_request_read_again_after_trynext_stays_live(tmp_path):
    # TRYNEXT after a failed receive goes on to parse the request received before
    text = SERVER.replace("            OpenLink;\n        ENDIF\n        RETRY;",
                          "            OpenLink;\n            TRYNEXT;\n        ENDIF\n        RETRY;")
    assert text != SERVER
    dead = dead_globals_by_line(text, tmp_path, {"SERVED"})
    assert "request" not in dead[RECEIVE_LINE]
    assert "reply" in dead[RECEIVE_LINE]


# test_reduction's program whose property fails when a call forgets what a routine it calls
# reads, with a global h no routine names, written again after the call
CALLED = DEAD_DATA_PATHS["call"].replace("  VAR num g := 0;\n", "  VAR num g := 0;\n  VAR num h := 0;\n") \
    .replace("    outer;\n", "    h := 1;\n    outer;\n    h := 0;\n")
CALL_LINE = CALLED.splitlines().index("    outer;") + 1


def test_a_call_keeps_what_its_routines_read_and_forgets_the_rest(tmp_path):
    dead = dead_globals_by_line(CALLED, tmp_path, {"FAILED"})
    assert dead[CALL_LINE] == {"h"}           # outer; reads g through look, never h
    late = dead_globals_by_line(CALLED.replace("    outer;", '    %"outer"%;'), tmp_path,
                                {"FAILED"})
    assert late[CALL_LINE] == set()           # a routine called by a computed name may read any


# a server loop of the pattern of a socket server with a TRAP (a reply built only to be
# sent, a move between): the reply dies after it is sent, the trap's data never does
TRAPPED = """MODULE Trapped
  VAR signaldi go;
  VAR intnum irq;
  VAR num code := 0;
  VAR num seen := 0;
  VAR num top := 0;
  VAR string reply := "";
  VAR robtarget spots{2};
  PROC main()
    AliasIO "GO", go;
    CONNECT irq WITH on_go;
    ISignalDI go, 1, irq;
    top := 1;
    WHILE TRUE DO
      code := clamp(DInput(go));
      WaitTime 0.1;
      MoveL spots{code + 1}, v100, fine, tool0;
      reply := NumToStr(code, 0) + " " + NumToStr(seen, 0);
      TPWrite reply;
    ENDWHILE
  ENDPROC
  FUNC num clamp(num v)
    IF v > top RETURN top;
    RETURN v;
  ENDFUNC
  TRAP on_go
    seen := seen + 1;
    IF seen > 2 seen := 0;
  ENDTRAP
ENDMODULE
"""


def line_of(text: str, part: str) -> int:
    return next(number for number, line in enumerate(text.splitlines(), start=1)
                if part in line)


def test_with_a_trap_globals_it_does_not_name_die_and_a_move_reads_only_its_target(tmp_path):
    dead = dead_globals_by_line(TRAPPED, tmp_path, set())
    move = line_of(TRAPPED, "MoveL")
    assert "reply" in dead[move] and "code" not in dead[move]
    # a user function reads what it names (top), a WaitTime nothing
    assert "reply" in dead[line_of(TRAPPED, "clamp(DInput")]
    assert "top" not in dead[line_of(TRAPPED, "clamp(DInput")]
    assert "reply" in dead[line_of(TRAPPED, "WaitTime")]
    assert "code" not in dead[line_of(TRAPPED, "WaitTime")]
    assert all("seen" not in names for names in dead.values())
    # the trap's data is live everywhere, and so is what a trap reads through a routine
    called = TRAPPED.replace("    seen := seen + 1;", "    seen := seen + 1;\n    note;") \
        .replace("  FUNC num clamp", "  PROC note()\n    TPWrite reply;\n  ENDPROC\n  FUNC num clamp")
    assert all("reply" not in names for names in dead_globals_by_line(called, tmp_path,
                                                                        set()).values())
    synced = TRAPPED.replace("MoveL spots{code + 1}, v100, fine, tool0;",
                             'MoveLSync spots{code + 1}, v100, fine, tool0, "Hook";') \
        .replace("  TRAP on_go", "  PROC Hook()\n    TPWrite reply;\n  ENDPROC\n  TRAP on_go")
    assert "reply" not in dead_globals_by_line(synced, tmp_path, set())[move]
