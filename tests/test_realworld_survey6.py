"""Survey round 6 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not load.

* ``tray_sorter.mod``: a group input read only as the subject of a TEST whose CASEs are
  numbers (``TEST giRecipe CASE 1:``) is a configured signal, as one compared with ``=``
  is; a conveyor named only in ActUnit/DeactUnit (``CNV1``) is a mechanical unit of the
  motion configuration.
* ``yumi_arm_stream.mod``: YuMi's arm ``ROB_L`` passed to EGMSetupUC is a mechanical unit
  too.
* ``pendant_texts.mod``: a missing number used as an array index gets 1 from
  ``rapidmc stubs`` (0 is outside every RAPID array).
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld_survey4 import cli, verdicts

HERE = Path(__file__).resolve().parent / "realworld" / "survey6"


def test_a_group_input_read_only_by_test_is_a_configured_signal():
    program = HERE / "tray_sorter.mod"
    code, out, err = cli("check", program, "--quiet",
                         "--formula", 'trays_bounded: G "nInA <= 2 AND nInB <= 2"',
                         "--formula", 'both_trays: G ("nInA + nInB = 4" -> "doVacuum = 0")')
    assert code == 0, err
    assert set(verdicts(out).values()) == {"HOLDS"}
    # the default domain of an input only compared with numbers names the CASE values
    assert "giRecipe: values 0..3 (group input only compared with 1, 2) [RMC515]" in err


def refusal(tmp_path, module: str, text: str) -> str:
    """The errors ``check`` reports for module ``module`` with the body ``text``."""
    program = tmp_path / f"{module}.mod"
    program.write_text(f"MODULE {module}\n{text}ENDMODULE\n")
    code, _, err = cli("check", program, "--quiet")
    assert code == 2
    return err


def test_a_test_subject_with_string_cases_is_not_taken_for_a_signal(tmp_path):
    err = refusal(tmp_path, "names", "  PROC main()\n    TEST sMode\n    CASE \"auto\":\n"
                  "      TPWrite \"a\";\n    ENDTEST\n  ENDPROC\n")
    assert "unknown name 'sMode' [RMC201]" in err


@pytest.mark.parametrize("program", ["tray_sorter.mod", "yumi_arm_stream.mod"])
def test_mechanical_units_of_the_configuration_need_no_declaration(program, tmp_path):
    code, out, err = cli("check", HERE / program, "--quiet")
    assert code == 0, err
    assert verdicts(out)["no_runtime_error"] == "HOLDS"
    # and the stubs leave them to the configuration too: nothing is missing
    code, _, err = cli("stubs", HERE / program, "-o", tmp_path / "Missing.mod")
    assert "CNV1" not in err and "ROB_L" not in err
    assert not (tmp_path / "Missing.mod").exists() or "mecunit" not in \
        (tmp_path / "Missing.mod").read_text()


def test_a_declared_mechanical_unit_name_is_not_redeclared(tmp_path):
    err = refusal(tmp_path, "own", "  VAR num CNV1 := 3;\n  PROC main()\n"
                  "    ActUnit CNV1;\n  ENDPROC\n")
    assert "CNV1" in err                        # a num where a mecunit is required


def test_stubs_start_a_missing_array_index_at_the_first_element(tmp_path):
    program = HERE / "pendant_texts.mod"
    output = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", output)
    assert code == 0, err
    text = output.read_text()
    assert "PERS num nLanguage := 1; ! an array index" in text
    assert "PERS string sTitle{10} :=" in text
    code, out, err = cli("check", program, output, "--quiet")
    assert code == 0, err
    assert verdicts(out)["no_runtime_error"] == "HOLDS"


def test_booked_error_numbers_in_handler_lists_are_caught_by_their_handler():
    program = HERE / "booked_recovery.mod"
    code, out, err = cli("check", program, "--quiet",
                         "--formula", "right_handler: G !bWrongHandler",
                         "--formula", 'recovers: G ("Ended()" -> "nRecovered + 2 >= nAttempts")',
                         "--formula", 'ends: F "Ended()"')
    assert code == 0, err
    assert set(verdicts(out).values()) == {"HOLDS"}, out
    # the handler that lists the other booked number never runs
    assert "booked_recovery.mod:26:5: warning: lines 26-27 of Pick are never reached" in err


def test_booked_numbers_are_raisable_and_the_same_in_every_load(tmp_path):
    program = tmp_path / "book.mod"
    program.write_text("MODULE book\n  VAR errnum ERR_A := -1;\n  VAR errnum ERR_B := -1;\n"
                       "  PROC main()\n    BookErrNo ERR_A;\n    BookErrNo ERR_B;\n"
                       "    TPWrite \"\" \\Num:=ERR_A;\n    TPWrite \"\" \\Num:=ERR_B;\n"
                       "    RAISE ERR_B;\n  ERROR\n    TPWrite \"caught\" \\Num:=ERRNO;\n"
                       "  ENDPROC\nENDMODULE\n")
    runs = [cli("run", program) for _ in range(2)]
    assert runs[0] == runs[1]                    # no numbering carried over between loads
    code, out, err = runs[0]
    assert code == 0, err
    assert out.split() == ["90", "89", "caught89"]


def test_routine_data_in_a_handler_list_is_still_refused(tmp_path):
    err = refusal(tmp_path, "routine_data", "  PROC main()\n    VAR errnum nMine := 5;\n"
                  "    RAISE 5;\n  ERROR (nMine)\n    TRYNEXT;\n  ENDPROC\n")
    assert "[RMC213]" in err


def test_numbers_of_the_program_compared_with_numbers_are_not_taken_for_signals(tmp_path):
    program = HERE / "seam_schedule.mod"
    code, _, err = cli("check", program, "--quiet")
    # ``nThickness <= 2.9`` and ``TEST nStation CASE 3:`` read numbers of a missing module;
    # ``partSensor = 1`` (no prefix, equality with 1) is still a digital input
    assert code == 2
    assert "unknown name 'nThickness'" in err and "unknown name 'nStation'" in err
    assert "partSensor" not in err
    output = tmp_path / "Missing.mod"
    code, _, err = cli("stubs", program, "-o", output)
    assert code == 0, err
    text = output.read_text()
    assert "PERS num nThickness := 0;" in text and "PERS num nStation := 0;" in text
    assert "partSensor" not in text
    # the stubs' PERS numbers are read and never written: data written outside the loaded
    # code (issue 28), so the thickness takes the values it is compared with and the alarm
    # branch runs; --fixed-outside-data keeps the stubs' neutral 0 (no alarm)
    code, out, err = cli("check", program, output, "--quiet", "--formula", "no_alarm: G !bAlarm")
    assert code == 1 and verdicts(out)["no_alarm"] == "VIOLATED", err
    assert "assumes: PERS nThickness is written outside the loaded code" in out
    code, out, err = cli("check", program, output, "--quiet", "--fixed-outside-data",
                         "--formula", "no_alarm: G !bAlarm")
    assert code == 0 and verdicts(out)["no_alarm"] == "HOLDS", err


def test_signal_parameters_can_be_handed_on_and_read():
    program = HERE / "beam_guard.mod"
    code, out, err = cli("run", program, "--io", "diLaser=1")
    assert code == 0, err                       # was an internal error (a signal index
    code, out, err = cli("check", program, "--quiet",       # read as a reference)
                         "--formula", 'two_pulses: G ("Ended()" -> "nPulses = 2")',
                         "--formula", 'clamp_after_beam: G ("doClamp = 1" -> bBeamSteady)')
    assert code == 0, err
    assert set(verdicts(out).values()) == {"HOLDS"}
