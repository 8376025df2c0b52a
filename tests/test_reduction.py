"""Reductions (sliced data, merged steps) keep every verdict and shrink the state space.

The differential tests run ``rapidmc check`` in-process with every reduction
on and with ``--no-reduce`` on generated programs (tests/reduction_programs.py),
on the data-driven check cases and on the case studies, and compare verdicts
(where both searches finished).  The other tests pin what the analyses
decide and what the counterexamples show.
"""
from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import pytest

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rapidmc import ast
from rapidmc.cli import main
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.reduction import plan_reductions
from rapidmc.model.reduction.relevance import find_slicing
from rapidmc.model.reduction.totality import Totality
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import parse_text

from fuzz_programs import programs
from reduction_programs import properties, random_program
from test_check_cases import SAFETY, run_check, verdict_cases
from cli_capture import run_cli

ROOT = Path(__file__).resolve().parent.parent
# the data-driven cases that expect verdicts (not input errors) and have a property file
CHECK_CASES = [case for case in verdict_cases() if (case.folder / "props.ltl").is_file()]
UNKNOWN = "UNKNOWN"


def check_json(argv: list[str]) -> dict[str, str]:
    """Verdict per property of one in-process ``rapidmc check --format json`` run."""
    document = json.loads(run_cli(["check", *argv, "--format", "json", "--quiet"]).out)
    return {p["name"]: p["verdict"] for p in document["properties"]}


def assert_same_verdicts(reduced: dict[str, str], plain: dict[str, str]) -> None:
    assert reduced.keys() == plain.keys()
    for name, verdict in plain.items():
        if UNKNOWN not in (verdict, reduced[name]):
            assert reduced[name] == verdict, name


def counters(n: int, statistics: bool = False) -> str:
    inputs = "\n".join(f"  VAR signaldi in{i};\n  VAR num c{i} := 0;" for i in range(n))
    aliases = "\n".join(f'    AliasIO "IN{i}", in{i};' for i in range(n))
    body = "\n".join(f"      IF in{i} = 1 c{i} := (c{i} + 1) MOD 4;" for i in range(n))
    extra = data = ""
    if statistics:
        data = '  VAR num nCycles := 0;\n  VAR string lastLog := "";\n'
        extra = '      nCycles := nCycles + 1;\n      lastLog := "cycle " + NumToStr(nCycles, 0);\n'
    return (f"MODULE Counters\n{inputs}\n{data}  PROC main()\n{aliases}\n    WHILE TRUE DO\n"
            f"{body}\n{extra}    ENDWHILE\n  ENDPROC\nENDMODULE\n")


def states_of(tmp_path: Path, text: str, formula: str, *flags: str) -> tuple[str, int]:
    path = tmp_path / "prog.mod"
    path.write_text(text)
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["check", str(path), "--formula", formula, "--format", "json", "--quiet", *flags])
    checked = json.loads(out.getvalue())["properties"][-1]
    return checked["verdict"], checked["stats"]["product_states"]


# --- differential -------------------------------------------------------------


# Unreduced, these generated programs grow without end (data only slicing bounds): every
# unreduced verdict is UNKNOWN at 20,000 states, so none is compared.  Their unreduced
# searches stop at 5,000, which compares as little (a violation within 5,000 states would
# have been found within 20,000: the search order is fixed).  The test checks that they
# still end UNKNOWN: a seed whose unreduced search starts to end fails, and leaves the set.
# (A property violated by a bad prefix seen within 5,000 states is VIOLATED unreduced too:
# seed 36's "safe".)
GROWING_UNREDUCED = {"plain": {8, 12, 24, 28, 36}, "numeric": {8, 12, 16}}


def assert_reduction_keeps_verdicts(argv: list[str], growing: bool) -> None:
    reduced = check_json(argv)
    if not growing:
        assert_same_verdicts(reduced, check_json(argv + ["--no-reduce"]))
        return
    plain = check_json(argv + ["--no-reduce", "--max-states", "5000"])
    assert reduced.keys() == plain.keys()
    # the unreduced state space does not end: its built-in checks stay UNKNOWN; a property
    # may be VIOLATED by a bad prefix the bounded search saw (a safety property's violation
    # needs no loop), and then the reduced search must say so too
    assert {plain[name] for name in SAFETY} == {UNKNOWN}, plain
    decided = {name: verdict for name, verdict in plain.items() if verdict != UNKNOWN}
    assert decided == {name: reduced[name] for name in decided}, (plain, reduced)


