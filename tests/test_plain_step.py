"""The plain and fused step drivers give exactly the transitions of the general one.

``step.successors`` serves plain states (one task, no interrupts, no
environment reaction, no stored inputs) through ``fused_step`` (a routine's
simple instructions as generated Python) or else ``plain_step``, and every
other state through ``general_successors``, the general driver (each choice
script run through ``step``).  These tests explore the reachable states of
programs the way a check does (the reduction plan's projection and merge
points, or none) and compare, at every state, each driver's transitions
with the general one's: labels, spans, successor states, output and the
waiting flag, in order.  The states the search stores (``successor_states``,
without labels) must be those of the transitions, in order.

Programs: the counters family of bench/check.py, generated programs
(tests/reduction_programs.py, tests/fuzz_programs.py), the data-driven
check cases (tests/check/) and the case studies.
"""
from __future__ import annotations

import contextlib
import io
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from rapidmc import api
from rapidmc.diagnostics import UserError
from rapidmc.model.reduction import ALL, NONE
from rapidmc.semantics.state import RUNNING
from rapidmc.semantics.fused_step import fused_successor_states, fused_successors
from rapidmc.semantics.plain_step import is_plain, plain_successors
from rapidmc.semantics.step import general_successors, successors

from fuzz_programs import programs
from reduction_programs import properties, random_program
from test_reduction import CHECK_CASES, counters

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
STATE_LIMIT = 1500
CASE_STUDIES = [("case_studies/sorter/sorter_b.mod", "case_studies/sorter/plant.mod",
                 "specs/sorter.ltl"),
                ("case_studies/door/door_race.mod", "case_studies/door/plant.mod",
                 "specs/door.ltl"),
                ("case_studies/hello/hello.mod", None, None)]


def compare_drivers(program, props, reductions, limit: int = STATE_LIMIT) -> tuple[int, int]:
    """Explore up to ``limit`` states as a check would; at each one the drivers must
    agree.  Returns how many of the states were plain, and how many of those fused."""
    model = api.prepare(program, props, api.CheckOptions(reductions=reductions))
    system = model.system
    config = system.config
    seen = dict.fromkeys(system.initial_states())
    todo = list(seen)
    plain = fused = 0
    while todo and len(seen) < limit:
        state = todo.pop()
        reference = outcome(general_successors, program, state, config)
        assert_same(outcome(successors, program, state, config), reference)
        if is_plain(program, state, config) and state.status == RUNNING:
            plain += 1
            assert_same(outcome(plain_successors, program, state, config), reference)
            fast = outcome(fused_successors, program, state, config)
            if fast is not None:
                fused += 1
                assert_same(fast, reference)
                # (without the writes to sliced data it skips: the same once projected)
                project = system.project or (lambda s: s)
                assert [project(s) for s in fused_successor_states(program, state, config)] \
                    == [project(transition.state) for transition in fast]
        if isinstance(reference, str):
            continue                         # a routine rapidmc does not model stops here
        # what the search stores: the same states, without the labels
        assert system.successor_states(state) == [after for _, after in system.successors(state)]
        for _, after in system.successors(state):
            if after not in seen:
                seen[after] = None
                todo.append(after)
    return plain, fused


def outcome(driver, program, state, config):
    """The driver's transitions, or the text of the diagnostic that stops the step
    (reaching a routine known by name only, RMC305): every driver must stop alike."""
    try:
        return driver(program, state, config)
    except UserError as exc:
        return str(exc)


def assert_same(transitions: list, reference: list) -> None:
    """Equal, and written alike (1 and 1.0, 0.0 and -0.0 are equal but not the same)."""
    assert transitions == reference
    assert repr(transitions) == repr(reference)


def load(tmp_path: Path, text: str, env: str | None = None):
    path = tmp_path / "prog.mod"
    path.write_text(text, encoding="latin-1")
    return api.load_program([str(path)], [env] if env else [])


def formulas(*texts: str) -> list:
    return [api.property_from_text(text, number) for number, text in enumerate(texts, 1)]


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
@pytest.mark.parametrize("size", [2, 3])
def test_counters_agree(tmp_path, size, reductions):
    bound = " & ".join(f'"c{i} < 4"' for i in range(size))
    program = load(tmp_path, counters(size, statistics=True))
    plain, fused = compare_drivers(program, formulas(f"b: G ({bound})"), reductions)
    assert plain > fused > 0


