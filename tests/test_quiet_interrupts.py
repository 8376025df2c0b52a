"""A task whose interrupts only its own steps can queue is ample while none is pending.

``reduction.interrupt_owners`` ("Quiet interrupts"): the joseballester socket server
connects ``ISignalDO USER_RESET_MOTION, 1, iMotionReset`` for the whole run, on an output
the user sets from outside and no loaded code sets to 1; beside it a logger task polls a
shared mutex and the robot.  The server used to count as serving that interrupt in every
state, so it was never ample and every server state was paired with every position of
the logger.  Now a connected interrupt that is not pending and is ordered on nothing, or
on the edge of a digital output that no other task's code writes, leaves its task free to
be ample.

Differential: generated programs of two tasks, a "server" connecting an interrupt (on an
output it sets itself, one nobody sets, or one the logger sets too; or not ordered at
all) whose TRAP writes its own data, shared PERS data and the output, beside a "logger"
on its own data, a shared flag and the output: checked with the reduction and with
``--no-por``, the same verdicts (built-in checks included) and the same lines never
reached, on both engines.  Mutants that take an interrupt the logger can queue, or a
pending one, as quiet lose a TRAP.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from rapidmc.api import load_program
from rapidmc.check import native
from rapidmc.model.reduction import interrupt_owners
from rapidmc.model.reduction.partial_order import PartialOrder
from rapidmc.semantics.state import Interrupt, Interrupts

from test_interrupt_ample import _loop, assert_same_as_unreduced, write_interrupt_tasks
from test_partial_order import check_json, never_reached, states

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

ORDERS = ["ISignalDO doR, 1, ir1;", "ISignalDO doR, 2, ir1;", "ISignalDO doR, 0, ir1;",
          "ISignalDO \\Single, doR, 1, ir1;", ""]
TRAP_LINES = [
    "hits := (hits + 1) MOD 3;",
    "shared := (shared + 1) MOD 2;",
    "flag := TRUE;",
    "SetDO doR, 0;",
    "IF hits = 2 RAISE ERR_DIVZERO;",
    "ISleep ir1; IWatch ir1;",
]
SERVER_LINES = [
    "n1 := (n1 + 1) MOD 3;",
    "IF n1 = 2 SetDO doR, 1;",
    "SetDO doR, 0;",
    "IF flag THEN flag := FALSE; hits := 0; ENDIF",
    "WaitUntil flag OR hits > 0;",
    "IDisable; n1 := 0; IEnable;",
    "shared := n1 MOD 2;",
    "quotient := 6 DIV (hits - 2);",
    'msg := "# " + NumToStr(n1, 0);',
]
LOGGER_LINES = [
    "n2 := (n2 + 1) MOD 3;",
    "IF n2 = 1 THEN data := n2; ENDIF",
    "flag := TRUE;",
    "IF shared = 1 n2 := 0;",
    "WaitUntil NOT flag;",
    "WHILE flag DO ENDWHILE",
    'k := (k + 1) MOD 2; msg := "# " + NumToStr(k, 0);',
]
LOGGER_SETS = "IF n2 = 2 SetDO doR, 1;"


def quiet_tasks(seed: int) -> tuple[str, str]:
    """(server, logger) module texts of ``seed``; one seed in four, the logger sets the
    watched output too (the interrupt is then not quiet)."""
    rnd = random.Random(seed)
    order = rnd.choice(ORDERS)
    trap = [rnd.choice(TRAP_LINES) for _ in range(rnd.randint(1, 3))]
    body = [rnd.choice(SERVER_LINES) for _ in range(rnd.randint(2, 4))]
    handler = ["  ERROR", "    TRYNEXT;"] if rnd.random() < 0.5 else []
    server = "\n".join([
        "MODULE Server",
        "  PERS num shared := 0;", "  PERS bool flag := FALSE;",
        "  VAR intnum ir1;", "  VAR num hits := 0;", "  VAR num n1 := 0;",
        "  VAR num quotient := 0;", '  VAR string msg := "";',
        "  PROC main()", "    CONNECT ir1 WITH onReset;", *([f"    {order}"] if order else []),
        *_loop(rnd, body), *handler, "  ENDPROC",
        "  TRAP onReset", *[f"    {line}" for line in trap], "  ENDTRAP",
        "ENDMODULE", ""])
    logger_body = [rnd.choice(LOGGER_LINES) for _ in range(rnd.randint(2, 4))]
    if rnd.random() < 0.25:
        logger_body.insert(rnd.randint(0, len(logger_body)), LOGGER_SETS)
    logger = "\n".join([
        "MODULE Logger",
        "  PERS num shared := 0;", "  PERS bool flag := FALSE;",
        "  VAR num n2 := 0;", "  VAR num data := 0;",
        "  VAR num k := 0;", '  VAR string msg := "";',
        "  PROC main()", *_loop(rnd, logger_body), "  ENDPROC",
        "ENDMODULE", ""])
    return server, logger


def write_quiet_tasks(folder: Path, seed: int) -> list[str]:
    return write_interrupt_tasks(folder, seed, quiet_tasks)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("seed", range(16))
def test_generated_quiet_interrupts_keep_their_verdicts(tmp_path, seed, engine):
    assert_same_as_unreduced(write_quiet_tasks(tmp_path, seed) + ["--engine", engine])


SERVER_ENDS = """MODULE Server
  VAR intnum ir1;
  VAR num hits := 0;
  VAR num n1 := 0;
  PROC main()
    CONNECT ir1 WITH onReset;
    ISignalDO doR, 1, ir1;
    FOR i FROM 1 TO 3 DO
      n1 := n1 + 1;
    ENDFOR
  ENDPROC
  TRAP onReset
    hits := hits + 1;
  ENDTRAP
