"""Syntax and lexical errors: each file in tests/syntax/bad/ must fail with a diagnostic.

The first line of a bad file says what to expect: ``! expect: RMC101 line 7``.
A case fails when parsing succeeds, raises something other than a
``UserError``, or reports another code or line.
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from rapidmc.diagnostics import UserError, render
from rapidmc.syntax import parse_file, parse_text

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

BAD = Path(__file__).parent / "syntax" / "bad"
EXPECT = re.compile(r"! expect: (RMC\d{3}) line (\d+)")


def bad_files() -> list:
    return [pytest.param(path, id=path.name) for path in sorted(BAD.glob("*.mod"))]


def first_diagnostic(path: Path):
    with pytest.raises(UserError) as failure:
        parse_file(str(path))
    return failure.value.diagnostics[0]


@pytest.mark.parametrize("path", bad_files())
def test_bad_file_reports_expected_code_and_line(path):
    code, line = EXPECT.match(path.read_text("latin-1")).groups()
    diagnostic = first_diagnostic(path)
    assert (diagnostic.code.code, diagnostic.span.line) == (code, int(line)), render(diagnostic)


def test_syntax_error_renders_position_readable_tokens_source_and_caret():
    path = BAD / "missing_semicolon.mod"
    assert render(first_diagnostic(path)).splitlines() == [
        f"{path}:5:5: error: unexpected 'y'; expected one of: ';' [RMC101]",
        "        y := 2;",
        "        ^",
    ]


def test_expected_tokens_are_named_as_written_not_as_lark_terminals():
    with pytest.raises(UserError) as failure:
        parse_text("MODULE m\nPROC main()\nIF a THEN\nx := 1;\nENDPROC\nENDMODULE\n", "e.mod")
    message = failure.value.diagnostics[0].message
    assert message == "unexpected 'ENDPROC'; expected one of: ELSE, ELSEIF, ENDIF"


def test_punctuation_and_token_classes_are_named_readably():
    with pytest.raises(UserError) as failure:
        parse_text("MODULE m\nPROC main()\nx := ;\nENDPROC\nENDMODULE\n", "e.mod")
    message = failure.value.diagnostics[0].message
    assert message.startswith("unexpected ';'; expected one of: '('")
    for readable in ("'-'", "'['", "identifier", "number", "string", "NOT", "TRUE"):
        assert readable in message
    for lark_name in ("LPAR", "LSQB", "NAME", "NUMBER", "MINUS"):
        assert lark_name not in message


def test_end_of_file_points_after_the_last_line():
    with pytest.raises(UserError) as failure:
        parse_text("MODULE m\n  PROC main()\n", "eof.mod")
    diagnostic = failure.value.diagnostics[0]
    assert (diagnostic.code.code, diagnostic.span.line) == ("RMC107", 2)
    assert "ENDPROC" in diagnostic.message


def test_placeholder_message_names_what_is_missing():
    diagnostic = first_diagnostic(BAD / "placeholder_declaration.mod")
    assert "<ID>" in diagnostic.message and "an identifier" in diagnostic.message


def message_cases() -> list:
    path = BAD.parent / "error_messages.txt"
    result = []
    for number, line in enumerate(path.read_text("latin-1").splitlines(), 1):
        if line.strip() and not line.startswith("#"):
            statement, expected = (part.strip() for part in line.split("=>"))
            column, message = expected.split(": ", 1)
            result.append(pytest.param(statement, int(column), message, id=f"line {number}"))
    return result


@pytest.mark.parametrize("statement, column, message", message_cases())
def test_error_message_names_the_tokens_the_parser_state_accepts(statement, column, message):
    with pytest.raises(UserError) as failure:
        parse_text(f"MODULE m\nPROC p()\n{statement}\nENDPROC\nENDMODULE\n", "e.mod")
    diagnostic = failure.value.diagnostics[0]
    span = diagnostic.span
    assert (span.line, span.column, diagnostic.message) == (3, column, message)
