"""Hypothesis: the interpreter evaluates random num and bool expressions like a reference model.

The reference is written independently of the interpreter: num arithmetic
rounds every result to IEEE single precision (struct), relations compare,
AND/OR/XOR/NOT are Python's boolean operators.  Expressions are printed fully
parenthesised, so precedence is the parser's job (tested elsewhere) and this
test pins evaluation.
"""
from __future__ import annotations

import io
import struct

from hypothesis import given, settings, strategies as st
import pytest

from rapidmc import ast
from rapidmc.commands.console import run_program
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def f32(x: float) -> float:
    return struct.unpack("f", struct.pack("f", x))[0]


numbers = st.integers(min_value=-1000, max_value=1000).map(float) | \
    st.sampled_from([0.5, 0.25, 1.5, 0.1, 2.75, 100.125])


def num_expressions():
    return st.recursive(
        numbers.map(lambda v: (repr_num(v), f32(v))),
        lambda inner: st.tuples(inner, st.sampled_from("+-*"), inner).map(combine),
        max_leaves=8)


def repr_num(v: float) -> str:
    text = repr(v)
    return f"({text})" if v < 0 else text


def combine(parts):
    (left_text, left), op, (right_text, right) = parts
    value = {"+": left + right, "-": left - right, "*": left * right}[op]
    return f"({left_text} {op} {right_text})", f32(value)


def bool_expressions():
    leaf = st.tuples(num_expressions(), st.sampled_from(["<", "<=", "=", "<>", ">", ">="]),
                     num_expressions()).map(relation)
    return st.recursive(
        leaf | st.booleans().map(lambda b: ("TRUE" if b else "FALSE", b)),
        lambda inner: st.one_of(
            st.tuples(inner, st.sampled_from(["AND", "OR", "XOR"]), inner).map(logical),
            inner.map(lambda e: (f"(NOT {e[0]})", not e[1]))),
        max_leaves=6)


def relation(parts):
    (left_text, left), op, (right_text, right) = parts
    value = {"<": left < right, "<=": left <= right, "=": left == right,
             "<>": left != right, ">": left > right, ">=": left >= right}[op]
    return f"({left_text} {op} {right_text})", value


def logical(parts):
    (left_text, left), op, (right_text, right) = parts
    value = {"AND": left and right, "OR": left or right, "XOR": left != right}[op]
    return f"({left_text} {op} {right_text})", value


def run(declaration: str, expression: str, show: str) -> str:
    text = (f"MODULE Eval\n  PROC main()\n    {declaration}\n    x := {expression};\n"
            f"    TPWrite {show};\n  ENDPROC\nENDMODULE\n")
    program = build(ast.Program(parse_text(text, "eval.mod")))
    out = io.StringIO()
    run_program(program, {}, io.StringIO(), out)
    return out.getvalue().strip()


@settings(max_examples=150, deadline=None)
@given(num_expressions())
def test_num_expressions_round_every_operation_to_single_precision(case):
    text, expected = case
    shown = run("VAR num x;", text, '"" \\Bool:=(x = expected)'.replace(
        "expected", repr_num(expected) if abs(expected) < 1e30 else "0"))
    assert shown == "TRUE", (text, expected)


@settings(max_examples=150, deadline=None)
@given(bool_expressions())
def test_bool_expressions_evaluate_like_the_reference(case):
    text, expected = case
    shown = run("VAR bool x;", text, '"" \\Bool:=x')
    assert shown == ("TRUE" if expected else "FALSE"), text
