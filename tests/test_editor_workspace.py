"""What the editor shows (``findings.editor``, ``findings.declarations``,
``report.lsp_diagnostics``): which documents make a program, which diagnostics a document gets,
where names are declared."""
from __future__ import annotations

import types
from pathlib import Path

import pytest

from rapidmc.ast import Span
from rapidmc.diagnostics import NEVER_REACHED, SYNTAX, Diagnostic
from rapidmc.findings.declarations import declaration_at, word_at
from rapidmc.findings.editor import Workspace
from rapidmc.report.lsp_diagnostics import lsp_diagnostic

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

SORTER = Path(__file__).resolve().parent.parent / "case_studies" / "sorter"
LINT_CODES = "RMC800"       # the lint stage's codes start here (docs/diagnostics.md)


def space_with(**documents: str) -> Workspace:
    space = Workspace()
    for name, text in documents.items():
        space.update(f"{name}.mod", text)
    return space


def test_two_main_modules_open_side_by_side_are_checked_apart():
    space = Workspace()
    for name in ("sorter_a.mod", "sorter_b.mod", "plant.mod"):
        space.update(name, (SORTER / name).read_text(encoding="latin-1"))
    assert [p.file for p in space.program_of("sorter_a.mod")] == ["sorter_a.mod"]
    for name in ("sorter_a.mod", "sorter_b.mod"):     # no duplicates: only lint findings
        assert all(d.code.code >= LINT_CODES for d in space.diagnostics(name))


def test_a_program_takes_the_modules_declaring_what_it_uses_transitively():
    space = space_with(
        main="MODULE M\nPROC main()\n  First;\nENDPROC\nENDMODULE\n",
        first="MODULE A\nPROC First()\n  Second;\nENDPROC\nENDMODULE\n",
        second="MODULE B\nPROC Second()\nENDPROC\nENDMODULE\n",
        unrelated="MODULE C\nPROC main()\nENDPROC\nENDMODULE\n")
    assert [p.file for p in space.program_of("main.mod")] == ["main.mod", "first.mod",
                                                              "second.mod"]
    assert space.diagnostics("main.mod") == []


def test_a_local_declaration_is_not_what_another_module_uses():
    space = space_with(
        main="MODULE M\nPROC main()\n  Helper;\nENDPROC\nENDMODULE\n",
        library="MODULE L\nLOCAL PROC Helper()\nENDPROC\nENDMODULE\n")
    assert [d.code.code for d in space.diagnostics("main.mod")] == ["RMC203"]


def test_a_library_module_without_main_is_not_told_it_lacks_one():
    space = space_with(library="MODULE L\nPROC Helper()\n  x := 1;\nENDPROC\nENDMODULE\n")
    assert [d.code.code for d in space.diagnostics("library.mod")] == ["RMC201"]


def test_a_syntax_error_elsewhere_leaves_its_module_out():
    space = space_with(
        main="MODULE M\nPROC main()\n  Helper;\nENDPROC\nENDMODULE\n",
        library="MODULE L\nPROC Helper()\n  x := ;\nENDPROC\nENDMODULE\n")
    assert [d.code.code for d in space.diagnostics("library.mod")] == ["RMC101"]
    assert [d.code.code for d in space.diagnostics("main.mod")] == ["RMC203"]


def test_with_read_folders_the_modules_beside_a_document_join_its_program(tmp_path):
    (tmp_path / "library.mod").write_text("MODULE L\nPROC Helper()\nENDPROC\nENDMODULE\n")
    (tmp_path / "other.mod").write_text("MODULE O\nPROC main()\nENDPROC\nENDMODULE\n")
    (tmp_path / "broken.mod").write_text("MODULE B\nPROC Helper2()\n x := ;\nENDPROC\n")
    (tmp_path / "notes.txt").write_text("PROC Helper3()")
    main = str(tmp_path / "main.mod")
    text = "MODULE M\nPROC main()\n  Helper;\n  Helper2;\nENDPROC\nENDMODULE\n"
    space = Workspace(read_folders=True)
    space.update(main, text)
    assert [p.file for p in space.program_of(main)] == [main, str(tmp_path / "library.mod")]
    assert [d.message for d in space.diagnostics(main)] == ["unknown procedure 'Helper2'"]
    (tmp_path / "library.mod").write_text("MODULE L\nPROC Helper2()\nENDPROC\nENDMODULE\n")
    assert [d.message for d in space.diagnostics(main)] == ["unknown procedure 'Helper'"]
    assert Workspace().neighbours(main) == {}            # off unless asked for


