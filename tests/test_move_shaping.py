"""Data that only shapes where moves go, left out of states while the robot is not tracked.

Differential: small programs of the public backups' pattern (a layer height or a stack
height that grows a step a cycle and reaches only ``Offs`` targets of moves, directly or
through an ``IN`` parameter), mixed at random with statements that make such data matter
(a condition, an index, a divisor, a product, a ``TPWrite``, an ``INOUT`` argument), are
checked with every reduction and with ``--no-slice`` on both engines: wherever both
searches end, the verdicts are the same.  Each program resets its data at the top of its
cycle, so that the search without slicing ends too.  The other tests pin what the analysis
decides (``find_slicing``), the ``assumes:`` line and that ``--track-robot`` keeps the data.
"""
from __future__ import annotations

import json
import random

import pytest

from rapidmc import ast
from rapidmc.check import native
from rapidmc.findings.assumptions import UNTRACKED_ROBOT
from rapidmc.model.reduction.relevance import find_slicing
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)
UNKNOWN = "UNKNOWN"

HEAD = """MODULE Prog
  VAR signaldi diPart;
  VAR num h := 0;
  VAR num z := 1;
  VAR num k := 1;
  VAR num n := 0;
  VAR num tab{3} := [1, 2, 3];
  CONST num size := 330;
  CONST robtarget pPlace := [[400, 0, 20], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST robtarget ptab{3} := [pPlace, pPlace, pPlace];
  PROC main()
    AliasIO "DI_PART", diPart;
    WHILE TRUE DO
      h := 0;
      z := 1;
      k := 1;
"""
TAIL = """      IF diPart = 1 n := n + 1;
      IF n > 2 n := 0;
    ENDWHILE
  ENDPROC
  PROC Place(robtarget p)
    MoveL Offs(p, 0, 0, 50), v500, z10, tool0;
    MoveL p, v200, fine, tool0;
  ENDPROC
  PROC Shift(INOUT num x)
    x := x + 1;
  ENDPROC
ENDMODULE
"""
# statements that only shape moves ...
SHAPING = [
    "h := h + 20;",
    "h := h - z;",
    "z := z + 5;",
    "MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;",
    "MoveJ Offs(pPlace, h, z, 0), v100, z10, tool0;",
    "Place Offs(pPlace, 0, 0, h);",
    "Place pPlace;",
    "FOR i FROM 1 TO 2 DO h := h + 10; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0; ENDFOR",
    "k := k + 1;",
    "h := k * size;",
    "MoveL Offs(pPlace, 0, 0, 2 * h), v100, fine, tool0;",
    "z := h * 3;",
]
# ... and statements after which the data matter, or that fail with them (each fails or
# waits for some value the shaping statements reach)
DECISIVE = [
    "IF h > 30 tab{4} := 0;",
    "MoveL Offs(pPlace, 0, 0, 100 / (h - 20)), v100, fine, tool0;",
    "MoveL ptab{h / 10 + 1}, v100, fine, tool0;",
    "MoveL Offs(pPlace, 0, 0, h * 1E37), v100, fine, tool0;",
    "IF h > 30 n := n + 1;",
    'TPWrite "height", \\Num:=h;',
    "Shift h;",
    "WaitUntil h < 30;",
]


def shaping_program(seed: int) -> str:
    """A program of the pattern: mostly shaping statements, now and then a decisive one."""
    rnd = random.Random(seed)
    body = [rnd.choice(SHAPING if rnd.random() < 0.7 else DECISIVE)
            for _ in range(rnd.randint(3, 7))]
    return HEAD + "".join(f"      {line}\n" for line in body) + TAIL


def check(tmp_path, text: str, *flags: str) -> dict:
    """Property -> (verdict, model states, assumes) of one in-process check."""
    (tmp_path / "prog.mod").write_text(text)
    found = run_cli(["check", "prog.mod", "--format", "json", "--quiet", "--max-states", "4000",
                     *flags], cwd=tmp_path)
    document = json.loads(found.out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"], p["assumes"])
            for p in document["properties"]}


def linked(text: str):
    return build(ast.Program(parse_text(text, "prog.mod")))


def sliced_names(text: str, moves_unobserved: bool = True) -> set[str]:
    slicing = find_slicing(linked(text), (), moves_unobserved)
    return {name for name, _ in slicing.move_shaping}


def decisive_program(statement: str) -> str:
    """The height grows to 20 and 40 by shaping statements, ``statement`` after each."""
    body = ["h := h + 20;", "MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", statement] * 2
    return HEAD + "".join(f"      {line}\n" for line in body) + TAIL


