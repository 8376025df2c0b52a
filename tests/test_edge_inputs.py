"""Inputs that only interrupts watch: an edge at any step, the value not stored.

Differential: small programs of the public backups' pattern (1-4 digital inputs watched by
``ISignalDI``, traps that set flags, write shared data or read an input, ``ISleep`` /
``IWatch`` / ``IDisable``, ``\\Single``, a cycle that waits for a trap's flag or fails
when traps come too often; one task or two) are checked with edge inputs (the default)
and with ``--exact-edges`` on both engines: the verdicts are the same, and the edge
model stores no more states.  Where no input qualifies (each is read, or watched for its
falling edge) the two searches are the same search.  The other tests pin which inputs
qualify (``edge_inputs``), the realizability of a counterexample and the check run again
with the values stored when a counterexample is not a run of the controller.
"""
from __future__ import annotations

import json
import random

import pytest

from rapidmc import api, ast
from rapidmc.check import native
from rapidmc.check.result import LassoStep, SearchResult
from rapidmc.model import edge_inputs as edges_module
from rapidmc.model.edge_inputs import edge_inputs, realizable
from rapidmc.model.inputs import observed_inputs
from rapidmc.model.properties import AtomCompiler
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

from cli_capture import assert_reduction_keeps_verdicts, run_cli, verdicts_and_states

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

# trap bodies: a flag, shared data, a read of another input, sleeping or watching again
TRAP_LINES = [
    "flag{K} := TRUE;",
    "count := (count + 1) MOD 3;",
    "IF di{J} = 1 count := 0;",
    "ISleep int{J};",
    "IWatch int{J};",
    "hits := (hits + 1) MOD 5;",
]
# main's cycle: what a trap's flags and data decide
MAIN_LINES = [
    "IF flag{K} THEN flag{K} := FALSE; n := (n + 1) MOD 3; ENDIF",
    "WaitUntil flag{K} OR count > 0;",
    "ISleep int{K}; WaitTime 0.1; IWatch int{K};",
    "IDisable; count := 0; IEnable;",
    "IF hits > 2 THEN x := 10 / (hits - 3); hits := 0; ENDIF",
    "IF hits > 1 hits := 0;",
    "count := 0;",
]


def edge_program(seed: int) -> str:
    """A program of the pattern with 1-4 watched inputs."""
    rnd = random.Random(seed)
    inputs = rnd.randint(1, 4)
    data = ["VAR num count := 0;", "VAR num hits := 0;", "VAR num n := 0;", "VAR num x := 0;"]
    data += [f"VAR intnum int{i};" for i in range(1, inputs + 1)]
    data += [f"VAR bool flag{i} := FALSE;" for i in range(1, inputs + 1)]
    orders = []
    traps = []
    for i in range(1, inputs + 1):
        trigger = rnd.choice([1, 1, 1, 2, 0])
        single = "\\Single, " if rnd.random() < 0.2 else ""
        orders += [f"CONNECT int{i} WITH trap{i};", f"ISignalDI {single}di{i}, {trigger}, int{i};"]
        body = [rnd.choice(TRAP_LINES) for _ in range(rnd.randint(1, 3))]
        traps.append(f"  TRAP trap{i}\n" + "".join(
            "    " + line.format(K=i, J=rnd.randint(1, inputs)) + "\n" for line in body) +
            "  ENDTRAP\n")
    cycle = [rnd.choice(MAIN_LINES).format(K=rnd.randint(1, inputs))
             for _ in range(rnd.randint(2, 4))]
    return ("MODULE Prog\n" + "".join(f"  {line}\n" for line in data) +
            "  PROC main()\n" + "".join(f"    {line}\n" for line in orders) +
            "    WHILE TRUE DO\n" + "".join(f"      {line}\n" for line in cycle) +
            "    ENDWHILE\n  ENDPROC\n" + "".join(traps) + "ENDMODULE\n")


SECOND_TASK = """MODULE Cell
  VAR intnum iStop;
  PERS num shared := 0;
  PROC main()
    CONNECT iStop WITH tStop;
    ISignalDI di1, 1, iStop;
    WHILE TRUE DO
      shared := 1;
      WaitTime 0.1;
      shared := 0;
    ENDWHILE
  ENDPROC
  TRAP tStop
    shared := 2;
  ENDTRAP
ENDMODULE
"""


def check(tmp_path, text: str, *flags: str, second: bool = False) -> dict:
    """Property -> (verdict, model states) of one in-process check."""
    (tmp_path / "prog.mod").write_text(text)
    extra = []
    if second:
        (tmp_path / "cell.mod").write_text(SECOND_TASK)
        extra = ["--add-task", "cell.mod"]
    return verdicts_and_states(["prog.mod", *extra, "--max-states", "6000",
                                "--formula", 'few: G "hits < 4"', *flags], cwd=tmp_path)


