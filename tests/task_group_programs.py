"""Random programs of four RAPID tasks in pairs, for the ample sets of task groups.

``group_tasks(seed)`` writes the task modules: tasks 1 and 2 share the PERS
``link12``/``ready12``, tasks 3 and 4 ``link34``/``ready34``, and with
``chain`` task 2 and task 3 also share ``link23``.  Each task loops over
statements on its own data, on a pair's data, waits for a pair's flag (which
may block forever), an ExitCycle, a division that may fail.  So at most states no task is
independent of all others, but the pairs are of each other: the reduction
keeps one pair's transitions (``reduction.task_groups``).
``group_properties(seed)`` writes LTL properties over the pairs' data and task
1's own.  The same seed always gives the same text; everything is kept small
by MOD, so the state spaces are finite.
"""
from __future__ import annotations

import random

PAIR_DATA = {1: "12", 2: "12", 3: "34", 4: "34"}


def group_tasks(seed: int, chain: bool = False, cell: bool = False) -> list[str]:
    """``cell``: the tasks also touch signals and robots (``_cell_statement``)."""
    rng = random.Random(seed)
    return [_task(rng, number, chain, cell) for number in range(1, 5)]


def _task(rng: random.Random, number: int, chain: bool, cell: bool = False) -> str:
    own, pair = f"own{number}", PAIR_DATA[number]
    links = [pair] + (["23"] if chain and number in (2, 3) else [])
    body = [_cell_statement(rng, number, own) if cell and rng.random() < 0.5
            else _statement(rng, own, links) for _ in range(rng.randint(2, 4 if cell else 3))]
    if cell and number % 2 == 1:
        # tasks 1 and 3 move a robot each (one robot per motion task) and set the pair's
        # output (an atom names do12)
        body[:0] = [f"      MoveJ Offs(pHome, {own} * 10, 0, 0), v100, fine, tool0;",
                    f"      SetDO do{pair}, {own} MOD 2;"]
    if rng.random() < 0.4:
        loop = ["    WHILE TRUE DO", *body, "    ENDWHILE"]
    else:
        loop = [f"    FOR i FROM 1 TO {rng.randint(1, 2)} DO", *body, "    ENDFOR"]
    declarations = [f"  PERS num link{link} := 0;\n  PERS bool ready{link} := FALSE;"
                    for link in links]
    handler = ["  ERROR", "    TRYNEXT;"] if rng.random() < 0.5 else []
    if cell:
        declarations.append("  CONST robtarget pHome := [[500,0,500],[1,0,0,0],[0,0,0,0],"
                            "[9E9,9E9,9E9,9E9,9E9,9E9]];")
    return "\n".join([f"MODULE Task{number}", *declarations,
                      f"  VAR num {own} := 0;", "  VAR num quotient := 0;",
                      "  PROC main()", *loop, *handler, "  ENDPROC", "ENDMODULE", ""])


def _statement(rng: random.Random, own: str, links: list) -> str:
    link = rng.choice(links)
    pad = "      "
    return rng.choice([
        f"{pad}{own} := ({own} + 1) MOD 3;",
        f"{pad}IF {own} = 2 {own} := 0;",
        f"{pad}link{link} := ({own} + 1) MOD 2;",
        f"{pad}link{link} := (link{link} + 1) MOD 3;",
        f"{pad}ready{link} := NOT ready{link};",
        f"{pad}ready{link} := TRUE;",
        f"{pad}IF ready{link} THEN\n{pad}  {own} := link{link};\n{pad}ENDIF",
        f"{pad}IF link{link} = 1 ready{link} := FALSE;",
        f"{pad}WaitUntil ready{link} = TRUE;",
        f"{pad}WaitUntil ready{link} = FALSE;",
        f"{pad}WaitUntil link{link} <> {own};",
        f"{pad}IF {own} = 1 AND ready{link} THEN\n{pad}  {own} := 2;\n{pad}  ExitCycle;\n"
        f"{pad}ENDIF",
        f"{pad}quotient := 6 DIV ({own} + link{link} - {rng.randint(0, 1)});",
    ])


def _cell_statement(rng: random.Random, number: int, own: str) -> str:
    """A statement on signals or robots: the odd task of a pair sets the pair's output
    ``do12``/``do34``, the even one reads it (and may wait for it forever); each task
    reads free inputs no task sets and sets an output only it names; the robots are read:
    the task's own, one named by a name no task has (the caller's), or task 1's (a
    reading of another task's robot)."""
    pad, pair = "      ", PAIR_DATA[number]
    shapes = [f"{pad}IF di{number} = 1 THEN\n{pad}  {own} := ({own} + 1) MOD 3;\n{pad}ENDIF",
              f"{pad}IF DInput(diAll) = 1 {own} := 0;",
              f"{pad}SetDO doMine{number}, {own} MOD 2;",
              f"{pad}IF doMine{number} = 1 {own} := 2;",
              f"{pad}IF CRobT().trans.x > 505 {own} := 1;",
              f"{pad}IF CJointT(\\TaskName:=\"T_GANTRY\").robax.rax_1 > 1 {own} := 0;"]
    if number % 2 == 1:
        shapes += [f"{pad}SetDO do{pair}, {own} MOD 2;", f"{pad}Set do{pair};",
                   f"{pad}Reset do{pair};", f"{pad}InvertDO do{pair};"]
    else:
        shapes += [f"{pad}IF do{pair} = 1 THEN\n{pad}  {own} := 1;\n{pad}ENDIF",
                   f"{pad}WaitUntil do{pair} = 1;", f"{pad}IF DOutput(do{pair}) = 0 {own} := 0;",
                   f"{pad}IF CRobT(\\TaskName:=\"task 3 (task3)\").trans.x > 505 {own} := 2;"]
    return rng.choice(shapes)


def group_properties(seed: int, cell: bool = False) -> list[str]:
    rng = random.Random(seed + 700)
    atoms = ['"link12 = 0"', "ready12", '"own1 = 0"', '"own1 < 2"', '"own1 = link12"'] + \
        (['"do12 = 1"', '"own4 = 1"'] if cell else [])
    shapes = ["G {a}", "F {a}", "G F {a}", "F G {a}", "G ({a} -> F {b})", "{a} U {b}"]
    lines = []
    for number in range(3):
        first, second = rng.sample(atoms, 2)
        lines.append(f"p{number}: " + rng.choice(shapes).format(a=first, b=second))
    return lines
