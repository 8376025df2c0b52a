"""RAPID is case-insensitive: keyword spelling never changes the tree (property test)."""
from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
import pytest

from rapidmc.syntax import parse_text
from rapidmc.syntax.sexpr import sexpr

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

KEYWORD_OPERATORS = ["AND", "OR", "XOR", "DIV", "MOD"]
SYMBOL_OPERATORS = ["+", "-", "*", "/", "<", "<=", "=", ">", ">=", "<>"]

atoms = st.sampled_from(["a", "b", "x1", "1", "2.5", "0xFF", "TRUE", "FALSE", '"s"', "p.x",
                         "arr{1, i}", "f(a \\Opt:=2)"])


def combine(children):
    binary = st.tuples(children, st.sampled_from(KEYWORD_OPERATORS + SYMBOL_OPERATORS), children)
    return st.one_of(
        binary.map(lambda t: f"{t[0]} {t[1]} {t[2]}"),
        children.map(lambda e: f"({e})"),
        children.map(lambda e: f"NOT {e}"),
        children.map(lambda e: f"-{e}"),
    )


# Relations are not associative, so some generated texts are not RAPID; every
# generated text is wrapped in parentheses at each level to keep it valid.
expressions = st.recursive(atoms, lambda children: combine(children.map(lambda e: f"({e})")),
                           max_leaves=12)

KEYWORDS = ["AND", "OR", "XOR", "DIV", "MOD", "NOT", "TRUE", "FALSE", "MODULE", "PROC", "ENDPROC",
            "ENDMODULE"]


def respell(text: str, choices: list[bool]) -> str:
    """``text`` with each keyword's letters upper- or lower-cased by ``choices``."""
    words = text.replace("(", " ( ").replace(")", " ) ").split(" ")
    result = []
    for number, word in enumerate(words):
        if word.upper() in KEYWORDS:
            flags = [choices[(number + k) % len(choices)] for k in range(len(word))]
            word = "".join(c.upper() if up else c.lower() for c, up in zip(word, flags))
        result.append(word)
    return " ".join(result)


def tree(expression: str) -> str:
    text = f"MODULE t PROC p() value := {expression}; ENDPROC ENDMODULE"
    return sexpr(parse_text(text, "case.mod")[0].routines[0].body[0].value)


@settings(max_examples=150, deadline=None)
@given(expressions, st.lists(st.booleans(), min_size=1, max_size=8))
def test_keyword_case_does_not_change_the_tree(expression, choices):
    assert tree(respell(expression, choices)) == tree(expression)


def test_identifiers_share_a_key_whatever_their_case():
    text = "module M proc Main() MoveL p10, V100 \\wobj:=WObj0; endproc endmodule"
    call = parse_text(text, "case.mod")[0].routines[0].body[0]
    assert call.name.key == "MOVEL" and call.args[-1].name.key == "WOBJ"
    assert call.args[-1].value.name.text == "WObj0"
