"""rapidmc.report.indented_json writes what ``json.dumps(indent=N, ensure_ascii=False)`` writes."""
from __future__ import annotations

import json
import math
from enum import IntEnum

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from cli_capture import run_cli
from rapidmc.report.indented_json import dumps

SCALARS = (st.none() | st.booleans() | st.integers() | st.floats(allow_nan=True)
           | st.text())
KEYS = st.text() | st.integers() | st.floats() | st.booleans() | st.none()
DOCUMENTS = st.recursive(
    SCALARS, lambda inner: st.lists(inner, max_size=4) | st.tuples(inner, inner)
    | st.dictionaries(KEYS, inner, max_size=4), max_leaves=30)


def standard(value, indent: int) -> str:
    return json.dumps(value, indent=indent, ensure_ascii=False)


# 300 documents: each has up to 30 leaves of every JSON type, nested lists, tuples and
# dicts, empty ones too; more finds nothing new in a 40-line writer
@pytest.mark.engine_independent
@settings(max_examples=300, deadline=None)
@given(DOCUMENTS, st.sampled_from([1, 2, 4]))
def test_generated_documents_give_the_standard_text(value, indent):
    assert dumps(value, indent) == standard(value, indent)


class Level(IntEnum):
    LOW = 1


@pytest.mark.engine_independent
@pytest.mark.parametrize("value", [
    "snow ❄ and \"quotes\" \\ \n\t\x01", -0.0, math.inf, -math.inf, 1e300, 2 ** 70, Level.LOW,
    {Level.LOW: [True, None]}, {1.5: {}}, {"a": []}, [], {}, (), [[[]]]])
def test_edge_values_give_the_standard_text(value):
    assert dumps(value, 2) == standard(value, 2)


@pytest.mark.engine_independent
@pytest.mark.parametrize("value", [{1, 2}, {"a": object()}, {(1, 2): 3}])
def test_values_the_encoder_refuses_raise_type_error(value):
    with pytest.raises(TypeError):
        standard(value, 2)
    with pytest.raises(TypeError):
        dumps(value, 2)


PROGRAM = "tests/check/vm_fallback_mix/prog.mod"


# a check's reports consult the engine (tests/conftest.py): they run in both runs of .ci/run
@pytest.mark.parametrize("argv", [
    ["check", PROGRAM, "--ltl", "tests/check/vm_fallback_mix/props.ltl", "--format", "json"],
    ["check", PROGRAM, "--format", "sarif"],
    ["check", PROGRAM, "--format", "codeclimate"],
], ids=["check-json", "check-sarif", "check-codeclimate"])
def test_check_reports_are_the_standard_text_of_their_documents(argv):
    assert_standard(argv)


@pytest.mark.engine_independent
@pytest.mark.parametrize("argv", [["lint", PROGRAM, "--format", "json"],
                                  ["lint", PROGRAM, "--format", "sarif"]],
                         ids=["lint-json", "lint-sarif"])
def test_lint_reports_are_the_standard_text_of_their_documents(argv):
    assert_standard(argv)


def assert_standard(argv: list[str]) -> None:
    code, out, err = run_cli(argv + (["--quiet"] if argv[0] == "check" else []))
    assert code in (0, 1), err
    second = out.split("\n")[1]
    indent = len(second) - len(second.lstrip(" "))
    # (the command ends the document with a line break, and ``check`` prints one more)
    assert out.rstrip("\n") == standard(json.loads(out), indent)
