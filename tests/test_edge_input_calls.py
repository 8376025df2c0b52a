"""Edge inputs beside late-bound calls and signal names given to a routine that ignores them.

PickMaster's backup (issue 27): the project task calls ``%"PmMain:Main"%`` and the
supervision task logs ``PmErrorLog 2384, ..., "pmProject_diSetDefaultHeight", ...`` to a
stub.  Neither reaches an input: a late-bound call binds only the loaded procedures, whose
code the walk sees, and a parameter the routine never names passes nothing on.  So the
inputs that only interrupts watch stay edge inputs (``edge_inputs``, ``idle_arguments``).

Differential: programs of the pattern (tests/test_edge_inputs.py's generator, with a
late-bound call in main's cycle and each trap giving its input's name to a logging routine)
are checked with edge inputs and with ``--exact-edges`` on both engines: same verdicts,
HOLDS and VIOLATED among them, and no more states.  A logging routine that names its
parameter (``TPWrite name``) keeps the input stored.
"""
from __future__ import annotations

import pytest

from rapidmc.check import native

from test_edge_inputs import ORDERS, _edges, check, edge_program, same_verdicts

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

ROUTINES = {
    "idle": "  PROC Log(string name)\n  ENDPROC\n",
    "named": "  PROC Log(string name)\n    TPWrite name;\n  ENDPROC\n",
}
CYCLE = "  PROC Cycle()\n    WaitTime 0.1;\n  ENDPROC\n"


def calls_program(seed: int, log: str = "idle") -> str:
    """``edge_program(seed)`` with ``%"Cycle"%`` in main's cycle and ``Log "diK"`` at the
    start of each trap ``trapK``."""
    text = edge_program(seed).replace("    WHILE TRUE DO\n",
                                      '    WHILE TRUE DO\n      %"Cycle"%;\n', 1)
    lines = []
    for line in text.splitlines(keepends=True):
        lines.append(line)
        if line.startswith("  TRAP trap"):
            lines.append(f'    Log "di{line.strip()[len("TRAP trap"):]}";\n')
    text = "".join(lines)
    return text.replace("ENDMODULE\n", CYCLE + ROUTINES[log] + "ENDMODULE\n")


@pytest.mark.parametrize("main, routines, expected", [
    ('%"Cycle"%;', CYCLE, {"diA": False, "diB": False}),
    ('%"Cycle"%;', "  PROC Cycle()\n    WaitDI diA, 1;\n  ENDPROC\n", {"diB": False}),
    ('%"Look"% diA;', "  PROC Look(VAR signaldi s)\n  ENDPROC\n", {"diB": False}),
    ('Log "diA";', ROUTINES["idle"], {"diA": False, "diB": False}),
    ('Log "diA";', ROUTINES["named"], {"diB": False}),
    ('Log "diA";', "  PROC Log(string name)\n    Pass name;\n  ENDPROC\n"
                   "  PROC Pass(string other)\n  ENDPROC\n", {"diB": False}),
    ('Log "diA", 3;', "  PROC Log(string name, num code)\n    n := code;\n  ENDPROC\n",
     {"diA": False, "diB": False}),
    ('Log \\name:="diA";', "  PROC Log(\\string name)\n    IF Present(name) n := 3;\n"
                           "  ENDPROC\n", {"diB": False}),
    ('Log \\name:="diA";', "  PROC Log(\\string name)\n    More \\other?name;\n  ENDPROC\n"
                           "  PROC More(\\string other)\n  ENDPROC\n", {"diB": False}),
    ('n := StrLen(Name("diA"));', "  FUNC string Name(string s)\n    RETURN \"x\";\n"
                               "  ENDFUNC\n", {"diA": False, "diB": False}),
    ('Log "diA";', "  PROC Log(string name)\n    VAR string v;\n    GetDataVal \"name\", v;\n"
                   "  ENDPROC\n", {"diB": False}),    # a parameter reached by a name
    ('TPWrite "diA";', "", {"diB": False}),
])
def test_which_inputs_stay_edge_inputs(main, routines, expected):
    text = ORDERS.replace("{A}", "1").replace("{MORE}", main).replace(
        "ENDMODULE\n", routines + "ENDMODULE\n")
    assert _edges(text) == expected


PROGRAMS = [calls_program(seed) for seed in range(12)]


@pytest.mark.parametrize("engine", ENGINES)
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, engine):
    """Every fourth program with a second task on di1; where the exact search holds and
    some input is an edge input, the edge model stores fewer states."""
    for number, text in enumerate(PROGRAMS):
        by_edges, exact = same_verdicts(tmp_path, text, engine, number % 4 == 3)
        verdict, states = exact["no_runtime_error"]
        if verdict == "HOLDS" and _edges(text):
            assert by_edges["no_runtime_error"][1] < states, text


def test_the_pattern_programs_have_edge_inputs_and_both_verdicts(tmp_path):
    """Most programs keep edge inputs beside the late-bound call and the log; the checks
    reach HOLDS and VIOLATED; with a log that names its parameter each input a trap logs is
    stored."""
    assert sum(1 for text in PROGRAMS if _edges(text)) >= 8
    verdicts = {verdict for text in PROGRAMS[:6]
                for verdict, _ in check(tmp_path, text, "--exact-edges").values()}
    assert {"HOLDS", "VIOLATED"} <= verdicts
    for seed in range(12):
        assert _edges(calls_program(seed, "named")) == {}
