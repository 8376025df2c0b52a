"""A task that serves no interrupt may be an ample set where interrupts are connected.

``reduction.interrupt_owners``: each task serves the interrupts it connected, in its
own steps, so in a state with interrupts a task serving none of them may be ample by
the usual conditions (the joseballester socket server's pattern: a server whose
``ISignalDO`` stays connected for the whole run, beside a logger task).

Differential: generated programs of two tasks, a "server" connecting interrupts (a
timer, an edge input, an output the other task sets, a stored input it also reads)
whose TRAPs write its own data, shared PERS data and outputs (now and then a PulseDO,
ISleep/IWatch, IDisable, RAISE), beside a "logger" running on its own data, a shared
flag and the watched output, now and then with a timer of its own: checked with the
reduction and with ``--no-por``, the same verdicts (built-in checks included) and the
same lines never reached, on both engines; and a mutant that lets a task serving an
interrupt be ample loses a TRAP.  tests/test_independence.py's ``clock_beside_traps``
checks the premise against the semantics: in every reached state with interrupts, an
independent instruction of a task serving none commutes with the other task's steps.
"""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from rapidmc.check import native
from rapidmc.model.reduction import interrupt_owners
from rapidmc.api import load_program
from rapidmc.semantics.state import Interrupts

from test_partial_order import check_json, never_reached, states, verdicts

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

SOURCES = [
    ("ITimer 1, ir1;", ""),
    ("ITimer \\Single, 1, ir1;", ""),
    ("ISignalDI diEdge, 1, ir1;", ""),
    ("ISignalDO doX, 1, ir1;", ""),
    ("ISignalDO doX, 2, ir1;", ""),
    ("ISignalDI diRead, 1, ir1;", "IF diRead = 1 n1 := (n1 + 1) MOD 3;"),
]
TRAP_LINES = [
    "hits := (hits + 1) MOD 3;",
    "shared := (shared + 1) MOD 2;",
    "flag := TRUE;",
    "SetDO doX, 0;",
    "PulseDO doP;",
    "IF hits = 2 RAISE ERR_DIVZERO;",
    "ISleep ir1; IWatch ir1;",
]
SERVER_LINES = [
    "n1 := (n1 + 1) MOD 3;",
    "IF n1 = 2 n1 := 0;",
    "IF flag THEN flag := FALSE; hits := 0; ENDIF",
    "WaitUntil flag OR hits > 0;",
    "IDisable; n1 := 0; IEnable;",
    "shared := n1 MOD 2;",
    "quotient := 6 DIV (hits - 2);",
]
LOGGER_LINES = [
    "n2 := (n2 + 1) MOD 3;",
    "data := data + 1; data := 0;",
    "IF n2 = 1 THEN data := n2; ENDIF",
    "SetDO doX, 1;",
    "SetDO doX, 0;",
    "flag := TRUE;",
    "IF shared = 1 n2 := 0;",
    "WaitUntil NOT flag;",
    'k := (k + 1) MOD 2; msg := "# " + NumToStr(k, 0);',
    'IF k = 1 THEN msg := msg + " done"; ENDIF',
]


def interrupt_tasks(seed: int) -> tuple[str, str]:
    """(server, logger) module texts of ``seed``."""
    rnd = random.Random(seed)
    order, read = rnd.choice(SOURCES)
    trap = [rnd.choice(TRAP_LINES) for _ in range(rnd.randint(1, 3))]
    body = [rnd.choice(SERVER_LINES) for _ in range(rnd.randint(1, 3))] + ([read] if read else [])
    handler = ["  ERROR", "    TRYNEXT;"] if rnd.random() < 0.5 else []
    server = "\n".join([
        "MODULE Server",
        "  PERS num shared := 0;", "  PERS bool flag := FALSE;",
        "  VAR intnum ir1;", "  VAR num hits := 0;", "  VAR num n1 := 0;",
        "  VAR num quotient := 0;",
        "  PROC main()", "    CONNECT ir1 WITH onEvent;", f"    {order}",
        *_loop(rnd, body), *handler, "  ENDPROC",
        "  TRAP onEvent", *[f"    {line}" for line in trap], "  ENDTRAP",
        "ENDMODULE", ""])
    logger_body = [rnd.choice(LOGGER_LINES) for _ in range(rnd.randint(2, 4))]
    timer = rnd.random() < 0.3
    logger = "\n".join([
        "MODULE Logger",
        "  PERS num shared := 0;", "  PERS bool flag := FALSE;",
        "  VAR num n2 := 0;", "  VAR num data := 0;", "  VAR intnum ir2;",
        "  VAR num k := 0;", '  VAR string msg := "";',
        "  PROC main()",
        *(["    CONNECT ir2 WITH onTick;", "    ITimer \\Single, 1, ir2;"] if timer else []),
        *_loop(rnd, logger_body), "  ENDPROC",
        *(["  TRAP onTick", "    data := 2;", "  ENDTRAP"] if timer else []),
        "ENDMODULE", ""])
    return server, logger


