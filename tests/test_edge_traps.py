"""An edge input's interrupt starts its TRAP in the step of the edge, or the edge is dropped.

Differential: small programs of the Hanoi cell's pattern (traps that run for several
steps and end the cycle or set flags, edge inputs beside an input that is watched and
read, whose interrupt stays queued; a timer; IDisable around a section; a TRAP reading
the time) are checked with edge inputs (the default: ``semantics.edge_traps``) and with
``--exact-edges`` (every watched input stored, each edge queued) on both engines: the
verdicts are the same wherever the exact search ends, and the edge model stores fewer
states.  The other tests pin which inputs are served this way (one task's), that a
counterexample whose served edge jumped a queued interrupt is sent to the exact model,
and the state counts of one program.
"""
from __future__ import annotations

import random

import pytest

from rapidmc import ast
from rapidmc.check import native
from rapidmc.check.result import LassoStep, SearchResult
from rapidmc.model.edge_inputs import edge_inputs, realizable, served_edges
from rapidmc.model.inputs import observed_inputs
from rapidmc.model.properties import AtomCompiler
from rapidmc.semantics.link import build
from rapidmc.semantics.state import Interrupts
from rapidmc.syntax import parse_text

from cli_capture import differing_verdicts, verdicts_and_states

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

# trap bodies: several steps, flags, shared data, the end of the cycle
TRAP_LINES = [
    "flag{K} := TRUE;",
    "count := (count + 1) MOD 3;",
    "WaitTime 0.1;",
    "IF di9 = 1 hits := (hits + 1) MOD 5;",
    "hits := (hits + 1) MOD 5;",
    "IF count = 2 ExitCycle;",
    "ISleep int{K}; IWatch int{K};",
]
MAIN_LINES = [
    "IF flag{K} THEN flag{K} := FALSE; n := (n + 1) MOD 3; ENDIF",
    "WaitUntil flag{K} OR count > 0;",
    "IDisable; count := 0; WaitTime 0.1; IEnable;",
    "IF hits > 2 THEN x := 10 / (hits - 3); hits := 0; ENDIF",
    "IF hits > 1 hits := 0;",
    "WaitDI di9, 0;",
    "count := 0;",
]


def trap_program(seed: int) -> str:
    """A program with 1-2 edge inputs ``di1..``, the stored input ``di9`` (watched and
    read), now and then a timer."""
    rnd = random.Random(seed)
    inputs = rnd.randint(1, 2)
    data = ["VAR num count := 0;", "VAR num hits := 0;", "VAR num n := 0;",
            "VAR num x := 0;", "VAR intnum int9;", "VAR intnum itime;"]
    data += [f"VAR intnum int{i};" for i in range(1, inputs + 1)]
    data += [f"VAR bool flag{i} := FALSE;" for i in range(1, inputs + 1)]
    orders = ["CONNECT int9 WITH trap9;", "ISignalDI di9, 1, int9;"]
    traps = ["  TRAP trap9\n    hits := (hits + 1) MOD 5;\n    WaitTime 0.1;\n  ENDTRAP\n"]
    if rnd.random() < 0.3:
        orders += ["CONNECT itime WITH ttime;", "ITimer \\Single, 1, itime;"]
        traps.append("  TRAP ttime\n    count := 1;\n  ENDTRAP\n")
    for i in range(1, inputs + 1):
        trigger = rnd.choice([1, 1, 2])
        orders += [f"CONNECT int{i} WITH trap{i};", f"ISignalDI di{i}, {trigger}, int{i};"]
        body = [rnd.choice(TRAP_LINES) for _ in range(rnd.randint(2, 4))]
        traps.append(f"  TRAP trap{i}\n" + "".join(
            "    " + line.format(K=i) + "\n" for line in body) + "  ENDTRAP\n")
    cycle = [rnd.choice(MAIN_LINES).format(K=rnd.randint(1, inputs))
             for _ in range(rnd.randint(2, 4))]
    return ("MODULE Prog\n" + "".join(f"  {line}\n" for line in data) +
            "  PROC main()\n" + "".join(f"    {line}\n" for line in orders) +
            "    WHILE TRUE DO\n" + "".join(f"      {line}\n" for line in cycle) +
            "    ENDWHILE\n  ENDPROC\n" + "".join(traps) + "ENDMODULE\n")


def check(tmp_path, text: str, *flags: str, bound: int = 30000) -> dict:
    """Property -> (verdict, model states) of one in-process check."""
    (tmp_path / "prog.mod").write_text(text)
    return verdicts_and_states(["prog.mod", "--max-states", str(bound),
                                "--formula", 'few: G "hits < 4"',
                                "--formula", 'calm: G F "n = 0"', *flags], cwd=tmp_path)


