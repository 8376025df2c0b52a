"""Default domains of free group and analog inputs (rapidmc/load/input_domains.py).

The defaults must lose no behaviour: a differential test checks generated
programs once with the derived domain and once with every 4-bit value, and
the verdicts must agree.
"""
from __future__ import annotations

import itertools
import json
import random
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.load.backup import map_width, read_eio
from rapidmc.cli import main
from rapidmc.diagnostics import UserError
from rapidmc.load.input_domains import analog_points, group_points
from tests.test_backup import make_backup

COMPARE = {"=": lambda a, b: a == b, "<>": lambda a, b: a != b, "<": lambda a, b: a < b,
           "<=": lambda a, b: a <= b, ">": lambda a, b: a > b, ">=": lambda a, b: a >= b}


def _outcomes(x: float, numbers) -> tuple:
    return tuple(test(x, c) for c in numbers for test in COMPARE.values())


@pytest.mark.parametrize("numbers", [(), (0,), (3,), (3, 5), (2.5, 7), (0.5, 1, 14.5),
                                     (-2, 1), (-0.5,), (9, 10, 11, 30)])
def test_group_points_meet_every_outcome_of_the_comparisons(numbers):
    """Every non-negative integer compares with the numbers as one of the points does."""
    points = group_points(sorted(numbers), 2 ** 32 - 1)
    assert all(p >= 0 and p == int(p) for p in points)
    seen = {_outcomes(p, numbers) for p in points}
    assert {_outcomes(x, numbers) for x in range(0, 64)} == seen


def test_group_points_stay_within_the_width():
    assert group_points([15], 15) == (0.0, 14.0, 15.0)


@pytest.mark.parametrize("numbers", [(), (4,), (2.5, 4), (-1, 0, 0.25, 100)])
def test_analog_points_meet_every_outcome_of_the_comparisons(numbers):
    points = analog_points(sorted(numbers))
    grid = [k / 8 for k in range(-200 * 8, 200 * 8)]
    assert {_outcomes(x, numbers) for x in grid} == {_outcomes(p, numbers) for p in points}


@pytest.mark.parametrize("mapping, width", [("0-3", 4), ("16-19", 4), ("3", 1), ("0-3,8", 5),
                                            ("7-0", 8), ("", None), ("a-b", None)])
def test_the_width_of_a_device_map(mapping, width):
    assert map_width(mapping) == width


EIO_GROUP = """EIO:CFG_1.0:6:1::
EIO_SIGNAL:
      -Name "giRecipe" -SignalType "GI" -Device "d652" -DeviceMap "4-7"
      -Name "giWide" -SignalType "GI" -Device "d652" -DeviceMap "8-15"
      -Name "giVirtual" -SignalType "GI"
"""

RECIPE_MOD = """MODULE MainModule
  VAR num recipe := 0;
  PROC main()
    recipe := GInput(giRecipe);
    IF GInput(giWide) = 200 recipe := 99;
  ENDPROC
ENDMODULE
"""


def test_eio_keeps_the_width_of_group_signals(tmp_path):
    (tmp_path / "EIO.cfg").write_text(EIO_GROUP)
    widths = {s.name: s.width for s in read_eio(str(tmp_path / "EIO.cfg"))}
    assert widths == {"giRecipe": 4, "giWide": 8, "giVirtual": None}


def test_a_backups_4_bit_group_input_takes_all_16_values(tmp_path, capsys):
    backup = make_backup(tmp_path, {"TASK1": {"PROGMOD/MainModule.mod": RECIPE_MOD}}, EIO_GROUP)
    code = main(["check", str(backup), "--formula", 'G "recipe < 15"', "--format", "json",
                 "--quiet"])
    document = json.loads(capsys.readouterr().out)
    notes = {w["message"] for w in document["warnings"] if w["code"] == "RMC515"}
    # 4 bits: every value; 8 bits (too many): the numbers it is compared with
    assert notes == {"giRecipe: values 0..15 (4-bit group input from the I/O configuration)",
                     "giWide: values 0, 199, 200, 201 (group input only compared with 200)"}
    assert code == 1                        # recipe 15 is reached
    assert document["properties"][-1]["verdict"] == "VIOLATED"


