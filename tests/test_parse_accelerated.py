"""The fast path (the scanner and lark_cython's compiled LALR loop) builds the same AST
as Lark's driver with RapidLexer, fails on every text that driver fails on, and errors
are reported from Lark's driver whichever path ran first."""
from __future__ import annotations

import dataclasses
import random
import sys
from pathlib import Path

import pytest

from rapidmc.diagnostics import UserError
from rapidmc.syntax import accelerated, parser
from rapidmc.syntax.tokens import TOKEN_TYPES, CompiledToken

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
PROGRAMS = sorted(path for path in ROOT.glob("**/*.mod")
                  if ".venv" not in path.parts and "site-packages" not in path.parts)

needs_compiled = pytest.mark.skipif(not accelerated.AVAILABLE, reason="lark_cython not installed")


def _outcome(text: str, filename: str, compiled: bool):
    """("ast", modules), ("diagnostics", messages), or the kind and place of a Lark
    syntax error (or of the scanner declining the text)."""
    try:
        return "ast", parser._parse(text, filename, compiled)
    except UserError as problem:
        return "diagnostics", [str(d) for d in problem.diagnostics]
    except Exception as failure:            # a Lark syntax error: its kind and position
        return type(failure).__name__, getattr(failure, "pos_in_stream", None)


def assert_same_parse(text: str, filename: str) -> None:
    """The fast path gives Lark's AST, or fails where Lark's driver fails."""
    lark = _outcome(text, filename, False)
    compiled = _outcome(text, filename, True)
    if lark[0] == "ast":
        assert compiled == lark
        assert _every_field(compiled) == _every_field(lark)   # names' spans too
        # lark_cython's tokens compare equal to strings: none may end up in the AST
        assert not _tokens_in(compiled)
    else:
        assert compiled[0] != "ast", f"the fast path accepts a text Lark's driver rejects: {lark}"


@needs_compiled
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(ROOT)))
def test_compiled_loop_builds_the_same_ast_as_lark(path):
    assert_same_parse(path.read_text(encoding="latin-1"), path.name)


@needs_compiled
@pytest.mark.parametrize("path", PROGRAMS, ids=lambda path: str(path.relative_to(ROOT)))
def test_diagnostics_of_every_program_do_not_depend_on_the_path(path, monkeypatch):
    text = path.read_text(encoding="latin-1")
    fast = _reported(text, path.name)
    monkeypatch.setattr(accelerated, "AVAILABLE", False)
    assert fast == _reported(text, path.name)


def _reported(text: str, filename: str):
    try:
        return parser.parse_modules(text, filename)
    except UserError as problem:
        return [str(d) for d in problem.diagnostics]


def _every_field(value):
    """The value with every field of every node, those equality leaves out included."""
    if dataclasses.is_dataclass(value):
        return (type(value).__name__,
                *(_every_field(getattr(value, f.name)) for f in dataclasses.fields(value)))
    if isinstance(value, (tuple, list)):
        return tuple(_every_field(item) for item in value)
    return value


def _tokens_in(value) -> list:
    if isinstance(value, TOKEN_TYPES):
        return [value]
    if dataclasses.is_dataclass(value):
        return [t for f in dataclasses.fields(value) for t in _tokens_in(getattr(value, f.name))]
    if isinstance(value, (tuple, list)):
        return [t for item in value for t in _tokens_in(item)]
    return []


@needs_compiled
def test_compiled_loop_is_the_one_used_when_installed(monkeypatch):
    used = []
    original = parser._Parsing.compiled

    def compiled(parsing, table):
        loop = original(parsing, table)
        used.append(type(loop))
        return loop
    monkeypatch.setattr(parser._Parsing, "compiled", compiled)
    parser.parse_modules("MODULE m\nPROC p()\n  x := 1;\nENDPROC\nENDMODULE\n", "m.mod")
    assert used == [accelerated.CompiledParser]


ERRONEOUS = [
    "MODULE m\nPROC p()\n  x := ;\n  y := 2 +;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1 $ 2;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  IF := 1;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1;\n",
    "MODULE m\nVAR num " + "a" * 40 + ";\nENDMODULE\n",
]


@pytest.mark.parametrize("text", ERRONEOUS)
def test_diagnostics_do_not_depend_on_lark_cython(text, monkeypatch):
    with pytest.raises(UserError) as compiled_first:
        parser.parse_modules(text, "m.mod")
    monkeypatch.setattr(accelerated, "AVAILABLE", False)
    with pytest.raises(UserError) as lark_only:
        parser.parse_modules(text, "m.mod")
    assert [str(d) for d in compiled_first.value.diagnostics] == \
        [str(d) for d in lark_only.value.diagnostics]
    assert compiled_first.value.diagnostics


