"""Small random RAPID programs that move relative to where the robot is, for the differential
test of the untracked robot position (tests/test_robot_tracking.py).

``random_program(seed)`` writes a module whose main loop first moves the robot to fixed
targets (so the tracked robot, too, has finitely many places) and then runs statements
drawn at random: positions and joints read back with ``CRobT``/``CJointT`` and moved to
again, shifted by ``Offs`` or by component arithmetic, inside the program's own routine
too; counters driven by free digital inputs, kept small by MOD; indexes computed from the
counters that may leave an array (a run-time error); a ``WaitUntil`` on a flag that only
some runs set (a deadlock) and a ``WaitDI``.  ``properties(seed)`` writes LTL properties
over the counters and flags, never over the robot.  The same seed always gives the same
text.
"""
from __future__ import annotations

import random

HEADER = """MODULE Prog
  VAR signaldi in0;
  VAR signaldi in1;
  VAR num a := 0;
  VAR num b := 0;
  VAR num k := 1;
  VAR bool f := FALSE;
  VAR num tab{3} := [1, 2, 3];
  VAR robtarget pos;
  VAR jointtarget jpos;
  CONST robtarget pHome := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0],
    [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
  CONST jointtarget jHome := [[0, 0, 0, 0, 30, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC Nudge()
    MoveL Offs(CRobT(\\Tool:=tool0), 0, 0, 20), v100, fine, tool0;
  ENDPROC

  PROC main()
    AliasIO "IN0", in0;
    AliasIO "IN1", in1;
    WHILE TRUE DO
      MoveAbsJ jHome, v1000, fine, tool0;
      MoveJ pHome, v1000, fine, tool0;
"""
FOOTER = """    ENDWHILE
  ENDPROC
ENDMODULE
"""

# statements that read the robot's position back only to move again
MOVES = (
    "pos := CRobT(\\Tool:=tool0); pos.trans.z := pos.trans.z + {d}; MoveL pos, v100, fine, tool0;",
    "MoveL Offs(CRobT(), -{d}, 0, 0), v100, z10, tool0;",
    "jpos := CJointT(); jpos.robax.rax_1 := jpos.robax.rax_1 + 90; "
    "MoveAbsJ jpos, v100, fine, tool0;",
    "pos := CRobT(); pos := Offs(pos, 0, {d}, -{d}); MoveJ pos, v100, z10, tool0;",
    "Nudge;",
    "IF b = 1 Nudge;",
)
# statements on the other data: choices, errors, waits
DATA = (
    "IF in0 = 1 a := (a + 1) MOD 3;",
    "IF in1 = 1 THEN\n        b := (b + 1) MOD 3;\n      ELSE\n        b := 0;\n      ENDIF",
    "k := tab{{a + 1}} - b;",
    "a := tab{{b + 1}} MOD 3;",
    "IF a = 2 AND b = 2 f := TRUE;",
    "IF f THEN\n        tab{{k}} := a;\n        f := FALSE;\n      ENDIF",
    "WaitUntil f OR a < 2;",
    "WaitDI in0, 1;",
    "IF b = 2 AND k > -1 k := k - 1;",
    "tab{{k}} := b;",
)
FORMULAS = ('G F "a = 0"', 'G ("f" -> F "b = 0")', 'F G "a = 1"', 'G "k >= 0"',
            'G ("a = 2" -> F "a = 0")', 'F "f"', 'G ("b = 1" -> X "b <> 0")')


def random_program(seed: int) -> str:
    rng = random.Random(seed)
    chosen = rng.sample(MOVES, rng.randint(2, 4)) + rng.sample(DATA, rng.randint(3, 5))
    rng.shuffle(chosen)
    body = "".join("      " + text.format(d=rng.choice((10, 20, 50))) + "\n"
                   for text in chosen)
    return HEADER + body + FOOTER


def properties(seed: int) -> list[str]:
    rng = random.Random(seed + 7000)
    return [f"P{number}: {formula}"
            for number, formula in enumerate(rng.sample(FORMULAS, 2), start=1)]
