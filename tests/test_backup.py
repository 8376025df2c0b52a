"""Controller backups (RAPID/<task>/SYSMOD, PROGMOD, SYSPAR/EIO.cfg) and --eio files."""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.load.backup import read_eio
from rapidmc.cli import main

EIO = """EIO:CFG_1.0:6:1::
#
EIO_DEVICE:
      -Name "d652" -VendorName "ABB"
#
EIO_SIGNAL:

      -Name "partPresent" -SignalType "DI" -Device "d652" -DeviceMap "0"

      -Name "gripClose" -SignalType "DO" -Device "d652"\\
      -DeviceMap "1"

      -Name "cellState" -SignalType "GO" -Device "d652" -DeviceMap "2-5"
#
"""

USER_SYS = """MODULE user(SYSMODULE)
  PERS tooldata tGripper := [TRUE,[[0,0,100],[1,0,0,0]],[1,[0,0,50],[1,0,0,0],0,0,0]];
ENDMODULE
"""

MAIN_MOD = """MODULE MainModule
  CONST robtarget pPick := [[500,0,200],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    IF partPresent = 1 THEN
      MoveL pPick, v100, fine, tGripper;
      SetDO gripClose, 1;
      SetGO cellState, 3;
      TPWrite "picked";
    ELSE
      TPWrite "no part";
    ENDIF
  ENDPROC
ENDMODULE
"""


def make_backup(root: Path, tasks: dict[str, dict[str, str]], eio: str = EIO) -> Path:
    backup = root / "backup"
    (backup / "BACKINFO").mkdir(parents=True)
    (backup / "SYSPAR").mkdir()
    (backup / "SYSPAR" / "EIO.cfg").write_text(eio)
    for task, files in tasks.items():
        for relative, text in files.items():
            path = backup / "RAPID" / task / relative
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
    return backup


def one_task(root: Path) -> Path:
    return make_backup(root, {"TASK1": {"SYSMOD/user.sys": USER_SYS,
                                        "PROGMOD/MainModule.mod": MAIN_MOD}})


def test_eio_signals_have_their_configured_types(tmp_path):
    path = tmp_path / "EIO.cfg"
    path.write_text(EIO)
    signals = [(s.name, s.kind) for s in read_eio(str(path))]
    assert signals == [("partPresent", "DI"), ("gripClose", "DO"), ("cellState", "GO")]


def test_a_backup_runs_with_its_system_modules_and_configured_signals(tmp_path, capsys):
    backup = one_task(tmp_path)
    assert main(["run", str(backup)]) == 0
    assert capsys.readouterr().out == "no part\n"
    assert main(["run", str(backup), "--io", "partPresent=1"]) == 0
    assert capsys.readouterr().out == "picked\n"


def test_a_backup_checks(tmp_path, capsys):
    backup = one_task(tmp_path)
    code = main(["check", str(backup), "--quiet", "--formula",
                 'p: G (gripClose -> "AtTarget(pPick)")'])
    assert code == 0 and "p: HOLDS" in capsys.readouterr().out


def test_a_configured_output_cannot_be_waited_on_as_an_input(tmp_path, capsys):
    wrong = MAIN_MOD.replace('TPWrite "picked";', "WaitDI gripClose, 1;")
    backup = make_backup(tmp_path, {"TASK1": {"SYSMOD/user.sys": USER_SYS,
                                              "PROGMOD/MainModule.mod": wrong}})
    assert main(["run", str(backup)]) == 2
    assert "[RMC206]" in capsys.readouterr().err


def test_several_tasks_need_a_choice_unless_one_has_main(tmp_path, capsys):
    background = "MODULE Bg\n  PROC bg_main()\n    TPWrite \"bg\";\n  ENDPROC\nENDMODULE\n"
    backup = make_backup(tmp_path, {"T_ROB1": {"SYSMOD/user.sys": USER_SYS,
                                               "PROGMOD/MainModule.mod": MAIN_MOD},
                                    "T_BG": {"PROGMOD/Bg.mod": background}})
    assert main(["run", str(backup)]) == 0                    # only T_ROB1 has main
    assert capsys.readouterr().out == "no part\n"
    assert main(["run", str(backup), "--task", "t_bg", "--entry", "bg_main"]) == 0
    assert capsys.readouterr().out == "bg\n"
    assert main(["run", str(backup), "--task", "NOPE"]) == 2
    assert "no task 'NOPE'" in capsys.readouterr().err


def test_eio_option_with_plain_module_files(tmp_path, capsys):
    (tmp_path / "EIO.cfg").write_text(EIO)
    (tmp_path / "user.sys").write_text(USER_SYS)
    (tmp_path / "main.mod").write_text(MAIN_MOD)
    code = main(["run", str(tmp_path / "user.sys"), str(tmp_path / "main.mod"),
                 "--eio", str(tmp_path / "EIO.cfg"), "--io", "partPresent=1"])
    assert code == 0 and capsys.readouterr().out == "picked\n"


def test_a_backup_without_a_program_is_a_note_and_exit_0(tmp_path, capsys):
    """Issue 28: a factory backup (system modules only) runs nothing: RMC736, exit 0."""
    backup = tmp_path / "factory"
    (backup / "RAPID" / "TASK1" / "SYSMOD").mkdir(parents=True)
    (backup / "RAPID" / "TASK1" / "SYSMOD" / "user.sys").write_text(USER_SYS)
    assert main(["check", str(backup)]) == 0
    err = capsys.readouterr().err
    assert "holds no program" in err and "[RMC736]" in err
    assert main(["check", str(backup), "--task", "TASK1"]) == 0       # the same, task by task
    assert "[RMC736]" in capsys.readouterr().err
    (backup / "RAPID" / "TASK1" / "PROGMOD").mkdir()
    (backup / "RAPID" / "TASK1" / "PROGMOD" / "Lib.mod").write_text(
        "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n")
    assert main(["check", str(backup)]) == 2          # a program module without main: an error
    assert "[RMC736]" not in capsys.readouterr().err


