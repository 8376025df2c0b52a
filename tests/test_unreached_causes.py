"""One coverage warning (RMC701) per cause, every stretch kept (findings/unreached_causes.py).

Each program below has one dead cause that gives several stretches: the arms of one TEST
that a client's command never opens, the code after an endless server loop and the
procedures only it calls, ERROR handlers no error enters.  The grouped warning names the
cause and lists each stretch; a differential check against the same report without
grouping shows that no reported line is lost, in the report's objects and in JSON, SARIF
and text.
"""
from __future__ import annotations

import json

import pytest

from rapidmc import api
from rapidmc.cli import main
from rapidmc.findings import coverage as coverage_module

# A client's command picks one arm of a TEST; the check tries 'A', 'B' and one the
# program does not expect, so the "C" and "D" arms are never reached with the messages
# tried, nor are the two arms of the IF on the state they set (and Clean, called only in
# the first): one cause, the IF.  The lines after the endless loop are dead under any
# input, and so is Report, which only they call: one cause, the loop.
TEST_ARMS = """MODULE Server
  VAR socketdev server;
  VAR socketdev client;
  VAR string command := "";
  VAR num state := 0;
  PROC main()
    SocketCreate server;
    SocketBind server, "0.0.0.0", 1025;
    SocketListen server;
    SocketAccept server, client \\Time:=WAIT_MAX;
    WHILE TRUE DO
      SocketReceive client \\Str:=command \\Time:=WAIT_MAX;
      TEST command
      CASE "A":
        state := 1;
      CASE "B":
        state := 2;
      CASE "C" + "":
        state := 3;
      CASE "D" + "":
        state := 6;
      DEFAULT:
        state := 0;
      ENDTEST
      IF state > 5 THEN
        state := 4;
        Clean;
      ELSEIF state < -5 THEN
        state := 5;
      ENDIF
    ENDWHILE
    SocketClose client;
    Report;
  ENDPROC
  PROC Clean()
    state := 0;
  ENDPROC
  PROC Report()
    state := -1;
  ERROR
    RAISE;
  ENDPROC
  PROC Tell()
    state := -2;
  ERROR
    RAISE;
  ENDPROC
  PROC Ask()
    Tell;
    state := 3;
  ERROR
    RAISE;
  ENDPROC
  PROC Wait(num n)
    Ask;
  ENDPROC
ENDMODULE
"""

# ERROR handlers that no error enters (only `RAISE;`, as the ROS servers' routines), in
# three procedures the program calls: one warning naming the three.
HANDLERS = """MODULE Handlers
  VAR num count := 0;
  PROC main()
    WHILE count < 3 DO
      First;
      Second;
      Third count;
    ENDWHILE
  ENDPROC
  PROC First()
    count := count + 1;
  ERROR
    RAISE;
  ENDPROC
  PROC Second()
    count := count + 0;
  ERROR
    RAISE;
  ENDPROC
  PROC Third(num n)
    count := n;
  ERROR
    RAISE;
  ENDPROC
ENDMODULE
"""


def check(tmp_path, text: str, name: str = "prog.mod") -> api.CheckReport:
    path = tmp_path / name
    path.write_text(text)
    return api.check(api.load_program([str(path)]))


def unreached(report: api.CheckReport) -> list:
    return [w for w in report.warnings if w.code.code == "RMC701"]


def lines(warnings) -> list[tuple[int, int]]:
    """Every place of the warnings, as (first, last line), sorted."""
    return sorted((span.line, max(span.line, span.end_line))
                  for w in warnings for span in (w.span, *w.places))


def ungrouped(program, found, wording):
    return [item.diagnostic(inputs) for item, inputs in zip(found, wording)]


@pytest.mark.parametrize("text", [TEST_ARMS, HANDLERS])
def test_grouping_loses_no_place(tmp_path, monkeypatch, text):
    """The grouped warnings hold the same stretches and routines as one warning each."""
    grouped = unreached(check(tmp_path, text))
    monkeypatch.setattr(coverage_module, "group_by_cause", ungrouped)
    alone = unreached(check(tmp_path, text))
    assert lines(grouped) == lines(alone)
    assert len(grouped) < len(alone)


def test_one_warning_per_cause_names_the_cause_and_each_stretch(tmp_path):
    """The IF's two arms and Clean (called only in the first): one warning; the lines
    after the endless loop and Report (called only there): one; the TEST's arms no
    message opens form one stretch already and keep their message."""
    warnings = unreached(check(tmp_path, TEST_ARMS))
    tried = "with the socket messages tried (SocketReceive at line 12)"
    assert [(w.span.line, w.message, [(p.line, p.end_line) for p in w.places])
            for w in warnings] == [
        (19, f"lines 19-21 of main are never reached {tried}", []),
        (26, f"never reached {tried}: the code the IF at line 25 never enters (lines 26-27, "
             "29 of main) and the routine only that code calls (Clean)", [(29, 29), (35, 37)]),
        (32, "never reached under any input: the code after the endless WHILE loop at line "
             "11 (lines 32-33 of main) and the routine only that code calls (Report)",
         [(38, 42)]),
        (43, "never reached under any input: 3 routines no call reaches (Tell, Ask, Wait)",
         [(48, 53), (54, 56)])]


def test_error_handlers_no_error_enters_are_one_warning(tmp_path):
    [warning] = unreached(check(tmp_path, HANDLERS))
    assert warning.message == ("never reached under any input: ERROR handlers no error "
                               "enters (line 13 of First; line 18 of Second; line 23 of Third)")
    assert (warning.span.line, [p.line for p in warning.places]) == (13, [18, 23])


