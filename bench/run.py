"""Interpreter speed: simple statements per second of ``rapidmc run`` on a loop-heavy program.

Usage: python bench/run.py [ITERATIONS]

The program runs nested FOR/WHILE loops with assignments, arithmetic,
array access, a function call and IF conditions; every step of the
small-step semantics (one simple statement, condition or routine
entry/exit) is counted.  The step function measured here is the one the
model checker uses.
"""
from __future__ import annotations

import io
import sys
import time

from rapidmc.commands.console import run_program
from rapidmc.semantics.link import build
from rapidmc.syntax import parse_text

PROGRAM = """
MODULE Bench
  VAR num total := 0;
  VAR num data{{100}};
  PROC main()
    VAR num i := 0;
    VAR num x := 1;
    WHILE i < {iterations} DO
      FOR k FROM 1 TO 100 DO
        data{{k}} := k * 2 + x;
        total := total + data{{k}} MOD 7;
        IF total > 1000000 total := 0;
      ENDFOR
      x := Twice(x) MOD 13;
      Incr i;
    ENDWHILE
    TPWrite "total=" \\Num:=total;
  ENDPROC
  FUNC num Twice(num v)
    RETURN v * 2;
  ENDFUNC
ENDMODULE
"""


def main() -> None:
    iterations = int(sys.argv[1]) if len(sys.argv) > 1 else 200
    modules = parse_text(PROGRAM.format(iterations=iterations), "bench.mod")
    from rapidmc import ast
    program = build(ast.Program(modules))
    out = io.StringIO()
    start = time.perf_counter()
    result = run_program(program, {}, io.StringIO(), out)
    seconds = time.perf_counter() - start
    print(f"program output: {out.getvalue().strip()}")
    print(f"steps: {result.steps:,}  time: {seconds:.2f} s  "
          f"speed: {result.steps / seconds:,.0f} steps/s")


if __name__ == "__main__":
    main()