ENDMODULE
"""
LOGGER_SETS_ONCE = """MODULE Logger
  PROC main()
    SetDO doR, 1;
  ENDPROC
ENDMODULE
"""


def _two_tasks(folder: Path, server: str, logger: str) -> list[str]:
    first, second = folder / "server.mod", folder / "logger.mod"
    first.write_text(server)
    second.write_text(logger)
    return [str(first), "--add-task", str(second)]


def test_an_output_another_task_sets_keeps_its_interrupt_serving(tmp_path, monkeypatch):
    """The differential can fail: the logger sets ``doR``, which queues the server's TRAP.
    A mutant that ignores the other tasks' writes takes the server as ample after its
    ISignalDO; it runs to its end before the logger's SetDO, and the TRAP is never
    entered."""
    argv = _two_tasks(tmp_path, SERVER_ENDS, LOGGER_SETS_ONCE)
    full = check_json(argv + ["--no-por"])
    assert never_reached(check_json(argv)) == never_reached(full)
    monkeypatch.setattr(interrupt_owners.InterruptOwners, "_own_output",
                        lambda self, task, index: True)
    lost = never_reached(check_json(argv)) - never_reached(full)
    assert {line for _, line in lost} == {12}           # TRAP onReset


def _interrupts(*table, pending=()) -> Interrupts:
    return Interrupts(tuple(Interrupt(number, trap, source) for number, trap, source in table),
                      pending, True, ())


def test_which_interrupts_are_quiet(tmp_path):
    """Not ordered, or on an output only its task sets, and not pending: quiet; the same
    output set by the other task, a pending interrupt, a timer: serving."""
    argv = _two_tasks(tmp_path, SERVER_ENDS, LOGGER_SETS_ONCE)
    idle = tmp_path / "idle.mod"
    idle.write_text("MODULE Idle\n  VAR num x := 0;\n  PROC main()\n    x := 1;\n"
                    "  ENDPROC\nENDMODULE\n")
    program = load_program([argv[0]], add_tasks=[argv[2]])
    alone = load_program([argv[0]], add_tasks=[str(idle)])
    for loaded, quiet_output in ((program, False), (alone, True)):
        owners = PartialOrder(loaded, set()).owners
        trap = next(r.index for r in loaded.routines if r.name == "onReset")
        signal = next(s.index for s in loaded.signals if s.key == "DOR")
        serving = interrupt_owners.serving_tasks
        on_output = (1, trap, ("signal", signal, 1.0, False))
        assert serving(loaded, _interrupts((1, trap, ())), owners) == frozenset()
        assert serving(loaded, _interrupts(on_output), owners) == \
            (frozenset() if quiet_output else frozenset({0}))
        assert serving(loaded, _interrupts(on_output, pending=(1,)), owners) == frozenset({0})
        assert serving(loaded, _interrupts((1, trap, ("timer", 1.0, False))), owners) == \
            frozenset({0})
        assert serving(loaded, _interrupts(on_output)) == frozenset({0})   # (no owners)


@pytest.mark.parametrize("seed", [3, 7])
def test_quiet_interrupts_leave_fewer_states(tmp_path, monkeypatch, seed):
    """The rule takes effect: with every interrupt counted as serving (the rule before),
    the generated programs of these seeds have more states."""
    argv = write_quiet_tasks(tmp_path, seed)
    reduced = sum(states(check_json(argv)).values())
    monkeypatch.setattr(interrupt_owners.InterruptOwners, "is_quiet",
                        lambda self, entry, pending: False)
    assert reduced < sum(states(check_json(argv)).values())


needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")


@needs_native
@pytest.mark.parametrize("seed", [3, 7])
def test_quiet_interrupts_report_the_same_with_both_engines(seed, tmp_path, monkeypatch):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_quiet_tasks(tmp_path, seed), monkeypatch,
                                   reuse=seed % 2 == 1)
    assert document["properties"]
