"""An ERROR handler's tests of ERRNO take only the branches the raising statement's errors
can take, in the dead-data analysis (``model/reduction/raised_errors.py``, issue 28).

The pattern of mcubelab's Motion server: ``cartesianPose := [[...], NOrient([...]), ...]``
can only raise ERR_ARGVALERR (a zero quaternion); the handler TRYNEXTs for ERR_UDPUC_COMM,
a booked ERR_MOTIONSUP, ERR_SOCK_CLOSED and ERR_ROBLIMIT and RETRYs for every other
number.  So after that statement's error only RETRY is taken, and the old pose, which the
statement after it reads, is not live before it.

Generated programs mix such statements with quotients (ERR_DIVZERO), a RAISE of a booked
number, handlers testing ERRNO with IF, ``<>`` and TEST (some TRYNEXT for ERR_ARGVALERR
itself), a user routine called before the test, and TRAPs with and without a handler
that catches an error (which changes ERRNO while main's handler runs).  Verdicts agree
with ``--no-dead``, ``--no-reduce`` and the Python engine, the projection commutes with
the step, and counterexamples replay.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.model.reduction.merging import nodes_by_span
from rapidmc.model.reduction.raised_errors import ErrnoTests, StatementErrors
from rapidmc.model.reduction.relevance import Resolver
from rapidmc.model.reduction.totality import Totality

from test_dead_data import dead_globals_by_line, line_of
from test_total_readings import generated_program_tests

SEEDS = range(30)

DECLARATIONS = """  VAR signaldi in0;
  VAR signaldi in1;
  VAR num a := 0;
  VAR num b := 0;
  VAR bool failed := FALSE;
  VAR errnum ERR_MINE := -1;
  VAR num q := 1;
  VAR num divisor := 1;
  VAR num x := 0;
  VAR num picked := 0;
  VAR intnum irq;
  VAR orient o := [1, 0, 0, 0];
  VAR robtarget pose;"""

STATEMENTS = (
    "q := DInput(in0);",
    "o := NOrient([q, 0, 0, 0]);",
    "pose := [[0, 0, 500], NOrient([q, 0, 0, 0]), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];",
    "pose := [[q, 0, 500], NOrient([1, q, 0, 0]), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];",
    "IF o.q1 = 1 a := (a + 1) MOD 3;",
    "IF pose.rot.q1 = 1 b := 1;",
    "IF pose.trans.x = 1 failed := TRUE;",
    "x := 6 / divisor;",
    "divisor := DInput(in1);",
    "IF DInput(in1) = 1 RAISE ERR_MINE;",
    "b := 0;",
)

HANDLERS = (
    "IF ERRNO = ERR_DIVZERO THEN\n  divisor := 1;\n  TRYNEXT;\nELSE\n  q := 1;\n  RETRY;\nENDIF",
    "IF ERRNO = ERR_ARGVALERR THEN\n  q := 1;\n  TRYNEXT;\nENDIF\ndivisor := 1;\nRETRY;",
    "TEST ERRNO\nCASE ERR_MINE:\n  TRYNEXT;\nCASE ERR_DIVZERO:\n  divisor := 1;\n  TRYNEXT;\n"
    "DEFAULT:\n  q := 1;\n  RETRY;\nENDTEST",
    "IF ERRNO <> ERR_ARGVALERR THEN\n  divisor := 1;\n  TRYNEXT;\nENDIF\nq := 1;\nRETRY;",
    "TEST ERRNO\nCASE ERR_DIVZERO, ERR_ARGVALERR:\n  q := 1;\n  divisor := 1;\n  TRYNEXT;\n"
    "DEFAULT:\n  TRYNEXT;\nENDTEST",
    "TEST ERRNO\nCASE picked:\n  q := 1;\n  TRYNEXT;\nDEFAULT:\n  q := 1;\n  divisor := 1;\n"
    "  RETRY;\nENDTEST",
    "note;\nIF ERRNO = ERR_DIVZERO THEN\n  divisor := 1;\n  TRYNEXT;\nENDIF\nq := 1;\nRETRY;",
)

# a routine the handler may call before its test: it handles an error of its own
NOTE = """  PROC note()
    VAR num r := 0;
    r := 1 / DInput(in0);
  ERROR
    TRYNEXT;
  ENDPROC"""

TRAPS = (
    ("", ""),
    ("  TRAP on_in0\n    b := 0;\n  ERROR\n    RAISE;\n  ENDTRAP",
     "CONNECT irq WITH on_in0;\n    ISignalDI in0, 1, irq;"),
    # a trap whose handler catches ERR_DIVZERO: ERRNO changes while main's handler runs
    ("  TRAP on_in0\n    VAR num t := 0;\n    t := 1 / DInput(in1);\n  ERROR\n    TRYNEXT;\n"
     "  ENDTRAP", "CONNECT irq WITH on_in0;\n    ISignalDI in0, 1, irq;"),
)


def program(seed: int) -> str:
    rng = random.Random(seed)
    body = [rng.choice(STATEMENTS) for _ in range(rng.randint(3, 6))]
    body.insert(rng.randrange(len(body) + 1), rng.choice(STATEMENTS[1:4]))
    body.insert(rng.randrange(len(body) + 1), rng.choice(STATEMENTS[4:7]))
    if rng.random() < 0.5:
        body.insert(rng.randrange(len(body) + 1), "picked := DInput(in1) * 1001 + 1000;")
    loop = "\n".join("      " + line for line in body)
    handler = "\n".join("    " + line for line in rng.choice(HANDLERS).splitlines())
    trap, connect = rng.choice(TRAPS)
    return f"""MODULE Errno{seed}
{DECLARATIONS}
{NOTE}
{trap}
  PROC main()
    BookErrNo ERR_MINE;
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    {connect}
    WHILE TRUE DO
{loop}
    ENDWHILE
  ERROR
{handler}
  ENDPROC