@pytest.mark.parametrize("seed", range(40))
def test_generated_programs_keep_their_verdicts(tmp_path, seed):
    program = tmp_path / "prog.mod"
    program.write_text(random_program(seed))
    spec = tmp_path / "props.ltl"
    # even seeds: X-free properties only, so that steps are merged
    spec.write_text("\n".join(properties(seed, with_next=seed % 2 == 1)) + "\n")
    argv = [str(program), "--ltl", str(spec), "--max-states", "20000"]
    assert_reduction_keeps_verdicts(argv, seed in GROWING_UNREDUCED["plain"])


# Each program's property fails exactly when the dead-data analysis forgets one path on
# which a value is read: the handler reading what an assignment that raised did not
# overwrite (t was once reset there), TRYNEXT going on after such a statement, a routine
# called through another that reads a global, a routine called by a computed name.  A
# version of the analysis without that path gives VIOLATED.
DEAD_DATA_PATHS = {
    "handler": """MODULE M
  VAR num y := 0;
  VAR bool failed := FALSE;
  PROC main()
    VAR num t := 0;
    t := 5;
    WaitTime 1;
    t := 10 / y;
  ERROR
    IF t <> 5 failed := TRUE;
    TRYNEXT;
  ENDPROC
ENDMODULE
""",
    "call": """MODULE M
  VAR num g := 0;
  VAR bool failed := FALSE;
  PROC look()
    IF g <> 5 failed := TRUE;
  ENDPROC
  PROC outer()
    look;
  ENDPROC
  PROC main()
    g := 5;
    WaitTime 1;
    outer;
    g := 0;
    WaitTime 1;
  ENDPROC
ENDMODULE
"""}
DEAD_DATA_PATHS["trynext"] = DEAD_DATA_PATHS["handler"].replace(
    "  ERROR\n    IF t <> 5 failed := TRUE;\n", "    IF t <> 5 failed := TRUE;\n  ERROR\n")
DEAD_DATA_PATHS["late_bound_call"] = DEAD_DATA_PATHS["call"].replace("    look;", '    %"look"%;')


@pytest.mark.parametrize("name", sorted(DEAD_DATA_PATHS))
@pytest.mark.parametrize("flags", [(), ("--no-merge",), ("--no-dead",), ("--no-reduce",)])
def test_dead_data_keeps_values_read_after_an_error_or_in_a_call(tmp_path, name, flags):
    assert states_of(tmp_path, DEAD_DATA_PATHS[name], 'P: G !failed', *flags)[0] == "HOLDS"


@pytest.mark.parametrize("seed", range(24))
def test_numeric_instructions_keep_their_verdicts(tmp_path, seed):
    """Incr, Decr, Clear and Add read as their assignments by slicing and merging."""
    program = tmp_path / "prog.mod"
    program.write_text(random_program(seed, numeric_updates=True))
    spec = tmp_path / "props.ltl"
    spec.write_text("\n".join(properties(seed, with_next=seed % 3 == 2)) + "\n")
    argv = [str(program), "--ltl", str(spec), "--max-states", "20000"]
    assert_reduction_keeps_verdicts(argv, seed in GROWING_UNREDUCED["numeric"])


@settings(max_examples=80, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck))
@given(programs(), st.randoms(use_true_random=False))
def test_fuzz_programs_keep_their_verdicts(tmp_path_factory, program, rnd):
    """The broad generator of tests/fuzz_programs.py: records, arrays, every parameter mode,
    handlers, interrupts, waits (programs that fail the static checks are skipped)."""
    path = tmp_path_factory.mktemp("fuzz") / "prog.mod"
    path.write_text(program.text, encoding="latin-1")
    argv = [str(path), "--max-states", "3000", "--max-seconds", "10"]
    if program.atoms:
        first, second = rnd.choice(program.atoms), rnd.choice(program.atoms)
        argv += [f'--formula=s: G "{first}"', f'--formula=r: G ("{first}" -> F "{second}")']
    try:
        reduced = check_json(argv)
    except json.JSONDecodeError:
        return                               # a static error, not a verdict
    assert_same_verdicts(reduced, check_json(argv + ["--no-reduce"]))