def _loop(rnd: random.Random, body: list) -> list:
    lines = [f"      {line}" for line in body]
    if rnd.random() < 0.5:
        return ["    WHILE TRUE DO", *lines, "    ENDWHILE"]
    return [f"    FOR i FROM 1 TO {rnd.randint(1, 2)} DO", *lines, "    ENDFOR"]


PROPERTIES = ['few: G "hits < 2"', 'calm: G F "n2 = 0"', 'apart: G ("shared = 0" | "data = 0")',
              'flagged: F "flag"']


def write_interrupt_tasks(folder: Path, seed: int, make=interrupt_tasks) -> list[str]:
    """The argument list checking the two tasks ``make(seed)`` gives against PROPERTIES."""
    argv = []
    for number, text in enumerate(make(seed), start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    spec = folder / "props.ltl"
    spec.write_text("\n".join(PROPERTIES) + "\n")
    return argv + ["--ltl", str(spec), "--max-states", "40000"]


SEEDS = range(16)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("seed", SEEDS)
def test_generated_interrupt_tasks_keep_their_verdicts(tmp_path, seed, engine):
    assert_same_as_unreduced(write_interrupt_tasks(tmp_path, seed) + ["--engine", engine])


def assert_same_as_unreduced(argv: list[str]) -> None:
    """The check of ``argv`` gives the verdicts and the lines never reached of
    ``--no-por``, which reaches a verdict for every property."""
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    assert never_reached(reduced) == never_reached(full)


def test_a_task_serving_an_interrupt_taken_as_ample_loses_a_trap(tmp_path, monkeypatch):
    """The differential can fail: seed 17's server watches ``doX`` (ISignalDO) and runs on
    its own data; the logger sets ``doX``, which queues the server's TRAP, so the server's
    next step enters the TRAP instead of its instruction.  Taken as ample there (as if it
    served no interrupt), the server runs to its end before the logger's first step, and
    the TRAP is never entered: a line the unreduced search reaches is reported as never
    reached."""
    argv = write_interrupt_tasks(tmp_path, 17)
    full = check_json(argv + ["--no-por"])
    assert never_reached(check_json(argv)) == never_reached(full)
    from rapidmc.model.reduction import partial_order
    monkeypatch.setattr(partial_order, "serving_tasks",
                        lambda program, interrupts, quiet=None, edges=(): frozenset())
    lost = never_reached(check_json(argv)) - never_reached(full)
    assert {line for _, line in lost} == {16}           # TRAP onEvent


def _interrupts(*table, pending=(), scheduled=()) -> Interrupts:
    from rapidmc.semantics.state import Interrupt
    return Interrupts(tuple(Interrupt(number, trap) for number, trap in table), pending,
                      True, scheduled)


def test_the_tasks_serving_interrupts_are_those_whose_traps_they_are(tmp_path):
    argv = write_interrupt_tasks(tmp_path, 17)
    program = load_program([argv[0]], add_tasks=[argv[2]])
    trap = next(r.index for r in program.routines if r.name == "onEvent")
    serving = interrupt_owners.serving_tasks
    assert serving(program, _interrupts()) == frozenset()
    assert serving(program, _interrupts((1, trap))) == frozenset({0})
    assert serving(program, _interrupts((1, trap), pending=(1,))) == frozenset({0})
    assert serving(program, _interrupts(pending=(1,))) is None       # no longer connected
    assert serving(program, _interrupts((1, trap), scheduled=((0.0, 0, 1.0),))) is None


needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")


@needs_native
@pytest.mark.parametrize("seed", [0, 12])
def test_generated_interrupt_tasks_report_the_same_with_both_engines(seed, tmp_path,
                                                                      monkeypatch):
    """States, counts and counterexamples alike: the compiled core hands the states with
    interrupts to Python, whose ample sets and local runs both engines then keep."""
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_interrupt_tasks(tmp_path, seed), monkeypatch,
                                   reuse=seed % 2 == 0)
    assert document["properties"]
