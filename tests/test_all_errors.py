"""Every static error at once (issue 8, part A): parse, run and check report all
recoverable syntax errors of each file and all static errors of the program, sorted
by file and line, capped, each unknown name once with the number of its uses."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from rapidmc.diagnostics.error_report import MAX_REPORTED
from tests.test_realworld import cli

HERE = Path(__file__).resolve().parent / "static_errors"
CELL = [str(HERE / "CellMain.mod"), str(HERE / "CellIO.mod")]


def error_lines(err: str) -> list[str]:
    return [line for line in err.splitlines() if ": error: " in line]


def positions(lines: list[str]) -> list[tuple[str, int, int]]:
    found = []
    for line in lines:
        match = re.match(r"(.*?):(\d+):(\d+): error", line)
        if match:
            found.append((match.group(1), int(match.group(2)), int(match.group(3))))
    return found


@pytest.mark.parametrize("command", [["run"], ["check", "--ltl", str(HERE / "cell.ltl")]])
def test_static_errors_of_every_module_are_reported_together(command):
    code, out, err = cli([command[0], *CELL, *command[1:]])
    lines = error_lines(err)
    assert code == 2 and out == ""
    expected = [
        ("CellIO.mod", 5, "unknown name 'tGripDelay'"),
        ("CellIO.mod", 6, "'Abs' is a function"),
        ("CellMain.mod", 5, "unknown data type 'gripdata'"),
        ("CellMain.mod", 9, "unknown name 'pApproach' (2 uses)"),
        ("CellMain.mod", 9, "unknown name 'tGripper' (3 uses)"),
        ("CellMain.mod", 9, "unknown name 'wobjTable' (3 uses)"),
        ("CellMain.mod", 10, "unknown name 'pPick'"),
        ("CellMain.mod", 13, "expected num, found string"),
        ("CellMain.mod", 14, "unknown name 'bStopReq'"),
        ("CellMain.mod", 22, "a variable or persistent is required"),
    ]
    assert len(lines) == len(expected), err
    for line, (file, number, message) in zip(lines, expected):
        assert f"{file}:{number}:" in line and message in line, line
    assert positions(lines) == sorted(positions(lines))


def test_unknown_name_is_reported_once_and_points_to_stubs():
    code, _, err = cli(["run", *CELL])
    assert code == 2
    assert sum("'tGripper'" in line for line in error_lines(err)) == 1
    assert err.count("rapidmc stubs") == 1          # one pointer, at the first unknown name


def test_uses_of_a_failed_declaration_are_not_reported_again():
    code, _, err = cli(["run", *CELL])
    assert "CellMain.mod:20:" not in err             # gMain.force := 20 follows from gripdata


def test_every_recoverable_syntax_error_of_a_file_is_reported():
    code, out, err = cli(["parse", str(HERE / "BrokenSyntax.mod")])
    assert code == 2
    assert [number for _, number, _ in positions(error_lines(err))] == [3, 5, 7, 9, 10]


def test_syntax_errors_of_several_files_are_reported_by_run():
    other = HERE / "BrokenSyntax.mod"
    code, _, err = cli(["run", str(other), str(HERE / "UtilLib.mod")])
    assert code == 2 and len(error_lines(err)) == 5


def test_a_statement_that_would_take_its_block_along_is_not_blanked(tmp_path):
    path = tmp_path / "m.mod"
    path.write_text("MODULE m\n  PROC main()\n    a := 1 +\n    IF b THEN\n      c := ;\n"
                    "    ENDIF\n  ENDPROC\nENDMODULE\n")
    code, _, err = cli(["parse", str(path)])
    assert code == 2 and [n for _, n, _ in positions(error_lines(err))] == [4]


def test_report_is_capped_with_a_count_of_the_rest(tmp_path):
    body = "\n".join(f"    x{i} := {i};" for i in range(MAX_REPORTED + 7))
    path = tmp_path / "many.mod"
    path.write_text(f"MODULE many\n  PROC main()\n{body}\n  ENDPROC\nENDMODULE\n")
    code, _, err = cli(["run", str(path)])
    lines = error_lines(err)
    assert code == 2 and len(lines) == MAX_REPORTED + 1
    assert lines[-1] == "rapidmc: error: 7 more errors not shown (the report stops after 50) [RMC215]"


def test_library_without_main_lists_the_procedures_to_start_from():
    code, _, err = cli(["run", str(HERE / "UtilLib.mod")])
    assert code == 2 and "[RMC211]" in err
    assert "procedures without parameters to start from with --entry: ResetCell, Service" in err
    code, out, _ = cli(["run", str(HERE / "UtilLib.mod"), "--entry", "Service"])
    assert code == 0


def test_statements_inside_a_failed_if_or_while_are_checked_too(tmp_path):
    path = tmp_path / "nested.mod"
    path.write_text("MODULE nested\n  PROC main()\n    IF bReady THEN\n      nParts := 1;\n"
                    "      WHILE bRunning DO\n        sText := 5;\n      ENDWHILE\n    ENDIF\n"
                    "  ENDPROC\nENDMODULE\n")
    code, _, err = cli(["run", str(path)])
    assert code == 2
    assert [n for _, n, _ in positions(error_lines(err))] == [3, 4, 5, 6]