@pytest.mark.parametrize("case", CHECK_CASES, ids=lambda case: case.name)
def test_check_cases_keep_their_verdicts(case, monkeypatch):
    # with the case's own options (its bound, further tasks, input and message domains), from
    # its folder as tests/test_check_cases.py runs it (the reduced side is that very run,
    # shared): without its bound, a case whose unreduced program grows without end searched
    # to the default bound (minutes)
    _, stdout, _ = run_check(case, monkeypatch)
    reduced = {p["name"]: p["verdict"] for p in json.loads(stdout)["properties"]}
    assert_same_verdicts(reduced, check_json([*case.argv()[1:], "--no-reduce"]))


@pytest.mark.parametrize("program, env, spec", [
    ("case_studies/sorter/sorter_a.mod", "case_studies/sorter/plant.mod", "specs/sorter.ltl"),
    ("case_studies/sorter/sorter_b.mod", "case_studies/sorter/plant.mod", "specs/sorter.ltl"),
    ("case_studies/door/door_race.mod", "case_studies/door/plant.mod", "specs/door.ltl"),
])
def test_case_studies_keep_their_verdicts(program, env, spec):
    argv = [str(ROOT / program), "--env", str(ROOT / env), "--ltl", str(ROOT / spec)]
    assert_same_verdicts(check_json(argv), check_json(argv + ["--no-reduce"]))


# --- what the reductions achieve ---------------------------------------------------


def test_statistics_variant_holds_with_as_many_states_as_the_counters(tmp_path):
    formula = 'bounded: G ("c0 < 4" & "c1 < 4" & "c2 < 4" & "c3 < 4" & "c4 < 4")'
    plain = states_of(tmp_path, counters(5), formula)
    with_statistics = states_of(tmp_path, counters(5, statistics=True), formula)
    assert plain[0] == with_statistics[0] == "HOLDS"
    assert with_statistics[1] == plain[1]


def test_statistics_variant_counting_with_incr_is_as_small(tmp_path):
    """`Incr nCycles` is sliced and merged as `nCycles := nCycles + 1` is."""
    formula = 'bounded: G ("c0 < 4" & "c1 < 4" & "c2 < 4")'
    incr = counters(3, statistics=True).replace("nCycles := nCycles + 1;", "Incr nCycles;")
    assert "Incr nCycles;" in incr
    assert states_of(tmp_path, incr, formula) == ("HOLDS", 195)
    assert states_of(tmp_path, incr, formula, "--no-merge") == ("HOLDS", 579)


def test_statistics_variant_without_slicing_is_bounded(tmp_path):
    verdict, _ = states_of(tmp_path, counters(3, statistics=True), 'b: G "c0 < 4"',
                           "--no-slice", "--max-states", "5000")
    assert verdict == UNKNOWN


@pytest.mark.parametrize("flags, states", [((), 195), (("--no-merge",), 451),
                                           (("--no-reduce",), 451)])
def test_merged_steps_store_fewer_states(tmp_path, flags, states):
    formula = 'bounded: G ("c0 < 4" & "c1 < 4" & "c2 < 4")'
    assert states_of(tmp_path, counters(3), formula, *flags) == ("HOLDS", states)


def test_merged_step_makes_one_outside_choice():
    """A merged step stops before a second instruction that chooses a value of data written
    from outside (``Instruction.chooses``): the IFs of tests/check/outside_pers_merged_choices
    each read such data, and merged together their choices multiplied into 145,423
    transitions between 24 states; stopping, the search has 560 between 36 (the same
    verdicts: ``test_check_cases_keep_their_verdicts``)."""
    case = ROOT / "tests" / "check" / "outside_pers_merged_choices"
    out = io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
        main(["check", str(case / "prog.mod"), "--format", "json", "--quiet"])
    stats = {p["name"]: p["stats"] for p in json.loads(out.getvalue())["properties"]}
    assert stats["no_deadlock"]["transitions"] <= 1_000
    assert stats["no_deadlock"]["model_states"] <= 100