ENDMODULE
"""


(test_generated_programs_project_as_the_program_steps,
 test_generated_programs_keep_their_verdicts_and_counterexamples_replay) = \
    generated_program_tests(program, SEEDS)


# --- the decisions, on the server's pattern ---------------------------------------------

SERVER = f"""MODULE Server
{DECLARATIONS}
{NOTE}
  PROC main()
    BookErrNo ERR_MINE;
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    WHILE TRUE DO
      q := DInput(in0);
      divisor := DInput(in1);
      x := 6 / divisor;
      pose := [[0, 0, 500], NOrient([q, 0, 0, 0]), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
      IF pose.rot.q1 = 1 b := 1;
    ENDWHILE
  ERROR
    IF ERRNO = ERR_UDPUC_COMM THEN
      TRYNEXT;
    ELSE
      TEST ERRNO
      CASE ERR_MINE:
        TRYNEXT;
      CASE ERR_DIVZERO, ERR_SOCK_CLOSED:
        divisor := 1;
        TRYNEXT;
      DEFAULT:
        q := 1;
        RETRY;
      ENDTEST
    ENDIF
  ENDPROC
ENDMODULE
"""
ATOMS = {"A", "B", "FAILED"}


def test_after_a_zero_quaternion_only_retry_is_taken_and_the_old_pose_is_dead(tmp_path):
    quotient = line_of(SERVER, "x := 6 / divisor")
    assert "pose" in dead_globals_by_line(SERVER, tmp_path, ATOMS)[quotient]


@pytest.mark.parametrize("change", [
    # the handler TRYNEXTs for the statement's own error
    ("CASE ERR_DIVZERO, ERR_SOCK_CLOSED:", "CASE ERR_DIVZERO, ERR_ARGVALERR:"),
    # a case value that may be any number: data the program writes
    ("CASE ERR_MINE:", "CASE picked:\n        TRYNEXT;\n      CASE ERR_MINE:"),
    # a booked number written by the program as well
    ("      q := DInput(in0);", "      q := DInput(in0);\n      ERR_MINE := DInput(in1) + 1040;"),
    # a routine that handles an error of its own runs before the test
    ("    IF ERRNO = ERR_UDPUC_COMM THEN", "    note;\n    IF ERRNO = ERR_UDPUC_COMM THEN"),
    # an interrupt whose trap catches an error may change ERRNO
    ("ENDMODULE", "  TRAP on_in0\n    x := 1 / DInput(in1);\n  ERROR\n    TRYNEXT;\n  ENDTRAP\n"
                  "ENDMODULE"),
    # an error of any number: a NOrient of a user function's result
    ("NOrient([q, 0, 0, 0])", "NOrient([half(q), 0, 0, 0])"),
])
def test_where_trynext_may_follow_the_old_pose_stays_live(tmp_path, change):
    text = SERVER.replace(*change)
    if "half(" in text:
        text = text.replace("  PROC main()", "  FUNC num half(num v)\n    RETURN v / 2;\n"
                                             "  ENDFUNC\n  PROC main()")
    assert text != SERVER
    text = text.replace("      q := DInput(in0);",
                        "      q := DInput(in0);\n      picked := DInput(in1) * 1001 + 1000;")
    quotient = line_of(text, "x := 6 / divisor")
    assert "pose" not in dead_globals_by_line(text, tmp_path, ATOMS)[quotient]


@pytest.mark.parametrize("statement, errors", [
    ("o := NOrient([q, 0, 0, 0]);", {"ERR_ARGVALERR"}),
    ("o := [q, 0, 0, 1];", set()),
    ("pose := [[0, 0, 500], NOrient([q, 0, 0, 0]), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];",
     {"ERR_ARGVALERR"}),
    ("o := NOrient([q / divisor, 0, 0, 0]);", None),
    ("x := 6 / divisor;", None),
    ("pose.rot := NOrient([q, 0, 0, 0]);", None),
])
def test_errors_of_a_statement(tmp_path, statement, errors):
    path = tmp_path / "prog.mod"
    path.write_text(f"MODULE M\n{DECLARATIONS}\n  PROC main()\n    {statement}\n  ENDPROC\n"
                    "ENDMODULE\n")
    program = api.load_program([str(path)], [])
    main = program.routines[program.entry]
    node = main.ast.body[0]
    found = StatementErrors(Totality(Resolver(main).symbol)).errors(node)
    assert found == (None if errors is None else frozenset(errors))


def test_the_tests_a_known_error_decides(tmp_path):
    path = tmp_path / "prog.mod"
    path.write_text(SERVER)
    program = api.load_program([str(path)], [])
    main = program.routines[program.entry]
    tests = ErrnoTests(program, main, nodes_by_span(main.ast))
    lines = {pc: main.code[pc].span.line for pc in range(main.handler_pc, len(main.code))}
    decided = {lines[pc]: sorted(lines[target] for target in taken)
               for pc in lines for taken in [tests.targets(pc, frozenset({"ERR_ARGVALERR"}))]
               if taken is not None}
    first = line_of(SERVER, "IF ERRNO = ERR_UDPUC_COMM")
    test = line_of(SERVER, "TEST ERRNO")
    assert decided == {first: [test], test: [line_of(SERVER, "        q := 1;")]}
    # ERR_DIVZERO takes its case; an error of unknown numbers decides nothing
    assert tests.targets(next(pc for pc in lines if lines[pc] == test),
                         frozenset({"ERR_DIVZERO"})) is not None
    assert all(tests.targets(pc, None) is None for pc in lines)


def test_the_booked_errnums_are_found_once_per_program(tmp_path, monkeypatch):
    """Every handler's tests share one walk of the program for the data only BookErrNo
    writes: a public controller backup with 168 routines with handlers spent 136 s in
    these walks, one per handler, before its search began."""
    from rapidmc.model.reduction import liveness
    routines = "\n".join(f"  PROC Step{n}()\n    x := 6 / divisor;\n  ERROR\n"
                         f"    IF ERRNO = ERR_MINE TRYNEXT;\n    RETRY;\n  ENDPROC"
                         for n in range(5))
    calls = "\n".join(f"    Step{n};" for n in range(5))
    path = tmp_path / "prog.mod"
    path.write_text(f"MODULE M\n{DECLARATIONS}\n  PROC main()\n    BookErrNo ERR_MINE;\n"
                    f"{calls}\n  ENDPROC\n{routines}\nENDMODULE\n")
    program = api.load_program([str(path)], [])
    walks = []
    found = liveness.booked_errnums
    monkeypatch.setattr(liveness, "booked_errnums",
                        lambda program: walks.append(program) or found(program))
    liveness.DeadData(program, set())
    assert len(walks) == 1 and found(program)      # ERR_MINE is booked
