"""RMC702: the controller readings a check takes as fixed or sampled values are named.

Each case is a main routine body; the expected warnings are (routine as
written, line of its first call, number of calls).  Readings inside output
text (TPWrite, ErrWrite) decide nothing and are not reported, nor are user
routines that happen to share a predefined name.
"""
from __future__ import annotations

import json
import re

import pytest

from rapidmc import ast
from rapidmc.cli import main
from rapidmc.findings.fixed_readings import fixed_readings
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

HEAD = "MODULE Readings\n  VAR num speed := 0;\n  VAR clock cycle;\n  VAR string text;\n  PROC main()\n"
TAIL = "  ENDPROC\nENDMODULE\n"
FIRST_LINE = HEAD.count("\n") + 1


def warnings_of(body: str, extra: str = "", HEAD_ROBOT: bool = False) -> list[tuple[str, int, int]]:
    head = HEAD.replace("  PROC main()", ROBOT + "  PROC main()") if HEAD_ROBOT else HEAD
    text = head + body + TAIL.replace("ENDMODULE", extra + "ENDMODULE")
    program = build(ast.Program(parse_text(text, "readings.mod")))
    found = []
    for diagnostic in fixed_readings(program):
        assert diagnostic.code.code == "RMC702" and diagnostic.severity == "warning"
        name = diagnostic.message.split()[0]
        calls = int(re.search(r"\((\d+) calls?\)", diagnostic.message).group(1))
        found.append((name, diagnostic.span.line - FIRST_LINE + 1 - HEAD_ROBOT, calls))
    return found


@pytest.mark.parametrize("body, expected", [
    ("    IF OpMode() = OP_AUTO speed := 100;\n", [("OpMode", 1, 1)]),
    ("    IF RunMode() = RUN_CONT_CYCLE speed := 1;\n    IF OpMode() = OP_MAN_PROG speed := 2;\n"
     "    IF RunMode() = RUN_STEP_MOVE speed := 3;\n", [("RunMode", 1, 2), ("OpMode", 2, 1)]),
    ("    ClkStart cycle;\n    speed := 3600 / ClkRead(cycle);\n", [("ClkRead", 2, 1)]),
    ('    TPWrite "Started " + CDate() + " " + CTime();\n', []),
    ('    ErrWrite "Stopped", "at " + CTime();\n', []),
    ('    text := CDate();\n', [("CDate", 1, 1)]),
    ("    speed := speed + 1;\n", []),
])
def test_fixed_and_sampled_readings(body, expected):
    assert warnings_of(body) == expected


def test_a_user_routine_with_a_predefined_name_is_not_a_reading():
    user = "  FUNC bool RobOS()\n    RETURN FALSE;\n  ENDFUNC\n"
    assert warnings_of("    IF RobOS() speed := 1;\n", user) == []


def test_the_warning_is_in_the_json_report_beside_the_verdicts(tmp_path, capsys):
    program = tmp_path / "prog.mod"
    program.write_text(HEAD + "    IF OpMode() = OP_AUTO THEN\n      speed := 100;\n    ELSE\n"
                       "      speed := 10;\n    ENDIF\n" + TAIL)
    code = main(["check", str(program), "--format", "json", "--quiet"])
    document = json.loads(capsys.readouterr().out)
    assert code == 0
    assert [(w["code"], w["location"]["line"]) for w in document["warnings"]] == \
        [("RMC702", FIRST_LINE), ("RMC701", FIRST_LINE + 3)]


def test_the_html_page_shades_only_unreached_lines_not_readings(tmp_path, capsys):
    program = tmp_path / "prog.mod"
    program.write_text(HEAD + "    IF OpMode() = OP_AUTO THEN\n      speed := 100;\n    ELSE\n"
                       "      speed := 10;\n    ENDIF\n" + TAIL)
    page = tmp_path / "report.html"
    main(["check", str(program), "--html", str(page), "--quiet"])
    capsys.readouterr()
    text = page.read_text()
    data = json.loads(text.split('id="report-data"', 1)[1].split(">", 1)[1].split("</script>")[0])
    assert [entry["line"] for entry in data["unreached"]] == [FIRST_LINE + 3]


ROBOT = "  VAR robtarget seen;\n"


@pytest.mark.parametrize("body, expected", [
    # T_ROB1 is the one task loaded (the main task's controller name): its robot is kept
    ('    seen := CRobT(\\TaskName:="T_ROB1");\n', []),
    ('    seen := CRobT(\\TaskRef:=T_ROB1Id);\n', []),
    ('    seen := CRobT();\n', []),
    # no loaded task of that name: the calling task's robot is read, and said so
    ('    seen := CRobT(\\TaskName:="T_ROB2");\n    seen := CRobT(\\TaskName:="T_ROB2");\n',
     [("CRobT", 1, 2)]),
    ('    speed := CJointT(\\TaskName:="T_ROB2").robax.rax_1;\n', [("CJointT", 1, 1)]),
    # a name known only when the program runs
    ('    text := "T_ROB1";\n    seen := CRobT(\\TaskName:=text);\n', [("CRobT", 2, 1)]),
])
def test_a_robot_reading_of_a_task_not_loaded_is_named(body, expected):
    """``CRobT(\\TaskName:=...)``, ``\\TaskRef``: the named task's robot where the check
    loads that task (tests/check/tasks_crobt_named_task), else the calling task's, with a
    warning that says so."""
    assert warnings_of(body, HEAD_ROBOT=True) == expected