def test_counterexample_lists_every_line_and_sliced_values(tmp_path):
    path = tmp_path / "prog.mod"
    path.write_text(counters(2, statistics=True))
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        # --full-trace: every step, none folded as not read by the property (issue 28)
        main(["check", str(path), "--formula", 'P: G "c1 < 1"', "--quiet", "--full-trace"])
    text = out.getvalue()
    assert "P: VIOLATED" in text
    assert 'lastLog = "cycle 1"' in text and "nCycles = 1" in text
    lines = [int(line.split("prog.mod:")[1].split()[0]) for line in text.splitlines()
             if "prog.mod:" in line]
    # in the loop, every statement appears: no line is skipped by a merged step
    loop = [line for line in lines if line >= 10]
    assert {10, 11, 12, 13, 14}.issubset(set(loop))


# --- the analyses ---------------------------------------------------------------


def linked(text: str):
    return build(ast.Program(parse_text(text, "prog.mod")))


def global_names(program, slots) -> set[str]:
    return {program.globals[slot].name for slot in slots}


def test_unread_counter_and_log_are_sliced_counters_are_not():
    program = linked(counters(2, statistics=True))
    slicing = find_slicing(program, ["c0 < 4"])
    assert global_names(program, slicing.globals) == {"nCycles", "lastLog"}


def test_total_writes_are_the_assignments_to_sliced_data():
    """The assignments a step may skip (``Slicing.total_writes``): nCycles's and lastLog's,
    not the counters' (which an atom reads)."""
    text = counters(2, statistics=True)
    slicing = find_slicing(linked(text), ["c0 < 4", "c1 < 4"])
    assert {span.line for span in slicing.total_writes} == {
        number for number, line in enumerate(text.splitlines(), 1)
        if line.lstrip().startswith(("nCycles :=", "lastLog :="))}


def test_projection_resets_sliced_data_and_keeps_a_projected_state():
    program = linked(counters(2, statistics=True))
    config = CheckConfig(program)
    plan = plan_reductions(program, config, ["c0 < 4"], [None])
    project = plan.projection
    state = RapidSystem(program, config).initial_states()[0]
    assert project(state) is state                     # nothing to reset: the same object
    slots = {program.globals[slot].name: slot for slot in plan.slicing.globals}
    logged = state._replace(store=state.store.set(slots["nCycles"], 5.0)
                            .set(slots["lastLog"], "cycle 5"))
    assert project(logged) == state
    assert not project.frame_resets                    # main has no routine data to reset


def test_data_an_atom_names_is_kept():
    program = linked(counters(1, statistics=True))
    slicing = find_slicing(program, ["nCycles > 3"])
    assert global_names(program, slicing.globals) == {"lastLog"}


@pytest.mark.parametrize("statement, sliced", [
    ("x := x + 1;", True),                          # a num plus a small literal never fails
    ("x := x * 2;", False),                         # may overflow: ERR_NUM_LIMIT
    ("x := 1 / x;", False),                         # may divide by zero
    ('s := "cycle " + NumToStr(x, 0);', True),      # at most 47 characters
    ('s := s + "x";', False),                       # may exceed 80 characters
    ("x := y;", True),                              # nothing reads x (y stays: a condition reads it)
    ("TPWrite NumToStr(x, 0);", False),             # any call observes its arguments
    ("Incr x;", True),                              # x := x + 1
    ("Decr x;", True),
    ("Clear x;", True),
    ("Add x, 3;", True),
    ("Add x, -3;", True),
    ("Add x, x;", False),                           # x := x + x may overflow
    ("Add x, y;", False),
    ("Incr x; TPWrite NumToStr(x, 0);", False),     # read elsewhere
])
def test_slicing_of_one_statement(statement, sliced):
    text = f"""MODULE M
  VAR num x := 0;
  VAR num y := 0;
  VAR string s := "";
  PROC main()
    WHILE TRUE DO
      IF y > 2 y := 0;
      {statement}
    ENDWHILE
  ENDPROC
ENDMODULE
"""
    program = linked(text)
    names = global_names(program, find_slicing(program).globals)
    target = "s" if statement.startswith("s :=") else "x"
    assert (target in names) == sliced