def test_an_edit_is_parsed_again_and_a_closed_document_is_gone():
    space = space_with(main="MODULE M\nPROC main()\n  x := ;\nENDPROC\nENDMODULE\n")
    assert space.diagnostics("main.mod")
    space.update("main.mod", "MODULE M\nPROC main()\nENDPROC\nENDMODULE\n")
    assert space.diagnostics("main.mod") == []
    space.remove("main.mod")
    assert space.program_modules("main.mod") == [] and space.text("main.mod") is None


CHAIN = "MODULE M\nPROC main()\n  VAR bool b;\n  b := TRUE AND NOT b AND b;\nENDPROC\nENDMODULE\n"


def test_lint_reports_a_not_inside_an_and_chain():
    space = space_with(main=CHAIN)
    assert "RMC801" in [d.code.code for d in space.diagnostics("main.mod")]


def test_lint_follows_the_nearest_pyproject_configuration(tmp_path):
    project = tmp_path / "cell"
    (project / "modules").mkdir(parents=True)
    (project / "pyproject.toml").write_text('[tool.rapidmc.lint]\nignore = ["not-chain"]\n')
    main = str(project / "modules" / "main.mod")
    space = Workspace(read_folders=True)
    space.update(main, CHAIN)
    assert "RMC801" not in [d.code.code for d in space.diagnostics(main)]
    (project / "pyproject.toml").write_text('[tool.rapidmc.lint]\nignored = ["not-chain"]\n')
    found = {d.code.code: d for d in space.diagnostics(main)}
    assert "RMC801" in found                              # a bad table: the defaults run
    assert "unknown key(s) ignored" in found["RMC840"].message
    assert str(project / "pyproject.toml") in found["RMC840"].message


# --- declarations --------------------------------------------------------------------

MODULE_A = """MODULE A
  VAR num count := 0;
  LOCAL VAR num hidden := 0;
  RECORD part
    num weight;
  ENDRECORD

  PROC main()
    VAR num count := 1;
    count := count + 1;
    Grip;
  again:
    GOTO again;
  ENDPROC

  PROC Grip(num force)
    count := force;
  ENDPROC
ENDMODULE
"""
MODULE_B = """MODULE B
  PERS part item := [1];
  PROC Other()
    count := hidden;
  ENDPROC
ENDMODULE
"""


@pytest.fixture(scope="module")
def modules():
    from rapidmc.syntax import parse_text
    return parse_text(MODULE_A, "a.mod") + parse_text(MODULE_B, "b.mod")


@pytest.mark.parametrize("file, line, word, kind, declared", [
    ("a.mod", 10, "count", "data", ("a.mod", 9)),        # routine data hides module data
    ("a.mod", 17, "COUNT", "data", ("a.mod", 2)),        # any case; the module's data
    ("a.mod", 17, "force", "parameter", ("a.mod", 16)),
    ("a.mod", 11, "Grip", "routine", ("a.mod", 16)),
    ("a.mod", 13, "again", "label", ("a.mod", 12)),
    ("b.mod", 4, "count", "data", ("a.mod", 2)),         # a global of another module
    ("b.mod", 2, "part", "record", ("a.mod", 4)),
])
def test_a_name_resolves_to_its_declaration(modules, file, line, word, kind, declared):
    found = declaration_at(modules, file, line, word)
    assert (found.kind, found.name.span.file, found.name.span.line) == (kind, *declared)


def test_local_data_of_another_module_and_predefined_names_resolve_to_nothing(modules):
    assert declaration_at(modules, "b.mod", 4, "hidden") is None
    assert declaration_at(modules, "a.mod", 11, "MoveL") is None
    assert declaration_at(modules, "c.mod", 1, "count").name.span.file == "a.mod"


