"""Survey round 8 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not load or was mis-handled.

* ``binary_log.mod``: ``Open ... \\Write\\Bin`` / ``\\Read\\Bin``, ReadRawBytes without
  ``\\NoOfBytes`` (a line of hex pairs is the bytes of a binary file), ReadStr until ``EOF``.
* ``arc_monitor.mod``: ISignalAO with its three limits written positionally, WaitDI with
  RobotWare 6's ``\\Visualize`` arguments.
* ``seam_tracking.mod``: ArcWare ``trackdata`` declared with nested aggregates; the stubs
  shape it as nested records.
* ``approach_point.mod``: a missing name inside an aggregate assigned to a ``pos``.
* ``line_selector.mod``: signals named with the kind last (``Line_Gi``, ``Vacuum_Do``).
* ``axis_select.mod``: missing constants one value is compared with in turn.
* ``task_lists.mod``: a task list of a module not given, assigned as an aggregate.

The diagnostic for a call written ``Name(a, b);`` as a statement (round 7, left open) is
tested on texts inline: a function called as a procedure and a procedure given its arguments
in parentheses each get their own message at the name.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld_survey4 import cli, verdicts
from tests.test_realworld_survey7 import assert_holds, stubs_text

HERE = Path(__file__).resolve().parent / "realworld" / "survey8"

CALL_STATEMENTS = """MODULE Calls
  VAR num nValue;
  VAR bool bOk;
  PROC main()
    StrToVal("12", nValue);
    IF bOk THEN NumToStr(nValue,0); ENDIF
    bOk := TRUE; Scaled(nValue, 2);
    Shift(nValue, 2);
    nValue := Scaled(Max(nValue, 1), 2);
  ENDPROC
  FUNC num Scaled(num a, num b)
    RETURN a * b;
  ENDFUNC
  PROC Shift(INOUT num a, num b)
    a := a + b;
  ENDPROC