def test_a_user_routine_named_incr_is_a_call():
    """Only the predefined Incr is read as `x := x + 1`: a program's own PROC Incr may do
    anything with its argument, so the data it is given stays."""
    text = """MODULE M
  VAR num x := 0;
  PROC Incr(INOUT num n)
    n := n * 2;
  ENDPROC
  PROC main()
    WHILE TRUE DO
      Incr x;
    ENDWHILE
  ENDPROC
ENDMODULE
"""
    program = linked(text)
    assert "x" not in global_names(program, find_slicing(program).globals)
    predefined = linked(text.replace("Incr(INOUT num n)", "Double(INOUT num n)"))
    assert "x" in global_names(predefined, find_slicing(predefined).globals)


def test_properties_given_as_automata_disable_merging():
    program = linked(counters(1))
    config = CheckConfig(program, observed=set())
    plan = plan_reductions(program, config, ["c0 < 4"], [None])
    assert plan.merge_points == {}          # an automaton given as HOA: X may occur


@pytest.mark.parametrize("expression, total", [
    ("1 + 2", True), ("x + 1", True), ("x + y", False), ("x DIV 2", False),
    ("NOT b AND b", True), ('"ab" + "cd"', True), ("NumToStr(x, 7)", False),
])
def test_totality(expression, total):
    program = linked(f"""MODULE M
  VAR num x := 0;
  VAR num y := 0;
  VAR bool b := FALSE;
  PROC main()
  ENDPROC
ENDMODULE
""")
    routine = program.routines[program.entry]
    expr = parse_text(f"MODULE E\n  PROC p()\n    TPWrite {expression} ;\n  ENDPROC\nENDMODULE\n",
                 "e.mod")[0].routines[0].body[0].args[0].value
    assert Totality(lambda name: routine.scope.lookup(name.key)).total(expr) == total


DEAD_LOCAL = """MODULE M
  VAR num x := 0;
  PROC main()
    VAR num t := 0;
    WHILE TRUE DO
      t := x + 1;
      x := t MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("flags, states", [(("--no-merge",), 9), (("--no-merge", "--no-dead"), 11),
                                           ((), 3), (("--no-dead",), 4)])
def test_dead_values_are_reset(tmp_path, flags, states):
    # t is written before it is read at the WHILE test: its old value is forgotten there
    assert states_of(tmp_path, DEAD_LOCAL, 'P: G "x < 3"', *flags) == ("HOLDS", states)


def test_liveness_of_a_local_along_the_loop():
    from rapidmc.model.reduction.liveness import DeadData
    program = linked(DEAD_LOCAL)
    dead = DeadData(program, {"X"})
    main = program.routines[program.entry]
    t_slot = main.local_names.index("t")
    lines = {pc: instruction.span.line for pc, instruction in enumerate(main.code)}
    dead_at = {lines[pc] for pc, slots in enumerate(dead.locals[main.index]) if t_slot in slots}
    assert dead_at == {5, 6, 9}          # the WHILE test, t := ..., ENDPROC


BUSY_LOOP = """MODULE M
  VAR num x := 0;
  VAR bool toggle := FALSE;
  PROC main()
    WHILE TRUE DO
      IF x > 5 x := 0;
      toggle := NOT toggle;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("flags", [(), ("--no-reduce",)])
def test_a_loop_that_changes_only_sliced_data_is_no_deadlock(tmp_path, flags):
    # reduced, every pass of the loop returns to the same stored state; the deadlock
    # check still sees that single instructions move on
    path = tmp_path / "prog.mod"
    path.write_text(BUSY_LOOP)
    assert check_json([str(path), "--formula", 'P: G "x < 6"', *flags])["no_deadlock"] == "HOLDS"


FLOW_INTO_ATOM = """MODULE M
  VAR signaldi in0;
  VAR bool f := FALSE;
  VAR bool g := FALSE;
  PROC main()
    AliasIO "IN0", in0;
    WHILE TRUE DO
      g := f;
      f := NOT g;
      WaitDI in0, 1;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("flags", [(), ("--no-reduce",)])
def test_data_flowing_into_an_atom_is_kept(tmp_path, flags):
    # f is read only by `g := f` (total): it matters because the atom reads g
    assert states_of(tmp_path, FLOW_INTO_ATOM, "flag: G (g -> F !g)", *flags)[0] == "VIOLATED"
    program = linked(FLOW_INTO_ATOM)
    assert "f" not in global_names(program, find_slicing(program, ["g"]).globals)
