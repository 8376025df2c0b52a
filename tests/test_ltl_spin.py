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
from ltl_cases import BINARY, WITHOUT_EQUIVALENCES, dwyer_patterns, random_formulas
from rapidmc.ltl import parse_formula, to_text
from rapidmc.ltl.lasso import accepts_lasso
from rapidmc.ltl.spin import cross_check, spin_translate
from rapidmc.ltl.translate import translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

SPIN = shutil.which("spin")
# SPIN blows up on some W / M / <-> / xor nests; a formula whose translation needs more than
# CPU_SECONDS of SPIN's CPU time is skipped.  A CPU limit, unlike a wall-clock one, skips the
# same formulas however busy the machine is (under a wall-clock limit a loaded machine skipped
# formulas SPIN translates in half a second).
CPU_SECONDS = 1
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
    automaton = spin_translate(parse_formula(text), ("p",), _backstop(CPU_SECONDS), SPIN,
                               CPU_SECONDS)
    assert accepts_lasso(automaton, *word) is accepted


PATTERN_CPU_SECONDS = 60  # SPIN needs ~8 s for "response after q until r"


def _check_all(formulas, atoms, cpu_seconds=CPU_SECONDS):
    def check(formula):
        return cross_check(formula, translate, atoms, _backstop(cpu_seconds), SPIN, cpu_seconds)
    with ThreadPoolExecutor(max_workers=4) as pool:
        return list(pool.map(check, formulas))


def _backstop(cpu_seconds: int) -> float:
    """The wall-clock limit: far beyond the CPU limit, for a SPIN that hangs."""
    return 30.0 + 10 * cpu_seconds


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


ATOMS3, ATOMS4 = ("a", "b", "c"), ("a", "b", "c", "d")
# (seed, count, atoms, binary operators, largest size).  SPIN blows up on <-> / xor nests, so
# most formulas leave them out and a smaller set keeps them, in small formulas.  One test per
# set, so that pytest-xdist spreads them over its workers.
RANDOM_SETS = {
    "3 atoms": (11, 550, ATOMS3, WITHOUT_EQUIVALENCES, 6),
    "4 atoms": (12, 450, ATOMS4, WITHOUT_EQUIVALENCES, 6),
    "small, with <-> and xor": (13, 200, ATOMS3, BINARY, 4),
}


@pytest.mark.parametrize("name", RANDOM_SETS)
def test_random_formulas_agree_with_spin(name):
    seed, count, atoms, binary, max_size = RANDOM_SETS[name]
    results = _check_all(random_formulas(seed, count, atoms, False, max_size, binary), atoms)
    assert len(results) == count
    _assert_agreement(results, f"random X-free formulas, {name}")


def test_dwyer_patterns_agree_with_spin():
    atoms = ("p", "q", "r", "s")
    formulas = [parse_formula(text) for _, text in dwyer_patterns()]
    assert len(formulas) == 25
    _assert_agreement(_check_all(formulas, atoms, PATTERN_CPU_SECONDS), "Dwyer patterns",
                      max_skipped_share=0)


# SPIN needs over 2.7 CPU seconds for this formula and for its negation
SPIN_BLOWS_UP = "G F (b W b R F b) M b"


def test_a_translation_beyond_the_cpu_limit_is_a_skip():
    result = cross_check(parse_formula(SPIN_BLOWS_UP), translate, ATOMS3,
                         _backstop(CPU_SECONDS), SPIN, CPU_SECONDS)
    assert result.agrees is None and result.detail == "spin timed out"