PROGRAMS = [trap_program(seed) for seed in range(12)]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    text = PROGRAMS[number]
    served = check(tmp_path, text, "--engine", engine)
    exact = check(tmp_path, text, "--engine", engine, "--exact-edges")
    assert exact.keys() == {"no_runtime_error", "no_deadlock", "few", "calm"}
    assert not differing_verdicts(served, exact), text
    verdict, states = exact["no_runtime_error"]
    if verdict == "HOLDS":
        assert served["no_runtime_error"][1] < states, text


def test_the_pattern_programs_reach_verdicts_both_ways():
    """The differential above compares something: most exact searches end, and both
    verdicts occur."""
    import tempfile
    from pathlib import Path
    verdicts = []
    for text in PROGRAMS[:6]:
        with tempfile.TemporaryDirectory() as scratch:
            verdicts += [v for v, _ in check(Path(scratch), text, "--exact-edges").values()]
    assert verdicts.count("UNKNOWN") < len(verdicts) // 2, verdicts
    assert {"HOLDS", "VIOLATED"} <= set(verdicts)


def _served(text: str) -> list:
    program = build(ast.Program(parse_text(text, "prog.mod")))
    atoms = AtomCompiler(program)
    edges = edge_inputs(program, atoms, observed_inputs(program, atoms))
    return [program.signals[i].name for i in served_edges(program, edges)]


def test_inputs_one_task_watches_are_served_and_read_ones_are_not():
    text = next(t for t in PROGRAMS if "WaitDI di9" in t or "IF di9" in t)
    assert _served(text) == [name for name in ("di1", "di2") if f"ISignalDI {name}," in text]
    assert _served(HANOI) == ["diReset", "diDone"]


HANOI = """MODULE Prog
  VAR intnum iReset;
  VAR intnum iDone;
  VAR bool done := FALSE;
  VAR num phase := 0;
  VAR num hits := 0;
  VAR num n := 0;
  PROC main()
    IDelete iReset;
    CONNECT iReset WITH tReset;
    ISignalDI diReset, 1, iReset;
    IDelete iDone;
    CONNECT iDone WITH tDone;
    ISignalDI diDone, 1, iDone;
    WHILE TRUE DO
      phase := (phase + 1) MOD 4;
      WaitTime 0.1;
    ENDWHILE
  ENDPROC
  TRAP tReset
    phase := 0;
    WaitTime 0.2;
    done := FALSE;
    ExitCycle;
  ENDTRAP
  TRAP tDone
    done := TRUE;
    WaitTime 0.2;
    WaitUntil phase < 4;
    ExitCycle;
  ENDTRAP
ENDMODULE
"""


def test_edges_while_a_trap_runs_queue_nothing(tmp_path):
    """Two edge inputs whose traps run several steps: no state keeps a pending interrupt,
    so the edge model has fewer states than the exact one, with the same verdicts."""
    served = check(tmp_path, HANOI)
    exact = check(tmp_path, HANOI, "--exact-edges")
    assert {n: v for n, (v, _) in served.items()} == {n: v for n, (v, _) in exact.items()}
    assert served["no_runtime_error"][1] < exact["no_runtime_error"][1] // 2


class _State:
    """Just what ``realizable`` reads of a state."""

    def __init__(self, frames, pending=()):
        self.frames = frames
        self.tasks = ()
        self.interrupts = Interrupts(pending=pending)


def test_a_served_edge_ahead_of_a_queued_interrupt_is_not_realizable():
    program = build(ast.Program(parse_text(HANOI, "prog.mod")))
    trap = next(r.index for r in program.routines if r.name == "tReset")
    main = next(r.index for r in program.routines if r.name == "main")
    index = next(s.index for s in program.signals if s.name == "diReset")
    names = {"diReset": index}
    edges = {index: False}
    idle, trapped = ((main, 3),), ((main, 3), (trap, 0))

    def result(pending, first_label):
        steps = [LassoStep(None, _State(idle, pending), 0),
                 LassoStep(((("diReset", first_label),),), _State(trapped), 0)]
        return SearchResult("VIOLATED", prefix=steps)

    assert realizable(result((), 1), edges, names, program, (index,))
    assert not realizable(result((2,), 1), edges, names, program, (index,))
    # an edge that started no TRAP was dropped: it needs no exact run
    dropped = SearchResult("VIOLATED", prefix=[
        LassoStep(None, _State(trapped, (2,)), 0),
        LassoStep(((("diReset", 1),),), _State(trapped, (2,)), 0),
        LassoStep(((("diReset", 1),),), _State(trapped, (2,)), 0)])
    assert realizable(dropped, edges, names, program, (index,))