def _load(tmp_path: Path, text: str):
    path = tmp_path / "prog.mod"
    path.write_text(text)
    return api.load_program([str(path)])


PASSED_ON = """MODULE M
  VAR signalgi gi_code;
  VAR num x := 0;
  PROC main()
    AliasIO "GI_CODE", gi_code;
    IF gi_code = 1 x := 1;
    show gi_code;
  ENDPROC
  PROC show(VAR signalgi s)
    x := 2;
  ENDPROC
ENDMODULE
"""


def _refusal(tmp_path, text: str, properties=(), **options) -> str:
    """The note of the RMC502 an input with no exact default gets with --exact-input-domains
    (without it, the values of ``stated_domains``: tests/test_stated_domains.py)."""
    with pytest.raises(UserError) as caught:
        api.prepare(_load(tmp_path, text), properties,
                    api.CheckOptions(exact_input_domains=True, **options))
    [diagnostic] = caught.value.diagnostics
    assert diagnostic.code.code == "RMC502"
    [note] = diagnostic.notes
    return note


def test_an_input_passed_to_a_routine_has_no_default(tmp_path):
    note = _refusal(tmp_path, PASSED_ON)
    assert "'gi_code' at " in note and "prog.mod:7:10 is passed as an argument" in note


def test_an_input_a_property_reads_has_no_default(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "")
    prop = api.property_from_text('p: G "GInput(gi_code) < 3"')
    assert "a property's atom reads GI_CODE" in _refusal(tmp_path, text, [prop])


def test_an_input_compared_with_a_variable_has_no_default(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "    IF gi_code < x x := 3;\n")
    assert "compared ('<') with something other than a number literal" in _refusal(tmp_path, text)


def test_an_input_compared_with_a_constant_gets_its_neighbours(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "    IF gi_code >= LIMIT x := 3;\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  CONST num LIMIT := 6;\n")
    model = api.prepare(_load(tmp_path, text), [])
    [assumed] = model.assumed
    assert assumed.values == (0.0, 1.0, 2.0, 5.0, 6.0, 7.0)


def test_an_explicit_domain_wins(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "")
    model = api.prepare(_load(tmp_path, text), [],
                        api.CheckOptions(input_domains={"GI_CODE": (5.0,)}))
    assert model.assumed == ()
    assert model.config.lazy_inputs[0][1] == (5.0,)


# --- differential: the derived domain against every 4-bit value -------------------------

NUMBERS = list(range(0, 15)) + [0.5, 2.5, 7.5]    # below 15: the class above them meets 0..15
OPS = list(COMPARE)


def _condition(rng: random.Random, pool: list, depth: int = 0) -> str:
    roll = rng.random()
    signal = rng.choice(["gi_a", "GInput(gi_a)", "gi_b"])
    if roll < 0.25:                     # a range: only values strictly between two numbers
        low, high = sorted(rng.sample(pool, 2))
        return f"({signal} > {low} AND {signal} < {high})"
    if depth < 2 and roll < 0.45:
        return f"({_condition(rng, pool, depth + 1)} {rng.choice(['AND', 'OR'])} " \
               f"{_condition(rng, pool, depth + 1)})"
    if depth < 2 and roll < 0.55:
        return f"NOT ({_condition(rng, pool, depth + 1)})"
    number = rng.choice(pool)
    if rng.random() < 0.5:
        return f"{signal} {rng.choice(OPS)} {number}"
    return f"{number} {rng.choice(OPS)} {signal}"


