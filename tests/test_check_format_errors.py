"""``check --format json|sarif`` on a program that does not load: the input errors in the
machine format on stdout (all of them, with the count of those a capped report leaves out),
the text diagnostics still on stderr, and the exit code of text output (2)."""
from __future__ import annotations

import json

import pytest

from cli_capture import run_cli

# (name, module text, expected (code, line, column) of every error, in order)
PROGRAMS = [
    ("static", "MODULE m\n  VAR num x;\n  PROC main()\n    x := y + 1;\n    x := \"a\";\n"
               "    Foo x;\n    x := y;\n  ENDPROC\nENDMODULE\n",
     [("RMC201", 4, 10), ("RMC206", 5, 10), ("RMC203", 6, 5)]),
    ("syntax", "MODULE m\n  VAR num x;\n  PROC main()\n    x := ;\n    x := 1;\n    x := 2 +;\n"
               "  ENDPROC\nENDMODULE\n",
     [("RMC101", 4, 10), ("RMC101", 6, 13)]),
]


def cli(*argv) -> tuple[int, str, str]:
    return run_cli(argv)


def write(tmp_path, text: str) -> str:
    path = tmp_path / "prog.mod"
    path.write_text(text)
    return str(path)


@pytest.mark.parametrize("name, text, expected", PROGRAMS, ids=[p[0] for p in PROGRAMS])
def test_json_lists_every_input_error_with_its_place(name, text, expected, tmp_path):
    program = write(tmp_path, text)
    code, out, err = cli("check", program, "--quiet", "--format", "json")
    assert code == 2
    document = json.loads(out)
    assert document["schema"] == "rapidmc-check/1"
    assert document["properties"] == [] and document["warnings"] == []
    found = [(e["code"], e["location"]["line"], e["location"]["column"])
             for e in document["errors"]]
    assert found == expected
    assert all(e["location"]["file"] == program and e["severity"] == "error"
               for e in document["errors"])
    assert document["errors_not_shown"] == 0
    # the people reading the CI log still get the diagnostics as text
    assert err.count(": error: ") == len(expected)


def test_json_error_carries_message_and_notes(tmp_path):
    code, out, _ = cli("check", write(tmp_path, PROGRAMS[0][1]), "--quiet", "--format", "json")
    first = json.loads(out)["errors"][0]
    assert first["message"] == "unknown name 'y' (2 uses)"
    assert any("rapidmc stubs" in note for note in first["notes"])
    assert first["location"]["end_column"] == 11


def test_capped_report_counts_the_rest_in_json_and_sarif(tmp_path):
    body = "".join(f"    x := missing_{i};\n" for i in range(57))
    program = write(tmp_path, f"MODULE m\n  VAR num x;\n  PROC main()\n{body}  ENDPROC\nENDMODULE\n")
    code, out, _ = cli("check", program, "--quiet", "--format", "json")
    document = json.loads(out)
    assert code == 2
    assert len(document["errors"]) == 50 and document["errors_not_shown"] == 7
    assert all(e["code"] == "RMC201" for e in document["errors"])
    code, out, _ = cli("check", program, "--quiet", "--format", "sarif")
    results = json.loads(out)["runs"][0]["results"]
    assert code == 2 and len(results) == 51
    assert results[-1]["ruleId"] == "RMC215"
    assert results[-1]["properties"] == {"errorsNotShown": 7}


def test_bad_property_and_missing_file_are_json_errors_too(tmp_path):
    program = write(tmp_path, "MODULE m\n  PROC main()\n  ENDPROC\nENDMODULE\n")
    code, out, _ = cli("check", program, "--quiet", "--format", "json", "--formula", "p: G (")
    (failure,) = json.loads(out)["errors"]
    assert code == 2 and failure["code"] == "RMC401"
    code, out, _ = cli("check", str(tmp_path / "absent.mod"), "--quiet", "--format", "json")
    (failure,) = json.loads(out)["errors"]
    assert code == 2 and failure["code"] == "RMC001"


def test_a_program_that_loads_has_no_errors_in_json(tmp_path):
    program = write(tmp_path, "MODULE m\n  PROC main()\n  ENDPROC\nENDMODULE\n")
    code, out, _ = cli("check", program, "--quiet", "--format", "json", "--formula", "p: G true")
    document = json.loads(out)
    assert code == 0
    assert document["errors"] == [] and document["errors_not_shown"] == 0
    assert [p["verdict"] for p in document["properties"]] == ["HOLDS"] * 3
