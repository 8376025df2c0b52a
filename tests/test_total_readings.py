"""Readings of the robot, aggregates and constant indexes never raise (``Totality``), so data
they write is dead before them when an ERROR handler's TRYNEXT would read it (issue 28).

The pattern of the socket servers (joseballester TASK1, mcubelab Motion): ``pose :=
CRobT(...)`` or ``joints := [[params{1}, ...], [0, 9E9, ...]]`` followed by reads of the
new value, in a loop whose handler TRYNEXTs.  While such an assignment might raise, the
statement after it (TRYNEXT's target) would read the old value, so the old value was live
everywhere.  Such assignments cannot raise, and the old value is dead again.

Generated programs mix these assignments with ones that may raise (an index read from an
input, a reading of another task's robot, a quotient) and handlers ending in TRYNEXT or
RETRY; verdicts agree with ``--no-dead``, ``--no-reduce`` and the Python engine, the
projection commutes with the step, and counterexamples replay.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.model.reduction.totality import Totality
from rapidmc.syntax import parse_text

from test_dead_data import (commuting_failures, dead_globals_by_line, line_of,
                            verdicts_agree_and_replay)

SEEDS = range(24)

DECLARATIONS = """  VAR signaldi in0;
  VAR signaldi in1;
  VAR num a := 0;
  VAR num b := 0;
  VAR bool failed := FALSE;
  VAR num k := 1;
  VAR num divisor := 1;
  VAR num x := 0;
  VAR num vals{3} := [0, 1, 2];
  VAR robtarget pose;
  VAR jointtarget joints;
  PERS tooldata grip := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,1],[1,0,0,0],0,0,0]];"""

# statements of the loop: (writes that never raise, writes that may, reads of the old value)
STATEMENTS = (
    "pose := CRobT(\\Tool:=grip \\WObj:=wobj0);",
    "joints := CJointT();",
    "joints := [[vals{1}, vals{2}, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]];",
    "pose := [[vals{3}, 0, 500], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];",
    "joints := [[vals{k}, 0, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]];",
    "pose := CRobT(\\TaskName:=\"T_ROB2\");",
    "joints.robax.rax_1 := 6 / divisor;",
    "x := 6 / divisor;",
    "IF joints.robax.rax_1 = 1 a := (a + 1) MOD 3;",
    "IF pose.trans.x > 0 b := 1;",
    "IF pose.trans.z = 2 failed := TRUE;",
    "MoveAbsJ joints, v100, fine, tool0;",
    "MoveL pose, v100, fine, tool0;",
    "vals{1} := DInput(in0);",
    "vals{3} := DInput(in1) + 1;",
    "k := DInput(in0) + DInput(in1);",
    "divisor := DInput(in1);",
    "b := 0;",
)

HANDLERS = (
    "  ERROR\n    divisor := 1;\n    TRYNEXT;",
    "  ERROR\n    IF joints.robax.rax_1 = 1 failed := TRUE;\n    k := 1;\n    TRYNEXT;",
    "  ERROR\n    IF pose.trans.x = 2 b := 1;\n    divisor := 1;\n    k := 1;\n    RETRY;",
)


def program(seed: int) -> str:
    rng = random.Random(seed)
    body = [rng.choice(STATEMENTS) for _ in range(rng.randint(5, 9))]
    # every program writes one of the never-raising forms and reads it after
    body.insert(rng.randrange(len(body) + 1), rng.choice(STATEMENTS[:4]))
    body.insert(rng.randrange(len(body) + 1), rng.choice(STATEMENTS[8:11]))
    loop = "\n".join("      " + line for line in body)
    return f"""MODULE Readings{seed}
{DECLARATIONS}
  PROC main()
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    WHILE TRUE DO
{loop}
    ENDWHILE
{rng.choice(HANDLERS)}
  ENDPROC
