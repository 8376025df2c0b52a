"""Whole programs parse, and their declarations come out as the AST promises.

Every file in tests/syntax/good/ and case_studies/ must parse; the
palletizer program (tests/syntax/good/palletizer.mod) is then inspected for
the constructs the statement tests cannot show: module attributes, scopes,
parameters, handlers and spans.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc import ast
from rapidmc.syntax import parse_file, parse_text
from rapidmc.syntax.sexpr import sexpr

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
GOOD = ROOT / "tests" / "syntax" / "good"
PROGRAMS = sorted(GOOD.glob("*.mod")) + sorted((ROOT / "case_studies").rglob("*.mod"))


@pytest.mark.parametrize("path", [pytest.param(p, id=str(p.relative_to(ROOT))) for p in PROGRAMS])
def test_program_parses(path):
    modules = parse_file(str(path))
    assert modules and all(isinstance(m, ast.Module) for m in modules)


def assignments(statements):
    """Every assignment in ``statements``, nested blocks included."""
    for statement in statements:
        if isinstance(statement, ast.Assignment):
            yield statement
        for block in ("body", "else_body", "default"):
            yield from assignments(getattr(statement, block, None) or ())
        for branch in getattr(statement, "branches", ()):
            yield from assignments(branch.body)


@pytest.mark.parametrize("program", ["sorter_a", "sorter_b", "sorter_c"])
def test_sorter_flag_2_reads_not_over_the_rest_of_the_expression(program):
    """The paper's property P2 depends on this reading (reference 2.7)."""
    path = ROOT / "case_studies" / "sorter" / f"{program}.mod"
    (module,) = parse_file(str(path))
    flags = [a for r in module.routines for a in assignments(r.body)
             if isinstance(a.target, ast.NameRef) and a.target.name.key == "FLAG_2"]
    assert [sexpr(a.value) for a in flags] == [
        "(AND (= c_in 0) (NOT (AND (= s1 1) (= s2 1))))"]


@pytest.fixture(scope="module")
def palletizer() -> ast.Module:
    (module,) = parse_file(str(GOOD / "palletizer.mod"))
    return module


def routine(module: ast.Module, name: str) -> ast.Routine:
    return next(r for r in module.routines if r.name.key == name.upper())


def data(module: ast.Module, name: str) -> ast.DataDeclaration:
    return next(d for d in module.data if d.name.key == name.upper())


def test_module_attributes_upper_case(palletizer):
    assert palletizer.attributes == ("SYSMODULE", "NOVIEW")


def test_local_record_and_alias(palletizer):
    record, alias = palletizer.types
    assert isinstance(record, ast.RecordDefinition) and record.local
    assert [(c.type.name.key, c.name.text) for c in record.components] == [
        ("NUM", "rows"), ("NUM", "cols"), ("POS", "pitch")]
    assert isinstance(alias, ast.AliasDefinition) and alias.local
    assert (alias.base.name.key, alias.name.text) == ("NUM", "counter")


@pytest.mark.parametrize("name, storage, scope, dims", [
    ("tGripper", "PERS", "GLOBAL", 0),
    ("wPallet", "PERS", "LOCAL", 0),
    ("nLayerDone", "PERS", "TASK", 0),
    ("lyStd", "CONST", "LOCAL", 0),
    ("pStack", "VAR", "GLOBAL", 2),
    ("grid", "CONST", "GLOBAL", 3),
    ("nCount", "VAR", "GLOBAL", 0),
    ("quat", "PERS", "GLOBAL", 1),
])
def test_data_declaration_storage_scope_and_rank(palletizer, name, storage, scope, dims):
    declaration = data(palletizer, name)
    assert (declaration.storage, declaration.scope, len(declaration.dims)) == (storage, scope, dims)


def test_multi_line_aggregate_initialiser(palletizer):
    init = data(palletizer, "wPallet").init
    assert isinstance(init, ast.Aggregate) and len(init.items) == 5
    assert (init.span.line, init.span.end_line) == (16, 18)


def test_integer_literals_stay_exact_and_others_are_float(palletizer):
    assert data(palletizer, "MASK").init.value == 255
    assert isinstance(data(palletizer, "MASK").init.value, int)
    assert data(palletizer, "lyStd").init.items[2].items[2].value == 180.0


def test_latin1_identifier(palletizer):
    assert data(palletizer, "größe").name.key == "GRÖSSE"


def test_parameters_modes_optional_and_alternative_groups(palletizer):
    parameters = routine(palletizer, "PlaceOne").parameters
    assert [(p.name.text, p.mode, p.optional, p.alternative_group, p.type.name.key)
            for p in parameters] == [
        ("r", "IN", False, None, "NUM"),
        ("c", "IN", False, None, "NUM"),
        ("Slow", "IN", True, 1, "SWITCH"),
        ("Fast", "IN", True, 1, "SWITCH"),
        ("Result", "VAR", True, None, "NUM"),
    ]


def test_array_parameters_inout_and_pers(palletizer):
    parameters = routine(palletizer, "Sum").parameters
    assert [(p.mode, p.array_rank) for p in parameters] == [
        ("IN", 1), ("IN", 2), ("INOUT", 0), ("PERS", 0)]


def test_routine_sections(palletizer):
    place = routine(palletizer, "PlaceOne")
    assert place.local and place.kind == ast.PROC
    assert len(place.data) == 1 and len(place.body) == 5
    assert len(place.backward) == 1 and len(place.undo) == 1
    assert [sexpr(n) for n in place.error.numbers] == ["ERR_PATH_STOP", "42"]
    assert place.end_span.line == place.span.end_line
    trap = routine(palletizer, "StopTrap")
    assert trap.kind == ast.TRAP and trap.error.numbers[0].name.key == "LONG_JMP_ALL_ERR"
    function = routine(palletizer, "Sum")
    assert function.kind == ast.FUNC and function.return_type.name.key == "NUM"
    assert function.error.numbers is None


def test_spans_cover_the_construct():
    text = "MODULE m\n  PROC main()\n    IF a THEN\n      x := 1;\n    ENDIF\n  ENDPROC\nENDMODULE\n"
    (module,) = parse_text(text, "span.mod")
    statement = module.routines[0].body[0]
    assert statement.span == ast.Span("span.mod", 3, 5, 5, 10)
    assignment = statement.branches[0].body[0]
    assert (assignment.span.line, assignment.span.column, assignment.span.end_column) == (4, 7, 14)
    assert module.span == ast.Span("span.mod", 1, 1, 7, 10)


def test_declarations_interleaved_with_statements_are_collected():
    text = "MODULE m\nPROC main()\nVAR num a;\nStop;\nVAR num b := 2;\nStop;\nENDPROC\nENDMODULE\n"
    main_routine = parse_text(text, "m.mod")[0].routines[0]
    assert [d.name.text for d in main_routine.data] == ["a", "b"]
    assert len(main_routine.body) == 2


def test_module_items_in_any_order():
    text = ("MODULE m\nPROC main()\nENDPROC\nVAR num late;\nRECORD r\nnum x;\nENDRECORD\n"
            "CONST num c := 1;\nENDMODULE\n")
    (module,) = parse_text(text, "m.mod")
    assert [d.name.text for d in module.data] == ["late", "c"]
    assert [t.name.text for t in module.types] == ["r"]
