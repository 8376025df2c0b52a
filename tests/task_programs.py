"""Small random programs of several RAPID tasks, for differential tests of partial-order reduction.

``random_tasks(seed)`` writes 2 or 3 task modules.  Every task declares the
same shared PERS data (a counter, a flag, a lock) and its own VAR data, and
runs a loop (bounded or endless) of statements drawn from: updates of its own
data, updates of the shared data, conditions on either, waits for shared data
(which may block forever), a lock taken with WaitTestAndSet, a division that
may fail (caught by an ERROR handler in about half the tasks).  Everything is kept small by MOD, so the state spaces are finite.
``task_properties(seed)`` writes LTL properties over the shared data and the
main task's own data.  The same seed always gives the same text.
"""
from __future__ import annotations

import functools
import random

SHARED = ("PERS num shared := 0;", "PERS bool flag := FALSE;", "PERS bool lock := FALSE;",
          "PERS num inside := 0;")
SHARED_ARRAY = ("PERS bool slots{2} := [FALSE, FALSE];",)


def random_tasks(seed: int, procedures: bool = False, arrays: bool = False,
                 local: bool = False, calls: bool = False) -> list[str]:
    """``procedures``: each task also has a procedure of its own (statements as the loop's)
    that its loop may call, so steps enter and leave routines (two tasks then: the
    state spaces stay small enough for the search without reduction).  ``arrays``: the
    statements also index arrays by data (its own ``marks``, the shared ``slots``: 
    conditions the fused step does not take) and reach data by name (GetDataVal,
    SetDataVal); two tasks then, as with procedures.  ``local``: most statements touch
    only the task's own data, so a task may loop for ever on steps of its own (what the
    reduction's cycle proviso is for) and its steps run on through several of them.
    ``calls``: statements whose footprint is read from their syntax (``syntax_footprint``):
    element and component writes, Incr, calls of the task's procedures and functions
    with arguments (by value and by reference, of its own data and of shared data),
    predefined functions, TPWrite and WaitTime; two tasks."""
    rng = random.Random(seed)
    count = 2 if procedures or arrays or calls else rng.randint(2, 3)
    return [_task(rng, number, procedures, arrays, local, calls)
            for number in range(1, count + 1)]


def _task(rng: random.Random, number: int, procedures: bool = False,
          arrays: bool = False, local: bool = False, calls: bool = False) -> str:
    own, mine = f"own{number}", f"mine{number}"
    draw = _array_statement if arrays else _local_statement if local else _statement
    if calls:
        draw = functools.partial(_call_statement, number=number)
    body = [draw(rng, own, mine, 3) for _ in range(rng.randint(2, 4))]
    routines = _called_routines(number, own) if calls else []
    if procedures:
        call = f"    Step{number};"
        body.insert(rng.randint(0, len(body)), "  " + call)
        routines = [f"  PROC Step{number}()",
                    *(_statement(rng, own, mine, 2) for _ in range(rng.randint(1, 2))),
                    "  ENDPROC"]
    if rng.random() < 0.4:
        loop = ["    WHILE TRUE DO", *body, "    ENDWHILE"]
    else:
        loop = [f"    FOR i FROM 1 TO {rng.randint(1, 3)} DO", *body, "    ENDFOR"]
    declarations = [f"  {line}" for line in SHARED + (SHARED_ARRAY if arrays else ())] + \
        [f"  VAR num {own} := 0;", f"  VAR bool {mine} := FALSE;", "  VAR num quotient := 0;"]
    if arrays or calls:
        declarations.append("  VAR bool marks{3} := [FALSE, TRUE, FALSE];")
    if calls:
        declarations.append("  VAR pos spot := [0, 0, 0];")
    # a handler every other task: a failed division sets ERRNO (every task's) and goes on
    handler = ["  ERROR", f"    {own} := 1;", "    RETRY;"] if rng.random() < 0.5 else []
    return "\n".join([f"MODULE Task{number}", *declarations, "  PROC main()", *loop,
                      *handler, "  ENDPROC", *routines, "ENDMODULE", ""])


def _statement(rng: random.Random, own: str, mine: str, indent: int) -> str:
    pad = "  " * indent
    choices = [
        f"{pad}{own} := ({own} + {rng.randint(1, 2)}) MOD 3;",
        f"{pad}{mine} := NOT {mine};",
        f"{pad}{own} := {own} * 2 MOD 3;",
        f"{pad}shared := (shared + 1) MOD 3;",
        f"{pad}shared := {own};",
        f"{pad}flag := NOT flag;",
        f"{pad}flag := {mine};",
        f"{pad}IF {own} = {rng.randint(0, 2)} THEN\n{pad}  {mine} := TRUE;\n{pad}ENDIF",
        f"{pad}IF shared > {own} THEN\n{pad}  {own} := shared;\n{pad}ELSE\n{pad}  "
        f"{own} := ({own} + 1) MOD 3;\n{pad}ENDIF",
        f"{pad}IF {mine} {own} := 0;",
        f"{pad}WaitUntil shared <> {rng.randint(0, 2)} OR {mine};",
        f"{pad}WaitTestAndSet lock;\n{pad}inside := inside + 1;\n{pad}{own} := ({own} + 1) "
        f"MOD 3;\n{pad}inside := inside - 1;\n{pad}lock := FALSE;",
        f"{pad}quotient := 6 DIV ({own} + {rng.randint(0, 1)});",
    ]
    return rng.choice(choices)


