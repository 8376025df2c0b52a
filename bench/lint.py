"""Lint speed: lint a large generated RAPID module and report lines per second.

Usage: python bench/lint.py [LINES] [RUNS]   (default 100000 lines, 3 runs)

The module is bench/parse.py's generated robot code (declarations, moves with optional
arguments, IF/FOR/WHILE/TEST, assignments), once as it is and once with an input flow
in every routine (the taint analysis has work everywhere).  Figures, CPU time, best of
RUNS: ``lint`` is ``lint_program`` on the parsed program (every rule), the work
``rapidmc lint`` adds to parsing; ``parse alone`` the front end (bench/parse.py);
``parse + lint`` the whole command's work on the file (reading excepted).  The issue's
target is 50,000 lines/s.

Figures on the project machine (2 cores shared with other helpers' jobs), 100,000
lines, best of 3: lint 187,000 lines/s (with a flow in every routine 112,600); parse
alone 60,000 (54,300); parse + lint 42,800 (36,900).
Linting costs a quarter of what parsing costs; the whole command stays below 50,000
lines/s because parsing alone is barely above it on this machine.
"""
from __future__ import annotations

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))

from parse import cpu_seconds, generated_module  # noqa: E402

from rapidmc import ast  # noqa: E402
from rapidmc.findings.lint import lint_program  # noqa: E402
from rapidmc.syntax import parse_text  # noqa: E402


def with_flows(text: str) -> str:
    """The same code where every routine reads a number from a serial channel and moves
    by it unchecked: the taint analysis has work everywhere (a finding per routine)."""
    return (text.replace("    VAR bool done := FALSE;\n",
                         "    VAR bool done := FALSE;\n    VAR num height := 0;\n")
            .replace("    WaitTime 0.25;\n", "    height := ReadNum(channel \\Time:=1);\n")
            .replace("    MoveL pPick,", "    MoveL Offs(pPick, 0, 0, height),"))


def measure(label: str, text: str, runs: int) -> None:
    count = text.count("\n")
    program = ast.Program(parse_text(text, "bench.mod"))
    findings = lint_program(program)
    linting = min(cpu_seconds(lambda: lint_program(program)) for _ in range(runs))
    parsing = min(cpu_seconds(lambda: parse_text(text, "bench.mod")) for _ in range(runs))
    whole = min(cpu_seconds(lambda: lint_program(ast.Program(parse_text(text, "bench.mod"))))
                for _ in range(runs))
    print(f"{label}: {count} lines, {len(findings)} findings")
    print(f"  lint          {linting:6.2f} s CPU  {count / linting:12,.0f} lines/s")
    print(f"  parse alone   {parsing:6.2f} s CPU  {count / parsing:12,.0f} lines/s")
    print(f"  parse + lint  {whole:6.2f} s CPU  {count / whole:12,.0f} lines/s")


def main(argv: list[str]) -> int:
    lines = int(argv[1]) if len(argv) > 1 else 100_000
    runs = int(argv[2]) if len(argv) > 2 else 3
    text = generated_module(lines)
    measure("robot code", text, runs)
    measure("robot code, an input flow in every routine", with_flows(text), runs)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
