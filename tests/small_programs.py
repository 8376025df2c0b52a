"""Seeded random RAPID programs with small state spaces, and atoms over them (no tests here).

``small_program(rng)`` writes a module over two bool and two num data
objects (nums kept in 0..2 by ``MOD 3``), two free digital inputs read
when the program decides to (``DInput``, ``WaitDI``, ``WaitUntil``) and
one digital output: assignments, IF, WHILE, TEST, calls of up to two
procedures (each calls only procedures defined after it, so there is no
recursion), waits, now and then an integer division that fails when its
divisor is 0, or an EXIT.  ``main`` is either a sequence (the program
ends) or a ``WHILE TRUE`` loop around one.  Some programs come with an
environment module that drives di2 (set in ``init``, possibly to either
value, and after every step from a counter, a random choice or the
program's output).  The state spaces stay in the tens to hundreds of
states, so a test can explore them whole.

``SmallProgram.atoms`` are the atoms (as ``ltl.Atom`` names) a property
may use: bool data, num comparisons, the signals the program uses, and
location atoms (``Ended()``, ``Failed()``, ``InRoutine``, ``AtLine`` of a
line of the program).

Example::

    >>> import random
    >>> program = small_program(random.Random(1))
    >>> program.text.startswith("MODULE Small")
    True
"""
from __future__ import annotations

import random
from dataclasses import dataclass
from typing import Optional

BOOLS = ("b", "c")
NUMS = ("x", "y")
INPUTS = ("di1", "di2")
DRIVEN = INPUTS[1]          # the input an environment module may drive
OUTPUT = "do1"


@dataclass(frozen=True)
class SmallProgram:
    text: str
    atoms: tuple[str, ...]
    environment: Optional[str] = None      # an environment module driving di2, if any


def small_program(rng: random.Random) -> SmallProgram:
    procedures = [f"p{i}" for i in range(1, rng.randint(0, 2) + 1)]
    bodies = [_block(rng, procedures[i + 1:], depth=1) for i in range(len(procedures))]
    main = _block(rng, procedures, depth=2, least=3)
    if rng.random() < 0.6:
        main = ["WHILE TRUE DO", *_indented(main), "ENDWHILE"]
    lines = ["MODULE Small",
             *(f"  VAR bool {name} := {rng.choice(('TRUE', 'FALSE'))};" for name in BOOLS),
             *(f"  VAR num {name} := {rng.randint(0, 2)};" for name in NUMS),
             "  PROC main()", *_indented(main, "    "), "  ENDPROC"]
    for name, body in zip(procedures, bodies):
        lines += [f"  PROC {name}()", *_indented(body, "    "), "  ENDPROC"]
    lines.append("ENDMODULE")
    text = "\n".join(lines) + "\n"
    environment = None
    if DRIVEN in text and rng.random() < 0.4:
        environment = _environment(rng, reads_output=OUTPUT in text)
    return SmallProgram(text, _atoms(rng, lines, procedures), environment)


def _environment(rng: random.Random, reads_output: bool) -> str:
    """A module that sets di2 in ``init`` (one or several initial states) and after every
    step: from a counter of its own, a random choice, or the program's output."""
    reaction = rng.choice([[f"SetDI {DRIVEN}, AnyNum(0, 1);"],
                           ["count := (count + 1) MOD 3;", f"SetDI {DRIVEN}, Trunc(count / 2);"]])
    if reads_output:
        reaction = [f"IF DOutput({OUTPUT}) = 1 THEN",
                    f"  SetDI {DRIVEN}, {rng.choice(('0', '1'))};",
                    "ELSE", *_indented(reaction), "ENDIF"]
    start = rng.choice(("0", "1", "AnyNum(0, 1)"))
    lines = ["MODULE SmallEnv", f"  VAR signaldi {DRIVEN};", "  VAR num count := 0;",
             *([f"  VAR signaldo {OUTPUT};"] if reads_output else []),
             "  PROC init()", f"    SetDI {DRIVEN}, {start};", "  ENDPROC",
             "  PROC react()", *_indented(reaction, "    "), "  ENDPROC", "ENDMODULE"]
    return "\n".join(lines) + "\n"