def _statement(rng: random.Random, pool: list) -> str:
    roll = rng.random()
    k1, k2 = rng.randrange(4), rng.randrange(4)
    if roll < 0.4:
        return f"IF {_condition(rng, pool)} THEN\n x := {k1};\n ELSE\n x := {k2};\n ENDIF"
    if roll < 0.65:
        return f"IF x = {k1} AND {_condition(rng, pool)} x := {k2};"
    if roll < 0.75:
        switch = rng.choice(["", " \\NOTEQ", " \\LT", " \\GT"])
        return f"WaitGI gi_b{switch}, {int(rng.choice(pool))};\n x := {k1};"
    cases = rng.sample(pool, 2)
    return (f"TEST GInput(gi_a)\n CASE {cases[0]}:\n x := {k1};\n"
            f" CASE {cases[1]}:\n x := {k2};\n DEFAULT:\n x := 3;\n ENDTEST")


def generated_program(seed: int) -> str:
    """A loop of 2-3 statements branching on two group inputs compared with 3 numbers."""
    rng = random.Random(seed)
    pool = rng.sample(NUMBERS, 3)
    body = "\n".join(_statement(rng, pool) for _ in range(rng.randint(2, 3)))
    return ("MODULE Gen\n  VAR signalgi gi_a;\n  VAR signalgi gi_b;\n  VAR num x := 0;\n"
            "  PROC main()\n    AliasIO \"GI_A\", gi_a;\n    AliasIO \"GI_B\", gi_b;\n"
            f"    WHILE TRUE DO\n{body}\n    ENDWHILE\n  ENDPROC\nENDMODULE\n")


PROPERTIES = "\n".join(
    [f"never_{k}: G !\"x = {k}\"" for k in range(4)]
    + [f"often_{k}: G F \"x = {k}\"" for k in range(4)]
    + [f"settles_{k}: F G \"x = {k}\"" for k in range(4)]
    + ["answer: G (\"x = 1\" -> F \"x = 2\")"]) + "\n"

FULL = tuple(float(v) for v in range(16))


@pytest.mark.parametrize("seed", range(40))
def test_derived_domains_keep_the_verdicts_of_every_4_bit_value(tmp_path, seed):
    program_text = generated_program(seed)
    (tmp_path / "props.ltl").write_text(PROPERTIES)
    properties = api.read_properties(str(tmp_path / "props.ltl"))
    derived = api.check(_load(tmp_path, program_text), properties)
    full = api.check(_load(tmp_path, program_text), properties,
                     api.CheckOptions(input_domains={"GI_A": FULL, "GI_B": FULL}))
    assert any(w.code.code == "RMC515" for w in derived.warnings)
    assert derived.verdicts == full.verdicts, program_text


def test_the_generated_programs_are_not_trivial(tmp_path):
    """Across the differential corpus both verdicts occur for each kind of property."""
    (tmp_path / "props.ltl").write_text(PROPERTIES)
    properties = api.read_properties(str(tmp_path / "props.ltl"))
    verdicts = set()
    for seed in range(10):
        report = api.check(_load(tmp_path, generated_program(seed)), properties)
        verdicts.update((name.split("_")[0], v) for name, v in report.verdicts.items())
    for kind, verdict in itertools.product(["never", "often", "settles"], ["HOLDS", "VIOLATED"]):
        assert (kind, verdict) in verdicts


def test_an_alias_with_a_computed_name_leaves_no_default(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "    AliasIO name, gi_other;\n    IF gi_other = 2 x := 2;\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  VAR string name := \"GI_CODE\";\n"
                 "  VAR signalgi gi_other;\n")
    # (the signal the run-time name stands for with no I/O configuration, a GI too, gets a
    # refusal of its own: library/signals.py ``_run_time_signal``)
    assert "prog.mod:9:5 names its signal at run time" in _refusal_notes(tmp_path, text, [])


def test_a_read_computed_into_an_index_names_the_first_such_read(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "    x := table{GInput(gi_code) + 1};\n"
                             "    x := table{gi_code - 1};\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  VAR num table{3} := [1, 2, 3];\n")
    note = _refusal(tmp_path, text)
    assert "prog.mod:8:23 is an operand of '+'" in note


def test_a_read_used_as_an_index_counts_each_element(tmp_path):
    text = PASSED_ON.replace("    show gi_code;\n", "    x := table{GInput(gi_code)};\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  VAR num table{3} := [1, 2, 3];\n")
    [assumed] = api.prepare(_load(tmp_path, text), []).assumed
    assert assumed.values == (0.0, 1.0, 2.0, 3.0, 4.0)


