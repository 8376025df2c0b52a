"""Stored inputs that no active interrupt watches are put at rest (``semantics.resting_inputs``).

Differential: small programs of Kraker1's pattern (an interrupt ordered on an input the
code also reads, connected inside a routine, slept and watched again, deleted; a TRAP that
tests the input; falling, rising and both edges; a second task that reads the input or
shares a flag) are checked with inputs at rest (the default) and with ``--exact-edges``
(every value stored) on both engines: the verdicts are the same wherever the exact search
ends.  One program pins the step that makes an interrupt active from an input at rest:
the input may already be 1 there, so no edge comes (the state at rest stands for both
values).
"""
from __future__ import annotations

import random

import pytest

from rapidmc.check import native

from cli_capture import (assert_reduction_keeps_verdicts, other_task_module, two_task_verdicts,
                         verdicts_and_states)

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

# what the cycle of the task that orders the interrupt does
ORDERING_LINES = [
    "rWatch TRUE;",
    "rWatch FALSE;",
    "IDelete int1; CONNECT int1 WITH trap1; ISignalDI di1, {T}, int1;",
    "IDelete int1;",
    "IF di1 = 1 n := (n + 1) MOD 3;",
    "WaitDI di1, {V};",
    "IF TestDI(di1) hits := 0;",
    "WaitTime 0.1;",
    "IF hits > 1 THEN x := 10 / (hits - 2); hits := 0; ENDIF",
    "flag := TRUE;",
    "IF di2 = 1 n := 0;",
]
TRAP_LINES = [
    "hits := (hits + 1) MOD 4;",
    "IF TestDI(di1) hits := (hits + 1) MOD 4;",
    "ISleep int1;",
    "WaitDI di1, 0;",
    "flag := FALSE;",
]
OTHER_LINES = [
    "IF flag THEN flag := FALSE; m := (m + 1) MOD 3; ENDIF",
    "WaitUntil flag OR m > 0;",
    "m := 0;",
    "IF di1 = 1 m := 1;",
    "IF di2 = 0 m := 2;",
]


def resting_program(seed: int) -> tuple[str, str]:
    """(the task ordering interrupts on di1 and, now and then, di2; another task), both
    reading the inputs now and then."""
    rnd = random.Random(seed)
    trigger = rnd.choice([0, 1, 1, 2])
    second = rnd.random() < 0.4
    data = ["PERS bool flag := FALSE;", "VAR num hits := 0;", "PERS num n := 0;",
            "VAR num x := 0;", "VAR intnum int1;", "VAR intnum int2;"]
    body = [rnd.choice(TRAP_LINES) for _ in range(rnd.randint(1, 3))]
    traps = "  TRAP trap1\n" + "".join(f"    {line}\n" for line in body) + "  ENDTRAP\n"
    orders = ""
    if second:
        orders = "    IDelete int2; CONNECT int2 WITH trap2; ISignalDI di2, 1, int2;\n"
        traps += "  TRAP trap2\n    n := 2;\n  ENDTRAP\n"
    cycle = [rnd.choice(ORDERING_LINES).format(T=trigger, V=rnd.randint(0, 1))
             for _ in range(rnd.randint(2, 5))]
    first = ("MODULE Prog\n" + "".join(f"  {line}\n" for line in data) +
             "  PROC main()\n" + orders +
             "    WHILE TRUE DO\n" + "".join(f"      {line}\n" for line in cycle) +
             "    ENDWHILE\n  ENDPROC\n"
             "  PROC rWatch(bool on)\n    IF on THEN\n"
             f"      IDelete int1; CONNECT int1 WITH trap1; ISignalDI di1, {trigger}, int1;\n"
             "      ISleep int1; IWatch int1;\n    ELSE\n      ISleep int1;\n    ENDIF\n"
             "  ENDPROC\n" + traps + "ENDMODULE\n")
    lines = [rnd.choice(OTHER_LINES) for _ in range(rnd.randint(1, 3))]
    return first, other_task_module(lines)


def check(tmp_path, program: tuple[str, str], *flags: str, bound: int = 20000) -> dict:
    """Property -> (verdict, model states) of one in-process check of both tasks."""
    return two_task_verdicts(tmp_path, program, ['few: G "hits < 3"', 'calm: G F "n = 0"'],
                             *flags, bound=bound)


PROGRAMS = [resting_program(seed) for seed in range(14)]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    program = PROGRAMS[number]
    resting = check(tmp_path, program, "--engine", engine)
    exact = check(tmp_path, program, "--engine", engine, "--exact-edges")
    assert_reduction_keeps_verdicts(resting, exact,
                                    {"no_runtime_error", "no_deadlock", "few", "calm"}, program)


def test_the_pattern_programs_reach_verdicts_both_ways():
    """The differential above compares something: most exact searches end, both verdicts
    occur, and inputs at rest store fewer states in some programs."""
    import tempfile
    from pathlib import Path
    verdicts, fewer = [], 0
    for program in PROGRAMS[:7]:
        with tempfile.TemporaryDirectory() as scratch:
            exact = check(Path(scratch), program, "--exact-edges")
            resting = check(Path(scratch), program)
        verdicts += [v for v, _ in exact.values()]
        fewer += exact["no_runtime_error"][1] > resting["no_runtime_error"][1]
    assert verdicts.count("UNKNOWN") < len(verdicts) // 2, verdicts
    assert {"HOLDS", "VIOLATED"} <= set(verdicts)
    assert fewer >= 2


ALREADY_HIGH = """MODULE Prog
  VAR intnum int1;
  VAR bool trapped := FALSE;
  VAR num n := 0;
  PROC main()
    CONNECT int1 WITH trap1;
    WaitTime 0.1;
    ISignalDI di1, 1, int1;
    WaitDI di1, 1;
    WaitTime 0.1;
    n := 1;
    WaitTime 0.1;
  ENDPROC
  TRAP trap1
    trapped := TRUE;
  ENDTRAP
ENDMODULE
"""


@pytest.mark.parametrize("engine", ENGINES)
def test_an_input_at_rest_may_be_high_when_its_interrupt_is_ordered(tmp_path, engine):
    """di1 is 1 before ISignalDI and stays 1: no edge, so ``n`` becomes 1 without the
    TRAP; with the rest taken for 0 only, every run would have the TRAP first."""
    (tmp_path / "prog.mod").write_text(ALREADY_HIGH)
    args = ["prog.mod", "--formula", 'trapped_first: G ("n = 1" -> "trapped")',
            "--engine", engine]
    for flags in ((), ("--exact-edges",)):
        found = verdicts_and_states([*args, *flags], cwd=tmp_path)
        assert found["trapped_first"][0] == "VIOLATED", flags