FUSED_FORMS = """MODULE Forms
  VAR signaldi in0;
  VAR num n := 0;
  VAR num k := 3;
  VAR bool b := FALSE;
  VAR dnum d := 1;
  PROC main()
    VAR num t := 0;
    AliasIO "IN0", in0;
    WHILE TRUE DO
      FOR i FROM 1 TO k STEP 2 DO
        t := t + i;
      ENDFOR
      FOR j FROM 3 TO 1 DO
        IF in0 = 1 n := (n + j) MOD 5;
      ENDFOR
      TEST n
      CASE 0, 1:
        b := NOT b XOR in0 = 0;
      CASE 2:
        k := 6 DIV (n - 2);
      DEFAULT:
        d := d * 2 - 1;
      ENDTEST
      IF t > 8 GOTO again;
      t := -t / 2;
      again:
      t := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_fused_forms_agree(tmp_path, reductions):
    """FOR (with and without STEP), TEST, compact IF, GOTO, locals, dnum, a division by
    zero (ERR_DIVZERO: the general step's error handling takes over)."""
    program = load(tmp_path, FUSED_FORMS)
    plain, fused = compare_drivers(program, formulas('b: G "n < 5"'), reductions)
    assert plain > fused > 0


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
@pytest.mark.parametrize("seed", range(24))
def test_generated_programs_agree(tmp_path, seed, reductions):
    program = load(tmp_path, random_program(seed))
    props = formulas(*properties(seed, with_next=seed % 2 == 1))
    compare_drivers(program, props, reductions)


@settings(max_examples=80, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck))
@given(programs())
def test_fuzz_programs_agree(tmp_path_factory, program):
    """Records, arrays, every parameter mode, handlers, interrupts, waits, FlexPendant
    reads (programs that fail the static checks are skipped)."""
    loaded = load_fuzz_program(tmp_path_factory.mktemp("fuzz"), program)
    for reductions in (ALL, NONE) if loaded else ():
        compare_drivers(*loaded, reductions, limit=400)


def load_fuzz_program(folder: Path, program):
    """The linked fuzz program and a property per atom it suggests, or None when it
    fails the static checks (a static error, not a state graph)."""
    try:
        with contextlib.redirect_stderr(io.StringIO()):
            linked = load(folder, program.text)
            props = formulas(*(f"a{n}: G {atom}" for n, atom in enumerate(program.atoms)))
            api.prepare(linked, props)
    except (UserError, SystemExit):
        return None
    return linked, props


def load_check_case(case):
    """The program and properties of a data-driven check case (``test_check_cases.Case``;
    skipped when it loads only with the options of its ``args`` file, e.g.
    ``--input-domain``, which this loader does not read)."""
    case = case.folder
    env = next((str(case / name) for name in ("env.mod", "env") if (case / name).is_file()),
               None)
    try:
        with contextlib.redirect_stderr(io.StringIO()):
            program = api.load_program([str(case / "prog.mod")], [env] if env else [])
            props = api.read_properties(str(case / "props.ltl"))
            api.prepare(program, props)
    except (UserError, SystemExit):
        pytest.skip("loads only with the options of its args file")
    return program, props


@pytest.mark.parametrize("case", CHECK_CASES, ids=lambda case: case.name)
def test_check_cases_agree(case):
    program, props = load_check_case(case)
    for reductions in (ALL, NONE):
        compare_drivers(program, props, reductions)


@pytest.mark.parametrize("program, env, spec", CASE_STUDIES)
def test_case_studies_agree(program, env, spec):
    linked = api.load_program([str(ROOT / program)], [str(ROOT / env)] if env else [])
    props = api.read_properties(str(ROOT / spec)) if spec else []
    for reductions in (ALL, NONE):
        compare_drivers(linked, props, reductions)


def test_plain_states_are_most_states_of_the_counters(tmp_path):
    """The fast driver is the one the bench's counters family runs on."""
    program = load(tmp_path, counters(3))
    model = api.prepare(program, formulas('b: G ("c0 < 4")'), api.CheckOptions())
    states = model.system.initial_states()
    assert all(is_plain(program, state, model.system.config) for state in states)
