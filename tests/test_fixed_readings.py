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

from rapidmc import api, ast
from rapidmc.cli import main
from rapidmc.findings.fixed_readings import fixed_readings
from rapidmc.findings.start_positions import named_targets
from rapidmc.semantics.values import UNCONNECTED_AXIS
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

HEAD = ("MODULE Readings\n  VAR num speed := 0;\n  VAR clock cycle;\n  VAR string text;\n"
        "  VAR socketdev link;\n  PROC main()\n")
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
    # the end point of a socket: the model's sockets never read it (the ROS drivers' bind)
    ("    SocketBind link, GetSysInfo(\\LanIp), 11002;\n", []),
    ('    SocketConnect link, GetSysInfo(\\LanIp), 1025 + Round(ClkRead(cycle));\n', []),
    ("    text := GetSysInfo(\\LanIp);\n    SocketBind link, text, 11002;\n",
     [("GetSysInfo", 1, 1)]),
])
def test_fixed_and_sampled_readings(body, expected):
    assert warnings_of(body) == expected


def test_a_user_routine_with_a_predefined_name_is_not_a_reading():
    user = "  FUNC bool RobOS()\n    RETURN FALSE;\n  ENDFUNC\n"
    assert warnings_of("    IF RobOS() speed := 1;\n", user) == []


def test_the_warning_is_in_the_json_report_beside_the_verdicts(tmp_path, capsys):
    program = tmp_path / "prog.mod"
    program.write_text(HEAD + "    IF CDate() = \"2026-01-01\" THEN\n      speed := 100;\n    ELSE\n"
                       "      speed := 10;\n    ENDIF\n" + TAIL)
    code = main(["check", str(program), "--format", "json", "--quiet"])
    document = json.loads(capsys.readouterr().out)
    assert code == 0
    assert [(w["code"], w["location"]["line"]) for w in document["warnings"]] == \
        [("RMC702", FIRST_LINE), ("RMC701", FIRST_LINE + 3)]