# Texts where the scanner's reading could differ from RapidLexer's: keywords in any case
# and as names, placeholders against '<', headers, other line breaks and white space,
# Latin-1 names, characters no token starts with, unterminated strings.
LEXICAL_CORNERS = [
    "module m\nproc p()\n  if A < B then x := -1; endif\nendproc\nendmodule\n",
    "MODULE m\nPROC p()\n  x := a<EXP>;\n  y := a <> b;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  <SMT>\n  x := <EXP>;\nENDPROC\nENDMODULE\n",
    "%%%\n  VERSION:1\n  LANGUAGE:ENGLISH\n%%%\nMODULE m\nENDMODULE\n",
    "MODULE m\r\nPROC p()\r\n  x := 1;\r\nENDPROC\r\nENDMODULE\r\n",
    "MODULE m\rPROC p()\r  x := 1;\rENDPROC\rENDMODULE",
    "MODULE m\n\tPROC p()\f\n\t\tx := 1;  ! done\nENDPROC\nENDMODULE",
    "MODULE m\nVAR num \xe4rger := 1;\nPROC p() \xe4rger := 2; ENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1\xa0+ 2;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  TPWrite \"open;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  Step := 1;\n  x := a AND b;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1.5E3 + .5 + 0x1F + 0b101 + 0o17;\nENDPROC\nENDMODULE\n",
    "MODULE m (SYSMODULE, NOVIEW)\nRECORD r num a; ENDRECORD\nENDMODULE\n",
    "MODULE m\nPROC p(\\switch s | num n, VAR num v{*})\n  q \\s?s;\nENDPROC\nENDMODULE\n",
    "MODULE m\nPROC p()\n  x := 1;\n",
    "",
    "! only a comment\n",
    "MODULE m\nENDMODULE\n  ! a comment after the module\n",
    "MODULE m\nENDMODULE ! c",
    "MODULE m\nENDMODULE\n\n\n",
]


@needs_compiled
@pytest.mark.parametrize("text", LEXICAL_CORNERS)
def test_lexical_corners_parse_the_same_on_both_paths(text, monkeypatch):
    assert_same_parse(text, "m.mod")
    fast = _reported(text, "m.mod")
    monkeypatch.setattr(accelerated, "AVAILABLE", False)
    assert fast == _reported(text, "m.mod")


@needs_compiled
@pytest.mark.parametrize("identifier", ["x\u017f", "\u212aey", "\u0178es", "a\u017fb\u212a"])
def test_identifiers_with_letters_beyond_latin_1_are_left_to_lark(identifier, monkeypatch):
    """Lark's identifier ignores case, so it takes the letters beyond Latin-1 whose other case
    is a letter it allows (long s, the Kelvin sign, Y with diaeresis); the scanner, which
    matches identifiers case-sensitively, declines such a text and Lark's driver reads it."""
    text = f"MODULE m\nPROC p()\n  {identifier} := 1;\nENDPROC\nENDMODULE\n"
    assert parser._scanner().scan(text, CompiledToken) is None
    fast = _reported(text, "m.mod")
    monkeypatch.setattr(accelerated, "AVAILABLE", False)
    assert fast == _reported(text, "m.mod")
    assert fast[0].routines[0].body[0].target.name.text == identifier


MUTANTS = 150


@needs_compiled
def test_mutated_programs_parse_the_same_on_both_paths():
    """Random edits of the repository's RAPID files (tokens deleted, swapped, replaced by
    keywords or literals; lines moved): the fast path gives Lark's AST or fails."""
    from fuzz_mutations import corpus_files, mutate
    rng = random.Random(20261125)
    corpus = corpus_files()
    accepted = 0
    for _ in range(MUTANTS):
        path = rng.choice(corpus)
        text = mutate(path.read_text(encoding="latin-1"), rng, rng.randint(1, 3))
        assert_same_parse(text, path.name)
        accepted += _outcome(text, path.name, False)[0] == "ast"
    assert accepted > MUTANTS // 10           # some mutants stay programs: both paths build


@needs_compiled
@pytest.mark.parametrize("opening, middle, closing, around", [
    ("NOT ", "a", "", 490),
    ("a + (", "a", ")", 160),
    ("-(", "a", ")", 240),
    ("IF a THEN ", "x := 1;", "ENDIF ", 165),
])
def test_nesting_limit_is_the_same_on_both_paths(opening, middle, closing, around):
    """The parser stack is as deep with the shortcuts as without: the same depths are
    refused (the limit lies within the swept range)."""
    outcomes = set()
    limit = sys.getrecursionlimit()
    sys.setrecursionlimit(20_000)           # comparing trees 490 levels deep recurses deeply
    try:
        for depth in range(around - 12, around + 12):
            nested = opening * depth + middle + closing * depth
            statement = nested if middle.endswith(";") else f"x := {nested};"
            text = f"MODULE m PROC p() {statement} ENDPROC ENDMODULE"
            assert_same_parse(text, "deep.mod")
            outcomes.add(_outcome(text, "deep.mod", False)[0])
    finally:
        sys.setrecursionlimit(limit)
    assert outcomes == {"ast", "diagnostics"}


@pytest.mark.parametrize("regexp, case_sensitive", [
    ("[a-zA-Z][a-zA-Z0-9_]*", True),
    ("[a-zA-Z\xc0-\xd6\xd8-\xf6\xf8-\xff][a-zA-Z0-9_\xc0-\xd6\xd8-\xf6\xf8-\xff]*", True),
    ("[a-z][a-z0-9]*", False),               # capitals only through the flag
    ("[a-zA-Z][a-z0-9]*", False),            # the same, after the first character
    ("[a-zA-Z\xc0-\xd6][a-zA-Z]*", False),   # \xe0-\xf6 only through the flag
])
def test_identifier_drops_its_i_flag_only_where_latin_1_matches_stay_the_same(
        regexp, case_sensitive):
    from lark.lexer import PatternRE, TerminalDef

    from rapidmc.syntax.scanner import _case_sensitive
    terminal = TerminalDef("NAME", PatternRE(regexp, ["i"]))
    assert (_case_sensitive(terminal) == regexp) == case_sensitive
