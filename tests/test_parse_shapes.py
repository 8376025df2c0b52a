"""Tree shapes of expressions and statements, from data files.

Each line of tests/syntax/expressions.txt and statements.txt is
``RAPID text => tree`` in the notation of ``rapidmc.syntax.sexpr``; a case
fails when the parser builds a different tree (precedence, associativity,
argument kinds, statement forms).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.syntax import parse_text
from rapidmc.syntax.sexpr import sexpr

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DATA = Path(__file__).parent / "syntax"


def cases(filename: str) -> list:
    result = []
    for number, line in enumerate((DATA / filename).read_text("latin-1").splitlines(), 1):
        if not line.strip() or line.startswith("#"):
            continue
        source, expected = (part.strip() for part in line.split("=>"))
        result.append(pytest.param(source, expected, id=f"{filename}:{number}"))
    return result


def parse_expression(text: str):
    module = parse_text(f"MODULE t\nPROC p()\nvalue := {text};\nENDPROC\nENDMODULE\n", "t.mod")[0]
    return module.routines[0].body[0].value


def parse_statement(text: str):
    module = parse_text(f"MODULE t\nPROC p()\n{text}\nENDPROC\nENDMODULE\n", "t.mod")[0]
    (statement,) = module.routines[0].body
    return statement


@pytest.mark.parametrize("source, expected", cases("expressions.txt"))
def test_expression_tree(source, expected):
    assert sexpr(parse_expression(source)) == expected


@pytest.mark.parametrize("source, expected", cases("statements.txt"))
def test_statement_tree(source, expected):
    assert sexpr(parse_statement(source)) == expected
