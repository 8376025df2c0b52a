"""The built-in translator against SPIN's (``spin -f``), an independent LTL → Büchi tool.

For each formula φ (random X-free ones, plus the Dwyer patterns) both
A(φ) × SPIN(¬φ) and SPIN(φ) × A(¬φ) must be empty.  SPIN is first checked
on trivial formulas to pin its convention (the claim accepts φ itself).
Without ``spin`` the tests skip, unless RAPIDMC_REQUIRE_SPIN=1 (CI).
"""
from __future__ import annotations

import shutil
from concurrent.futures import ThreadPoolExecutor
from statistics import mean

import pytest

from tool_requirements import require_tool
from ltl_cases import WITHOUT_EQUIVALENCES, dwyer_patterns, random_formulas
from rapidmc.ltl import parse_formula, to_text
from rapidmc.ltl.lasso import accepts_lasso
from rapidmc.ltl.spin import cross_check, spin_translate
from rapidmc.ltl.translate import translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

SPIN = shutil.which("spin")
TIMEOUT = 3.0          # SPIN can blow up on <-> / xor nests; such formulas are skipped
MAX_SKIPPED_SHARE = 0.05


def _require_spin() -> None:
    require_tool(SPIN is not None, "RAPIDMC_REQUIRE_SPIN",
                 "spin is not installed (Debian package 'spin')")


@pytest.fixture(autouse=True)
def spin_present():
    _require_spin()


@pytest.mark.parametrize("text, word, accepted", [
    ("p", ([], [{"p"}]), True),
    ("p", ([], [set()]), False),
    ("F p", ([set(), {"p"}], [set()]), True),
    ("G F p", ([], [{"p"}, set()]), True),
    ("F G p", ([], [{"p"}, set()]), False),
])
def test_spin_claim_accepts_the_formula_itself(text, word, accepted):
    automaton = spin_translate(parse_formula(text), ("p",), TIMEOUT, SPIN)
    assert accepts_lasso(automaton, *word) is accepted


PATTERN_TIMEOUT = 60.0  # SPIN needs ~8 s for "response after q until r"


def _check_all(formulas, atoms, timeout=TIMEOUT):
    with ThreadPoolExecutor(max_workers=4) as pool:
        return list(pool.map(lambda f: cross_check(f, translate, atoms, timeout, SPIN), formulas))


def _assert_agreement(results, report_name, max_skipped_share=MAX_SKIPPED_SHARE):
    failures = [f"{to_text(r.formula)}: {r.detail}" for r in results if r.agrees is False]
    skipped = [r for r in results if r.agrees is None]
    checked = [r for r in results if r.agrees is not None]
    print(f"\n{report_name}: {len(checked)} checked, {len(skipped)} skipped (spin timeout); "
          f"states ours mean {mean(r.our_states for r in checked):.2f} max "
          f"{max(r.our_states for r in checked)}, spin mean "
          f"{mean(r.spin_states for r in checked):.2f} max {max(r.spin_states for r in checked)}")
    assert not failures, "\n".join(failures[:20])
    assert len(skipped) <= max_skipped_share * len(results), f"spin timeouts: {len(skipped)}"


def test_random_formulas_agree_with_spin():
    atoms3, atoms4 = ("a", "b", "c"), ("a", "b", "c", "d")
    # SPIN blows up on <-> / xor nests, so most formulas leave them out and a
    # smaller batch keeps them, in small formulas.
    results = (
        _check_all(random_formulas(11, 550, atoms3, False, 6, WITHOUT_EQUIVALENCES), atoms3)
        + _check_all(random_formulas(12, 450, atoms4, False, 6, WITHOUT_EQUIVALENCES), atoms4)
        + _check_all(random_formulas(13, 200, atoms3, False, max_size=4), atoms3))
    assert len(results) >= 1000
    _assert_agreement(results, "random X-free formulas")


def test_dwyer_patterns_agree_with_spin():
    atoms = ("p", "q", "r", "s")
    formulas = [parse_formula(text) for _, text in dwyer_patterns()]
    assert len(formulas) == 25
    _assert_agreement(_check_all(formulas, atoms, PATTERN_TIMEOUT), "Dwyer patterns",
                      max_skipped_share=0)
