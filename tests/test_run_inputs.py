"""``rapidmc run --inputs FILE``: input changes at virtual times; waits let time pass."""
from __future__ import annotations

import pytest

from rapidmc.cli import main

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

PROGRAM = """MODULE In
  VAR signaldi start;
  PROC main()
    AliasIO "DI_START", start;
    TPWrite "waiting";
    WaitDI start, 1;
    TPWrite "started";
    WaitTime 5;
    TPWrite "after wait:" \\Num:=DInput(start);
  ENDPROC
ENDMODULE
"""


def run(tmp_path, capsys, script: str):
    program = tmp_path / "in.mod"
    program.write_text(PROGRAM)
    inputs = tmp_path / "inputs.txt"
    inputs.write_text(script)
    code = main(["run", str(program), "--inputs", str(inputs)])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_a_wait_lasts_until_the_scripted_change_and_waittime_applies_later_ones(tmp_path, capsys):
    code, out, _ = run(tmp_path, capsys, "# seconds name=value\n1.5 DI_START=1\n4 DI_START=0\n")
    assert code == 0
    assert out == "waiting\nstarted\nafter wait:0\n"


def test_without_a_change_the_wait_is_a_deadlock(tmp_path, capsys):
    code, out, err = run(tmp_path, capsys, "2 DI_START=0\n")
    assert code == 1 and out == "waiting\n"
    assert "deadlock" in err and "in.mod:6:" in err


def test_bad_script_lines_are_diagnostics(tmp_path, capsys):
    code, _, err = run(tmp_path, capsys, "soon DI_START=1\n")
    assert code == 2 and "inputs.txt:1:1" in err and "[RMC601]" in err
    code, _, err = run(tmp_path, capsys, "1 NOPE=1\n")
    assert code == 2 and "unknown signal 'NOPE'" in err


TRAP_PROGRAM = """MODULE T
  VAR signaldi sensor;
  VAR intnum irq;
  VAR num hits := 0;
  PROC main()
    AliasIO "DI_SENSOR", sensor;
    CONNECT irq WITH OnSensor;
    ISignalDI sensor, 1, irq;
    WaitUntil hits >= 2;
    TPWrite "hits=" \\Num:=hits;
  ENDPROC
  TRAP OnSensor
    Incr hits;
  ENDTRAP
ENDMODULE
"""


def test_scripted_rising_edges_run_the_trap_while_the_program_waits(tmp_path, capsys):
    program = tmp_path / "trap.mod"
    program.write_text(TRAP_PROGRAM)
    inputs = tmp_path / "inputs.txt"
    inputs.write_text("1 DI_SENSOR=1\n2 DI_SENSOR=0\n3 DI_SENSOR=1\n")
    assert main(["run", str(program), "--inputs", str(inputs)]) == 0
    assert capsys.readouterr().out == "hits=2\n"
