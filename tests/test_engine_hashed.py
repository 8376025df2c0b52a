"""Hashed searches (--compact, --bitstate): violations found are real, "holds" is never said."""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest

from rapidmc.check import HOLDS, UNKNOWN, VIOLATED, check_property, find_reachable
from rapidmc.check.hashed import BITSTATE, COMPACT
from rapidmc.cli import main
from rapidmc.ltl import parse_formula, to_buchi

ROOT = Path(__file__).resolve().parent.parent


class Counter:
    """x counts 0..size-1 and wraps; atom "zero" holds at 0, "top" at size-1."""

    def __init__(self, size: int):
        self.size = size

    def initial_states(self):
        return (0,)

    def successors(self, state):
        return (("inc", (state + 1) % self.size), ("stay", state))


def valuation_for(buchi, size: int):
    tests = {"zero": lambda s: s == 0, "top": lambda s: s == size - 1}
    return lambda s: sum(1 << i for i, atom in enumerate(buchi.atoms) if tests[atom](s))


STORAGES = [(COMPACT,), (BITSTATE, 1 << 16)]


@pytest.mark.parametrize("storage", STORAGES, ids=["compact", "bitstate"])
def test_a_property_that_holds_is_only_probably_holding(storage):
    buchi = to_buchi(parse_formula("!(G (top -> X (top | zero)))"))
    exact = check_property(Counter(500), buchi, valuation_for(buchi, 500))
    hashed = check_property(Counter(500), buchi, valuation_for(buchi, 500), storage=storage)
    assert exact.verdict == HOLDS
    assert hashed.verdict == UNKNOWN and "probably holds" in hashed.reason


@pytest.mark.parametrize("storage", STORAGES, ids=["compact", "bitstate"])
def test_violations_are_found_with_a_real_lasso(storage):
    model = Counter(50)
    buchi = to_buchi(parse_formula("!(G F top)"))     # violated: stay forever
    result = check_property(model, buchi, valuation_for(buchi, 50), storage=storage)
    assert result.verdict == VIOLATED
    steps = result.prefix + result.cycle
    for before, after in zip(steps, steps[1:]):
        assert (after.label, after.state) in model.successors(before.state)
    assert (result.closing_label, result.cycle[0].state) in model.successors(steps[-1].state)


@pytest.mark.parametrize("storage", STORAGES, ids=["compact", "bitstate"])
def test_reachability_path_is_a_real_path(storage):
    model = Counter(300)
    result = find_reachable(model, lambda s: s == 299, storage=storage)
    assert result.verdict == VIOLATED and result.prefix[-1].state == 299
    for before, after in zip(result.prefix, result.prefix[1:]):
        assert (after.label, after.state) in model.successors(before.state)


def test_a_tiny_bit_array_misses_states():
    result = find_reachable(Counter(5000), lambda s: False, storage=(BITSTATE, 64))
    assert result.verdict == UNKNOWN and result.stats.product_states < 5000


@pytest.mark.parametrize("flags", [["--compact"], ["--bitstate", "1MB"]])
def test_command_exits_3_and_says_probably(flags):
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        code = main(["check", str(ROOT / "tests/check/loop_mod_counter/prog.mod"),
                     "--formula", 'P: G "x < 3"', "--quiet", *flags])
    assert code == 3
    assert "HOLDS" not in out.getvalue() and "probably holds" in out.getvalue()