# --- issue 28: an input whose value reaches nothing needs one value ----------------------

SPEED_ONLY = """MODULE M
  VAR signalgi gi_speed;
  VAR num override := 100;
  VAR num x := 0;
  PROC main()
    AliasIO "GI_CODE", gi_speed;
    VelSet GInput(gi_speed) * 2 - 1, 5000;
    AccSet gi_speed, 100;
    x := 1;
  ENDPROC
ENDMODULE
"""


def test_an_input_that_reaches_only_routines_with_no_effect_takes_one_value(tmp_path):
    model = api.prepare(_load(tmp_path, SPEED_ONLY), [])
    [assumed] = model.assumed
    assert assumed.values == (0.0,) and "reaches no condition" in assumed.reason


def test_an_override_given_to_speed_refresh_is_compared_with_its_limits(tmp_path):
    """SpeedRefresh raises ERR_SPEED_REFRESH_LIM outside 0-100 %: the value is compared with
    0 and 100 (review of session 5; before, SpeedRefresh had no effect: one value)."""
    text = SPEED_ONLY.replace("    AccSet gi_speed, 100;\n", "    SpeedRefresh gi_speed;\n")
    [assumed] = api.prepare(_load(tmp_path, text), []).assumed
    assert assumed.values == (0.0, 1.0, 99.0, 100.0, 101.0)
    assert "only compared with 0, 100" in assumed.reason


@pytest.mark.parametrize("use, found", [
    ("    VelSet 100 / gi_speed, 5000;\n", "operand of '/'"),  # a divisor: can fail
    ("    show gi_speed * 2;\n", "operand of '*'"),             # the program's own routine
])
def test_an_input_whose_value_reaches_a_condition_or_divisor_has_no_default(tmp_path, use, found):
    text = SPEED_ONLY.replace("    x := 1;\n", use) + "\n"
    text = text.replace("ENDMODULE", "  PROC show(num n)\n  ENDPROC\nENDMODULE")
    assert found in _refusal(tmp_path, text)


def test_an_input_stored_into_data_a_property_reads_has_no_default(tmp_path):
    text = SPEED_ONLY.replace("    x := 1;\n", "    override := gi_speed;\n")
    prop = api.property_from_text('p: G "override < 1000"')
    assert "is assigned" in _refusal(tmp_path, text, [prop])


# --- issue 28: a value followed through the data it is stored into -----------------------
# Survey of public backups: a part code from a PLC, range-checked, copied into a routine's
# INOUT parameter and used as an array index; a PLC's speed percentage scaled into a
# speeddata that only moves read.

PART_CODE = """MODULE M
  VAR signalgi gi_code;
  VAR bool taken{4} := [FALSE, FALSE, FALSE, FALSE];
  VAR num picked := 0;
  PROC main()
    VAR num code;
    VAR bool ready;
    AliasIO "GI_CODE", gi_code;
    WHILE TRUE DO
      ready := ChoosePart(code);
      IF ready THEN
        taken{code} := TRUE;
        picked := picked + 1;
        IF picked > 2 picked := 0;
      ENDIF
    ENDWHILE
  ENDPROC
  FUNC bool ChoosePart(INOUT num part)
    part := 0;
    IF GInput(gi_code) >= LOW AND gi_code <= 4 THEN
      IF taken{GInput(gi_code)} = FALSE THEN
        part := GInput(gi_code);
        RETURN TRUE;
      ENDIF
    ENDIF
    RETURN FALSE;
  ENDFUNC
ENDMODULE
"""


def test_a_range_checked_part_code_used_as_an_index_gets_each_element(tmp_path):
    text = PART_CODE.replace("VAR num picked := 0;", "VAR num picked := 0;\n  CONST num LOW := 1;")
    model = api.prepare(_load(tmp_path, text), [])
    [assumed] = model.assumed
    assert assumed.values == tuple(float(v) for v in range(6))
    assert "compared with 1, 4, an index of a 4-element array" in assumed.reason
    assert "followed through part, code" in assumed.reason