@pytest.mark.parametrize("text, character, expected", [
    ("  MoveL p10, v100;", 2, ("MoveL", 2)), ("  MoveL p10, v100;", 7, ("MoveL", 2)),
    ("  MoveL p10, v100;", 8, ("p10", 8)), ("  MoveL p10, v100;", 0, None),
])
def test_word_at(text, character, expected):
    assert word_at(text, character) == expected


def test_a_diagnostic_without_an_end_covers_its_word():
    found = Diagnostic(SYNTAX, "x", Span("a.mod", 2, 3))
    assert lsp_diagnostic(found, ["", "  Grip_1 := 2;"])["range"] == {
        "start": {"line": 1, "character": 2}, "end": {"line": 1, "character": 8}}
    placeless = lsp_diagnostic(Diagnostic(SYNTAX, "y", None, notes=("a note",)), [])
    assert placeless["range"]["start"] == {"line": 0, "character": 0}
    assert placeless["message"] == "y\nnote: a note"


def test_document_lines_break_where_the_parser_counts_a_line():
    from rapidmc.report.lsp_diagnostics import document_lines
    assert document_lines("a\r\nb\x0cc\x85d\ne") == ["a", "b\x0cc\x85d", "e"]


@pytest.mark.parametrize("word, shown", [
    ("waittime", "WaitTime(\\switch InPos, num Time)"),
    ("V100", "CONST speeddata v100"),
    ("robtarget",
     "**robtarget** (record): pos trans, orient rot, confdata robconf, extjoint extax"),
])
def test_hover_on_predefined_routines_data_and_types(word, shown):
    from rapidmc.report.hover import predefined_hover
    assert shown in predefined_hover(word)


@pytest.mark.parametrize("word", ["switch", "anytype", "PickPart", "MODULE"])
def test_no_hover_for_hidden_types_and_unknown_words(word):
    from rapidmc.report.hover import predefined_hover
    assert predefined_hover(word) is None


def test_a_flow_is_related_information_step_by_step():
    """A lint flow finding (RMC820 of the lint stage: a Diagnostic with ``flow`` steps) shows
    its path from the input to its use; a stand-in carries the same fields here."""
    from rapidmc.diagnostics import SourceCache
    SourceCache.remember("flow.mod", "MODULE F\n  SocketReceive s \\Str:=text;\n  MoveL p;\n")
    source, sink = Span("flow.mod", 2, 3), Span("flow.mod", 3, 9, 3, 10)
    finding = types.SimpleNamespace(
        code=NEVER_REACHED, message="input reaches a target", span=sink, severity="warning",
        notes=(), flow=((source, "SocketReceive reads it"), (sink, "MoveL takes it")))
    shown = lsp_diagnostic(finding, [], lambda file: f"file:///work/{file}")
    assert shown["relatedInformation"] == [
        {"location": {"uri": "file:///work/flow.mod",
                      "range": {"start": {"line": 1, "character": 2},
                                "end": {"line": 1, "character": 15}}},
         "message": "SocketReceive reads it"},
        {"location": {"uri": "file:///work/flow.mod",
                      "range": {"start": {"line": 2, "character": 8},
                                "end": {"line": 2, "character": 9}}},
         "message": "MoveL takes it"}]
    assert "relatedInformation" not in lsp_diagnostic(Diagnostic(SYNTAX, "x", sink), [])


def test_the_other_places_of_a_finding_are_related_information():
    """A finding given once per cause (``findings.grouping``) lists its other places."""
    from rapidmc.diagnostics import SHARED_INDEX, SourceCache
    SourceCache.remember("idx.mod", "MODULE I\n  MoveL p{n};\n  MoveJ p{n};\n")
    first, second = Span("idx.mod", 2, 11), Span("idx.mod", 3, 11)
    finding = Diagnostic(SHARED_INDEX, "PERS 'n' is used as an index", first, "warning",
                         places=(second,))
    shown = lsp_diagnostic(finding, [], lambda file: f"file:///work/{file}")
    assert shown["message"].endswith("note: 1 more place: idx.mod line 3")
    assert shown["relatedInformation"] == [
        {"location": {"uri": "file:///work/idx.mod",
                      "range": {"start": {"line": 2, "character": 10},
                                "end": {"line": 2, "character": 11}}},
         "message": "the same finding"}]
