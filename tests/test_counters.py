"""Wrapping counters of message logs (model/reduction/counters.py) and dead data past an
ExitCycle (model/reduction/liveness.py): reductions that keep every verdict.

Differential: small programs of the Hanoi socket task's pattern (a counter moved on by
one or more, an array written at it, an ``IF n > K THEN n := R; ENDIF`` that wraps it,
bounds that hold and bounds one short, the write before or after the increment; a second
counter wrapped by a compact IF, which is no guard; a TRAP that ends the cycle, an ERROR
handler that does, waits and conditions on free inputs) are checked with every reduction
and with ``--no-reduce`` on both engines: the verdicts are the same wherever the exact
search ends.  An index out of bounds stays found.  With slicing off, the projection of
dead data commutes with the step on every state the plain program reaches (the ExitCycle
a TRAP runs, WaitUntil and CONNECT read only what they name).  The other tests pin which
counters qualify and that a guard's body is not reported unreached.
"""
from __future__ import annotations

import json
import random
from collections import Counter

import pytest

from rapidmc import api, ast
from rapidmc.check import native
from rapidmc.cli import build_parser
from rapidmc.commands.check import prepare_model
from rapidmc.model.reduction.counters import find_counters
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

from cli_capture import assert_reduction_keeps_verdicts, run_cli, verdicts_and_states
from reached_states import breadth_first

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)


def counter_program(seed: int) -> str:
    """A program of the pattern; about half of them write out of the log's bounds."""
    rnd = random.Random(seed)
    size = rnd.choice([3, 4, 5])
    bound = size - 1 + rnd.choice([0, 0, 0, 1])       # size: n reaches size + 1
    step = rnd.choice([1, 1, 1, 2])
    reset = rnd.choice([1, 1, 1, 0])
    start = rnd.choice([1, 1, 1, 0])
    initial = rnd.choice([1, 1, 1, 0, 7])
    write_first = rnd.random() < 0.3
    log_lines = ["log{n} := msg;", f"n := n + {step};"]
    if write_first:
        log_lines.reverse()
    log_lines.append(f"IF n > {bound} THEN\n        n := {reset};\n      ENDIF")
    cycle = ["\n      ".join(log_lines)]
    cycle += rnd.sample([
        "IF di2 = 1 phase := (phase + 1) MOD 3;",
        "WaitUntil di3 = 1 OR phase = 2;",
        "IF phase = 2 THEN\n        hits := hits + 1;\n      ENDIF",
        "IF hits > 2 hits := 0;",
        "Incr m;\n      codes{m} := phase;\n      IF m >= 3 m := 0;",
        "IF di2 = 1 THEN\n        msg := \"b\";\n      ELSE\n        msg := \"a\";\n      ENDIF",
    ], rnd.randint(2, 4))
    trap = rnd.choice(["ExitCycle;", "hits := 0;", "ExitCycle;"])
    handler = rnd.choice(["", "  ERROR\n    ExitCycle;\n", "  ERROR\n    TRYNEXT;\n"])
    orders = "    IDelete irq;\n    CONNECT irq WITH tReset;\n    ISignalDI di1, 1, irq;\n" \
        if rnd.random() < 0.7 else ""
    empty = ", ".join(['""'] * size)
    return (
        "MODULE Prog\n"
        "  VAR intnum irq;\n"
        f"  PERS num n := {initial};\n"
        "  VAR num m := 0;\n"
        f"  PERS string log{{{size}}} := [{empty}];\n"
        "  VAR num codes{4};\n"
        "  VAR num phase := 0;\n"
        "  VAR num hits := 0;\n"
        "  VAR string msg := \"a\";\n"
        "  PROC main()\n"
        f"{orders}"
        f"    n := {start};\n"
        "    WHILE TRUE DO\n"
        + "".join(f"      {line}\n" for line in cycle) +
        "    ENDWHILE\n"
        f"{handler}"
        "  ENDPROC\n"
        "  TRAP tReset\n"
        f"    {trap}\n"
        "  ENDTRAP\n"
        "ENDMODULE\n")


PROGRAMS = [counter_program(seed) for seed in range(24)]
FORMULAS = ["few: G \"hits < 3\"", "phases: G F \"phase = 0\""]


def check(tmp_path, text: str, *flags: str) -> dict:
    """Property -> (verdict, model states) of one in-process check."""
    (tmp_path / "prog.mod").write_text(text)
    argv = ["prog.mod", "--max-states", "20000"]
    for formula in FORMULAS:
        argv += ["--formula", formula]
    return verdicts_and_states([*argv, *flags], cwd=tmp_path)


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    text = PROGRAMS[number]
    reduced = check(tmp_path, text, "--engine", engine)
    exact = check(tmp_path, text, "--engine", engine, "--no-reduce")
    assert_reduction_keeps_verdicts(reduced, exact,
                                    {"no_runtime_error", "no_deadlock", "few", "phases"}, text)


