"""Free inputs: the fast path (step once, inputs applied after) equals re-running the step."""
from __future__ import annotations

from rapidmc import ast
from rapidmc.semantics.link import build
from rapidmc.semantics.step import (CheckConfig, ScriptChooser, enumerate_choices,
                                   initial_states, step, successors)
from rapidmc.syntax import parse_text

PROGRAM = """
MODULE Inputs
  VAR signaldi a;
  VAR signaldi b;
  VAR num n := 0;
  VAR num total := 0;
  PROC main()
    AliasIO "A", a;
    AliasIO "B", b;
    WHILE TRUE DO
      n := n + 1;
      IF a = 1 THEN
        total := (total + 1) MOD 3;
      ENDIF
      IF n > 3 n := 0;
      total := (total + b) MOD 3;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def program():
    return build(ast.Program(parse_text(PROGRAM, "inputs.mod")))


def rerun_every_valuation(prog, state, config):
    return list(enumerate_choices(lambda chooser: step(prog, state, chooser),
                                  lambda script: ScriptChooser(script, config)))


def test_fast_input_branching_gives_the_same_successors_as_rerunning_the_step():
    prog = program()
    config = CheckConfig(prog)
    assert len(config.free_inputs) == 2
    frontier = initial_states(prog, lambda script: ScriptChooser(script, config))
    seen = set(frontier)
    compared = 0
    while frontier:
        state = frontier.pop()
        fast = successors(prog, state, config)
        slow = rerun_every_valuation(prog, state, config)
        assert sorted(map(repr, fast)) == sorted(map(repr, slow))
        compared += 1
        for transition in fast:
            if transition.state not in seen:
                seen.add(transition.state)
                frontier.append(transition.state)
    assert compared == len(seen) > 50


def test_an_instruction_that_reads_a_signal_is_marked():
    prog = program()
    main = prog.routines[prog.entry]
    reading = {ins.span.line for ins in main.code if ins.reads_io}
    assert reading == {12, 16}      # IF a = 1 ... ; total := (total + b) MOD 3;


MANY_INPUTS = """
MODULE Many
  VAR num n := 0;
  PROC main()
    WHILE TRUE DO
      WaitDI di_start, 1;
      n := n + 1;
      IF n > 2 OR DInput(di_abort) = 1 n := 0;
      SetDO do_busy, DInput(di_1);
    ENDWHILE
  ENDPROC
  PROC unused()
    SetDO do_x, DInput(di_2) + DInput(di_3) + DInput(di_4) + DInput(di_5) + DInput(di_6);
  ENDPROC
ENDMODULE
"""


def explore(prog, config):
    from rapidmc.check import check_property
    from rapidmc.ltl import parse_formula, to_buchi
    from rapidmc.ltl.syntax import Not
    from rapidmc.model.rapid_system import RapidSystem
    from rapidmc.model.properties import AtomCompiler
    buchi = to_buchi(Not(parse_formula('G F "n = 0"')))
    valuation = AtomCompiler(prog).valuation(buchi.atoms, {})
    return check_property(RapidSystem(prog, config), buchi, valuation)


def test_inputs_no_property_observes_are_chosen_when_read_not_stored():
    prog = build(ast.Program(parse_text(MANY_INPUTS, "many.mod")))
    eager = explore(prog, CheckConfig(prog))
    lazy = explore(prog, CheckConfig(prog, observed=set()))
    assert eager.verdict == lazy.verdict == "VIOLATED"    # di_start may stay 0 after n := 1
    # 8 free inputs stored in every state multiply the states; chosen on reading they do not
    assert len(CheckConfig(prog).free_inputs) == 8          # di_start, di_abort, di_1 .. di_6
    assert lazy.stats.model_states * 50 < eager.stats.model_states


def test_a_lazily_chosen_input_is_consistent_within_one_step():
    text = """
MODULE Same
  VAR bool odd := FALSE;
  PROC main()
    odd := DInput(di_a) = 1 AND DInput(di_a) = 0;
  ENDPROC
ENDMODULE
"""
    prog = build(ast.Program(parse_text(text, "same.mod")))
    config = CheckConfig(prog, observed=set())
    (start,) = initial_states(prog, lambda script: ScriptChooser(script, config))
    after = successors(prog, start, config)
    assert len(after) == 2                                  # di_a = 0 or 1, read once
    assert all(t.state.store[0] is False for t in after)
