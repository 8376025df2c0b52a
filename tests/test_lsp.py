"""``rapidmc lsp`` driven as an editor drives it: a client of our own over the server's pipes.

One server session per test module (starting Python and pygls takes a while on a loaded
machine); the tests run in order within it, each on documents of its own.
"""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytest.importorskip("pygls")

from lsp_client import LspClient  # noqa: E402  (after the skip: the server needs pygls)

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

BROKEN = """MODULE Broken
  PROC main()
    VAR num x;
    x := ;
  ENDPROC
ENDMODULE
"""
FIXED = BROKEN.replace("x := ;", "x := 1;")
MAIN = """MODULE CellMain
  PROC main()
    MoveL p10, v100, fine, tool0;
    PickPart;
  ENDPROC
ENDMODULE
"""
LIBRARY = """MODULE CellLib
  CONST robtarget p10 := [[500,0,400],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

  PROC PickPart()
    WaitTime 0.5;
  ENDPROC
ENDMODULE
"""


def without_lint(diagnostics: list[dict]) -> list[dict]:
    """The syntax and static diagnostics (the lint stage's codes start at RMC800)."""
    return [d for d in diagnostics if d["code"] < "RMC800"]


@pytest.fixture(scope="module")
def client(tmp_path_factory):
    root = tmp_path_factory.mktemp("workspace")
    session = LspClient()
    session.root = root
    result = session.initialize(root)
    capabilities = result["capabilities"]
    assert capabilities["hoverProvider"] and capabilities["definitionProvider"]
    yield session
    assert session.close() == 0


def test_an_opened_document_with_a_syntax_error_gets_its_diagnostic(client):
    path = client.root / "broken.mod"
    client.open(path, BROKEN)
    [diagnostic] = client.diagnostics(path.as_uri())
    assert diagnostic["code"] == "RMC101"
    assert diagnostic["severity"] == 1 and diagnostic["source"] == "rapidmc"
    assert diagnostic["message"].startswith("unexpected ';'")
    assert diagnostic["range"] == {"start": {"line": 3, "character": 9},
                                   "end": {"line": 3, "character": 10}}


def test_fixing_the_error_clears_the_diagnostics(client):
    path = client.root / "broken.mod"
    client.change(path, FIXED)
    assert client.diagnostics(path.as_uri()) == []


def test_a_static_error_is_published_with_its_code(client):
    path = client.root / "unknown.mod"
    client.open(path, FIXED.replace("MODULE Broken", "MODULE Unknown")
                .replace("PROC main", "PROC other").replace("x := 1;", "y := 1;"))
    [diagnostic] = without_lint(client.diagnostics(path.as_uri()))
    assert diagnostic["code"] == "RMC201" and "unknown name 'y'" in diagnostic["message"]
    assert diagnostic["range"]["start"] == {"line": 3, "character": 4}


def test_a_call_into_a_module_neither_open_nor_on_disk_is_unknown_until_it_opens(client):
    main, library = client.root / "cell_main.mod", client.root / "cell_lib.mod"
    client.open(main, MAIN)
    codes = sorted(d["code"] for d in without_lint(client.diagnostics(main.as_uri())))
    assert codes == ["RMC201", "RMC203"]            # p10 and PickPart
    client.open(library, LIBRARY)
    assert without_lint(client.diagnostics(main.as_uri())) == []


def test_lint_findings_are_published(client):
    path = client.root / "chain.mod"
    client.open(path, "MODULE Chain\n  PROC main()\n    VAR bool b;\n"
                "    b := TRUE AND NOT b AND b;\n  ENDPROC\nENDMODULE\n")
    found = [d for d in client.diagnostics(path.as_uri()) if d["code"] == "RMC801"]
    assert [d["range"]["start"]["line"] for d in found] == [3]


NETWORK = """MODULE Net
  VAR socketdev sock;
  VAR string text;
  VAR num x;
  VAR robtarget target := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    SocketReceive sock \\Str:=text \\Time:=5;
    IF StrToVal(text, x) THEN
      target.trans.x := x;
      MoveL target, v100, fine, tool0;
    ENDIF
  ENDPROC
ENDMODULE
"""


def test_a_lint_flow_arrives_with_its_path_as_related_information(client):
    path = client.root / "network.mod"
    client.open(path, NETWORK)
    [flow] = [d for d in client.diagnostics(path.as_uri()) if d["code"] == "RMC820"]
    assert flow["range"]["start"]["line"] == 9                       # the MoveL
    steps = flow["relatedInformation"]
    assert {step["location"]["uri"] for step in steps} == {path.as_uri()}
    assert steps[0]["location"]["range"]["start"]["line"] == 6        # the SocketReceive
    assert steps[-1]["location"]["range"]["start"]["line"] == 9


def test_hover_on_a_predefined_instruction_shows_signature_and_modelling(client):
    main = client.root / "cell_main.mod"
    hover = client.at("textDocument/hover", main, 2, 6)        # on MoveL
    text = hover["contents"]["value"]
    assert "MoveL(\\switch Conc, robtarget ToPoint" in text
    assert "modelled: robot state only" in text
    speed = client.at("textDocument/hover", main, 2, 16)["contents"]["value"]   # on v100
    assert "CONST speeddata v100" in speed


def test_hover_on_a_declared_routine_shows_its_declaration(client):
    main = client.root / "cell_main.mod"
    text = client.at("textDocument/hover", main, 3, 6)["contents"]["value"]   # on PickPart
    assert "PROC PickPart()" in text and "cell_lib.mod:4" in text


def test_definition_of_a_routine_called_in_another_module(client):
    main, library = client.root / "cell_main.mod", client.root / "cell_lib.mod"
    location = client.at("textDocument/definition", main, 3, 8)
    assert location["uri"] == library.as_uri()
    assert location["range"] == {"start": {"line": 3, "character": 7},
                                 "end": {"line": 3, "character": 15}}
    target = client.at("textDocument/definition", main, 2, 11)        # on p10
    assert target["range"]["start"] == {"line": 1, "character": 18}


def test_a_module_on_disk_beside_the_document_counts_without_being_opened(client):
    folder = client.root / "cell"
    folder.mkdir()
    (folder / "cell_lib.mod").write_text(LIBRARY.replace("CellLib", "DiskLib"))
    main = folder / "cell_main.mod"
    client.open(main, MAIN.replace("CellMain", "DiskMain"))
    assert without_lint(client.diagnostics(main.as_uri())) == []
    location = client.at("textDocument/definition", main, 3, 8)
    assert location["uri"] == (folder / "cell_lib.mod").as_uri()
    assert location["range"]["start"] == {"line": 3, "character": 7}


def test_nothing_to_show_off_a_name(client):
    main = client.root / "cell_main.mod"
    assert client.at("textDocument/definition", main, 2, 0) is None
    assert client.at("textDocument/hover", main, 0, 2) is None     # MODULE


def test_without_pygls_the_command_is_a_diagnostic_and_exit_2():
    hide_pygls = ("import sys; sys.modules['pygls'] = None; sys.modules['pygls.lsp'] = None; "
                  "sys.modules['pygls.lsp.server'] = None; from rapidmc.cli import main; "
                  "sys.exit(main(['lsp']))")
    done = subprocess.run([sys.executable, "-c", hide_pygls], capture_output=True, text=True,
                          timeout=60)
    assert done.returncode == 2
    assert "'rapidmc lsp' needs pygls, which is not installed [RMC850]" in done.stderr
    assert "pip install 'rapidmc[lsp]'" in done.stderr
