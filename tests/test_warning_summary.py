"""The text report's warnings are bounded; --all-warnings and the machine formats keep all.

A whole backup's text report was 31 KB, mostly warnings after the verdicts (issue 28).  Text
shows ``WARNINGS_SHOWN`` of them in full, warnings before notes and unreached code (RMC701)
after both, then how many of each code it left out; ``--all-warnings`` shows every one; JSON and SARIF list every one whatever the
text shows.
"""
from __future__ import annotations

import json

from rapidmc.cli import main
from rapidmc.commands.check import WARNINGS_SHOWN, warnings_text
from rapidmc.diagnostics import ENCRYPTED_SKIPPED, FIXED_READING, Diagnostic

UNREACHED = 14          # stretches of the program below that no input reaches


def program(tmp_path):
    branches = "\n".join(f"        IF n = {100 + i} THEN\n            n := {i};\n        ENDIF"
                         for i in range(UNREACHED))
    path = tmp_path / "prog.mod"
    path.write_text(f"MODULE Many\n    VAR num n := 0;\n    PROC main()\n{branches}\n"
                    "        n := 1;\n    ENDPROC\nENDMODULE\n")
    return str(path)


def test_text_shows_the_first_warnings_then_a_count_per_code(tmp_path, capsys):
    assert main(["check", program(tmp_path), "--quiet"]) == 0
    captured = capsys.readouterr()
    assert "no_runtime_error: HOLDS" in captured.out
    assert captured.err.count("warning: never reached") == WARNINGS_SHOWN
    left = UNREACHED - WARNINGS_SHOWN
    assert f"and {left} more warnings and notes ({left} RMC701): --all-warnings" \
        in captured.err, captured.err


def test_all_warnings_shows_each(tmp_path, capsys):
    assert main(["check", program(tmp_path), "--quiet", "--all-warnings"]) == 0
    err = capsys.readouterr().err
    assert err.count("warning: never reached") == UNREACHED
    assert "more warnings and notes" not in err


def test_json_and_sarif_keep_every_warning(tmp_path, capsys):
    path = program(tmp_path)
    main(["check", path, "--quiet", "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    assert sum(w["code"] == "RMC701" for w in report["warnings"]) == UNREACHED
    main(["check", path, "--quiet", "--format", "sarif"])
    sarif = json.loads(capsys.readouterr().out)
    results = [r for run in sarif["runs"] for r in run["results"]]
    assert sum(r["ruleId"] == "RMC701" for r in results) == UNREACHED


def test_warnings_come_before_notes_in_the_bounded_text():
    notes = [Diagnostic(ENCRYPTED_SKIPPED, f"module M{i}.sys is encrypted", None,
                        severity="note") for i in range(WARNINGS_SHOWN)]
    warning = Diagnostic(FIXED_READING, "ClkRead reads 1 s", None, severity="warning")
    text = warnings_text(notes + [warning])
    assert "ClkRead reads 1 s" in text
    assert "and 1 more warnings and notes (1 RMC735)" in text
    assert "ClkRead" in warnings_text(notes + [warning], every=True)
    assert "more warnings" not in warnings_text(notes + [warning], every=True)


def test_unreached_code_comes_after_what_the_verdicts_rest_on(tmp_path, capsys):
    """ECL 7600: 90 unreached stretches, then a ClkRead reading and the encrypted modules'
    notes; the reading and the notes are shown, stretches fill the rest."""
    path = program(tmp_path)
    source = open(path).read().replace("        n := 1;\n", "        n := ClkRead(clock);\n")
    open(path, "w").write(source.replace("    VAR num n := 0;\n",
                                         "    VAR num n := 0;\n    VAR clock clock;\n"))
    main(["check", path, "--quiet"])
    err = capsys.readouterr().err
    assert "[RMC702]" in err.split("warning: never reached")[0], err
    assert err.count("warning: never reached") == WARNINGS_SHOWN - 1