ENDMODULE
"""


def properties(seed: int) -> list[str]:
    """Properties over the data the generated programs set from the data they write."""
    rng = random.Random(seed * 5 + 1)
    return [f'safe: G "a < {rng.randint(1, 2)}"', "never_failed: G !failed",
            'live: G F "b = 0"']


def written(tmp_path: Path, text: str, seed: int) -> list[str]:
    """``check`` arguments of the program ``text`` with the properties of ``seed``."""
    path, spec = tmp_path / "prog.mod", tmp_path / "props.ltl"
    path.write_text(text)
    spec.write_text("\n".join(properties(seed)) + "\n")
    return [str(path), "--ltl", str(spec), "--max-states", "20000"]


def assert_projects(argv: list[str]) -> None:
    compared, failures = commuting_failures(argv)
    assert compared > 0
    assert not failures, f"{len(failures)} of {compared} states, first: {failures[0]}"


def generated_program_tests(program_of, seeds) -> tuple:
    """The two tests of a family of generated programs (``program_of(seed)``): each
    projects as the program steps, and each keeps its verdicts with ``--no-dead`` with
    counterexamples that replay.  A test module binds them to ``test_`` names."""
    @pytest.mark.parametrize("seed", seeds)
    def projects_as_the_program_steps(tmp_path, seed):
        assert_projects(written(tmp_path, program_of(seed), seed))

    @pytest.mark.parametrize("seed", seeds)
    def keeps_its_verdicts_and_counterexamples_replay(tmp_path, seed):
        verdicts_agree_and_replay(tmp_path, written(tmp_path, program_of(seed), seed),
                                  "--no-dead")
    return projects_as_the_program_steps, keeps_its_verdicts_and_counterexamples_replay


(test_generated_programs_project_as_the_program_steps,
 test_generated_programs_keep_their_verdicts_and_counterexamples_replay) = \
    generated_program_tests(program, SEEDS)


# --- what is total, and what the dead data analysis then finds -------------------------

@pytest.mark.parametrize("expression, is_total", [
    ("CRobT(\\Tool:=grip \\WObj:=wobj0)", True),
    ("CRobT()", True),
    ("CJointT()", True),
    ("CPos(\\Tool:=grip)", True),
    ("CRobT(\\TaskName:=\"T_ROB2\")", False),
    ("CRobT(\\Tool:=tools{1})", False),
    ("vals{1}", True),
    ("vals{3}", True),
    ("vals{4}", False),
    ("vals{0}", False),
    ("vals{k}", False),
    ("vals{1.5}", False),
])
def test_total_expressions(tmp_path, expression, is_total):
    assert totality_of(tmp_path).total(expression_of(expression)) == is_total


@pytest.mark.parametrize("target, expression, is_assignable", [
    ("joints", "[[vals{1}, vals{2}, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]]", True),
    ("joints", "[[vals{1}, vals{2}, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]]", False),
    ("joints", "[[vals{k}, 0, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]]", False),
    ("joints", "[[1E39, 0, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]]", False),
    ("joints", "[[x / 2, 0, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]]", False),
    ("pose", "[[0, 0, 500], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]", True),
    ("pose", "[[0, 0, 500], NOrient([1, 0, 0, 0]), [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]]",
     False),
    ("vals", "[1, 2, 3]", True),
    ("vals", "[1, 2]", False),
    ("vals", "[TRUE, 2, 3]", False),
    ("x", "9E9", True),
    ("failed", "[TRUE]", False),
])
def test_assignable_aggregates(tmp_path, target, expression, is_assignable):
    totality = totality_of(tmp_path)
    symbol = totality.lookup(parse_name(target))
    assert totality.assignable(expression_of(expression), symbol.type) == is_assignable


ATOMS = {"A", "B", "FAILED"}
SERVER = f"""MODULE Server
{DECLARATIONS}
  PROC main()
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    WHILE TRUE DO
      divisor := DInput(in1);
      x := 6 / divisor;
      pose := CRobT(\\Tool:=grip \\WObj:=wobj0);
      IF pose.trans.x > 0 b := 1;
      joints := [[vals{{1}}, vals{{2}}, 0, 0, 0, 0], [0, 9E9, 9E9, 9E9, 9E9, 9E9]];
      MoveAbsJ joints, v100, fine, tool0;
    ENDWHILE
  ERROR
    divisor := 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
"""


def test_written_by_a_reading_or_a_total_aggregate_the_old_value_is_dead(tmp_path):
    dead = dead_globals_by_line(SERVER, tmp_path, ATOMS)
    quotient = line_of(SERVER, "x := 6 / divisor")
    assert {"pose", "joints"} <= dead[quotient]
    # a reading of another task's robot (as any call the analysis does not know) may raise:
    # TRYNEXT then goes on to read the old pose
    other = SERVER.replace("CRobT(\\Tool:=grip \\WObj:=wobj0)", 'CRobT(\\TaskName:="T_ROB2")')
    dead = dead_globals_by_line(other, tmp_path, ATOMS)
    assert "pose" not in dead[quotient] and "joints" in dead[quotient]
    indexed = SERVER.replace("[[vals{1}, vals{2}", "[[vals{k}, vals{2}")
    dead = dead_globals_by_line(indexed, tmp_path, ATOMS)
    assert "joints" not in dead[quotient] and "pose" in dead[quotient]


# --- helpers --------------------------------------------------------------------------

def linked(tmp_path: Path, text: str):
    path = tmp_path / "prog.mod"
    path.write_text(text)
    return api.load_program([str(path)], [])


def totality_of(tmp_path: Path) -> Totality:
    program = linked(tmp_path, f"MODULE M\n{DECLARATIONS}\n  VAR tooldata tools{{2}};\n"
                               "  PROC main()\n  ENDPROC\nENDMODULE\n")
    routine = program.routines[program.entry]
    return Totality(lambda name: routine.scope.lookup(name.key))


def expression_of(text: str):
    module = parse_text(f"MODULE E\n  PROC p()\n    x := {text};\n  ENDPROC\nENDMODULE\n",
                        "e.mod")[0]
    return module.routines[0].body[0].value


def parse_name(text: str):
    module = parse_text(f"MODULE E\n  PROC p()\n    {text} := 0;\n  ENDPROC\nENDMODULE\n",
                        "e.mod")[0]
    return module.routines[0].body[0].target.name
