"""Positions and error order of the one-pass front end (AST built while parsing).

Spans come from the tokens: a node runs from the first token of its text to
the last.  A parenthesised operand belongs to the text of the operation
around it, while the expression inside keeps its own span.  Lexical problems
found while building nodes (bad strings, long names) are reported only
after the whole file has parsed, so a syntax error anywhere wins.
"""
from __future__ import annotations

import pytest

from rapidmc.diagnostics import UserError
from rapidmc.syntax import parse_text

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def value_of(expression: str):
    text = f"MODULE t\nPROC p()\nx := {expression};\nENDPROC\nENDMODULE\n"
    return parse_text(text, "t.mod")[0].routines[0].body[0].value


def columns(node) -> tuple[int, int]:
    """Start and end column of a node on line 3 (the text starts at column 6)."""
    assert node.span.line == node.span.end_line == 3
    return node.span.column - 5, node.span.end_column - 5


@pytest.mark.parametrize("expression, path, expected", [
    ("(a + b) * c", "", (1, 12)),            # the product starts at its parenthesis
    ("(a + b) * c", "left", (2, 7)),         # the sum inside keeps its own span
    ("c * (a + b)", "", (1, 12)),            # ... and ends after the closing one
    ("((a)) + 1", "", (1, 10)),
    ("((a)) + 1", "left", (3, 4)),
    ("(p).x", "", (1, 6)),
    ("(p){1}", "", (1, 7)),
    ("-a * b", "", (1, 7)),
    ("NOT a AND b", "operand", (5, 12)),
])
def test_spans_cover_the_text_of_each_node(expression, path, expected):
    node = value_of(expression)
    for step in filter(None, path.split(".")):
        node = getattr(node, step)
    assert columns(node) == expected


def test_statement_span_runs_from_first_to_last_token():
    text = "MODULE t\nPROC p()\n  IF a THEN\n    x := 1;\n  ENDIF\nENDPROC\nENDMODULE\n"
    statement = parse_text(text, "t.mod")[0].routines[0].body[0]
    span = statement.span
    assert (span.line, span.column, span.end_line, span.end_column) == (3, 3, 5, 8)


def first_code(text: str) -> str:
    with pytest.raises(UserError) as failure:
        parse_text(text, "e.mod")
    return failure.value.diagnostics[0].code.code


def test_syntax_error_later_in_the_file_wins_over_a_bad_string_before_it():
    text = 'MODULE m\nPROC p()\nx := "bad \\q";\ny := ;\nENDPROC\nENDMODULE\n'
    assert first_code(text) == "RMC101"


def test_first_lexical_problem_in_the_text_is_reported():
    long_name = "n" * 40
    text = f'MODULE m\nPROC p()\nx := "bad \\q";\n{long_name} := 1;\nENDPROC\nENDMODULE\n'
    with pytest.raises(UserError) as failure:
        parse_text(text, "e.mod")
    diagnostic = failure.value.diagnostics[0]
    assert (diagnostic.code.code, diagnostic.span.line) == ("RMC103", 3)


@pytest.mark.parametrize("text, expected", [
    # A keyword where only a name fits is read as a name, then refused as one.
    ("MODULE m\nVAR num if := 1;\nENDMODULE\n", "'if' is a reserved word"),
    # A keyword where neither it nor a name fits is reported as that keyword.
    ("MODULE m\nPROC p()\nIF a THEN\nx := 1;\nENDPROC\nENDMODULE\n",
     "unexpected 'ENDPROC'; expected one of: ELSE, ELSEIF, ENDIF"),
    # '<EXP>' after an operand cannot be a placeholder.
    ("MODULE m\nPROC p()\nx := a <EXP>;\nENDPROC\nENDMODULE\n", "placeholder <EXP>"),
    # ':=' where only ':' fits is read as ':' and '='.
    ("MODULE m\nPROC p()\nTEST a\nCASE 1:= x := 1;\nENDTEST\nENDPROC\nENDMODULE\n",
     "unexpected '='"),  # read as ':' then '='
])
def test_tokens_depend_on_what_the_parser_accepts(text, expected):
    with pytest.raises(UserError) as failure:
        parse_text(text, "e.mod")
    assert expected in failure.value.diagnostics[0].message


def test_placeholder_is_an_expression_where_one_fits():
    assert value_of("<EXP>").kind == "EXP"


def test_no_token_spans_lines():
    """The lowering reads a token's line as its ``end_line`` (``lower.Lowering``): that
    holds while no terminal of the grammar, ignored text apart, takes a line break."""
    import re

    from rapidmc.syntax.parser import rapid_parser
    conf = rapid_parser().parser.lexer_conf
    samples = ["\n", "a\nb", "A\nB", '"a\nb"', '"\n"', "1\n2", "<\n>", "<EXP\n>", ":\n=", "!\n"]
    for terminal in conf.terminals:
        if terminal.name not in conf.ignore:
            pattern = re.compile(terminal.pattern.to_regexp())
            assert not [text for text in samples if pattern.fullmatch(text)], terminal.name


def test_spans_of_tokens_after_line_breaks_count_lines():
    text = "MODULE t\nPROC p()\n\n  x :=\n    a +\n  1;\nENDPROC\nENDMODULE\n"
    statement = parse_text(text, "t.mod")[0].routines[0].body[0]
    assert (statement.span.line, statement.span.end_line) == (4, 6)
    assert (statement.target.span.line, statement.value.left.span.line) == (4, 5)
    assert statement.value.right.span.line == statement.value.right.span.end_line == 6