SPEED_PERCENT = """MODULE M
  VAR signalgi gi_speed;
  VAR speeddata speed := [100, 500, 5000, 1000];
  VAR num x := 0;
  PROC main()
    AliasIO "GI_SPEED", gi_speed;
    WHILE TRUE DO
      speed.v_tcp := MaxRobSpeed() / 100 * gi_speed;
      speed.v_ori := MaxRobReorientSpeed() / 100 * GInput(gi_speed) * 0.2;
      MoveL Offs(home, 0, 0, 50), speed, z10, tool0;
      MoveJ \\Conc, home, speed \\V:=gi_speed * 2, fine, tool0;
      x := x + 1;
      IF x > 2 x := 0;
    ENDWHILE
  ENDPROC
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
ENDMODULE
"""


def test_a_speed_percentage_that_only_moves_read_takes_one_value(tmp_path):
    model = api.prepare(_load(tmp_path, SPEED_PERCENT), [])
    [assumed] = model.assumed
    assert assumed.values == (0.0,)
    assert "followed through speed" in assumed.reason


@pytest.mark.parametrize("text, found", [
    # the scaled speed is compared: its value tells behaviours apart
    (SPEED_PERCENT.replace("      x := x + 1;\n", "      IF speed.v_tcp > 100 x := 2;\n"),
     "'gi_speed' at "),
    # the speed is passed where a routine of the program may read it
    (SPEED_PERCENT.replace("      x := x + 1;\n", "      Slow speed;\n")
     .replace("ENDMODULE", "  PROC Slow(speeddata s)\n  ENDPROC\nENDMODULE"), "'gi_speed' at "),
    # the part code indexes an array too big to branch over each element
    (PART_CODE.replace("taken{4} := [FALSE, FALSE, FALSE, FALSE]", "taken{100}"),
     "an index of an array of more than 64 elements"),
    # the stored code is computed with before it is used
    (PART_CODE.replace("taken{code} := TRUE;", "taken{code + 1} := TRUE;"),
     "prog.mod:12:15 is an operand of '+'"),
    # a call by a computed name may pass other data for the INOUT parameter
    (PART_CODE.replace("      ready := ChoosePart(code);\n",
                       "      ready := ChoosePart(code);\n      %\"Grab\"% spare;\n"
                       "      picked := spare * 2 / spare;\n")
     .replace("    VAR bool ready;\n", "    VAR bool ready;\n    VAR num spare;\n")
     .replace("ENDMODULE", "  PROC Grab(INOUT num n)\n    n := gi_code;\n  ENDPROC\nENDMODULE"),
     "called by a name computed at run time"),
    # data read by a computed name: a value stored anywhere may be read unseen
    (PART_CODE.replace("        picked := picked + 1;\n",
                       "        picked := picked + 1;\n        GetDataVal \"code\", picked;\n"),
     "'gi_code' at "),
    # a PERS receives the code: another task may read it
    (PART_CODE.replace("    VAR num code;\n", "").replace(
        "VAR num picked := 0;", "VAR num picked := 0;\n  PERS num code := 0;"),
     "passed for ChoosePart's INOUT parameter part, which holds an input's value, and is "
     "PERS data, which another task may read"),
])
def test_a_value_followed_through_data_to_a_use_it_cannot_place_has_no_default(tmp_path, text,
                                                                                 found):
    text = text.replace("GInput(gi_code) >= LOW", "GInput(gi_code) >= 1")
    assert found in _refusal(tmp_path, text)


def test_a_followed_value_a_property_reads_has_no_default(tmp_path):
    text = PART_CODE.replace("GInput(gi_code) >= LOW", "GInput(gi_code) >= 1") \
        .replace("    VAR num code;\n", "").replace(
            "VAR num picked := 0;", "VAR num picked := 0;\n  VAR num code := 0;")
    prop = api.property_from_text('p: G "code < 7"')
    assert "is data a property's atom reads" in _refusal(tmp_path, text, [prop])