def test_json_sarif_and_text_carry_every_place(tmp_path, monkeypatch, capsys):
    (tmp_path / "prog.mod").write_text(HANDLERS)
    monkeypatch.chdir(tmp_path)
    main(["check", "prog.mod", "--quiet", "--format", "json"])
    [warning] = [w for w in json.loads(capsys.readouterr().out)["warnings"]
                 if w["code"] == "RMC701"]
    assert [(one["line"], one["end_line"]) for one in warning["lines"]] == \
        [(13, 13), (18, 18), (23, 23)]
    main(["check", "prog.mod", "--quiet", "--format", "sarif"])
    [result] = [r for r in json.loads(capsys.readouterr().out)["runs"][0]["results"]
                if r["ruleId"] == "RMC701"]
    assert [r["physicalLocation"]["region"]["startLine"] for r in result["relatedLocations"]] \
        == [18, 23]
    main(["check", "prog.mod", "--quiet"])
    assert "note: 2 more places: prog.mod lines 18, 23" in capsys.readouterr().err


def after_the_loop(code: str, data: str, routines: str) -> str:
    """TEST_ARMS with ``code`` after the endless loop's code, ``data`` declared after
    ``state`` and ``routines`` before Clean."""
    return TEST_ARMS.replace("    Report;\n", "    Report;\n" + code).replace(
        "  VAR num state := 0;\n", "  VAR num state := 0;\n" + data).replace(
        "  PROC Clean()", routines + "  PROC Clean()")


def test_functions_called_only_after_the_endless_loop_join_its_warning(tmp_path):
    """Two functions called only after the endless loop never run whatever a client
    sends, as Report does: one warning "under any input" with the loop's other code
    (``coverage._called_from_dead_code`` counts functions as well as procedures)."""
    text = after_the_loop("    state := Half(Twice(state));\n", "",
                          "  FUNC num Twice(num x)\n    RETURN 2 * x;\n  ENDFUNC\n"
                          "  FUNC num Half(num x)\n    RETURN x / 2;\n  ENDFUNC\n")
    warnings = {w.span.line: w for w in unreached(check(tmp_path, text))}
    assert warnings[32].message == (
        "never reached under any input: the code after the endless WHILE loop at line 11 "
        "(lines 32-34 of main) and the routines only that code calls (Twice, Half, Report)")
    assert [(p.line, p.end_line) for p in warnings[32].places] == [(36, 38), (39, 41), (45, 49)]


def test_routines_worded_apart_from_the_code_that_calls_them_are_one_warning(tmp_path):
    """Two TRAPs connected only after the endless loop share its cause, but keep the
    wording of the inputs tried (``coverage`` never counts a TRAP as called only from dead
    code), so they are a warning of their own that names the code connecting them."""
    text = after_the_loop("    CONNECT tick WITH OnTick;\n    CONNECT tock WITH OnTock;\n",
                          "  VAR intnum tick;\n  VAR intnum tock;\n",
                          "  TRAP OnTick\n    state := 7;\n  ENDTRAP\n"
                          "  TRAP OnTock\n    state := 8;\n  ENDTRAP\n")
    warnings = {w.span.line: w for w in unreached(check(tmp_path, text))}
    assert warnings[39].message == (
        "never reached with the socket messages tried (SocketReceive at line 14): routines "
        "OnTick, OnTock, called only in the code after the endless WHILE loop at line 13")
    assert [(p.line, p.end_line) for p in warnings[39].places] == [(42, 44)]

# MARC-HT25's format check, copied after each StrFind: StrFind from start_index returns
# start_index or more (StrLen + 1 when not found), so "end_index < start_index" never
# holds.  The two copies are one cause; the IF on another test stays a warning of its own.
SAME_TEST = TEST_ARMS.split("      TEST command")[0].replace(
    "  VAR num state := 0;\n", "  VAR num first := 0;\n  VAR num bad := 0;\n") + """      Fields;
    ENDWHILE
  ENDPROC
  PROC Fields()
    VAR num start_index := 1;
    VAR num end_index := 0;
    end_index := StrFind(command, start_index, ",");
    IF end_index < start_index THEN
      bad := 1;
    ENDIF
    first := end_index;
    start_index := end_index + 1;
    end_index := StrFind(command, start_index, ",");
    IF end_index  <  start_index THEN
      bad := 2;
    ENDIF
    IF end_index < 0 THEN
      bad := 3;
    ENDIF
    first := end_index;
  ENDPROC
ENDMODULE
"""


def test_ifs_of_one_test_never_true_are_one_warning(tmp_path, monkeypatch):
    """The two IFs testing 'end_index < start_index' (written with other spaces) are one
    warning naming the test and both arms; the IF on another test keeps its own."""
    warnings = unreached(check(tmp_path, SAME_TEST))
    tried = "with the socket messages tried (SocketReceive at line 13)"
    assert [(w.span.line, w.message, [p.line for p in w.places]) for w in warnings] == [
        (22, f"never reached {tried}: the code IFs testing 'end_index < start_index' never "
             "enter (lines 22, 28 of Fields)", [28]),
        (31, f"never reached {tried}", [])]
    monkeypatch.setattr(coverage_module, "group_by_cause", ungrouped)
    assert lines(unreached(check(tmp_path, SAME_TEST))) == lines(warnings)
