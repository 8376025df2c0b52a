"""LTL parser and printers: precedence, spellings, round trips, error positions."""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from ltl_cases import random_formula
from rapidmc.diagnostics import LTL_SYNTAX, UserError
from rapidmc.ltl import parse_formula, to_spin, to_text
from rapidmc.ltl.syntax import (And, Atom, Finally, Globally, Next, Not, Or, Until, atoms_of)

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DATA = Path(__file__).parent / "ltl"


def _data_lines(name: str, separator: str, fields: int) -> list[list[str]]:
    """Rows of a data file; fields split at the last ``fields - 1`` separators."""
    rows = []
    for line in (DATA / name).read_text().splitlines():
        if not line.startswith("#") and separator in line:
            rows.append([part.strip() for part in line.rsplit(separator, fields - 1)])
    return rows


@pytest.mark.parametrize("written, grouped", _data_lines("parse_cases.txt", "==", 2))
def test_parse_groups_like_spot(written, grouped):
    assert parse_formula(written) == parse_formula(grouped)


def test_grouped_forms_are_not_all_equal():
    # Guards against a parser that ignores structure: the grouping matters.
    assert parse_formula("a -> b -> c") != parse_formula("(a -> b) -> c")
    assert parse_formula("a U b U c") != parse_formula("(a U b) U c")
    assert parse_formula("a & b | c") == Or(And(Atom("a"), Atom("b")), Atom("c"))


def test_quoted_atom_kept_verbatim():
    formula = parse_formula('G(!"c_in = 0 AND s1 = 1" -> F "x\\"y")')
    assert atoms_of(formula) == ("c_in = 0 AND s1 = 1", 'x"y')


@pytest.mark.parametrize("text, column, message", _data_lines("parse_errors.txt", "|", 3))
def test_errors_point_at_the_offending_token(text, column, message):
    with pytest.raises(UserError) as caught:
        parse_formula(text)
    diagnostic = caught.value.diagnostics[0]
    assert diagnostic.code is LTL_SYNTAX
    assert diagnostic.span.column == int(column)
    assert message in diagnostic.message


def test_error_span_is_relative_to_the_property_file():
    with pytest.raises(UserError) as caught:
        parse_formula("G (a | )", file="door.prop", line=7, column=12)
    span = caught.value.diagnostics[0].span
    assert (span.file, span.line, span.column) == ("door.prop", 7, 12 + 7)


def test_to_text_round_trips_on_random_formulas():
    rng = random.Random(3)
    for _ in range(500):
        formula = random_formula(rng, ["a", "b", "x = 1", "G1"], rng.randint(0, 8))
        assert parse_formula(to_text(formula)) == formula, to_text(formula)


@pytest.mark.parametrize("formula, minimal", [
    (Until(Atom("a"), Until(Atom("b"), Atom("c"))), "a U b U c"),
    (Until(Until(Atom("a"), Atom("b")), Atom("c")), "(a U b) U c"),
    (Not(And(Atom("a"), Atom("b"))), "!(a & b)"),
    (Globally(Finally(Atom("G"))), 'G F "G"'),
    (Next(Atom("x = 1")), 'X "x = 1"'),
])
def test_to_text_uses_minimal_parentheses(formula, minimal):
    assert to_text(formula) == minimal


@pytest.mark.parametrize("text, spin", [
    ("G(a -> F b)", "[]((p0 -> <>(p1)))"),
    ("a R b", "(p0 V p1)"),
    ("a W b", "((p0 U p1) || [](p0))"),
    ("a M b", "(p1 U (p0 && p1))"),
    ("a xor b", "!((p0 <-> p1))"),
    ('!"x = 1" | true & false', "(!(p0) || (true && false))"),
])
def test_to_spin(text, spin):
    assert to_spin(parse_formula(text)) == spin
