"""Survey round 4 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not reach a verdict.

* ``cycle_rate.mod`` (a rate from a measured cycle time; tests/test_time_readings.py).
* ``layer_palletizer.mod``: a recipe read from a PLC's group inputs. Each free group input
  needs a finite domain when checking; all of those that lack one are named in one run,
  and with the domains the program reaches a verdict.
* ``config_lookup.mod``: ReadCfgData of an instance that may not be configured. When
  checking, ERR_CFG_NOTFND is a possible outcome for an instance a standard robot may lack,
  so the program's handler is explored (it used to be dead code, and its fallback value
  never seen); the standard arms are found (issue 19).
* ``paint_strokes.mod``: the Paint option's PaintL and SetBrush with a spray gun taught in
  a module that is not given: the instructions are known, and ``rapidmc stubs`` declares
  the tool and work object so that the program reaches a verdict.
* ``glue_bead.mod``: a routine of a library that is not given, called with ``\\WObj:=`` as
  the motion instructions are: the stubs type the work object passed from the parameter's
  name (before, its type was not inferred and the stubs did not load).
"""
from __future__ import annotations

from pathlib import Path

from cli_capture import run_cli

HERE = Path(__file__).resolve().parent / "realworld" / "survey4"
GROUP_INPUTS = ("giBoxHeight", "giLayers", "giBoxesPerLayer")


def cli(*argv) -> tuple[int, str, str]:
    return run_cli(argv)


def verdicts(out: str) -> dict[str, str]:
    return {line.split(":")[0]: line.split(": ")[1].split()[0]
            for line in out.splitlines() if ": " in line and not line.startswith(" ")}


def test_every_group_input_without_a_domain_is_named_in_one_run():
    code, out, err = cli("check", HERE / "layer_palletizer.mod", "--quiet",
                         "--exact-input-domains")
    assert code == 2 and out == ""
    named = [line for line in err.splitlines() if "[RMC502]" in line]
    assert len(named) == 3
    for signal in GROUP_INPUTS[1:]:       # compared with variables: no default
        assert any(f"--input-domain {signal}=" in line for line in named), err
    # the box height only shapes a move's target, and nothing reads the robot's position,
    # but 'layer * boxHeight' multiplies it by a num of any size: the product may leave the
    # range of num (ERR_NUM_LIMIT), so it too needs a domain
    assert "'boxHeight' at " in err and "is an operand of '*'" in err, err


def test_with_domains_the_palletizer_reaches_a_verdict():
    domains = ["--input-domain", "giBoxHeight=100,200", "--input-domain", "giLayers=0,2",
               "--input-domain", "giBoxesPerLayer=1,3"]
    code, out, err = cli("check", HERE / "layer_palletizer.mod", "--quiet", *domains,
                         "--formula", 'bounded: G "placed <= 6"',
                         "--formula", 'always_full: F "placed = 6"')
    found = verdicts(out)
    assert found["no_runtime_error"] == "HOLDS" and found["bounded"] == "HOLDS"
    assert found["always_full"] == "VIOLATED"          # a recipe of 0 layers places nothing
    assert code == 1


def test_a_configuration_read_may_find_nothing_when_checking():
    program = HERE / "config_lookup.mod"
    code, out, err = cli("check", program, "--quiet",
                         "--formula", 'never_missing: G "missing = 0"',
                         "--formula", 'not_all_missing: G !"missing = 4"')
    found = verdicts(out)
    assert found["no_runtime_error"] == "HOLDS"
    # the handler runs for the instance a standard robot may lack ("track1"); the arms
    # rob1_1..rob1_3 of a standard six-axis robot are always found (issue 19)
    assert found["never_missing"] == "VIOLATED" and found["not_all_missing"] == "HOLDS"
    assert "never reached" not in err                  # no dead handler any more
    code, out, _ = cli("run", program)                 # run: every instance is configured
    assert code == 0 and out == "Robot on a track\n"


def test_paint_instructions_are_known_and_stubs_supply_the_taught_data(tmp_path):
    program = HERE / "paint_strokes.mod"
    code, _, err = cli("check", program, "--quiet")
    assert code == 2
    assert "'PaintL'" not in err and "'SetBrush'" not in err and "[RMC203]" not in err
    assert "unknown name 'tSprayGun'" in err and "unknown name 'woPanel'" in err
    stubs = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", stubs)
    assert code == 0, err
    text = stubs.read_text(encoding="latin-1")
    assert "PERS tooldata tSprayGun" in text and "PERS wobjdata woPanel" in text
    code, out, err = cli("check", program, stubs, "--quiet", "--formula", 'p: G "panels <= 3"')
    found = verdicts(out)
    assert code == 0, out + err
    assert found["no_runtime_error"] == "HOLDS" and found["p"] == "HOLDS"


def test_a_work_object_passed_as_wobj_to_a_missing_routine_is_typed(tmp_path):
    program = HERE / "glue_bead.mod"
    stubs = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", stubs)
    assert code == 0, err
    text = stubs.read_text(encoding="latin-1")
    assert "PERS wobjdata woPart" in text
    assert "PROC BeadL(robtarget p1, speeddata p2, zonedata p3, tooldata p4, \\wobjdata WObj)" in text
    code, out, err = cli("check", program, stubs, "--quiet", "--formula", 'once: F "beads = 1"')
    assert code == 0, out + err
    assert verdicts(out)["once"] == "HOLDS"


# the new nondeterministic readings (ClkRead, ReadCfgData) under the default reductions
# give the verdicts of the unreduced search
DIFFERENTIAL = [
    ("cycle_rate.mod", ['never_slow: G "slow_cycles = 0"', 'rate: F "parts_per_hour > 0"']),
    ("config_lookup.mod", ['never_missing: G "missing = 0"', 'some: F "missing >= 1"']),
]


def test_reductions_keep_the_verdicts_of_the_new_choices():
    for name, formulas in DIFFERENTIAL:
        args = ["check", HERE / name, "--quiet"]
        for formula in formulas:
            args += ["--formula", formula]
        reduced = verdicts(cli(*args)[1])
        plain = verdicts(cli(*args, "--no-reduce")[1])
        assert reduced == plain and len(reduced) == 4, (name, reduced, plain)