FOLLOWED_PROPERTIES = "\n".join([
    "never_full: G !\"taken{1} AND taken{2} AND taken{3} AND taken{4}\"",
    "counts: G F \"picked = 0\"",
    "fourth: G !\"taken{4}\"",
    "last_first: G (\"taken{4}\" -> \"taken{1}\")"]) + "\n"


@pytest.mark.parametrize("variant", [
    "", "        picked := 0;\n", "      IF code = 3 picked := 0;\n",
])
def test_followed_domains_keep_the_verdicts_of_every_4_bit_value(tmp_path, variant):
    """The default (0..5, from the range check and the 4-element index) against every value
    of a 4-bit input, with run-time errors (an index out of bounds) among the properties."""
    text = PART_CODE.replace("GInput(gi_code) >= LOW", "GInput(gi_code) >= 0") \
        .replace("      ENDIF\n    ENDWHILE", "      ENDIF\n" + variant + "    ENDWHILE") \
        .replace("VAR num picked := 0;", "VAR num picked := 0;\n  VAR bool unused;")
    (tmp_path / "props.ltl").write_text(FOLLOWED_PROPERTIES)
    properties = api.read_properties(str(tmp_path / "props.ltl"))
    derived = api.check(_load(tmp_path, text), properties)
    full = api.check(_load(tmp_path, text), properties,
                     api.CheckOptions(input_domains={"GI_CODE": FULL}))
    assert any(w.code.code == "RMC515" for w in derived.warnings)
    assert derived.verdicts == full.verdicts
    assert "VIOLATED" in derived.verdicts.values()


def test_a_computed_alias_onto_digital_signal_data_leaves_the_default(tmp_path):
    """Survey of public backups: clamp checks bind ``signaldi`` data to a computed name; no
    group input can be read through it."""
    text = PASSED_ON.replace("    show gi_code;\n", "    AliasIO name, di_clamp;\n    IF di_clamp = 1 x := 2;\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  VAR string name := \"DI_CLAMP\";\n"
                 "  VAR signaldi di_clamp;\n")
    model = api.prepare(_load(tmp_path, text), [])
    assert [a.values for a in model.assumed] == [(0.0, 1.0, 2.0)]


def test_an_input_no_statement_reads_beside_a_computed_digital_alias_takes_one_value(tmp_path):
    text = PASSED_ON.replace("    IF gi_code = 1 x := 1;\n    show gi_code;\n",
                             "    AliasIO name, di_clamp;\n    IF di_clamp = 1 x := 2;\n") \
        .replace("  VAR num x := 0;\n", "  VAR num x := 0;\n  VAR string name := \"DI_CLAMP\";\n"
                 "  VAR signaldi di_clamp;\n")
    model = api.prepare(_load(tmp_path, text), [])
    assert [(a.values, a.reason) for a in model.assumed] == \
        [((0.0,), "no statement reads it: one value")]


