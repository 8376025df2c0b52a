"""An unknown atom written like ``GFa`` gets a note with the spaced operator form (``G F a``).

rapidmc reads a word as one name (``Go``, ``GRIPPER`` are atoms), Spot
reads leading ``F``/``G``/``X`` letters as operators; when such a word names
nothing, the diagnostic says how to write the operators.  The note is only
given for bare words (a quoted atom is clearly meant as a name) and prefers
a split that leaves a known name.
"""
from __future__ import annotations

import doctest

import pytest

import rapidmc.model.properties as properties
from rapidmc.cli import main

PROGRAM = ("MODULE M\n  VAR bool flag := FALSE;\n  PROC main()\n    WHILE TRUE DO\n"
           "      flag := NOT flag;\n    ENDWHILE\n  ENDPROC\nENDMODULE\n")


@pytest.mark.parametrize("formula, spaced", [
    ("GFflag", "G F flag"),
    ("XXflag", "X X flag"),
    ("GRIPPER", "G RIPPER"),          # nothing known either way: the longest operator run
    ("GFlag", "G Flag"),              # 'Flag' names the bool flag (names ignore case)
    ("F flag -> GFXflag", "G F X flag"),
])
def test_the_note_spells_out_the_operators(formula, spaced, monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "prog.mod").write_text(PROGRAM)
    assert main(["check", "prog.mod", "--formula", f"p: {formula}", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "[RMC402]" in err
    assert f"for the operators write '{spaced}' (with spaces)" in err


@pytest.mark.parametrize("formula", ['G "GFflag"', "G no_such", "G F flag2x"])
def test_no_note_for_quoted_atoms_or_other_unknown_names(formula, monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "prog.mod").write_text(PROGRAM)
    assert main(["check", "prog.mod", "--formula", f"p: {formula}", "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "[RMC402]" in err and "note:" not in err


def test_the_spelling_function_examples_run():
    finder = doctest.DocTestFinder()
    (test,) = finder.find(properties.operators_spelled_out,
                          globs={"operators_spelled_out": properties.operators_spelled_out})
    result = doctest.DocTestRunner().run(test)
    assert (result.failed, result.attempted) == (0, 2)