ENDMODULE
"""


def syntax_errors(tmp_path: Path, text: str) -> list[str]:
    program = tmp_path / "Calls.mod"
    program.write_text(text)
    code, out, err = cli("check", program, "--quiet")
    assert code == 2 and out == ""
    return err.splitlines()


@pytest.mark.parametrize("line, column, name", [(5, 5, "StrToVal"), (6, 17, "NumToStr"),
                                                (7, 18, "Scaled")])
def test_a_function_called_as_a_procedure_is_named_at_the_call(tmp_path, line, column, name):
    lines = syntax_errors(tmp_path, CALL_STATEMENTS)
    at = lines.index(next(text for text in lines if f"Calls.mod:{line}:{column}:" in text))
    assert lines[at].endswith(f"error: '{name}' is a function, called here as if it were a "
                              "procedure: a function call is not a statement; use its value, "
                              f"e.g. `result := {name}(...);` [RMC101]")
    assert lines[at + 2].strip() == "^" + "~" * (len(name) - 1)


def test_a_procedure_with_parenthesised_arguments_is_told_how_to_write_them(tmp_path):
    lines = syntax_errors(tmp_path, CALL_STATEMENTS)
    shift = [text for text in lines if "Calls.mod:8:5:" in text]
    assert shift == ["%s:8:5: error: procedure call with its arguments in parentheses: write "
                     "`Shift arg1, arg2;` (a function call is not a statement) [RMC101]"
                     % (tmp_path / "Calls.mod")]
    assert not any("unexpected ','" in text for text in lines)
    assert sum("[RMC101]" in text for text in lines) == 4     # the expression call is fine


def test_bin_goes_with_read_and_write_and_raw_bytes_are_read_without_a_count():
    program = HERE / "binary_log.mod"
    code, out, err = cli("check", program, "--quiet", "--file-lines", "07 00 2a",
                         "--formula", 'raw: G ("Ended()" -> "nBytesRead = 0 OR nBytesRead = 3")',
                         "--formula", 'some: G ("Ended()" -> "nBytesRead = 0")')
    assert code == 1, err
    found = verdicts(out)
    assert found["no_runtime_error"] == found["raw"] == "HOLDS", out
    assert found["some"] == "VIOLATED", out        # a line of hex pairs: the 3 bytes it stands for


def test_open_still_refuses_two_access_modes(tmp_path):
    program = tmp_path / "Modes.mod"
    program.write_text('MODULE Modes\n  VAR iodev f;\n  PROC main()\n'
                       '    Open "HOME:" \\File:="a.txt", f \\Read\\Write;\n  ENDPROC\nENDMODULE\n')
    code, _, err = cli("check", program, "--quiet")
    assert code == 2 and "arguments Read and Write of Open exclude each other [RMC205]" in err


def test_the_eof_constant_is_what_readstr_returns_at_the_end_of_a_file():
    program = HERE / "binary_log.mod"
    code, out, err = cli("check", program, "--quiet", "--file-lines", "OK",
                         "--formula", 'end: G !"bAtEnd"', "--formula", 'line: G !"bGotLine"')
    assert code == 1, err
    found = verdicts(out)
    assert found["end"] == found["line"] == "VIOLATED", out     # both branches are reached


def test_analog_interrupt_limits_are_positional_and_waits_take_visualize(tmp_path):
    program = HERE / "arc_monitor.mod"
    code, out, err = cli("check", program, "--quiet")
    assert code == 0, err
    assert set(verdicts(out).values()) == {"HOLDS"}
    without_limits = tmp_path / "NoLimits.mod"
    without_limits.write_text(program.read_text().replace("AIO_BETWEEN, 400, 0, 1,",
                                                          "AIO_BETWEEN,"))
    code, _, err = cli("check", without_limits, "--quiet")
    assert code == 2 and "ISignalAO" in err and "[RMC205]" in err


def test_stubs_shape_a_missing_type_declared_with_nested_aggregates(tmp_path):
    program = HERE / "seam_tracking.mod"
    text = stubs_text(program, tmp_path)
    assert ("RECORD trackdata\n    num c1;\n    bool c2;\n    num c3;\n"
            "    trackdata_c4 c4;\n    trackdata_c5 c5;\n  ENDRECORD") in text
    assert "RECORD trackdata_c4\n" + "".join(f"    num c{n};\n" for n in range(1, 10)) in text
    assert "RECORD trackdata_c5\n" + "".join(f"    num c{n};\n" for n in range(1, 8)) in text
    assert_holds(program, tmp_path / "Missing.mod",
                 formula='fill: G ("Ended()" -> "trackActive = trackFill")')


def test_signals_named_with_the_kind_last_are_configured_signals():
    program = HERE / "line_selector.mod"
    code, _, err = cli("check", program, "--quiet")     # nothing reads nLine: one value
    assert code == 0 and "Line_Gi: values 0 (stored into nLine, which no statement reads" in err
    code, _, err = cli("check", program, "--quiet", "--formula", 'line: G !"nLine = 7"',
                       "--exact-input-domains")
    assert code == 2 and "free GI input 'Line_Gi' needs a finite set of values" in err
    # without --exact-input-domains the property's 7 is among the values assumed and named
    code, out, _ = cli("check", program, "--quiet", "--formula", 'line: G !"nLine = 7"')
    assert code == 1 and "assumes: input Line_Gi takes only values 0, 1, 6, 7, 8" in out
    code, out, err = cli("check", program, "--quiet", "--input-domain", "Line_Gi=2,3",
                         "--formula", 'line: G ("Ended()" -> "nLine = 2 OR nLine = 3")',
                         "--formula", 'empty: G !"bEmpty"')
    assert code == 1, err
    found = verdicts(out)
    assert found["line"] == "HOLDS" and found["empty"] == "VIOLATED", out   # Suck_Gi may be 0


def test_an_empty_line_of_a_binary_file_gives_no_bytes():
    program = HERE / "binary_log.mod"
    code, out, err = cli("check", program, "--quiet",       # default: one empty line
                         "--formula", 'nothing: G ("Ended()" -> "nBytesRead = 0")')
    assert code == 0, err                                   # was: the read never ended
    assert set(verdicts(out).values()) == {"HOLDS"}, out


def test_stubs_give_names_compared_in_turn_distinct_numbers(tmp_path):
    program = HERE / "axis_select.mod"
    text = stubs_text(program, tmp_path)
    for name, number, count in (("axisX", 1, 3), ("axisY", 2, 3), ("axisZ", 3, 3),
                                ("STATION_LOAD", 1, 2), ("STATION_UNLOAD", 2, 2)):
        assert (f"PERS num {name} := {number}; ! {number} of the {count} names one value "
                "is compared with in turn") in text
    # with one neutral 0 for every name, no branch was taken
    assert_holds(program, tmp_path / "Missing.mod",
                 formula='picked: G ("Ended()" -> "vDir.y = 1 AND sStation = \\"load\\"")')


@pytest.mark.parametrize("program, declaration, formula", [
    # a part of an aggregate assigned to a pos is a num
    ("approach_point.mod", "PERS num xCameraOffset := 0;",
     'height: G ("Ended()" -> "pApproach.trans.z = 250")'),
    # data assigned an aggregate of task names is a task list of that size
    ("task_lists.mod", 'PERS tasks tlCurrent{3} := [[""],[""],[""]];',
     'second: G ("Ended()" -> "sSecond = \\"T_ROB2\\"")'),
])
def test_stubs_type_missing_data_from_the_aggregates_it_meets(tmp_path, program, declaration,
                                                               formula):
    text = stubs_text(HERE / program, tmp_path)    # was: type not inferred, left to the user
    assert declaration in text
    assert_holds(HERE / program, tmp_path / "Missing.mod", formula=formula)