def same_verdicts(tmp_path, text: str, engine: str, second: bool) -> tuple:
    """(edge model's, exact model's) property -> (verdict, states) of ``text``, after
    asserting that each verdict the exact search reaches is the edge model's too."""
    by_edges = check(tmp_path, text, "--engine", engine, second=second)
    exact = check(tmp_path, text, "--engine", engine, "--exact-edges", second=second)
    # (the edge model is no bigger: where the exact search ends, it ends too)
    assert_reduction_keeps_verdicts(by_edges, exact, {"no_runtime_error", "no_deadlock", "few"},
                                    text)
    return by_edges, exact


PROGRAMS = [edge_program(seed) for seed in range(30)]


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("number", range(len(PROGRAMS)))
def test_programs_of_the_pattern_keep_their_verdicts(tmp_path, number, engine):
    text = PROGRAMS[number]
    second = number % 5 == 4                 # every fifth with a second task on di1
    by_edges, exact = same_verdicts(tmp_path, text, engine, second)
    verdict, states = exact["no_runtime_error"]
    if verdict == "HOLDS":                   # (the same search, both complete)
        assert by_edges["no_runtime_error"][1] <= states, text
        if not _edges(text):
            assert by_edges["no_runtime_error"][1] == states, text


def test_the_pattern_programs_have_edge_inputs_and_exact_ones():
    """The programs exercise both: some inputs qualify, some do not."""
    qualifying = [len(_edges(text)) for text in PROGRAMS]
    assert sum(1 for found in qualifying if found) >= 15
    assert sum(1 for found in qualifying if not found) >= 2


def _edges(text: str) -> dict:
    program = build(ast.Program(parse_text(text, "prog.mod")))
    atoms = AtomCompiler(program)
    found = edge_inputs(program, atoms, observed_inputs(program, atoms))
    return {program.signals[index].name: both for index, both in found.items()}


ORDERS = """MODULE Prog
  VAR intnum iA;
  VAR intnum iB;
  VAR num n := 0;
  VAR num hits := 0;
  PROC main()
    CONNECT iA WITH tA;
    ISignalDI diA, {A}, iA;
    CONNECT iB WITH tB;
    ISignalDI diB, 1, iB;
    {MORE}
    WHILE TRUE DO
      WaitTime 0.1;
    ENDWHILE
  ENDPROC
  TRAP tA
    n := 1;
  ENDTRAP
  TRAP tB
    n := 2;
  ENDTRAP
ENDMODULE
"""


@pytest.mark.parametrize("trigger, more, expected", [
    ("1", "", {"diA": False, "diB": False}),
    ("2", "", {"diA": True, "diB": False}),
    ("0", "", {"diB": False}),                      # a falling edge: stored
    ("1", "WaitDI diA, 1;", {"diB": False}),         # read by a wait
    ("1", "IF DInput(diA) = 1 n := 3;", {"diB": False}),
    ("1", 'AliasIO "diA", diAlias;', {"diA": False, "diB": False}),  # it only binds
    ("1", 'AliasIO "diA", diAlias; IF DInput(diAlias) = 1 n := 3;', {"diB": False}),
    ("1", 'TPWrite "diA";', {"diB": False}),          # a string naming it
    ("1", "ISignalDI diA, 2, iB;", {"diB": False}),  # watched for two kinds of edge
    ("1", "AliasIO diA, diAlias;", {"diB": False}),
    ("1", "AliasIO \"di\" + \"A\", diAlias;", {}),     # a name built at run time
])
def test_which_inputs_only_interrupts_watch(trigger, more, expected):
    text = ORDERS.replace("{A}", trigger).replace("{MORE}", more)
    if "diAlias" in more:
        text = text.replace("  VAR num n := 0;", "  VAR num n := 0;\n  VAR signaldi diAlias;")
    assert _edges(text) == expected


def _result(labels: list, loop: int = -1) -> SearchResult:
    """A counterexample whose steps chose ``labels`` (lists of (name, value)); from
    ``loop`` on, a cycle closed by the last label."""
    steps = [LassoStep(None, 0, -1)] + [LassoStep((tuple(label), None, ""), i + 1, -1)
                                       for i, label in enumerate(labels[:-1] if loop >= 0
                                                                 else labels)]
    if loop < 0:
        return SearchResult("VIOLATED", prefix=steps)
    return SearchResult("VIOLATED", prefix=steps[:loop + 1], cycle=steps[loop + 1:],
                        closing_label=(tuple(labels[-1]), None, ""))


def test_a_counterexample_is_a_run_when_no_input_rises_twice_in_a_row():
    edges, names = {3: False, 4: True}, {"diA": 3, "diB": 4}
    up, down, both = [("diA", 1.0)], [("diA", 0.0)], [("diB", 1.0)]
    assert realizable(_result([up, down, up, down]), edges, names)
    assert not realizable(_result([down, up, up]), edges, names)
    assert realizable(_result([both, both, both]), edges, names)    # both edges: it flips
    # round the loop: the closing step rises, then the loop's first again
    assert not realizable(_result([down, down, up, down, up], loop=1), edges, names)
    assert realizable(_result([down, down, up, down, down], loop=1), edges, names)
    assert realizable(_result([down, up, down, up], loop=1), edges, names)
    assert not realizable(_result([down, up], loop=0), edges, names)  # a loop of one edge


