"""A read of PERS data written outside the loaded code whose value indexes an array takes only
that array's indexes (``ExpressionCompiler._outside_index``, issue 28).

The taeyangshim 2026-02-11 backup: a PC writes ``nRunningStep``, which no loaded task writes;
the welding task indexes ``Welds1{nRunningStep{1}}`` unguarded, and a robot task copies it
into a local that only indexes (``i := nRunningStep{1}; ... Welds1{i}``).  The data's domain
holds the values the code's comparisons tell apart (``<> 0``, ``1 <=``: -1, 0, 0.5 ...), so
each read was an ERR_OUTOFBND that rests only on the assumed writer: a false VIOLATED of the
whole backup.  Such a read now takes the whole numbers 1 .. length of its domain, and the
``assumes:`` line says so beside the verdict, where the routine reads the data only as
indexes; every other read (a comparison, a local that is also tested, an index in a routine
that also tests the data: a race with the writer) keeps the whole domain, and an index the
program computes itself still fails.
"""
from __future__ import annotations

import json

import pytest

from rapidmc.check import native

from cli_capture import run_cli

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

HEAD = """MODULE M
  PERS num runStep{2} := [1,1];
  PERS num table{3} := [10,20,30];
  PERS num grid{2,3} := [[1,2,3],[4,5,6]];
  VAR num x;
  VAR num mine := 1;
"""
GUARDS = """    IF runStep{1} <> 0 THEN
      x := 1;
    ENDIF
    IF 1 <= runStep{2} THEN
      x := 2;
    ENDIF
"""

CASES = {
    # name: (body of a routine ``use`` that main calls after its guards, verdict, index
    # places named)
    "direct index": ("    x := table{runStep{1}};\n", "HOLDS", ["prog.mod:17"]),
    "second dimension": ("    x := grid{2, runStep{2}};\n", "HOLDS", ["prog.mod:17"]),
    "local that only indexes": ("    VAR num i;\n    i := runStep{2};\n    x := table{i};\n",
                                "HOLDS", ["prog.mod:18"]),
    # the local is tested as well: a branch could tell its values apart, the domain stays
    "local that is also tested": (
        "    VAR num i;\n    i := runStep{2};\n    IF i = 0 i := 1;\n    x := table{i + 1};\n",
        "VIOLATED", []),
    # the routine tests the data and indexes with it: two reads, the writer may write 0
    # between them (a race the code has: tests/counterexamples/outside_string_and_element)
    "tested where it indexes": ("    IF runStep{1} <> 0 x := table{runStep{1}};\n",
                                "VIOLATED", []),
    # an index the program computes from the data is the program's own arithmetic
    "computed index": ("    x := table{runStep{1} + 1};\n", "VIOLATED", []),
    # the program's own index, left 0 by a branch: a real defect stays found
    "own index left 0": ("    IF runStep{1} = 1 mine := 0;\n    x := table{mine};\n",
                         "VIOLATED", []),
}


def program(body: str) -> str:
    return (f"{HEAD}  PROC main()\n{GUARDS}    use;\n  ENDPROC\n"
            f"  PROC use()\n{body}  ENDPROC\nENDMODULE\n")


def report(tmp_path, text: str, engine: str, *options: str) -> dict:
    path = tmp_path / "prog.mod"
    path.write_text(text)
    captured = run_cli(["check", path, "--engine", engine, "--format", "json", "--quiet",
                        *options], cwd=tmp_path)
    return json.loads(captured.out)


def runtime(document: dict) -> dict:
    return next(p for p in document["properties"] if p["name"] == "no_runtime_error")


def assumption_texts(document: dict) -> list[str]:
    return [text for prop in document["properties"] for text in prop["assumes"]]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("name", list(CASES))
def test_outside_reads_that_index_take_the_arrays_indexes(tmp_path, name, engine):
    body, verdict, places = CASES[name]
    document = report(tmp_path, program(body), engine)
    assert runtime(document)["verdict"] == verdict
    texts = [t for t in assumption_texts(document) if "PERS runStep" in t]
    assert texts, "the verdict names the data written outside"
    named = [t for t in texts if "only that array's indexes" in t]
    if places:
        assert named and all(place in named[0] for place in places), texts
    else:
        assert not named, texts


def test_the_comparisons_still_see_every_value(tmp_path):
    """The guards read the whole domain: with the direct index, both branches of ``<> 0``
    still run (no line is reported never reached)."""
    body = "    x := table{runStep{1}};\n"
    text = program(body).replace("      x := 1;", "      x := 1;\n    ELSE\n      x := 3;")
    path = tmp_path / "prog.mod"
    path.write_text(text)
    captured = run_cli(["check", path, "--all-warnings"], cwd=tmp_path)
    assert "HOLDS" in captured.out
    assert "RMC701" not in captured.out + captured.err


def test_fixed_outside_data_keeps_the_stored_index(tmp_path):
    """``--fixed-outside-data`` reads the stored values: no choice, nothing narrowed."""
    document = report(tmp_path, program("    x := table{runStep{1}};\n"), native.PYTHON,
                      "--fixed-outside-data")
    assert runtime(document)["verdict"] == "HOLDS"
    assert not [t for t in assumption_texts(document) if "only that array's indexes" in t]
