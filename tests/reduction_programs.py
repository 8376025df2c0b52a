"""Small random RAPID programs with finite state spaces, for differential tests of reductions.

``random_program(seed)`` writes a module: a few num counters kept small by
MOD, bools, free digital inputs, a cycle counter and a log string nothing
reads, a procedure with an IN and a VAR parameter, and a main loop of
IF / compact IF / TEST / FOR / WHILE statements, divisions that may fail,
and WaitDI that may block.  ``properties(seed)`` writes LTL properties over
its data.  The same seed always gives the same text.
``random_program(seed, numeric_updates=True)`` writes the same program with
its counter updates spelt as RAPID's numeric instructions (``Incr``,
``Decr``, ``Clear``, ``Add``) and a few more of them.
"""
from __future__ import annotations

import random
import re

COUNTERS = ("a", "b", "c")
FLAGS = ("f", "g")
INPUTS = ("in0", "in1")


def random_program(seed: int, numeric_updates: bool = False) -> str:
    text = _random_program(seed)
    return _numeric_updates(text, seed) if numeric_updates else text


# assignments and the numeric instruction each amounts to
SPELLINGS = (("nCycles := nCycles + 1;", "Incr nCycles;"), ("a := 0;", "Clear a;"),
             ("b := 0;", "Clear b;"), ("c := 0;", "Clear c;"))


def _numeric_updates(text: str, seed: int) -> str:
    """``text`` with the numeric instructions: the spellings above, plus bounded updates
    of a counter an atom may name and of data a condition reads (``Add`` of a sum the
    slicing cannot prove total, and of a literal)."""
    for assignment, instruction in SPELLINGS:        # statements, not declarations
        text = re.sub(r"(?<!num )\b" + re.escape(assignment), instruction, text)
    rng = random.Random(seed + 1000)
    counter = rng.choice(COUNTERS)
    extra = rng.sample([f"IF {counter} > 0 Decr {counter};", f"IF {counter} < 2 Incr {counter};",
                        f"IF scratch < 3 AND scratch > -3 Add scratch, {counter};",
                        "IF scratch > 0 Add scratch, -1;"], rng.randint(2, 3))
    loop_end = "    ENDWHILE\n"
    return text.replace(loop_end, "".join(f"      {line}\n" for line in extra) + loop_end, 1)


def _random_program(seed: int) -> str:
    rng = random.Random(seed)
    body = [_statement(rng, 2) for _ in range(rng.randint(2, 5))]
    declarations = "\n".join(
        [f"  VAR signaldi {name};" for name in INPUTS] +
        [f"  VAR num {name} := 0;" for name in COUNTERS] +
        [f"  VAR bool {name} := FALSE;" for name in FLAGS] +
        ["  VAR num nCycles := 0;", '  VAR string lastLog := "";', "  VAR num scratch := 0;",
         "  VAR bool toggle := FALSE;", "  VAR num shadow := 0;"])
    # data nothing reads, with finitely many values (an unbounded cycle counter every
    # fourth program: there only the reduced search can finish)
    unread = ["toggle := NOT toggle;", "shadow := " + rng.choice(COUNTERS) + " + 1;",
              'lastLog := "a=" + NumToStr(a, 0);']
    if seed % 4 == 0:
        unread += ["nCycles := nCycles + 1;", 'lastLog := "cycle " + NumToStr(nCycles, 0);']
    body += rng.sample(unread, rng.randint(1, len(unread)))
    aliases = "\n".join(f'    AliasIO "{name.upper()}", {name};' for name in INPUTS)
    loop = "\n".join("      " + line for statement in body for line in statement.splitlines())
    return f"""MODULE Random{seed}
{declarations}
  PROC bump(num amount, VAR num target)
    VAR num calls := 0;
    calls := calls + 1;
    target := (target + amount) MOD 3;
  ENDPROC
  PROC main()
    VAR num tmp := 0;
{aliases}
    WHILE TRUE DO
{loop}
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def properties(seed: int, with_next: bool = True) -> list[str]:
    """Properties over the program's data; ``with_next`` adds one with X (which turns
    merged steps off for the whole check)."""
    rng = random.Random(seed * 7 + 1)
    counter, other = rng.sample(COUNTERS, 2)
    flag = rng.choice(FLAGS)
    result = [f'safe: G "{counter} < {rng.randint(1, 3)}"',
              f'live: G F "{other} = 0"',
              f"flag: G ({flag} -> F !{flag})",
              f'until: G ("{other} = 1" -> ("{other} = 1" U ({flag} | "{counter} = 0")))']
    if with_next:
        result.append(f'next: G ("{counter} = 1" -> X "{counter} <> 0")')
    return result


def _condition(rng: random.Random) -> str:
    choice = rng.randrange(5)
    if choice == 0:
        return f"{rng.choice(INPUTS)} = 1"
    if choice == 1:
        return rng.choice(FLAGS)
    if choice == 2:
        return f"{rng.choice(COUNTERS)} {rng.choice(('<', '=', '>'))} {rng.randint(0, 2)}"
    if choice == 3:
        return f"NOT {rng.choice(FLAGS)} AND {rng.choice(INPUTS)} = 0"
    return f"{rng.choice(('scratch', 'tmp'))} > {rng.randint(0, 2)}"


def _simple(rng: random.Random) -> str:
    counter = rng.choice(COUNTERS)
    choice = rng.randrange(10)
    if choice == 0:
        return f"{counter} := ({counter} + 1) MOD {rng.randint(2, 3)};"
    if choice == 1:
        return f"{rng.choice(FLAGS)} := {_condition(rng)};"
    if choice == 2:
        return f"bump {rng.randint(1, 2)}, {counter};"
    if choice == 3:
        return f"scratch := {counter} * 2;"
    if choice == 4:
        return f"{counter} := 6 DIV ({counter} {rng.choice(('+', '-'))} 1);"
    if choice == 5:
        return f"WaitDI {rng.choice(INPUTS)}, 1;"
    if choice == 6:
        return f"{counter} := 0;"
    if choice == 7:
        return f'lastLog := lastLog + "x";'
    if choice == 8:
        return f"tmp := {counter} + 1;"
    return f"{rng.choice(FLAGS)} := NOT {rng.choice(FLAGS)};"


def _statement(rng: random.Random, depth: int) -> str:
    choice = rng.randrange(6) if depth > 0 else 0
    if choice <= 1:
        return _simple(rng)
    inner = "\n".join("  " + line for _ in range(rng.randint(1, 2))
                      for line in _statement(rng, depth - 1).splitlines())
    if choice == 2:
        return f"IF {_condition(rng)} THEN\n{inner}\nENDIF"
    if choice == 3:
        return f"IF {_condition(rng)} {_simple(rng)}"
    if choice == 4:
        return f"FOR i FROM 1 TO {rng.randint(1, 2)} DO\n{inner}\nENDFOR"
    counter = rng.choice(COUNTERS)
    return f"TEST {counter}\nCASE 0:\n{inner}\nDEFAULT:\n  {_simple(rng)}\nENDTEST"
