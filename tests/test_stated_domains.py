"""Free analog and group inputs with no exact default take values the program singles out
(rapidmc/load/stated_domains.py), stated beside every verdict.

The verdicts and ``assumes:`` lines of each program are cases under tests/assumptions/
(``input_*``, run by test_assumptions.py).  Here: what the values are drawn from, that
"never reached" says the values were assumed, that ``--exact-input-domains`` still refuses
(RMC502), and that both engines agree.
"""
from __future__ import annotations

import json
import shlex
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.load.backup import read_eio
from tests.test_assumptions import check_in_folder, run

CASES = Path(__file__).resolve().parent / "assumptions"
STATED = sorted(p.name for p in CASES.iterdir() if p.is_dir() and p.name.startswith("input_")
                and p.name != "input_domain_given")


def _notes(folder: Path) -> dict:
    _, out = run(folder, "--format", "json")
    return {w["message"].split(":")[0]: w["message"] for w in json.loads(out)["warnings"]
            if w["code"] == "RMC515"}


def test_eio_keeps_an_analog_signals_logical_range():
    signals = {s.name: (s.low, s.high) for s in read_eio(str(CASES / "input_configured_range"
                                                            / "EIO.cfg"))}
    assert signals["aiGantryX"] == (-1000.0, 1000.0)
    assert signals["doTooClose"] == (None, None)


def test_each_component_takes_the_numbers_it_is_compared_with():
    notes = _notes(CASES / "input_camera_clamped")
    # x: 80 and 110 (and 0), with a value between and beyond; z only its own 350
    assert notes["AI_X"].startswith("AI_X: values -1, 0, 40, 80, 95, 110, 111 (assumed, not exact")
    assert notes["AI_Z"].startswith("AI_Z: values -1, 0, 175, 350, 351 (assumed, not exact")


def test_the_configured_range_bounds_the_values_and_a_propertys_numbers_count():
    note = _notes(CASES / "input_configured_range")["aiGantryX"]
    assert note.startswith("aiGantryX: values -1000, -500, 0, 25, 50, 525, 1000 ")
    assert "compared with 50, 1200, configured -1000..1000" in note


def test_unreached_code_says_the_input_values_were_assumed():
    folder = CASES / "input_configured_range"
    _, out = run(folder, "--format", "json")
    [warning] = [w for w in json.loads(out)["warnings"] if w["code"] == "RMC701"]
    assert "never reached with the assumed input values tried (aiGantryX at line 10)" \
        in warning["message"]
    # given the commanded position too, both branches are reached and the warning goes
    _, out = run(folder, "--format", "json", "--input-domain", "aiGantryX=0,200")
    assert not [w for w in json.loads(out)["warnings"] if w["code"] == "RMC701"]


@pytest.mark.parametrize("name", STATED)
def test_exact_input_domains_refuses_them(name):
    folder = CASES / name
    args = shlex.split((folder / "args").read_text())
    code, out = check_in_folder(folder, *args, "--exact-input-domains")
    assert code == 2 and out == ""


@pytest.mark.skipif(not native.available(), reason="the native core is not built")
@pytest.mark.parametrize("name", STATED)
def test_both_engines_give_the_same_verdicts_and_counts(name):
    folder = CASES / name
    reports = [json.loads(run(folder, "--format", "json", "--engine", engine)[1])
               for engine in ("native", "python")]
    figures = [[(p["name"], p["verdict"], p["stats"]["model_states"],
                 p["stats"]["transitions"], p["assumes"]) for p in report["properties"]]
               for report in reports]
    assert figures[0] == figures[1]


def test_an_explicit_domain_leaves_nothing_assumed(tmp_path):
    text = (CASES / "input_line_in_pers" / "prog.mod").read_text()
    path = tmp_path / "prog.mod"
    path.write_text(text)
    program = api.load_program([str(path)])
    given = api.prepare(program, [], api.CheckOptions(input_domains={"GILINE": (1.0,)}))
    assert given.assumed == ()
    [stated] = api.prepare(program, [], api.CheckOptions()).assumed
    assert not stated.exact and stated.values == (0.0, 1.0, 2.0, 3.0, 4.0)
