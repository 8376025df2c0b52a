"""``rapidmc stubs`` (issue 8, part B): programs with missing modules load once the
written module fills the gaps.  Each folder of tests/stubs is a program; the module
stubs writes is compared with its ``Missing.expected``, and the program together with
it must pass ``rapidmc parse`` and ``rapidmc check`` (tests/stubs/README.md)."""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld import cli

HERE = Path(__file__).resolve().parent / "stubs"
PROGRAMS = sorted(p for p in HERE.iterdir() if p.is_dir())


def program_files(folder: Path) -> list[str]:
    return [str(p) for p in sorted(folder.glob("*.mod"))]


def expected_exit(folder: Path) -> int:
    path = folder / "exit"
    return int(path.read_text()) if path.exists() else 0


@pytest.mark.parametrize("folder", PROGRAMS, ids=[p.name for p in PROGRAMS])
def test_stubs_writes_the_expected_declarations(folder, tmp_path):
    output = tmp_path / "Missing.mod"
    code, out, err = cli(["stubs", *program_files(folder), "-o", str(output)])
    assert code == expected_exit(folder), err
    assert output.read_text() == (folder / "Missing.expected").read_text()


@pytest.mark.parametrize("folder", [p for p in PROGRAMS if expected_exit(p) == 0],
                         ids=lambda p: p.name)
def test_program_with_written_module_parses_and_checks(folder, tmp_path):
    output = tmp_path / "Missing.mod"
    cli(["stubs", *program_files(folder), "-o", str(output)])
    files = program_files(folder) + [str(output)]
    code, out, err = cli(["parse", *files])
    assert code == 0, err
    properties = tmp_path / "p.ltl"
    properties.write_text('ends: F "Ended()"\n')
    code, out, err = cli(["check", *files, "--ltl", str(properties)])
    assert code in (0, 1) and "no_runtime_error" in out, err


def test_without_stubs_the_programs_do_not_load():
    for folder in PROGRAMS:
        code, _, err = cli(["run", *program_files(folder)])
        assert code == 2 and ("[RMC201]" in err or "[RMC202]" in err), folder.name


def test_uninferred_names_are_left_to_the_user_and_reported():
    folder = HERE / "untyped_copy"
    code, out, err = cli(["stubs", *program_files(folder), "-o", "/dev/null"])
    assert code == 2
    assert "left to you (type not inferred, or an array too large to write): pSaved, pHome" \
        in out
    assert "unknown name 'pHome'" in err and "nCopies" not in err


def test_stubs_to_stdout_and_nothing_to_declare(tmp_path):
    code, out, err = cli(["stubs", *program_files(HERE / "socket_client")])
    assert code == 0 and out.startswith("MODULE Missing\n") and "11 declarations" in err
    complete = tmp_path / "Done.mod"
    complete.write_text("MODULE Done\n  PROC main()\n    TPWrite \"ok\";\n  ENDPROC\nENDMODULE\n")
    code, out, _ = cli(["stubs", str(complete)])
    assert code == 0 and "nothing to declare" in out


def test_output_file_among_the_inputs_is_refused():
    files = program_files(HERE / "job_table")
    code, _, err = cli(["stubs", *files, "-o", files[0]])
    assert code == 2 and "[RMC601]" in err and "is one of the program's files" in err


def test_a_misused_predefined_routine_is_not_declared_again(tmp_path):
    program = tmp_path / "m.mod"
    program.write_text("MODULE m\n  PROC main()\n    Abs 3;\n    x := Set(1);\n  ENDPROC\n"
                       "ENDMODULE\n")
    code, out, err = cli(["stubs", str(program)])
    assert "PROC Abs" not in out and "FUNC" not in out
    assert code == 2 and "'Abs' is a function" in err


def test_stubs_of_a_backup_leave_the_configured_signals_alone(tmp_path):
    from tests.test_backup import USER_SYS, make_backup
    main_mod = ("MODULE MainModule\n  PROC main()\n    nState := cellState;\n"
                "    IF bAuto THEN\n      SetDO gripClose, 1;\n    ENDIF\n  ENDPROC\nENDMODULE\n")
    backup = make_backup(tmp_path, {"TASK1": {"SYSMOD/user.sys": USER_SYS,
                                              "PROGMOD/MainModule.mod": main_mod}})
    output = tmp_path / "Missing.mod"
    code, out, err = cli(["stubs", str(backup), "-o", str(output)])
    assert code == 0, err
    text = output.read_text()
    assert "PERS num nState := 0;" in text and "PERS bool bAuto := FALSE;" in text
    assert "cellState" not in text and "gripClose" not in text


def test_an_error_inside_the_written_module_is_reported_as_a_fault_of_stubs(capsys):
    from rapidmc import ast
    from rapidmc.commands.stubs import _verify
    from rapidmc.load.stubs import Stubs
    from rapidmc.syntax import parse_text
    program = parse_text("MODULE m\n  PROC main()\n    n := 1;\n  ENDPROC\nENDMODULE\n", "m.mod")
    broken = Stubs("MODULE Missing\n  PERS nosuchtype n := 0;\nENDMODULE\n", (), ())
    assert _verify(ast.Program(program), broken, "Missing.mod", ()) == 2
    err = capsys.readouterr().err
    assert "Missing.mod:2:8: error:" in err and "a fault of rapidmc" in err