PROGRAMS = [shaping_program(seed) for seed in range(24)] + \
    [decisive_program(statement) for statement in DECISIVE]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    text = PROGRAMS[number]
    reduced = check(tmp_path, text, "--engine", engine)
    plain = check(tmp_path, text, "--engine", engine, "--no-slice")
    assert reduced.keys() == plain.keys()
    for name, (verdict, states, _) in plain.items():
        assert verdict != UNKNOWN, (name, text)      # each cycle starts from the same data
        if reduced[name][0] != UNKNOWN:
            assert reduced[name][0] == verdict, (name, text)
        assert reduced[name][1] <= states, (name, text)


def test_the_pattern_programs_slice_and_keep_both():
    """The generated programs exercise both outcomes of the analysis."""
    found = [sliced_names(shaping_program(seed)) for seed in range(24)]
    assert any("h" in names for names in found)
    assert any("h" not in names for names in found)


@pytest.mark.parametrize("statement, shaped", [
    ("h := h + 20; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", {"h"}),
    ("h := h - z; Place Offs(pPlace, z, 0, h);", {"h", "z"}),
    ("h := h + 20; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0; IF h > 30 n := 0;", set()),
    ("h := h + 20; MoveL Offs(pPlace, 0, 0, 100 / h), v100, fine, tool0;", set()),
    ("k := k + 1; MoveL ptab{k}, v100, fine, tool0;", set()),
    ("h := h + 20; Shift h; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", set()),
    ('h := h + 20; TPWrite "h", \\Num:=h;', set()),
    ("h := h * 2; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", set()),
    # a layer count times a constant (Zollman94's nActLayer*nBoxSizeZ)
    ("k := k + 1; h := k * size; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", {"h", "k"}),
    ("h := h + 20; MoveL Offs(pPlace, 0, 0, 3 * h), v100, fine, tool0;", {"h"}),
    # ... but not a product fed back into its factor, nor one of two data
    ("h := h * size; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", set()),
    ("z := h * 3; h := z + 1; MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;", set()),
    ("h := h + 20; MoveL Offs(pPlace, 0, 0, h * k), v100, fine, tool0;", set()),
])
def test_which_data_only_shape_moves(statement, shaped):
    text = HEAD + f"      {statement}\n" + TAIL
    assert sliced_names(text) == shaped
    assert sliced_names(text, moves_unobserved=False) == set()


PATTERN = HEAD.replace("      h := 0;\n", "") + """      FOR i FROM 1 TO 2 DO
        Place Offs(pPlace, 0, 0, h);
        h := h + 20;
      ENDFOR
""" + TAIL


def test_a_layer_height_that_grows_ends_only_when_left_out(tmp_path):
    """The public backups' pattern (JuanLopezP's Practica5: ``h := h + 20`` each place):
    the height is never reset, so with it in the states no search ends; left out, the
    check ends and names it under ``assumes:``."""
    reduced = check(tmp_path, PATTERN)
    tracked = check(tmp_path, PATTERN, "--track-robot")
    plain = check(tmp_path, PATTERN, "--no-slice")
    line = ("h (prog.mod:3) only shapes where moves go: with the robot's position not tracked, "
            "it is left out of states, and its arithmetic is taken to stay within num's range "
            "(ERR_NUM_LIMIT is not looked for there; --track-robot keeps it)")
    for name, (verdict, states, assumes) in reduced.items():
        assert verdict == "HOLDS" and states < 100, name
        assert assumes == [UNTRACKED_ROBOT.text, line], name
        assert tracked[name][0] == plain[name][0] == UNKNOWN, name
        assert line not in tracked[name][2] + plain[name][2]


def test_a_violation_away_from_the_moves_does_not_name_the_data(tmp_path):
    text = PATTERN.replace("    WHILE TRUE DO\n", "    IF diPart = 1 tab{n} := 0;\n    WHILE TRUE DO\n")
    found = check(tmp_path, text)
    verdict, _, assumes = found["no_runtime_error"]
    assert verdict == "VIOLATED"
    assert not any(line.startswith("h (prog.mod:3)") for line in assumes)


COUNTED = HEAD.replace("      k := 1;\n", "") + """      k := k + 1;
      h := k * size;
      MoveL Offs(pPlace, 0, 0, h), v100, fine, tool0;
""" + TAIL


def test_a_layer_count_times_a_constant_ends_only_when_left_out(tmp_path):
    """Zollman94's palletiser: ``Incr nActLayer`` each layer, ``nActBoxZOff :=
    nActLayer*nBoxSizeZ`` only reaches ``Offs`` targets; never reset, so the search ends
    only with both left out, named under ``assumes:``."""
    reduced = check(tmp_path, COUNTED)
    plain = check(tmp_path, COUNTED, "--no-slice")
    for name, (verdict, states, assumes) in reduced.items():
        assert verdict == "HOLDS" and states < 100, name
        assert any(line.startswith("h (prog.mod:3), k (prog.mod:5) only shape") for line in
                   assumes), assumes
        assert plain[name][0] == UNKNOWN, name
