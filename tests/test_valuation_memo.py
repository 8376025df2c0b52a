"""The remembered valuation of atoms gives the bits of the plain one in every state.

``AtomCompiler.valuation`` evaluates atoms that read only global data and
signals once per distinct (global data, signals) pair; the others in every
state.  Differential: on generated programs (tests/reduction_programs.py,
tests/fuzz_programs.py), every reachable state gets the same bits with the
memo as without it.
"""
from __future__ import annotations

import pytest
from hypothesis import HealthCheck, given, settings

from rapidmc import ast
from rapidmc.check import find_reachable
from rapidmc.diagnostics import UserError
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.properties import AtomCompiler, reads_data_only, parse_atom_expression
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import parse_text

from fuzz_programs import programs
from reduction_programs import random_program

# data atoms, and atoms that read the call stack, locals or the status
RANDOM_ATOMS = ("a < 2", "b = 0", "f", "NOT g AND c > 0", "in0 = 1", "lastLog = \"\"",
                'InRoutine("bump")', "bump.calls > 0", "main.tmp = 1", "Ended()",
                "a = 1 AND InRoutine(\"main\")")


def reachable_states(program, max_states: int = 3000) -> list:
    system = RapidSystem(program, CheckConfig(program))
    seen: list = []
    find_reachable(system, lambda state: False, max_states=max_states,
                   observe=lambda state, successors: seen.append(state))
    return seen


def assert_same_bits(program, atoms: tuple[str, ...]) -> None:
    remembered = AtomCompiler(program).valuation(atoms, {})
    plain = AtomCompiler(program).valuation(atoms, {}, memo=False)
    states = reachable_states(program)
    assert states
    for state in states + states:           # the second pass answers from the memo
        assert remembered(state) == plain(state)


@pytest.mark.parametrize("seed", range(12))
def test_generated_programs_get_the_same_bits_with_the_memo(seed):
    program = build(ast.Program(parse_text(random_program(seed), "random.mod")))
    assert_same_bits(program, RANDOM_ATOMS)


@settings(max_examples=30, derandomize=True, deadline=None, database=None,
          suppress_health_check=list(HealthCheck))
@given(programs())
def test_fuzz_programs_get_the_same_bits_with_the_memo(generated):
    """Records, arrays, signals, functions in atoms (programs failing static checks skipped)."""
    if not generated.atoms:
        return
    try:
        program = build(ast.Program(parse_text(generated.text, "fuzz.mod")))
        atoms = tuple(dict.fromkeys(generated.atoms))[:8]
        AtomCompiler(program).valuation(atoms, {})
    except UserError:
        return
    assert_same_bits(program, atoms)


PROGRAM = """MODULE M
  VAR num x := 0;
  VAR signaldi di;
  CONST num K := 3;
  FUNC num twice(num v)
    RETURN 2 * v;
  ENDFUNC
  PROC main()
    VAR num tmp := 0;
    x := x + 1;
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("atom, data_only", [
    ("x < K", True), ("x = 1 OR NOT (x > 2)", True), ("di = 1", True),
    ("twice(x) > 2", False), ('InRoutine("main")', False), ("main.tmp = 0", False),
    ("ERRNO = 0", False), ("Ended()", False), ("AtLine(10)", False),
])
def test_atoms_reading_only_data_are_told_apart(atom, data_only):
    program = build(ast.Program(parse_text(PROGRAM, "m.mod")))
    compiler = AtomCompiler(program)
    expr = parse_atom_expression(atom, ast.Span("<formula>", 1, 1))
    assert reads_data_only(compiler.symbols(expr)) is data_only