def test_the_html_page_shades_only_unreached_lines_not_readings(tmp_path, capsys):
    program = tmp_path / "prog.mod"
    program.write_text(HEAD + "    IF CDate() = \"2026-01-01\" THEN\n      speed := 100;\n    ELSE\n"
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


# --- the readings probe (library.probed_readings): other readings a controller gives ---

MODES = """MODULE Modes
  VAR num mode := 0;
  VAR num host := 0;
  PROC main()
    TEST OpMode()
    CASE OP_AUTO:
      mode := 1;
    CASE OP_MAN_PROG:
      mode := 2;
    CASE OP_MAN_TEST:
      mode := 3 / 0;
    DEFAULT:
      mode := 4;
    ENDTEST
    IF RobOS() THEN
      host := 1;
    ENDIF
    IF RunMode() = RUN_STEP_MOVE host := 2;
  ENDPROC
ENDMODULE
"""


def line_of(text: str, code: str) -> int:
    return next(number for number, line in enumerate(text.splitlines(), 1) if code in line)


def test_code_another_controller_reading_runs_counts_as_reached(tmp_path):
    """A TEST over OpMode, a branch on RobOS and on RunMode: every arm runs on some real
    controller (manual mode, the robot's own operating system, stepwise), so the readings
    probe shows each reached, OP_UNDEF's DEFAULT included.  The verdicts keep the fixed
    readings: the division by zero of manual test mode is no run-time error of the check
    (RMC702 says the verdicts hold for that value only)."""
    path = tmp_path / "modes.mod"
    path.write_text(MODES)
    report = api.check(api.load_program([str(path)]))
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    assert [w.code.code for w in report.warnings] == ["RMC702", "RMC702", "RMC702"]
    for code in ("mode := 2;", "mode := 3 / 0;", "mode := 4;", "host := 1;", "host := 2;"):
        assert (str(path), line_of(MODES, code)) in report.executed, code


def test_a_readings_probe_the_bound_stops_keeps_the_wording(tmp_path, monkeypatch):
    """A readings probe stopped by its bound shows nothing about the lines it did not run:
    their warnings still name the fixed reading."""
    monkeypatch.setattr(api, "PROBE_STATES", 1)
    path = tmp_path / "modes.mod"
    path.write_text(MODES)
    warnings = [w.message for w in api.check(api.load_program([str(path)])).warnings
                if w.code.code == "RMC701"]
    assert warnings and all("readings fixed (OpMode at line 5; RobOS at line 15; "
                            "RunMode at line 18)" in m for m in warnings)


def test_dead_code_beside_a_reading_stays_unreached_under_any_input(tmp_path):
    """Freeing the readings makes no line reached that no reading reaches: code after an
    endless loop stays unreached, now "under any input" (the probe was complete)."""
    path = tmp_path / "modes.mod"
    path.write_text(MODES.replace("  ENDPROC", "    WHILE TRUE DO\n      WaitTime 1;\n"
                                  "    ENDWHILE\n    host := 3;\n  ENDPROC"))
    warnings = [w.message for w in api.check(api.load_program([str(path)])).warnings
                if w.code.code == "RMC701"]
    assert warnings == ["never reached under any input: the code after the endless "
                        "WHILE loop at line 19"]


def test_a_reading_called_all_over_a_backup_names_five_lines_and_counts_the_rest():
    """Survey of public backups: MaxRobSpeed at 39 lines made three warnings of 400
    characters each; the warning names the first five lines and counts the others."""
    from rapidmc import ast
    from rapidmc.findings.tried_inputs import FIXED, TriedInput, qualifier
    inputs = [TriedInput(FIXED, "MaxRobSpeed", ast.Span("a.mod", line, 5))
              for line in (55, 60, 80, 85, 90, 95, 109)] + \
        [TriedInput(FIXED, "OpMode", ast.Span("a.mod", 7, 5))]
    assert qualifier(inputs) == ("with the controller's readings fixed (MaxRobSpeed at lines "
                                 "55, 60, 80, 85, 90 and 2 more; OpMode at line 7)")


REACH = """MODULE Reach
    VAR robtarget goal := [[500,0,400],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR num failures := 0;
    PROC main()
        VAR bool moved;
        moved := MoveTo(goal);
        IF NOT moved THEN
            failures := failures + 1;
        ENDIF
        WHILE TRUE DO
            WaitTime 1;
        ENDWHILE
    ENDPROC
    FUNC bool MoveTo(robtarget target)
        VAR jointtarget joints;
        joints := CalcJointT(target, tool0 \\WObj:=wobj0);
        IF joints.robax.rax_1 > 90 THEN
            failures := -1;
        ENDIF
        MoveAbsJ joints, v100, z100, tool0;
        RETURN TRUE;
    ERROR
        IF ERRNO = ERR_ROBLIMIT THEN
            RETURN FALSE;
        ENDIF
    ENDFUNC
ENDMODULE
"""


def test_a_handler_for_a_target_out_of_reach_is_reached_by_the_readings_probe(tmp_path):
    """The check takes every target as reachable; a controller raises ERR_ROBLIMIT in
    CalcJointT for one out of reach.  The readings probe lets each call fail, so the
    handler and the branch its answer feeds count as reached, while the verdicts keep
    reachable targets.  CalcJointT's value stays fixed when it succeeds (no kinematics),
    so code that depends on the joints it computes keeps naming it."""
    path = tmp_path / "reach.mod"
    path.write_text(REACH)
    report = api.check(api.load_program([str(path)]))
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    for code in ("failures := failures + 1;", "RETURN FALSE;"):
        assert (str(path), line_of(REACH, code)) in report.executed, code
    assert [w.message for w in report.warnings if w.code.code == "RMC701"] == [
        "never reached with the controller's readings fixed (CalcJointT at line 16)"]


def test_calc_rob_t_reads_a_fixed_target_with_the_joint_targets_external_axes(tmp_path, capsys):
    """Survey of issue 28: gantry tasks compute a robtarget from joints they read back, and
    the check stopped at CalcRobT (no kinematics). It now reads the target the robot has (as
    CRobT does) with the joint target's external axes, named as a fixed reading (RMC702)."""
    path = tmp_path / "gantry.mod"
    path.write_text("""MODULE Gantry
  VAR jointtarget joints := [[0, 0, 0, 0, 30, 0], [1500, 9E9, 9E9, 9E9, 9E9, 9E9]];
  VAR robtarget above;
  PROC main()
    MoveL [[500, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;
    above := CalcRobT(joints, tool0);
    TPWrite "x " \\Num:=above.trans.x;
    TPWrite "gantry " \\Num:=above.extax.eax_a;
  ENDPROC
ENDMODULE
""")
    assert main(["run", str(path)]) == 0
    assert capsys.readouterr().out == "x 500\ngantry 1500\n"
    assert warnings_of("    speed := CalcRobT(CJointT(), tool0).trans.z;\n") == [("CalcRobT", 1, 1)]


AXES = """MODULE Axes
    VAR num connected := 0;
    VAR num manual := 0;
    PROC main()
        VAR jointtarget joints;
        VAR robtarget here;
        joints := CJointT();
        IF joints.extax.eax_a <> 9E9 THEN
            connected := connected + 1;
        ENDIF
        here := CRobT(\\Tool:=tool0 \\WObj:=wobj0);
        IF here.extax.eax_b <> 9E9 THEN
            connected := connected + 2;
        ENDIF
        IF OpMode() = OP_MAN_PROG manual := 1;
    ENDPROC
ENDMODULE
"""


def test_code_for_external_axes_is_reached_by_the_readings_probe(tmp_path):
    """The ROS modules convert each external axis unless it reads 9E9 (not connected):
    the check's robot has none, but the driver runs on cells that have them.  The readings
    probe lets CJointT and CRobT read the axes connected, so that code counts as reached
    instead of "never reached under any input" once the probe freed OpMode; the verdicts
    keep the modelled robot."""
    path = tmp_path / "axes.mod"
    path.write_text(AXES)
    report = api.check(api.load_program([str(path)]))
    assert report.verdicts == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
    for code in ("connected := connected + 1;", "connected := connected + 2;",
                 "manual := 1;"):
        assert (str(path), line_of(AXES, code)) in report.executed, code
    assert [w for w in report.warnings if w.code.code == "RMC701"] == []


@pytest.mark.parametrize("test, named", [("<> 9E9", True), ("<> 9000000000", True),
                                        ("< 100", False)])
def test_only_a_program_that_tells_axes_apart_has_them_connected(tmp_path, monkeypatch,
                                                                  test, named):
    """Connecting the axes doubles a probe's states after each CRobT: only a program that
    compares a value with 9E9 (the value of an axis a robot lacks) gets it, and only there
    does a probe the bound stops leave CJointT and CRobT named."""
    from rapidmc.findings import tried_inputs
    from rapidmc.findings.tried_inputs import tests_axes
    # (the reads compared with 100 also rest on the robot's start position, which names
    # CJointT and CRobT under a phrase of its own: left out here, pinned in
    # test_a_branch_on_a_position_read_back_names_the_start_position)
    monkeypatch.setattr(tried_inputs, "start_position_reads", lambda program: [])
    monkeypatch.setattr(api, "PROBE_STATES", 1)
    monkeypatch.setattr(api, "PROBE_GROWTH", 1)
    path = tmp_path / "axes.mod"
    path.write_text(AXES.replace("<> 9E9", test))
    program = api.load_program([str(path)])
    assert tests_axes(program) == named
    warnings = [w.message for w in api.check(program).warnings if w.code.code == "RMC701"]
    assert warnings and all(("CJointT at line 7; CRobT at line 11" in m) == named
                            for m in warnings)


START = """
MODULE Start
    VAR num steps := 0;
    PROC main()
        VAR robtarget here;
        here := CRobT();
        IF here.trans.z < 500 THEN
            steps := steps + 1;
        ELSE
            steps := steps + 2;
        ENDIF
        MoveL Offs(CRobT(), 0, 0, 10), v100, fine, tool0;
    ENDPROC
ENDMODULE
"""


def test_a_branch_on_a_position_read_back_names_the_start_position(tmp_path):
    """The check's robot starts at its home position, a real one wherever it was left: a
    branch on a position read back is not "never reached under any input", and the
    verdicts say what they assume.  A read that only shapes a move's target (line 12) is
    not named."""
    path = tmp_path / "start.mod"
    path.write_text(START)
    report = api.check(api.load_program([str(path)]))
    warnings = [w.message for w in report.warnings if w.code.code == "RMC701"]
    assert warnings == ["never reached with the robot starting at the check's home "
                        "position (CRobT at line 6)"]
    result = next(r for r in report.results if r.name == "no_runtime_error")
    assert list(result.assumes) == [
        "the robot starts at the check's home position (every coordinate 0); CRobT at "
        "start.mod:6 reads where it is"]


TAUGHT = """
MODULE Taught
    CONST robtarget pPick := [[100,0,800],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    VAR num steps := 0;
    PROC main()
        VAR robtarget here;
        here := CRobT();
        IF here.trans.z > pPick.trans.z - 100 THEN
            steps := 1;
        ELSEIF here.trans.z < -100 THEN
            steps := 3;
        ENDIF
        MoveL pPick, v100, fine, tool0;
    ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("targets_tried", [True, False])
def test_a_robot_starting_at_a_named_target_reaches_its_branch(tmp_path, monkeypatch,
                                                               targets_tried):
    """A start-up routine's branch for a robot found at a taught position (Hanoi's
    ``rMoveHome``) runs when the readings probe starts the robot at the targets the program
    compares a position with (``start_positions``): only the branch no such target
    reaches is left, still naming the start.  Without the targets both branches are
    reported."""
    if not targets_tried:
        monkeypatch.setattr(api, "named_targets", lambda program: ())
    path = tmp_path / "taught.mod"
    path.write_text(TAUGHT)
    report = api.check(api.load_program([str(path)]))
    warnings = [(w.span.line, w.message) for w in report.warnings if w.code.code == "RMC701"]
    left = [(11, "never reached with the robot starting at the check's home position "
                 "(CRobT at line 7)")]
    # without the targets, both arms of one IF: one warning (one cause) naming each
    expected = left if targets_tried else [
        (9, "never reached with the robot starting at the check's home position "
            "(CRobT at line 7): the code the IF at line 8 never enters (lines 9, 11 of main)")]
    assert warnings == expected
    assert named_targets(api.load_program([str(path)])) == (
        ((100.0, 0.0, 800.0), (1.0, 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 0.0), (UNCONNECTED_AXIS,) * 6),)
