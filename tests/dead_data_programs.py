"""Small random RAPID programs whose data dies in the places the dead-data analysis reasons about.

``dead_data_program(seed)`` writes a module with a main loop over free digital inputs.
Data no property names (``w``, ``x``, ``reply``, ``parts``, ``count``, ``divisor`` and
routine data) is written, read and written again around:

* calls of a routine with two FOR loops over routine data, filling an array passed by
  reference (the pattern of ``tests/check/socket_split_fields``: a split routine);
* a routine that reads a global only through another routine it calls;
* divisions that may raise, in main and in a routine, with ERROR handlers that read
  data, repair the divisor and end in RETRY or TRYNEXT (or pass the error on);
* a user function called inside an expression;
* with ``moves_and_trap``: moves whose targets read data (one indexes an array with
  data that may be 0, so the move raises), and a TRAP on a free input that reads one
  global and writes another (globals no trap names die around it).

``dead_data_properties(seed)`` writes properties over ``a``, ``b`` and ``failed``, which
the statements set from the other data, so a value forgotten too early changes a
verdict.  The same seed always gives the same text; every program has finitely many
states.
"""
from __future__ import annotations

import random

INPUTS = ("in0", "in1")

# statements of the main loop: each reads or writes data the properties do not name
MAIN_STATEMENTS = (
    "w := {c};",
    "x := {c};",
    "w := (w + 1) MOD 3;",
    "IF {i} = 1 THEN\n  w := 0;\nENDIF",
    "split w, parts, count;",
    "split x + 1, parts, count;",
    "a := (a + count) MOD 3;",
    "b := parts{{1}} MOD 2;",
    "IF parts{{2}} = 1 b := 1;",
    "IF w = x a := 0;",
    "outer;",
    "risky;",
    "divisor := {i};",
    "x := 6 / divisor;",
    "reply := \"w\" + NumToStr(w, 0);",
    "IF reply = \"w1\" failed := TRUE;",
    "a := twice(x) MOD 3;",
    "WaitDI {i}, 1;",
    "ok := w > 0;",
    "IF ok b := 0;",
)

ROUTINES = """
  PROC split(num seed, VAR num out{{*}}, VAR num n)
    VAR num start := 1;
    VAR num next := 0;
    FOR i FROM 1 TO Dim(out, 1) DO
      out{{i}} := 0;
    ENDFOR
    n := 0;
    FOR i FROM 1 TO Dim(out, 1) DO
      next := (start + seed) MOD 3;
      out{{i}} := next;
      n := n + 1;
      IF next = 0 RETURN;
      start := next + 1;
    ENDFOR
  ENDPROC

  PROC look()
    IF w = 2 failed := TRUE;
  ENDPROC

  PROC outer()
    look;
  ENDPROC

  PROC risky()
    VAR num t := 0;
    t := w;
    x := 6 / divisor;
    t := 0;
{risky_handler}
  ENDPROC

  FUNC num twice(num v)
    RETURN v * 2;
  ENDFUNC
"""

HANDLERS = (
    "",
    "  ERROR\n    IF t = 2 b := 1;\n    divisor := 1;\n    RETRY;",
    "  ERROR\n    IF t = 1 failed := TRUE;\n    TRYNEXT;",
    "  ERROR\n    x := t;\n    RAISE;",
)

MAIN_HANDLERS = (
    "",
    "  ERROR\n    divisor := 1;\n    RETRY;",
    "  ERROR\n    IF x = 3 a := 1;\n    TRYNEXT;",
    "  ERROR\n    IF w = 1 failed := TRUE;\n    TRYNEXT;",
)


# main-loop statements of ``moves_and_trap`` programs: moves read their targets' data
MOVE_STATEMENTS = (
    "MoveL Offs(home, w, 0, 0), v100, fine, tool0;",
    "MoveJ spots{{x}}, v100, z10, tool0;",
    "MoveL spots{{w + 1}}, v100, fine, tool0;",
    "MoveAbsJ joints{{count + 1}}, v100, fine, tool0;",
    "WaitTime 0.1;",
)

TRAP = """
  TRAP on_input
    IF x = 2 b := 1;
    ok := FALSE;
  ENDTRAP
"""


def dead_data_program(seed: int, moves_and_trap: bool = False) -> str:
    rng = random.Random(seed)
    count = rng.randint(4, 8)
    body = []
    statements = MAIN_STATEMENTS + MOVE_STATEMENTS if moves_and_trap else MAIN_STATEMENTS
    for _ in range(count):
        template = rng.choice(statements)
        body.append(template.format(c=rng.randint(0, 2), i=rng.choice(INPUTS)))
    # every program splits at least once and calls the routine with a handler or the one
    # that reads a global through another, so calls stand between writes and reads
    body.insert(rng.randrange(len(body) + 1), "split w, parts, count;")
    body.insert(rng.randrange(len(body) + 1), rng.choice(("outer;", "risky;")))
    if moves_and_trap:
        body.insert(rng.randrange(len(body) + 1), rng.choice(MOVE_STATEMENTS[1:]).format())
    loop = "\n".join("      " + line for statement in body for line in statement.splitlines())
    aliases = "\n".join(f'    AliasIO "{name.upper()}", {name};' for name in INPUTS)
    if moves_and_trap:
        aliases += "\n    CONNECT irq WITH on_input;\n    ISignalDI in1, 1, irq;"
    declarations = "\n".join(
        [f"  VAR signaldi {name};" for name in INPUTS] +
        ["  VAR num a := 0;", "  VAR num b := 0;", "  VAR bool failed := FALSE;",
         "  VAR num w := 0;", "  VAR num x := 0;", "  VAR num parts{3};", "  VAR num count := 0;",
         "  VAR num divisor := 1;", '  VAR string reply := "";', "  VAR bool ok := FALSE;"] +
        (["  VAR intnum irq;", "  VAR robtarget spots{3};", "  VAR jointtarget joints{3};",
          "  CONST robtarget home := [[500,0,400],[1,0,0,0],[0,0,0,0],"
          "[9E9,9E9,9E9,9E9,9E9,9E9]];"] if moves_and_trap else []))
    routines = ROUTINES.format(risky_handler=rng.choice(HANDLERS)) + \
        (TRAP if moves_and_trap else "")
    return f"""MODULE Dead{seed}
{declarations}
{routines}
  PROC main()
{aliases}
    WHILE TRUE DO
{loop}
    ENDWHILE
{rng.choice(MAIN_HANDLERS)}
  ENDPROC
ENDMODULE
"""


def dead_data_properties(seed: int) -> list[str]:
    rng = random.Random(seed * 7 + 3)
    return [f'safe: G "a < {rng.randint(1, 2)}"',
            'never_failed: G !failed',
            'live: G F "b = 0"',
            f'response: G ("a = {rng.randint(0, 2)}" -> F "b = 1")']
