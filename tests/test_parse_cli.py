"""``rapidmc parse``: summary lines, diagnostics on stderr, exit codes, JSON trees."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from rapidmc.cli import main

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
HELLO = str(ROOT / "case_studies" / "hello" / "hello.mod")
BAD = str(ROOT / "tests" / "syntax" / "bad" / "missing_semicolon.mod")


def test_summary_line_per_file_and_exit_0(capsys):
    assert main(["parse", HELLO]) == 0
    assert capsys.readouterr().out == f"{HELLO}: ok: 1 routines, 5 data\n"


def test_bad_file_gives_diagnostic_on_stderr_and_exit_2(capsys):
    assert main(["parse", HELLO, BAD]) == 2
    captured = capsys.readouterr()
    assert captured.out == f"{HELLO}: ok: 1 routines, 5 data\n"
    assert captured.err.startswith(f"{BAD}:5:5: error: unexpected 'y'")
    assert "[RMC101]" in captured.err


def test_missing_file_is_a_diagnostic(capsys):
    assert main(["parse", "no/such/file.mod"]) == 2
    assert "[RMC001]" in capsys.readouterr().err


def test_json_dump_of_the_syntax_tree(capsys):
    assert main(["parse", "--json", HELLO]) == 0
    (entry,) = json.loads(capsys.readouterr().out)["files"]
    assert entry["ok"] and entry["diagnostics"] == []
    (module,) = entry["modules"]
    assert module["node"] == "Module" and module["name"]["text"] == "Hello"
    main_routine = module["routines"][0]
    assert main_routine["node"] == "Routine" and main_routine["kind"] == "PROC"
    first_call = main_routine["body"][0]
    assert first_call["node"] == "ProcedureCall" and first_call["name"]["key"] == "TPWRITE"
    assert first_call["span"]["line"] == 16


def test_json_lists_diagnostics_of_failed_files(capsys):
    assert main(["parse", "--json", BAD]) == 2
    (entry,) = json.loads(capsys.readouterr().out)["files"]
    assert not entry["ok"]
    assert entry["diagnostics"][0]["code"] == "RMC101"
    assert entry["diagnostics"][0]["span"]["line"] == 5
