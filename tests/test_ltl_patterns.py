"""Specification patterns (``rapidmc.ltl.patterns``): each pattern x scope means what a
hand-written LTL formula means (tests/ltl/pattern_equivalents.txt), by Spot and by the built-in
translator; malformed patterns are diagnostics."""
from __future__ import annotations

from pathlib import Path

import pytest

from tool_requirements import require_tool
from rapidmc.diagnostics import LTL_SYNTAX, PATTERN, UserError
from rapidmc.ltl import parse_formula, to_text
from rapidmc.ltl.lasso import product_is_empty
from rapidmc.ltl.patterns import (MAPPINGS, PATTERNS, SCOPES, is_pattern, parse_pattern,
                                  pattern_formula)
from rapidmc.ltl.spot_backend import spot_available, to_spot
from rapidmc.ltl.syntax import Not
from rapidmc.ltl.translate import translate

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DATA = Path(__file__).parent / "ltl" / "pattern_equivalents.txt"


def equivalents() -> list[tuple[str, str]]:
    rows = []
    for line in DATA.read_text().splitlines():
        if line.strip() and not line.startswith("#"):
            pattern, formula = (part.strip() for part in line.split("|", 1))
            rows.append((pattern, formula))
    return rows


def test_the_data_covers_every_pattern_and_scope():
    covered = {(p.kind, p.scope) for p in (parse_pattern(text) for text, _ in equivalents())}
    assert covered == set(MAPPINGS) == {(k, s) for k in PATTERNS for s in SCOPES}


@pytest.mark.parametrize("pattern, written", equivalents())
def test_the_builtin_translator_finds_the_pattern_and_the_formula_equivalent(pattern, written):
    ours, theirs = pattern_formula(parse_pattern(pattern)), parse_formula(written)
    assert product_is_empty(translate(ours), translate(Not(theirs))), "a word of the pattern " \
        "violates the hand-written formula"
    assert product_is_empty(translate(Not(ours)), translate(theirs)), "a word of the " \
        "hand-written formula violates the pattern"


@pytest.mark.parametrize("pattern, written", equivalents())
def test_spot_finds_the_pattern_and_the_formula_equivalent(pattern, written):
    require_tool(spot_available(), "RAPIDMC_REQUIRE_SPOT",
                 "Spot's Python bindings are not installed (../shared/spot/install)")
    import spot
    ours, theirs = pattern_formula(parse_pattern(pattern)), parse_formula(written)
    assert spot.are_equivalent(to_spot(ours), to_spot(theirs))


def test_a_wrong_hand_written_formula_is_told_apart():
    """The equivalence checks can fail: before(r) and after_until differ from their
    neighbours' formulas."""
    ours = pattern_formula(parse_pattern("existence(p) between(q, r)"))
    other = pattern_formula(parse_pattern("existence(p) after_until(q, r)"))
    assert not product_is_empty(translate(ours), translate(Not(other)))


def test_conditions_are_any_state_formula_with_quoted_atoms():
    pattern = parse_pattern('response(!C_IN & (S_1 & S_2), "s3 = 1, or (not) 2" | x) '
                            'between(InRoutine, "a = \\"(\\"")')
    assert [to_text(f) for f in pattern.arguments] == ["!C_IN & (S_1 & S_2)",
                                                       '"s3 = 1, or (not) 2" | x']
    assert pattern.scope == "between" and to_text(pattern.bounds[1]) == '"a = \\"(\\""'
    assert str(parse_pattern("Absence( p )  GLOBALLY")) == "absence(p) globally"


def test_only_text_that_starts_with_a_pattern_is_one():
    assert is_pattern("  response (a, b)") and is_pattern("absence(p) before(r)")
    assert not is_pattern("G(a -> F b)") and not is_pattern("response") \
        and not is_pattern('"response(a)"')


@pytest.mark.parametrize("text, code, column, message", [
    ("response(a)", PATTERN, 1, "response takes 2 conditions (P, S), found 1"),
    ("absence(a, b)", PATTERN, 1, "absence takes 1 condition (P), found 2"),
    ("response(a, F b)", PATTERN, 13, "a pattern's conditions hold in one state"),
    ("absence(a) within(q)", PATTERN, 12, "expected one of globally, before"),
    ("absence(a) after(q) extra", PATTERN, 21, "expected a scope"),
    ("absence(a", PATTERN, 8, "expected ')' to close the '('"),
    ("response(a,)", PATTERN, 12, "expected a condition"),
    ("absence(a &)", LTL_SYNTAX, 12, "expected a formula"),
    ("absence(a) between q", PATTERN, 20, "expected '(' after between"),
])
def test_malformed_patterns_are_diagnostics_pointing_into_the_text(text, code, column, message):
    with pytest.raises(UserError) as raised:
        parse_pattern(text, "p.ltl", 3, 5)
    [diagnostic] = raised.value.diagnostics
    assert diagnostic.code is code and message in diagnostic.message
    assert (diagnostic.span.file, diagnostic.span.line, diagnostic.span.column) == \
        ("p.ltl", 3, 4 + column)