def _atoms(rng: random.Random, lines: list[str], procedures: list[str]) -> tuple[str, ...]:
    statement_lines = [number for number, line in enumerate(lines, start=1)
                       if line.endswith(";") and not line.lstrip().startswith("VAR")]
    used_signals = [name.upper() for name in (*INPUTS, OUTPUT)
                    if any(name in line for line in lines)]
    atoms = [*BOOLS, "x = 0", "x > 1", "y = 1", *used_signals, "Ended()", "Failed()",
             *(f"InRoutine({name})" for name in procedures)]
    if statement_lines:
        atoms.append(f"AtLine({rng.choice(statement_lines)})")
    return tuple(atoms)


def _indented(lines: list[str], margin: str = "  ") -> list[str]:
    return [margin + line for line in lines]


def _block(rng: random.Random, procedures: list[str], depth: int, least: int = 1) -> list[str]:
    lines: list[str] = []
    for _ in range(rng.randint(least, 4)):
        lines += _statement(rng, procedures, depth)
    return lines


def _statement(rng: random.Random, procedures: list[str], depth: int) -> list[str]:
    kinds = ["assign", "assign", "assign", "assign", "output", "output", "wait"]
    if procedures:
        kinds += ["call", "call"]
    if depth > 0:
        kinds += ["if", "if", "while", "test"]
    kinds += ["divide"] if rng.random() < 0.1 else []
    kinds += ["exit"] if rng.random() < 0.05 else []
    kind = rng.choice(kinds)
    if kind == "assign":
        return [_assignment(rng)]
    if kind == "output":
        return [f"SetDO {OUTPUT}, {rng.randint(0, 1)};"]
    if kind == "wait":
        if rng.random() < 0.5:
            return [f"WaitDI {rng.choice(INPUTS)}, 1;"]
        return [f"WaitUntil {_condition(rng)} OR DInput({rng.choice(INPUTS)}) = 1;"]
    if kind == "call":
        return [f"{rng.choice(procedures)};"]
    if kind == "divide":
        return [f"{rng.choice(NUMS)} := 2 DIV {rng.choice(NUMS)};"]
    if kind == "exit":
        return ["EXIT;"]
    inner = lambda: _indented(_block(rng, procedures, depth - 1))  # noqa: E731
    if kind == "if":
        lines = [f"IF {_condition(rng)} THEN", *inner()]
        if rng.random() < 0.5:
            lines += ["ELSE", *inner()]
        return lines + ["ENDIF"]
    if kind == "while":
        counter = rng.choice(NUMS)
        return [f"WHILE {counter} < 2 AND {_condition(rng)} DO", *inner(),
                f"  {counter} := {counter} + 1;", "ENDWHILE"]
    subject = rng.choice(NUMS)
    return [f"TEST {subject}", "CASE 0:", *inner(), "CASE 1, 2:", *inner(), "DEFAULT:",
            *inner(), "ENDTEST"]


def _assignment(rng: random.Random) -> str:
    if rng.random() < 0.5:
        name = rng.choice(BOOLS)
        value = rng.choice(("TRUE", "FALSE", f"NOT {name}", _condition(rng)))
        return f"{name} := {value};"
    name = rng.choice(NUMS)
    value = rng.choice((str(rng.randint(0, 2)), f"({name} + 1) MOD 3",
                        f"({rng.choice(NUMS)} + {rng.randint(1, 2)}) MOD 3"))
    return f"{name} := {value};"


def _condition(rng: random.Random) -> str:
    return rng.choice((f"DInput({rng.choice(INPUTS)}) = 1", rng.choice(BOOLS),
                       f"NOT {rng.choice(BOOLS)}", f"{rng.choice(NUMS)} = {rng.randint(0, 2)}",
                       f"{rng.choice(NUMS)} < {rng.randint(1, 2)}", f"DOutput({OUTPUT}) = 1",
                       f"{rng.choice(BOOLS)} AND DInput({rng.choice(INPUTS)}) = 1"))