def test_a_task_of_system_modules_only_is_a_note_and_exit_0(tmp_path, capsys):
    """Issue 28: ``--task`` naming a task of system modules only (a shared or command task)
    says it holds no program (RMC736, exit 0), as a backup of such tasks does; with
    ``--entry`` one of its routines is checked, and a task with a program module but no
    entry routine stays an error."""
    backup = tmp_path / "cell"
    (backup / "RAPID" / "TASK1" / "PROGMOD").mkdir(parents=True)
    (backup / "RAPID" / "TASK1" / "PROGMOD" / "Main.mod").write_text(
        "MODULE Main\n  PROC main()\n    TPWrite \"run\";\n  ENDPROC\nENDMODULE\n")
    (backup / "RAPID" / "TASK2" / "SYSMOD").mkdir(parents=True)
    (backup / "RAPID" / "TASK2" / "SYSMOD" / "cmd.sys").write_text(
        "MODULE cmd(SYSMODULE)\n  PROC service()\n    TPWrite \"service\";\n  ENDPROC\nENDMODULE\n")
    assert main(["check", str(backup), "--task", "TASK2"]) == 0
    err = capsys.readouterr().err
    assert "task TASK2 of backup" in err and "holds no program" in err and "[RMC736]" in err
    assert main(["check", str(backup), "--task", "TASK2", "--entry", "service"]) == 0
    assert "[RMC736]" not in capsys.readouterr().err
    (backup / "RAPID" / "TASK2" / "PROGMOD").mkdir()
    (backup / "RAPID" / "TASK2" / "PROGMOD" / "Lib.mod").write_text(
        "MODULE Lib\n  PROC helper()\n  ENDPROC\nENDMODULE\n")
    assert main(["check", str(backup), "--task", "TASK2"]) == 2
    assert "[RMC211]" in capsys.readouterr().err


def test_task_identities_name_the_backups_tasks_only(tmp_path, capsys):
    """Issue 28: the controller declares ``<task name>Id`` (taskid) for each task it runs,
    so ``T_ROB1Id`` resolves in a backup whose task is T_ROB1 (its folder's name here, as no
    backinfo names it) and with plain module files (whose one task is T_ROB1); a name of a
    task the controller does not have stays unknown."""
    uses = "MODULE Main\n  VAR robtarget p;\n  PROC main()\n    p := CRobT(\\TaskRef:={});\n" \
           "    TPWrite \"x\" \\Num:=p.trans.x;\n  ENDPROC\nENDMODULE\n"
    backup = make_backup(tmp_path, {"T_ROB1": {"PROGMOD/Main.mod": uses.format("T_ROB1Id")}})
    assert main(["check", str(backup)]) == 0
    assert main(["check", str(backup / "RAPID" / "T_ROB1" / "PROGMOD" / "Main.mod")]) == 0
    capsys.readouterr()
    (backup / "RAPID" / "T_ROB1" / "PROGMOD" / "Main.mod").write_text(uses.format("T_ROB2Id"))
    assert main(["check", str(backup)]) == 2
    assert "unknown name 'T_ROB2Id'" in capsys.readouterr().err


OLD_MAIN = """MODULE Added
  PROC main()
    TPWrite "added after the backup";
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("separator, loaded_as", [("/", " mainmodule.mod"), ("\\", ""),
                                                   ("/", "")])
def test_a_module_backinfo_does_not_list_is_left_out_with_a_warning(tmp_path, capsys,
                                                                    separator, loaded_as):
    """backinfo.txt lists the modules the controller had loaded (a virtual controller
    writes the folder with a backslash; some backups leave the name after "@" empty): a
    file put in the task's folder afterwards, here a second ``main``, is not loaded, and a
    warning (RMC737) names it."""
    backup = make_backup(tmp_path, {"TASK1": {"SYSMOD/user.sys": USER_SYS,
                                              "PROGMOD/MainModule.mod": MAIN_MOD,
                                              "PROGMOD/Added.mod": OLD_MAIN}})
    (backup / "BACKINFO" / "backinfo.txt").write_text(
        ">>TASK1: (T_ROB1,Main,)\n"
        f"SYSMOD{separator}user.sys @ user.sys\n"
        f"PROGMOD{separator}MainModule.mod @{loaded_as}\n\n>>EOF:\n")
    assert main(["check", str(backup), "--quiet"]) == 0
    err = capsys.readouterr().err
    assert "module Added.mod is in the folder of task T_ROB1 but backinfo.txt does not " \
           "list it" in err and "[RMC737]" in err


def test_without_a_module_list_every_module_of_the_folder_is_loaded(tmp_path, capsys):
    """A backinfo.txt that names the task but lists no module (or none of the folder's)
    leaves every module loaded: here the second ``main`` is the error it is."""
    backup = make_backup(tmp_path, {"TASK1": {"PROGMOD/MainModule.mod": MAIN_MOD,
                                              "PROGMOD/Added.mod": OLD_MAIN}})
    (backup / "BACKINFO" / "backinfo.txt").write_text(
        ">>TASK1: (T_ROB1,Main,)\nPROGMOD/Other.mod @ other.mod\n\n>>EOF:\n")
    assert main(["check", str(backup), "--quiet"]) == 2
    err = capsys.readouterr().err
    assert "RMC737" not in err and "declared twice" in err
