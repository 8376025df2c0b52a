"""Every task has its own ``main``: analyses that follow data through calls walk each.

The domains of data written from outside the loaded code and of analog inputs come from the
comparisons the data reaches, through the program's routines.  Those routines were kept by
name, program-wide, so a second task's ``main`` hid the first's: a value passed from the
main task's ``main`` to the routine that compares it gave no value, and a property HELD that
the program with one task refutes.
"""
from __future__ import annotations

import pytest

from rapidmc.check import native
from cli_capture import verdicts_and_states

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

OUTSIDE_MODE = """MODULE Cell
  PERS num mode := 0;
  VAR num y := 0;
  PROC main()
    Pick mode;
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
  PROC Pick(num m)
    IF m = 7 THEN
      y := 1;
    ENDIF
  ENDPROC
ENDMODULE
"""

IDLE = """MODULE Idle
  PROC main()
    WHILE TRUE DO
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

LEVEL_READER = """MODULE Reader
  PERS num level := 0;
  PROC main()
    WHILE TRUE DO
      level := AInput(aiLevel);
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

LEVEL_USER = """MODULE User
  PERS num level := 0;
  VAR num x := 0;
  PROC main()
    WHILE TRUE DO
      IF level > 61 AND level < 63 THEN
        x := 1;
      ENDIF
      WaitTime 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""

EIO = """EIO:CFG_1.0:6:1::
EIO_SIGNAL:
      -Name "aiLevel" -SignalType "AI" -MinLog 0 -MaxLog 100
"""


def verdicts(tmp_path, tasks: list, formula: str, *flags: str) -> dict:
    names = []
    for number, text in enumerate(tasks):
        (tmp_path / f"task{number}.mod").write_text(text)
        names.append(f"task{number}.mod")
    (tmp_path / "eio.cfg").write_text(EIO)
    added = [word for name in names[1:] for word in ("--add-task", name)]
    return verdicts_and_states([names[0], *added, "--eio", "eio.cfg", "--formula", formula,
                                *flags], cwd=tmp_path)


@pytest.mark.parametrize("engine", ENGINES)
def test_data_written_from_outside_reaches_a_comparison_beside_another_task(tmp_path, engine):
    """``mode`` (no loaded code writes it) goes from the main task's ``main`` to ``Pick``,
    which compares it with 7: with an idle second task too, 7 is tried."""
    alone = verdicts(tmp_path, [OUTSIDE_MODE], 'P: G "y = 0"', "--engine", engine)
    beside = verdicts(tmp_path, [OUTSIDE_MODE, IDLE], 'P: G "y = 0"', "--engine", engine)
    assert alone["P"][0] == beside["P"][0] == "VIOLATED"


@pytest.mark.parametrize("engine", ENGINES)
def test_an_analog_input_takes_values_around_another_tasks_comparisons(tmp_path, engine):
    """The reader task stores the input in PERS ``level``; the other task compares it with
    61 and 63: the values singled out fall between them, so ``x := 1`` is reached."""
    found = verdicts(tmp_path, [LEVEL_READER, LEVEL_USER], 'P: G "x = 0"', "--engine", engine)
    assert found["P"][0] == "VIOLATED"