def test_a_counterexample_that_is_no_run_is_checked_again_with_values_stored(tmp_path,
                                                                           monkeypatch):
    """The check falls back to the exact model, with a note (RMC733), and its verdicts."""
    text = PROGRAMS[0]
    exact = check(tmp_path, text, "--exact-edges")
    assert "VIOLATED" in {verdict for verdict, _ in exact.values()}
    monkeypatch.setattr(api, "realizable", lambda *arguments: False)
    (tmp_path / "prog.mod").write_text(text)
    found = run_cli(["check", "prog.mod", "--format", "json", "--quiet", "--max-states",
                     "6000", "--formula", 'few: G "hits < 4"'], cwd=tmp_path)
    document = json.loads(found.out)
    assert {p["name"]: (p["verdict"], p["stats"]["model_states"])
            for p in document["properties"]} == exact
    assert "RMC733" in {w["code"] for w in document["warnings"]}


def test_a_state_keeps_the_input_at_rest(tmp_path):
    """After a step the input is 0 again: the edge model has fewer states than the exact one
    on a program with one watched input, and the same verdicts."""
    text = ORDERS.replace("{A}", "1").replace("{MORE}", "")
    by_edges = check(tmp_path, text)
    exact = check(tmp_path, text, "--exact-edges")
    assert {k: v[0] for k, v in by_edges.items()} == {k: v[0] for k, v in exact.items()}
    assert by_edges["no_runtime_error"][1] < exact["no_runtime_error"][1]
    assert edges_module.realizable(_result([]), {}, {})


# PickMaster's supervision task: signal data bound by AliasIO from a string, orders on it.
ALIASED = """MODULE Prog
  VAR intnum iA;
  VAR intnum iB;
  VAR num n := 0;
  VAR signaldi aliasA;
  VAR signaldi aliasB;
  PROC main()
    VAR string name;
    name := "diA";
    AliasIO name, aliasA;
    name := "diB";
    AliasIO name, aliasB;
    {MORE}
    CONNECT iA WITH tA;
    ISignalDI aliasA, 1, iA;
    CONNECT iB WITH tB;
    ISignalDI aliasB, 1, iB;
    WHILE TRUE DO
      WaitTime 0.1;
      IF n = 2 n := 0;
    ENDWHILE
  ENDPROC
  TRAP tA
    n := (n + 1) MOD 3;
  ENDTRAP
  TRAP tB
    n := 0;
  ENDTRAP
ENDMODULE
"""

ALIAS_EIO = """EIO:CFG_1.0:6:1::
#
EIO_SIGNAL:
      -Name "diA" -SignalType "DI" -DeviceMap "0"
      -Name "diB" -SignalType "DI" -DeviceMap "1"
#
"""


def _aliased_edges(more: str) -> dict:
    from rapidmc.load.backup import read_eio
    import tempfile
    with tempfile.TemporaryDirectory() as folder:
        path = f"{folder}/EIO.cfg"
        with open(path, "w") as stream:
            stream.write(ALIAS_EIO)
        signals = read_eio(path)
    program = build(ast.Program(parse_text(ALIASED.replace("{MORE}", more), "prog.mod")),
                    options={"configured_signals": signals})
    atoms = AtomCompiler(program)
    found = edge_inputs(program, atoms, observed_inputs(program, atoms))
    return {program.signals[index].name: both for index, both in found.items()}


@pytest.mark.parametrize("more, expected", [
    ("", {"diA": False, "diB": False}),
    ("WaitDI aliasA, 1;", {"diB": False}),            # the bound data read
    ("TPWrite name;", {}),                            # the name used otherwise: a read
    ("AliasIO name, aliasA;", {}),     # aliasA bound to diA or diB: its order reads both
    ('TPWrite "diA";', {"diB": False}),               # another string naming it
])
def test_orders_on_signal_data_aliasio_binds_watch_edge_inputs(more, expected):
    assert _aliased_edges(more) == expected


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("more", ["", "WaitDI aliasA, 1;"])
def test_aliased_edge_inputs_keep_the_verdicts(tmp_path, engine, more):
    (tmp_path / "EIO.cfg").write_text(ALIAS_EIO)
    (tmp_path / "prog.mod").write_text(ALIASED.replace("{MORE}", more))
    argv = ["prog.mod", "--eio", "EIO.cfg", "--engine", engine, "--max-states", "6000",
            "--formula", 'small: G "n < 2"']
    by_edges = verdicts_and_states(argv, cwd=tmp_path)
    exact = verdicts_and_states(argv + ["--exact-edges"], cwd=tmp_path)
    assert {k: v[0] for k, v in by_edges.items()} == {k: v[0] for k, v in exact.items()}
    assert exact["small"][0] == "VIOLATED"            # two rising edges of diA in a row
    if not more:
        assert by_edges["no_runtime_error"][1] < exact["no_runtime_error"][1]
