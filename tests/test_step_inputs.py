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
