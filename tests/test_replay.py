"""Counterexamples are replayed through the step function before they are printed."""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.check import VIOLATED, check_property
from rapidmc.ltl import to_buchi
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem, replay
from rapidmc.model.properties import AtomCompiler, read_property_file
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program

ROOT = Path(__file__).resolve().parent.parent
SORTER = ROOT / "case_studies" / "sorter"


def violation(program_file: str, property_name: str):
    program = build(load_program([str(SORTER / program_file)]),
                    environment=load_program([str(SORTER / "plant.mod")]))
    system = RapidSystem(program, CheckConfig(program))
    prop = next(p for p in read_property_file(str(ROOT / "specs" / "sorter.ltl"))
                if p.name == property_name)
    buchi = to_buchi(Not(prop.formula))
    result = check_property(system, buchi, AtomCompiler(program).valuation(buchi.atoms, {}))
    assert result.verdict == VIOLATED
    return system, result


def test_a_reported_counterexample_replays():
    system, result = violation("sorter_b.mod", "P2")
    replay(system, result)            # raises when a step is not a transition of the program


def test_a_corrupted_counterexample_does_not_replay():
    system, result = violation("sorter_b.mod", "P2")
    middle = result.prefix[len(result.prefix) // 2]
    middle.state = middle.state._replace(errno=middle.state.errno + 1)
    with pytest.raises(AssertionError):
        replay(system, result)


def test_a_cycle_that_does_not_close_does_not_replay():
    system, result = violation("sorter_c.mod", "P3")
    result.closing_label = ("not", "a", "label")
    with pytest.raises(AssertionError):
        replay(system, result)
