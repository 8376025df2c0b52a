"""Survey round 3 (docs/realworld-survey.md): programs of ours in the styles of public
RAPID code that uses names declared in modules that were not given.

Each program stops at static checking on its own (exit 2); ``rapidmc stubs`` must
declare everything it lacks so that the program plus the written module links and
``check`` reaches a verdict.  ``DECLARED`` pins the declaration that makes each one
work: a RECORD for a type used only as a record component, a FUNC returning a record
the stubs declare (through a local, as no literal exists for it) with an array of
strings for a caption aggregate, and a function whose value only goes to another
missing function's parameter; components of components get record types of their
own, named after the record and the component, unless a known record (a jointtarget for
``.robax`` and ``.extax``) has them all.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from cli_capture import run_cli

HERE = Path(__file__).resolve().parent / "realworld" / "survey3"

# (program, declarations the written module must contain)
DECLARED = [
    ("record_of_missing_types.mod",
     ["RECORD gripper_cfg", "RECORD feeder_cfg"]),
    ("menu_function.mod",
     ["RECORD choice", "FUNC choice ShowMenu(string p1, string p2{*}, string p3{*}, "
      "\\choice initial)", "VAR choice result;"]),
    ("passed_function_value.mod",
     ["FUNC num GetNextGoal()", "FUNC bool TryMove(num p1)"]),
    ("nested_message.mod",
     ["RECORD state_msgs", "state_msgs_header header;", "RECORD state_msgs_header",
      "num sequence;", "RECORD state_msgs_feedback", "jointtarget angles;",
      "FUNC num ReadGripperWidth()"]),
]


@pytest.mark.parametrize("name, declarations", DECLARED, ids=[d[0] for d in DECLARED])
def test_stubs_make_the_program_reach_a_verdict(name, declarations, tmp_path):
    program = str(HERE / name)
    code, _, err = run_cli(["check", program, "--quiet"])
    assert code == 2, err                              # on its own it does not link
    stubs = tmp_path / "Missing.mod"
    code, _, err = run_cli(["stubs", program, "-o", str(stubs)])
    assert code == 0, err
    text = stubs.read_text(encoding="latin-1")
    for declaration in declarations:
        assert declaration in text, text
    assert "could not be inferred" not in text
    assert "_robax" not in text and "_extax" not in text      # no records for a jointtarget's parts
    code, out, err = run_cli(["check", program, str(stubs), "--max-states", "20000", "--quiet",
                              "--formula", "p: G true"])
    assert code == 0, out + err
    assert "no_runtime_error: HOLDS" in out and "p: HOLDS" in out


def test_a_record_that_contains_itself_is_a_diagnostic_not_a_crash(tmp_path):
    # seen while surveying: a component typed with its own record (here through another)
    program = tmp_path / "nested.mod"
    program.write_text("MODULE m\n  RECORD part_a\n    part_b inner;\n  ENDRECORD\n"
                       "  RECORD part_b\n    part_a outer;\n  ENDRECORD\n"
                       "  VAR part_a x;\n  PROC main()\n  ENDPROC\nENDMODULE\n")
    code, _, err = run_cli(["check", str(program), "--quiet"])
    assert code == 2
    assert "defined in terms of itself" in err and "internal error" not in err