# A camera's pick position sent as group inputs, stored, and given to Offs for a move's
# target (survey of public backups): the robot goes there, and nothing reads its position.
CAMERA_PICK = """MODULE M
  VAR signalgi gi_x;
  VAR signalgi gi_y;
  VAR num pick_x := 0;
  VAR num pick_y := 0;
  VAR num parts := 0;
  CONST robtarget table := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    AliasIO "GI_X", gi_x;
    AliasIO "GI_Y", gi_y;
    WHILE TRUE DO
      pick_x := GInput(gi_x);
      pick_y := gi_y;
      MoveL Offs(table, pick_x, pick_y * 2 + 10, 250), v1000, z10, tool0;
      MoveL Offs(table, pick_x, pick_y, 0), v100, fine, tool0;
      parts := parts + 1;
      IF parts > 2 parts := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def test_a_pick_position_that_only_moves_the_robot_takes_one_value(tmp_path):
    model = api.prepare(_load(tmp_path, CAMERA_PICK), [])
    assert {a.signal.name: a.values for a in model.assumed} == {"GI_X": (0.0,), "GI_Y": (0.0,)}
    assert all("followed through pick_" in a.reason for a in model.assumed)


@pytest.mark.parametrize("change, properties", [
    # the program reads the robot's position back
    (("      parts := parts + 1;\n", "      IF CRobT().trans.x > 600 parts := 0;\n"), ()),
    # a property reads it
    (("", ""), ('p: G "CPos().x < 900"',)),
    # an offset position is computed with, not moved to
    (("      parts := parts + 1;\n", "      IF Offs(table, pick_x, 0, 0).trans.x > 600 parts := 0;\n"),
     ()),
])
def test_a_pick_position_the_code_or_a_property_can_observe_has_no_default(tmp_path, change,
                                                                           properties):
    text = CAMERA_PICK.replace(*change) if change[0] else CAMERA_PICK
    props = [api.property_from_text(p) for p in properties]
    assert "no default" in _refusal_notes(tmp_path, text, props)


# the robot's position and joints read back, shifted by the inputs and moved to again
READ_BACK = CAMERA_PICK.replace("      parts := parts + 1;\n", """      here := CRobT();
      here.trans.z := here.trans.z - 250 - GInput(gi_x) / 10;
      MoveL here, v100, fine, tool0;
      joints := CJointT();
      joints.robax.rax_4 := joints.robax.rax_4 + gi_y * 2;
      MoveAbsJ joints, v100, fine, tool0;
      parts := parts + 1;
""").replace("  VAR num parts := 0;\n", "  VAR num parts := 0;\n  VAR robtarget here;\n"
             "  VAR jointtarget joints;\n")


def test_a_position_read_back_only_to_move_again_leaves_the_default(tmp_path):
    """Survey (nine versions of one public program): the robot's position is read back, moved
    down by a height from a group input and moved to; joints are read, turned and moved to.
    Nothing but moves sees where the robot is."""
    text = READ_BACK
    model = api.prepare(_load(tmp_path, text), [])
    assert {a.signal.name: a.values for a in model.assumed} == {"GI_X": (0.0,), "GI_Y": (0.0,)}


@pytest.mark.parametrize("change", [
    ("MoveL here, v100, fine, tool0;", "MoveL here, v100, fine, tool0;\n"
     "      IF here.trans.z < 0 parts := 0;"),                    # the position is compared
    ("here.trans.z - 250 - GInput(gi_x) / 10", "here.trans.z - 250 - 10 / GInput(gi_x)"),  # a divisor
    ("joints := CJointT();", "joints := CalcJointT(here, tool0);"),  # may fail: out of reach
])
def test_a_position_read_back_and_observed_has_no_default(tmp_path, change):
    text = READ_BACK.replace(*change)
    assert "no default" in _refusal_notes(tmp_path, text, [])


# Survey (sss.mod of the public program above): the turn and the offsets are stored into module
# data first, ``GInput(gi) / 10`` and ``GInput(gi)``; module data every write of which has a
# known size keeps it, so the sums stay within num and nothing but moves sees the position.
STORED_TURN = READ_BACK.replace("joints.robax.rax_4 + gi_y * 2", "joints.robax.rax_4 + turn") \
    .replace("      pick_x := GInput(gi_x);\n", "      pick_x := GInput(gi_x) / 10;\n"
             "      turn := GInput(gi_y);\n") \
    .replace("  VAR num parts := 0;\n", "  VAR num parts := 0;\n  VAR num turn := 0;\n")


def test_an_input_stored_into_module_data_of_a_known_size_leaves_the_default(tmp_path):
    model = api.prepare(_load(tmp_path, STORED_TURN), [])
    assert {a.signal.name: a.values for a in model.assumed} == {"GI_X": (0.0,), "GI_Y": (0.0,)}
    assert model.config.robot_untracked


@pytest.mark.parametrize("change", [
    ("      turn := GInput(gi_y);\n", "      turn := GInput(gi_y);\n      turn := turn * 2;\n"),
    ("      turn := GInput(gi_y);\n", "      turn := GInput(gi_y);\n      Add turn, 1;\n"),
    ("  VAR num turn := 0;\n", "  PERS num turn := 0;\n"),   # another task may write it
])
def test_module_data_written_beyond_a_known_size_has_no_default(tmp_path, change):
    """A write that reads the data itself, a write through a reference (``Add``) or a PERS:
    the size is unknown, and the sum with a joint read back may leave the range of num."""
    assert "no default" in _refusal_notes(tmp_path, STORED_TURN.replace(*change), [])


# two cycles, so that the search with the robot tracked ends too; an error at the end
TWO_PICKS = """MODULE M
  VAR signalgi gi_x;
  VAR signalgi gi_turn;
  VAR num pick_x := 0;
  VAR num turn := 0;
  VAR num parts := 0;
  VAR robtarget here;
  VAR jointtarget joints;
  CONST robtarget table := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  PROC main()
    AliasIO "GI_X", gi_x;
    AliasIO "GI_TURN", gi_turn;
    FOR k FROM 1 TO 2 DO
      pick_x := GInput(gi_x) / 10;
      turn := GInput(gi_turn);
      MoveL Offs(table, pick_x, 0, 250), v1000, z10, tool0;
      here := CRobT();
      here.trans.z := here.trans.z - 250;
      MoveL here, v100, fine, tool0;
      joints := CJointT();
      joints.robax.rax_4 := joints.robax.rax_4 + turn;
      MoveAbsJ joints, v100, fine, tool0;
      parts := parts + 1;
    ENDFOR
    IF parts = 2 parts := 10 / (parts - 2);
  ENDPROC
