"""HOA v1: writing, reading back (languages compared on lassos), malformed input."""
from __future__ import annotations

import random
import re
from pathlib import Path

import pytest

from tool_requirements import require_tool

from ltl_cases import random_formulas, random_lasso
from rapidmc.diagnostics import AUTOMATON, UserError
from rapidmc.ltl import parse_formula, read_hoa, to_text, write_hoa
from rapidmc.ltl.lasso import accepts_lasso, holds_on_lasso
from rapidmc.ltl.spot_backend import spot_available, spot_translate, with_atoms
from rapidmc.ltl.translate import translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DATA = Path(__file__).parent / "ltl"


def test_written_header_and_body():
    text = write_hoa(translate(parse_formula('G F "x = 1"')))
    lines = text.splitlines()
    assert lines[:2] == ["HOA: v1", "States: 2"]
    assert 'AP: 1 "x = 1"' in lines and "acc-name: Buchi" in lines
    assert "Acceptance: 1 Inf(0)" in lines and lines[-1] == "--END--"
    assert "properties: trans-labels explicit-labels state-acc" in lines
    assert sum(1 for line in lines if re.fullmatch(r"State: \d+ \{0\}", line)) == 1


def test_round_trip_preserves_the_automaton_and_its_language():
    rng = random.Random(9)
    atoms = ("a", "b", 'c "quoted"')
    for formula in random_formulas(9, 150, atoms):
        automaton = translate(formula, atoms)
        again = read_hoa(write_hoa(automaton, name=to_text(formula)))
        assert again == automaton
        for _ in range(4):
            prefix, cycle = random_lasso(rng, atoms)
            assert accepts_lasso(again, prefix, cycle) == holds_on_lasso(formula, prefix, cycle)


TRANSITION_BASED_GF_P = """HOA: v1
name: "GF p, transition-based"
States: 1
Start: 0
AP: 1 "p"
acc-name: Buchi
Acceptance: 1 Inf(0)
properties: trans-labels explicit-labels trans-acc
--BODY--
State: 0 "only"
[0] 0 {0}
[!0] 0
--END--
"""


def test_transition_based_acceptance_is_made_state_based():
    automaton = read_hoa(TRANSITION_BASED_GF_P)
    formula = parse_formula("G F p")
    words = [([], [{"p"}]), ([], [set()]), ([{"p"}], [set()]), ([set()], [set(), {"p"}])]
    for prefix, cycle in words:
        assert accepts_lasso(automaton, prefix, cycle) == holds_on_lasso(formula, prefix, cycle)


def test_dnf_labels_become_one_edge_per_cube_and_several_starts_merge():
    text = """HOA: v1
States: 2
Start: 0
Start: 1
AP: 2 "a" "b"
Acceptance: 1 Inf(0)
--BODY--
State: 0 {0}
[0&!1 | (1) | f] 0
State: 1 {0}
[t] 1
--END--"""
    automaton = read_hoa(text)
    assert automaton.state_count == 3          # a fresh start state, then states 0 and 1
    assert len(automaton.edges[1]) == 2        # [0&!1] and [1]; f gives none
    assert accepts_lasso(automaton, [], [set()])   # through start state 1
    assert accepts_lasso(automaton, [{"a"}], [{"b"}])


def _malformed_cases():
    text = (DATA / "malformed.hoa").read_text()
    for block in re.split(r"^\[case ", text, flags=re.M)[1:]:
        name, rest = block.split("]\n", 1)
        expect, body = rest.split("\n", 1)
        line, message = expect.removeprefix("expect: ").split(" ", 1)
        yield pytest.param(body, int(line), message, id=name)


@pytest.mark.parametrize("text, line, message", list(_malformed_cases()))
def test_malformed_files_give_automaton_diagnostics(text, line, message):
    with pytest.raises(UserError) as caught:
        read_hoa(text, file="bad.hoa")
    diagnostic = caught.value.diagnostics[0]
    assert diagnostic.code is AUTOMATON
    assert message in diagnostic.message
    assert (diagnostic.span.file, diagnostic.span.line) == ("bad.hoa", line)


def test_with_atoms_renumbers_bits():
    automaton = translate(parse_formula("b U a"))            # atoms ("b", "a")
    moved = with_atoms(automaton, ("a", "c", "b"))
    for prefix, cycle in [([{"b"}], [{"a"}]), ([], [{"b"}]), ([{"c"}], [{"a"}])]:
        assert accepts_lasso(moved, prefix, cycle) == accepts_lasso(automaton, prefix, cycle)


def test_spot_backend_agrees_with_lasso_oracle():
    require_tool(spot_available(), "RAPIDMC_REQUIRE_SPOT",
                 "Spot's Python bindings are not installed (../shared/spot/install)")
    rng = random.Random(4)
    atoms = ("a", "b", "c")
    for formula in random_formulas(4, 200, atoms):
        automaton = spot_translate(formula, atoms)
        assert automaton.atoms == atoms
        for _ in range(5):
            prefix, cycle = random_lasso(rng, atoms)
            assert accepts_lasso(automaton, prefix, cycle) == holds_on_lasso(formula, prefix, cycle)
