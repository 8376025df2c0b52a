"""Reading files: every failure is a diagnostic with its own code, never a traceback."""
from __future__ import annotations

import os
from pathlib import Path

import pytest

from rapidmc.diagnostics import SourceCache, UserError
from rapidmc.load.source import MAX_FILE_BYTES, program_paths, read_source
from rapidmc.syntax import load_program, parse_file, parse_text

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

MODULE = b"MODULE m\n  PROC main()\n    Stop;\n  ENDPROC\nENDMODULE\n"


def write(tmp_path: Path, name: str, data: bytes) -> str:
    path = tmp_path / name
    path.write_bytes(data)
    return str(path)


def code_of(action) -> str:
    with pytest.raises(UserError) as failure:
        action()
    return failure.value.diagnostics[0].code.code


@pytest.mark.parametrize("name, data, code", [
    ("empty.mod", b"", "RMC006"),
    ("blank.mod", b"  \n\t\n", "RMC006"),
    ("comments.mod", b"! only\n! comments\n", "RMC006"),
    ("header_only.mod", b"%%%\n  VERSION:1\n%%%\n", "RMC006"),
    ("nul.mod", MODULE.replace(b"Stop", b"St\0p"), "RMC004"),
    ("controls.bin", bytes(range(1, 9)) * 100, "RMC004"),
    ("encrypted.mod", b"\xf3\x01\x02" + MODULE, "RMC005"),
    ("english.txt", b"This is not RAPID at all.\n", "RMC101"),
    ("python.mod", b"def main():\n    print('hi')\n", "RMC101"),
], ids=lambda value: value if isinstance(value, str) and value.endswith(("mod", "txt", "bin")) else "")
def test_unusable_file_gives_its_diagnostic(tmp_path, name, data, code):
    path = write(tmp_path, name, data)
    assert code_of(lambda: parse_file(path)) == code


def test_missing_file(tmp_path):
    assert code_of(lambda: parse_file(str(tmp_path / "nope.mod"))) == "RMC001"


def test_directory(tmp_path):
    assert code_of(lambda: parse_file(str(tmp_path))) == "RMC002"


@pytest.mark.skipif(os.geteuid() == 0, reason="root can read any file")
def test_unreadable_file(tmp_path):
    path = write(tmp_path, "secret.mod", MODULE)
    os.chmod(path, 0)
    assert code_of(lambda: parse_file(path)) == "RMC003"


def test_ten_megabyte_file_is_refused_at_once(tmp_path):
    statement = b"    MoveL Offs(p10, 1, 2, 3), v1000, z50, tool0 \\WObj:=wobj0;\n"
    body = statement * (10_000_000 // len(statement))
    path = write(tmp_path, "huge.mod", b"MODULE big\nPROC main()\n" + body + b"ENDPROC\nENDMODULE\n")
    assert os.path.getsize(path) > 10_000_000 > MAX_FILE_BYTES
    assert code_of(lambda: parse_file(path)) == "RMC007"


def test_deep_nesting_is_a_diagnostic_not_a_crash():
    text = "MODULE m PROC p() x := " + "NOT " * 3000 + "a; ENDPROC ENDMODULE"
    assert code_of(lambda: parse_text(text, "deep.mod")) == "RMC305"


@pytest.mark.parametrize("opening, middle, closing", [
    ("IF a THEN ", "x := 1;", "ENDIF "),
    ("a + (", "a", ")"),
    ("-(", "a", ")"),
])
def test_deep_nesting_of_any_shape_is_a_diagnostic(opening, middle, closing):
    nested = opening * 600 + middle + closing * 600
    statement = nested if middle.endswith(";") else f"x := {nested};"
    text = f"MODULE m PROC p() {statement} ENDPROC ENDMODULE"
    assert code_of(lambda: parse_text(text, "deep.mod")) == "RMC305"


def test_nesting_of_ordinary_depth_parses():
    text = "MODULE m PROC p() " + "IF a THEN " * 40 + "x := 1;" + "ENDIF " * 40 + "ENDPROC ENDMODULE"
    assert parse_text(text, "nested.mod")


def test_latin1_identifiers_and_strings(tmp_path):
    text = "MODULE Größe\n  VAR string s := \"Grüße ÿ\";\n  VAR num øre := 1;\nENDMODULE\n"
    path = write(tmp_path, "umlaut.mod", text.encode("latin-1"))
    (module,) = parse_file(path)
    assert module.name.text == "Größe"
    assert module.data[0].init.value == "Grüße ÿ"
    assert module.data[1].name.key == "ØRE"


def test_utf8_file_with_byte_order_mark(tmp_path):
    text = "MODULE m\n  VAR string s := \"Grüße\";\nENDMODULE\n"
    path = write(tmp_path, "bom.mod", b"\xef\xbb\xbf" + text.encode("utf-8"))
    assert parse_file(path)[0].data[0].init.value == "Grüße"


def test_source_lines_are_remembered_for_diagnostics(tmp_path):
    path = write(tmp_path, "m.mod", MODULE)
    read_source(path)
    assert SourceCache.line(path, 3) == "    Stop;"


def test_several_modules_in_one_file(tmp_path):
    path = write(tmp_path, "two.prg", MODULE + MODULE.replace(b"MODULE m", b"MODULE n"))
    assert [m.name.text for m in parse_file(path)] == ["m", "n"]


PGF = b"""<?xml version="1.0" encoding="ISO-8859-1" ?>
<Program>
    <Module>A.mod</Module>
    <Module>sub/B.mod</Module>
</Program>
"""


def test_program_file_expands_to_its_modules_relative_to_itself(tmp_path):
    (tmp_path / "sub").mkdir()
    write(tmp_path, "A.mod", MODULE.replace(b"MODULE m", b"MODULE A"))
    write(tmp_path, "sub/B.mod", b"MODULE B\nENDMODULE\n")
    pgf = write(tmp_path, "cell.pgf", PGF)
    assert program_paths([pgf]) == [str(tmp_path / "A.mod"), str(tmp_path / "sub/B.mod")]
    program = load_program([pgf])
    assert [m.name.text for m in program.modules] == ["A", "B"]


@pytest.mark.parametrize("content", [
    PGF,                                   # names modules that do not exist
    b"<Program><Module>A.mod</Program>",   # not XML
    b"<Program></Program>",                # no modules
])
def test_bad_program_file(tmp_path, content):
    pgf = write(tmp_path, "cell.pgf", content)
    assert code_of(lambda: load_program([pgf])) == "RMC008"


def test_load_program_keeps_file_order(tmp_path):
    first = write(tmp_path, "z.mod", b"MODULE z\nENDMODULE\n")
    second = write(tmp_path, "a.mod", b"MODULE a\nENDMODULE\n")
    assert [m.name.key for m in load_program([first, second]).modules] == ["Z", "A"]