ENDMODULE
"""


def test_inputs_stored_into_module_data_keep_the_verdicts_of_the_tracked_robot(tmp_path):
    """The default (one value each, the robot untracked) against four values each over the
    whole 4-bit width with the robot tracked: the same verdicts, the error included."""
    derived = api.prepare(_load(tmp_path, TWO_PICKS), [])
    assert {a.signal.name: a.values for a in derived.assumed} == \
        {"GI_X": (0.0,), "GI_TURN": (0.0,)}
    assert derived.config.robot_untracked
    spread = (0.0, 5.0, 10.0, 15.0)
    full = api.prepare(_load(tmp_path, TWO_PICKS), [], api.CheckOptions(
        input_domains={"GI_X": spread, "GI_TURN": spread}, track_robot=True))
    assert not full.config.robot_untracked
    derived, full = api.check_model(derived), api.check_model(full)
    assert derived.verdicts == full.verdicts == \
        {"no_runtime_error": "VIOLATED", "no_deadlock": "HOLDS"}


def _refusal_notes(tmp_path, text: str, properties) -> str:
    with pytest.raises(UserError) as caught:
        api.prepare(_load(tmp_path, text), properties, api.CheckOptions(exact_input_domains=True))
    return " ".join(note for d in caught.value.diagnostics for note in d.notes)


# --- review of session 5: an operation that may leave the range of num can fail ----------

@pytest.mark.parametrize("scaled, default", [
    ("AInput(ai_speed) * 0.5 + 100", True),     # at most half the largest num, plus 100
    ("-AInput(ai_speed) / 2", True),
    ("AInput(ai_speed) * 10", False),           # the largest num times 10: ERR_NUM_LIMIT
    ("AInput(ai_speed) + 2E38", False),
    ("AInput(ai_speed) / 0.5", False),
    ("AInput(ai_speed) * MaxRobSpeed()", False),  # its fixed reading, 5000
])
def test_an_analog_value_scaled_beyond_the_num_range_has_no_default(tmp_path, scaled, default):
    text = SPEED_PERCENT.replace("signalgi gi_speed", "signalai gi_speed") \
        .replace("MaxRobSpeed() / 100 * gi_speed", scaled.replace("ai_speed", "gi_speed")) \
        .replace("MaxRobReorientSpeed() / 100 * GInput(gi_speed) * 0.2", "100") \
        .replace("speed \\V:=gi_speed * 2", "speed")
    if default:
        [assumed] = api.prepare(_load(tmp_path, text), []).assumed
        assert assumed.values == (0.0,)
    else:
        assert "is an operand of" in _refusal(tmp_path, text)
