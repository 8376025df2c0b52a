"""Survey round 8 (docs/realworld-survey.md): programs of ours in the styles of the public
RAPID code surveyed, one per cause of a program that did not load or was mis-handled.

The diagnostic for a call written ``Name(a, b);`` as a statement (round 7, left open) is
tested on texts inline: a function called as a procedure and a procedure given its arguments
in parentheses each get their own message at the name.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from tests.test_realworld_survey4 import cli, verdicts

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
