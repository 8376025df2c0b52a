"""The generated valuation of atoms (``fused_atoms``) gives the bits of the reference one.

``AtomCompiler.valuation`` evaluates atoms with a source by one generated
function; ``memo=False`` evaluates every atom on a ``Machine`` (the
reference).  These tests explore the states of programs as a check does and
compare both valuations at every state: the data-driven check cases,
generated programs, fuzz programs with their atoms, and atoms that raise a
RAPID error (false), read signals, or name a num bare.
"""
from __future__ import annotations


import pytest
from hypothesis import HealthCheck, given, settings

from rapidmc import api
from rapidmc.diagnostics import UserError
from rapidmc.model.reduction import NONE
from rapidmc.model.properties import AtomCompiler

from fuzz_programs import programs
from reduction_programs import properties, random_program
from test_plain_step import formulas, load, load_check_case, load_fuzz_program
from test_reduction import CHECK_CASES

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

STATE_LIMIT = 600


def compare_valuations(program, props, limit: int = STATE_LIMIT) -> int:
    """Explore up to ``limit`` states; at each, the generated valuation of every
    property's atoms must equal the reference.  Returns how many valuations were
    generated functions (``fused_atoms``)."""
    model = api.prepare(program, props, api.CheckOptions(reductions=NONE))
    system = model.system
    atoms = AtomCompiler(program)
    pairs = []
    generated = 0
    for _, buchi, _ in model.jobs:
        fast = atoms.valuation(buchi.atoms, {})
        generated += getattr(fast, "__code__", None) is not None and \
            fast.__code__.co_filename == "<fused atoms>"
        pairs.append((fast, atoms.valuation(buchi.atoms, {}, memo=False)))
    seen = dict.fromkeys(system.initial_states())
    todo = list(seen)
    while todo and len(seen) < limit:
        state = todo.pop()
        for fast, reference in pairs:
            assert fast(state) == reference(state), state
        try:
            found = system.successors(state)
        except UserError:
            continue                        # a routine rapidmc does not model stops here
        for _, after in found:
            if after not in seen:
                seen[after] = None
                todo.append(after)
    return generated


ATOMS_PROGRAM = """MODULE Atoms
  VAR signaldi in0;
  VAR signaldi unbound;
  VAR num n := 0;
  VAR num d := 0;
  VAR num arr{3} := [1, 2, 3];
  VAR string s := "a";
  VAR bool b := FALSE;
  PROC main()
    AliasIO "IN0", in0;
    WHILE TRUE DO
      n := (n + 1) MOD 5;
      d := n - 2;
      IF n = 3 s := s + "b";
      IF StrLen(s) > 3 s := "a";
      b := NOT b;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def test_error_signal_and_bare_atoms_agree(tmp_path):
    """Division by zero and an index out of range (false), a signal and signal data
    (bound and not), a num named bare (= 1), strings and bools."""
    program = load(tmp_path, ATOMS_PROGRAM)
    props = formulas('a: G ("6 / d > 1" | "arr{n} = 2" | in0 | "unbound = 1")',
                     'b: G F (n | "s = \\"ab\\"" | b | "IN0 = 0" | "n + d >= 2")')
    assert compare_valuations(program, props) == 2


@pytest.mark.parametrize("seed", range(12))
def test_generated_programs_agree(tmp_path, seed):
    program = load(tmp_path, random_program(seed))
    assert compare_valuations(program, formulas(*properties(seed))) > 0


@pytest.mark.parametrize("case", CHECK_CASES, ids=lambda case: case.name)
def test_check_cases_agree(case):
    compare_valuations(*load_check_case(case))


@settings(max_examples=40, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck))
@given(programs())
def test_fuzz_programs_agree(tmp_path_factory, program):
    loaded = load_fuzz_program(tmp_path_factory.mktemp("fuzz"), program)
    if loaded:
        compare_valuations(*loaded, limit=200)
