"""Reads of data written from outside that only a comparison with a constant uses choose one
value per outcome of the comparison (``semantics.expressions.decisive_read``, issue 28).

The taeyangshim gantry tasks, each checked alone, read commands and macro numbers that
another task writes (``load.outside_data``): ``IF (nMacro010{1}=3 AND nMacro010{2}=3) OR
(nMacro010{1}=4 AND nMacro010{2}=4)`` chose each of its four reads among the eight values of
the data's domain, 32,768 transitions to two successors.  Now ``nMacro010{1}=3`` chooses 3 or
one other value.  The generated programs mix such comparisons (equality and ordering, the
constant on either side, a CONST, inside AND/OR/NOT) with reads whose value goes on: a TEST,
an assignment, an index, a division, a wait, a FUNC a wait calls.  Checked with the
narrowing and without it (``decisive_read`` replaced by one that keeps every operand), on both
engines, the verdicts and the states of every search must be equal, and the narrowed search
must take fewer transitions.
"""
from __future__ import annotations

import json
import random

import pytest

from rapidmc.check import native
from rapidmc.semantics import expressions

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

COMPARED = [
    "nMacro{1} = 3", "3 = nMacro{2}", "nMacro{1} <> 4", "nMacro{2} > 4", "nMacro{1} <= 3",
    "nMacro{2} = LIMIT", "stCmd = \"go\"", "\"stop\" <> stCmd", "mode.speed >= 50",
    "mode.on = TRUE", "NOT (nMacro{1} = 4)",
    "(nMacro{1} = 3 AND nMacro{2} = 3) OR (nMacro{1} = 4 AND nMacro{2} = 4)",
]
GOING_ON = [
    "count := nMacro{1};",
    "count := arr{nMacro{2}};",
    "count := 10 / nMacro{1};",
    "TEST nMacro{1} CASE 3: count := count + 1; CASE 4: count := 8; ENDTEST",
    "WaitUntil stCmd = \"go\" \\MaxTime:=1;",
    "IF Ready() count := 0;",
    "text := stCmd;",
]


def program(seed: int) -> str:
    rnd = random.Random(seed)
    body = []
    for _ in range(rnd.randint(3, 6)):
        if rnd.random() < 0.6:
            body.append(f"IF {rnd.choice(COMPARED)} THEN count := {rnd.randint(0, 3)}; "
                        f"ELSE count := count + 1; ENDIF")
        else:
            body.append(rnd.choice(GOING_ON))
    body.append("IF count > 3 count := 0;")
    loop = "\n      ".join(body)
    return f"""MODULE Gantry
  RECORD speedmode
    num speed;
    bool on;
  ENDRECORD
  CONST num LIMIT := 4;
  PERS num nMacro{{2}} := [4, 4];
  PERS string stCmd := "";
  PERS speedmode mode := [100, FALSE];
  VAR num count := 0;
  VAR num arr{{3}} := [1, 2, 3];
  VAR string text := "";
  FUNC bool Ready()
    RETURN nMacro{{1}} = 3 OR stCmd = "stop";
  ENDFUNC
  PROC main()
    WHILE TRUE DO
      {loop}
      IF mode.speed = 0 OR nMacro{{2}} < 0 WaitUntil Ready();
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def searches(path, engine: str) -> dict:
    document = json.loads(run_cli(["check", path, "--engine", engine, "--format", "json",
                                   "--quiet"]).out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"], p["stats"]["transitions"])
            for p in document["properties"]}


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("seed", range(10))
def test_narrowed_reads_keep_verdicts_and_states(tmp_path, monkeypatch, seed, engine):
    path = tmp_path / "gantry.mod"
    path.write_text(program(seed))
    narrowed = searches(path, engine)
    with monkeypatch.context() as patch:
        patch.setattr(expressions, "decisive_read", lambda compare, left, right: (left, right))
        every = searches(path, engine)
    assert {name: (verdict, states) for name, (verdict, states, _) in narrowed.items()} == \
        {name: (verdict, states) for name, (verdict, states, _) in every.items()}
    assert all(narrowed[name][2] <= every[name][2] for name in every)


def test_the_gantry_condition_takes_few_transitions(tmp_path, monkeypatch):
    """The condition of the gantry's weld command, four reads of two macro numbers: without
    the narrowing each read takes the data's eight values (8**4 transitions), with it two."""
    path = tmp_path / "gantry.mod"
    path.write_text(program(0).replace(
        program(0).split("WHILE TRUE DO")[1].split("ENDWHILE")[0],
        "\n      IF (nMacro{1} = 3 AND nMacro{2} = 3) OR (nMacro{1} = 4 AND nMacro{2} = 4) "
        "THEN count := 1; ELSE count := 0; ENDIF\n"
        "      TEST nMacro{1} CASE 3, 4: count := 2; ENDTEST\n"
        "      IF nMacro{2} < 0 OR mode.speed = 0 OR stCmd = \"stop\" count := 3;\n    "))
    narrowed = searches(path, native.PYTHON)
    with monkeypatch.context() as patch:
        patch.setattr(expressions, "decisive_read", lambda compare, left, right: (left, right))
        every = searches(path, native.PYTHON)
    assert narrowed["no_runtime_error"][:2] == every["no_runtime_error"][:2]
    assert every["no_runtime_error"][2] >= 16 * narrowed["no_runtime_error"][2]