def _local_statement(rng: random.Random, own: str, mine: str, indent: int) -> str:
    """A statement on the task's own data (three times in four), else one of
    ``_statement``."""
    return _mixed(rng, own, mine, indent, 0.25, lambda pad: [
        f"{pad}{own} := ({own} + {rng.randint(1, 2)}) MOD 3;",
        f"{pad}{mine} := NOT {mine};",
        f"{pad}IF {own} = {rng.randint(0, 2)} THEN\n{pad}  {mine} := NOT {mine};\n{pad}ENDIF",
        f"{pad}IF {mine} {own} := 0;",
        f"{pad}quotient := 6 DIV ({own} + {rng.randint(0, 1)});",
    ])


def _array_statement(rng: random.Random, own: str, mine: str, indent: int) -> str:
    """A statement of ``_statement`` or one on arrays indexed by data or on data reached
    by name."""
    return _mixed(rng, own, mine, indent, 0.5, lambda pad: [
        f"{pad}IF marks{{{own} + 1}} = TRUE THEN\n{pad}  {mine} := NOT {mine};\n{pad}ENDIF",
        f"{pad}marks{{{own} + 1}} := {mine};",
        f"{pad}IF slots{{{own} MOD 2 + 1}} {own} := ({own} + 1) MOD 3;",
        f"{pad}slots{{{own} MOD 2 + 1}} := NOT {mine};",
        f"{pad}IF marks{{{own} + 1}} AND slots{{1}} THEN\n{pad}  shared := {own};\n{pad}ENDIF",
        f'{pad}GetDataVal "{own}", quotient;',
        f'{pad}SetDataVal "{own}", ({own} + 1) MOD 3;',
        f'{pad}SetDataVal "shared", {own};',
    ])


def _call_statement(rng: random.Random, own: str, mine: str, indent: int,
                    number: int) -> str:
    """A statement of ``_statement`` (one time in three) or one whose footprint is read
    from its syntax, on the task's own data or on shared data."""
    return _mixed(rng, own, mine, indent, 0.35, lambda pad: [
        f"{pad}marks{{{own} + 1}} := NOT {mine};",
        f"{pad}spot.x := (spot.x + {own} + 1) MOD 3;",
        f"{pad}IF spot.x = {own} {mine} := NOT {mine};",
        f"{pad}Incr {own};\n{pad}{own} := {own} MOD 3;",
        f"{pad}Incr shared;\n{pad}shared := shared MOD 3;",
        f"{pad}Bump{number} {own};",
        f"{pad}Bump{number} shared;",
        f"{pad}Copy{number} shared;",
        f"{pad}Copy{number} {own};",
        f"{pad}Note{number} {own};",
        f"{pad}Note{number} shared;",
        f"{pad}{own} := Next{number}({own});",
        f"{pad}{own} := Next{number}(shared);",
        f"{pad}IF Next{number}({own}) = 0 {mine} := NOT {mine};",
        f"{pad}{own} := Abs({own} - 1);",
        f"{pad}{mine} := StrLen(NumToStr({own}, 0)) = 1;",
        f'{pad}TPWrite "own ", \\Num:={own};',
        f'{pad}TPWrite "shared ", \\Num:=shared;',
        f"{pad}WaitTime 0.1;",
        f"{pad}quotient := 6 DIV (spot.x + {rng.randint(0, 1)});",
    ])


def _called_routines(number: int, own: str) -> list[str]:
    """The routines ``_call_statement`` calls: a write and a read through a reference,
    a procedure and a function taking a value."""
    return [f"  PROC Bump{number}(INOUT num counter)",
            "    counter := (counter + 1) MOD 3;",
            "  ENDPROC",
            f"  PROC Copy{number}(INOUT num counter)",
            f"    IF counter > 0 {own} := counter;",
            "  ENDPROC",
            f"  PROC Note{number}(num value)",
            "    quotient := value;",
            "  ENDPROC",
            f"  FUNC num Next{number}(num value)",
            "    RETURN (value + 1) MOD 3;",
            "  ENDFUNC"]


def _mixed(rng: random.Random, own: str, mine: str, indent: int, plain: float,
           statements) -> str:
    """With probability ``plain`` a statement of ``_statement``, else one of
    ``statements(pad)`` (the same draws as before this helper: the seeds keep their
    programs)."""
    if rng.random() < plain:
        return _statement(rng, own, mine, indent)
    return rng.choice(statements("  " * indent))


def task_properties(seed: int) -> list[str]:
    """Properties over the shared data and the main task's own data (``own1``)."""
    rng = random.Random(seed + 500)
    atoms = ['"shared = 0"', '"shared < 2"', "flag", '"own1 = 0"', "mine1", '"inside <= 1"',
             '"own1 = shared"']
    shapes = ["G {a}", "F {a}", "G F {a}", "F G {a}", "G ({a} -> F {b})", "{a} U {b}",
              "G ({a} | {b})", "F ({a} & {b})"]
    lines = []
    for number in range(4):
        first, second = rng.sample(atoms, 2)
        lines.append(f"p{number}: " + rng.choice(shapes).format(a=first, b=second))
    return lines
