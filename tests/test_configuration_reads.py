"""ReadCfgData against a backup's SYSPAR files and a standard robot's instances (issue 19).

A backup's configuration file is the truth for its domain: an instance it lists is found
with the value it writes, one it does not list is not found. Without the file, the
instances of a standard six-axis robot are found with values rapidmc does not know.
"""
from __future__ import annotations

from pathlib import Path

from rapidmc.load.configuration import attributes, read_configuration
from rapidmc.semantics.library.configuration import (FOUND, NOT_FOUND, NOT_KNOWN,
                                                     UNKNOWN_VALUE, look_up)
from tests.test_realworld import cli

MOC = """MOC:CFG_1.0:6:0::
#
ROBOT:

      -name "ROB_1" -use_robot_type "ROB1_910SC_0.55_3" -use_joint_0 "rob1_1"
#
ARM:

      -name "rob1_1" -use_arm_type "ROB1_1" -upper_joint_bound 2.44347\\
      -lower_joint_bound -2.44347

      -name "rob1_2" -upper_joint_bound 2.618 -lower_joint_bound -2.618

      -name "rob1_3"
#
MOTOR_CALIB:

      -name "rob1_1" -com_offset 0.950014 -valid_com_offset  -valid_cal_offset
"""

PROGRAM = """MODULE MainModule
  VAR num upper{4} := [0, 0, 0, 0];
  VAR num lower := 0;
  VAR string robot := "";
  VAR bool valid := FALSE;
  VAR num missing := 0;
  PROC main()
    FOR i FROM 1 TO 4 DO
      ReadCfgData "/MOC/ARM/rob1_" + NumToStr(i, 0), "upper_joint_bound", upper{i};
    ENDFOR
    ReadCfgData "/MOC/ARM/rob1_1", "lower_joint_bound", lower;
    ReadCfgData "/MOC/ROBOT/ROB_1", "use_robot_type", robot;
    ReadCfgData "/MOC/MOTOR_CALIB/rob1_1", "valid_com_offset", valid;
    TPWrite "upper " \\Num:=upper{1};
    TPWrite "lower " \\Num:=lower;
    TPWrite robot;
    TPWrite "missing " \\Num:=missing;
  ERROR
    IF ERRNO = ERR_CFG_NOTFND THEN
      missing := missing + 1;
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
"""


def backup(tmp_path: Path) -> Path:
    folder = tmp_path / "backup"
    (folder / "RAPID" / "TASK1" / "PROGMOD").mkdir(parents=True)
    (folder / "RAPID" / "TASK1" / "PROGMOD" / "MainModule.mod").write_text(PROGRAM)
    (folder / "SYSPAR").mkdir()
    (folder / "SYSPAR" / "MOC.cfg").write_text(MOC)
    return folder


def test_a_configuration_line_gives_values_flags_and_negative_numbers():
    found = dict(attributes('-name "rob1_1" -valid_com_offset  -lower_joint_bound -2.4 '
                            '-text_id 30,82 -last_flag'))
    assert found == {"name": "rob1_1", "valid_com_offset": True, "lower_joint_bound": "-2.4",
                     "text_id": "30,82", "last_flag": True}


def test_the_backup_file_is_the_truth_for_its_domain(tmp_path):
    configuration = read_configuration(backup(tmp_path) / "SYSPAR")
    assert look_up(configuration, "/MOC/ARM/rob1_1", "upper_joint_bound").value == "2.44347"
    assert look_up(configuration, "MOC/ARM/rob1_2", "Lower_Joint_Bound").value == "-2.618"
    # listed, the attribute left at its default: found, value unknown
    assert look_up(configuration, "/MOC/ARM/rob1_3", "upper_joint_bound").value is UNKNOWN_VALUE
    assert look_up(configuration, "/MOC/ARM/rob1_3", "upper_joint_bound").outcome == FOUND
    # not listed: not found, although a standard six-axis robot has it
    assert look_up(configuration, "/MOC/ARM/rob1_4", "upper_joint_bound").outcome == NOT_FOUND
    # a name that differs only in case, an attribute no instance of the type has
    assert look_up(configuration, "/MOC/ARM/ROB1_1", "upper_joint_bound").outcome == NOT_KNOWN
    assert look_up(configuration, "/MOC/ARM/rob1_1", "no_such").outcome == NOT_KNOWN
    # a domain without a file in the backup: the standard instances
    assert look_up(configuration, "/SYS/CAB_TASKS/T_ROB1", "type").outcome == FOUND


def test_without_a_backup_the_standard_instances_are_found_without_values():
    assert look_up(None, "/MOC/ARM/rob1_6", "upper_joint_bound") == look_up(None, "/MOC/ARM/rob1_1",
                                                                             "cal_position")
    assert look_up(None, "/MOC/ARM/rob1_6", "upper_joint_bound").value is UNKNOWN_VALUE
    assert look_up(None, "/MOC/ARM/rob1_7", "upper_joint_bound").outcome == NOT_KNOWN
    assert look_up(None, "/MOC/ARM/rob1_2", "name").value == "rob1_2"
    assert look_up(None, "/EIO/EIO_SIGNAL/SignalType/DI", "Name").outcome == NOT_KNOWN


def test_run_reads_the_values_of_the_backup(tmp_path):
    code, out, err = cli(["run", str(backup(tmp_path))])
    assert code == 0, err
    assert out == "upper 2.44347\nlower -2.44347\nROB1_910SC_0.55_3\nmissing 1\n"


def test_check_explores_only_what_the_backup_allows(tmp_path):
    properties = tmp_path / "p.ltl"
    properties.write_text('one_missing: G ("Ended()" -> "missing = 1")\n'
                          'values: G ("Ended()" -> ("upper{1} = 2.44347" & "upper{2} = 2.618" '
                          '& "upper{3} = 0" & valid))\n')
    code, out, err = cli(["check", str(backup(tmp_path)), "--ltl", str(properties), "--quiet"])
    assert "one_missing: HOLDS" in out and "values: HOLDS" in out, out + err
    assert "no_runtime_error: HOLDS" in out and code == 0


def test_the_fixed_reading_note_names_the_configuration(tmp_path):
    program = tmp_path / "p.mod"
    program.write_text('MODULE M\n  VAR num b;\n  PROC main()\n'
                       '    ReadCfgData "/MOC/ARM/rob1_1", "upper_joint_bound", b;\n'
                       '  ENDPROC\nENDMODULE\n')
    code, out, err = cli(["check", str(program), "--quiet"])
    assert code == 0, out + err
    assert "ReadCfgData reads the controller's configuration" in err and "[RMC702]" in err