def _program(text: str):
    return build(ast.Program(parse_text(text, "prog.mod")))


def test_the_pattern_has_counters_proven_and_bounds_too_short():
    """Both kinds occur among the generated programs."""
    proven = [not find_counters(_program(text)).empty for text in PROGRAMS]
    assert 5 <= sum(proven) <= len(PROGRAMS) - 5


@pytest.mark.parametrize("number", range(0, len(PROGRAMS), 3))
def test_dead_data_commutes_with_the_step(number):
    """With slicing off, the reduced successors of each projected state are the projections
    of the plain successors (an ExitCycle, from a TRAP or a handler, goes back to main's
    start, where what main reads first is live)."""
    import tempfile
    from pathlib import Path
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "prog.mod"
        path.write_text(PROGRAMS[number])
        args = build_parser().parse_args(["check", str(path), "--no-merge", "--no-por",
                                          "--no-slice"])
        system = prepare_model(args).system
        project = system.project
        assert project is not None
        for state, successors in breadth_first(system.unreduced(), 2000):
            projected = Counter((label, project(after)) for label, after in successors)
            assert projected == Counter(system.successors(project(state))), PROGRAMS[number]


HANOI = """MODULE Socket
  VAR intnum iReset;
  VAR string received := "";
  PERS num ncycle := 1;
  PERS string recstring{5} := ["", "", "", "", ""];
  PROC main()
    IDelete iReset;
    CONNECT iReset WITH tReset;
    ISignalDI diReset, 1, iReset;
    ncycle := 1;
    WHILE TRUE DO
      received := "";
      IF di2 = 1 received := "go";
      ncycle := ncycle + 1;
      recstring{ncycle} := received;
      IF ncycle > BOUND THEN
        ncycle := 1;
      ENDIF
      IF received = "stop" THEN
        TPWrite "never";
      ENDIF
    ENDWHILE
  ENDPROC
  TRAP tReset
    ExitCycle;
  ENDTRAP
ENDMODULE
"""


def test_a_message_log_counter_is_sliced_and_its_guard_not_reported(tmp_path):
    text = HANOI.replace("BOUND", "4")
    program = _program(text)
    counters = find_counters(program)
    assert len(counters.bounded_writes) == 1 and len(counters.guards) == 1
    (tmp_path / "prog.mod").write_text(text)
    found = run_cli(["check", "prog.mod", "--format", "json"], cwd=tmp_path)
    document = json.loads(found.out)
    assert {p["verdict"] for p in document["properties"]} == {"HOLDS"}
    unreached = [w["lines"] for w in document["warnings"] if w.get("code") == "RMC701"]
    lines = json.dumps(unreached)
    assert '"line": 20' in lines and '"line": 17' not in lines, document["warnings"]
    exact = run_cli(["check", "prog.mod", "--format", "json", "--no-reduce"], cwd=tmp_path)
    states = {p["stats"]["model_states"] for p in document["properties"]}
    assert max(states) < min(p["stats"]["model_states"]
                             for p in json.loads(exact.out)["properties"])


def test_an_index_one_past_the_log_stays_found(tmp_path):
    text = HANOI.replace("BOUND", "5")
    assert find_counters(_program(text)).empty
    (tmp_path / "prog.mod").write_text(text)
    document = json.loads(run_cli(["check", "prog.mod", "--format", "json", "--quiet"],
                                  cwd=tmp_path).out)
    verdicts = {p["name"]: p["verdict"] for p in document["properties"]}
    assert verdicts["no_runtime_error"] == "VIOLATED"


@pytest.mark.parametrize("change", [
    ("TPWrite \"never\";", "TPWrite \"n\" \\Num:=ncycle;"),      # read by another statement
    ("IF ncycle > BOUND THEN\n        ncycle := 1;\n      ENDIF", "IF ncycle > 4 ncycle := 1;"),
    ("ncycle := ncycle + 1;", "ncycle := ncycle + 0.5;"),           # not a whole number
    ("  TRAP tReset\n    ExitCycle;", "  TRAP tReset\n    ncycle := 3;\n    ExitCycle;"),
    ("recstring{5} := [\"\", ", "recstring{4} := ["),                  # the log is shorter
    ("ncycle := 1;\n    WHILE", "WHILE"),                                # no start value
])
def test_what_is_no_counter(change):
    text = HANOI.replace(*change).replace("BOUND", "4")
    assert find_counters(_program(text)).empty, text


def test_a_counter_some_property_names_is_kept(tmp_path):
    text = HANOI.replace("BOUND", "4")
    program = _program(text)
    model = api.prepare(program, [api.parse_property('low: G "ncycle < 6"')],
                        api.CheckOptions())
    assert "NCYCLE" not in {program.globals[slot].key for slot in model.plan.slicing.globals}
    plain = api.prepare(program, [], api.CheckOptions())
    assert "NCYCLE" in {program.globals[slot].key for slot in plain.plan.slicing.globals}
