"""docs/lint.md, generated from the lint rules' registry.

``python -m rapidmc.findings.lint.documentation`` rewrites the page; with ``--check`` it
exits 1 when the committed page differs from what the registry gives
(tests/test_lint.py does the same).  The page opens with the hand-written text of
``INTRODUCTION`` and lists every rule: code, name, severity, summary, why it matters,
a bad and a good example.
"""
from __future__ import annotations

import sys
from pathlib import Path

from ...semantics.library.documentation import write_or_check
from . import RULES

DOC = Path(__file__).resolve().parents[3] / "docs" / "lint.md"

INTRODUCTION = """\
# `rapidmc lint`: rules

`rapidmc lint FILE... | BACKUP` reports mistakes visible without a search, and input that
reaches a move, a file path, a late-bound call or an output with no check on the way. It
reads the syntax tree only (a program that does not link is still linted), and runs at some
hundreds of thousands of lines a second (`bench/lint.py`).

```
$ rapidmc lint case_studies/sorter/sorter_a.mod
case_studies/sorter/sorter_a.mod:73:34: warning: NOT negates the whole 'AND' chain to its right; write the parentheses: NOT (...) if that is meant, (NOT ...) otherwise [RMC801]
                flag_2 := c_in=0 AND NOT s1=1 AND s2=1;
                                     ^~~~~~~~~~~~~~~~~
1 file, 97 lines: 1 finding (1 warning)
```

* **Output**: text (as above; a flow's steps follow as `flow:` lines), `--format json`
  (`findings`: code, rule, severity, message, location, notes, flow, places; `summary`; `lines`;
  `exit_code`) or `--format sarif` (SARIF 2.1.0; a flow is the result's code flow).
* **One finding per cause**: a rule that finds the same thing at several places (one PERS
  used unchecked as an index in every line of a routine, one socket read reaching many move
  targets) gives one finding at the first place, with every other place: a note in text
  (`3 more places: m.mod lines 14, 22, 30`), `places` in JSON, related
  locations in SARIF and in the editor. A flow (RMC820) is one finding per source and kind of
  use (target, tool, speed ...), with the path to its first use as its flow.
* **Exit code**: 1 when a finding at or above `--severity` remains (default `warning`:
  notes alone give 0), 0 otherwise, 2 for input errors (syntax, missing files, a bad
  configuration: RMC840).
* **Choosing rules**: `--select` and `--ignore` take codes, code prefixes (`RMC80`) or rule
  names (`not-chain`), comma-separated.
* **Suppressing one finding**: a comment on its line or on a comment line right above it,
  `! rapidmc: ignore[RMC801]` (several: `ignore[RMC801, unused-data]`; every rule:
  `! rapidmc: ignore`).
* **Configuration**: the nearest `pyproject.toml` from the current folder upward:

  ```toml
  [tool.rapidmc.lint]
  select = ["RMC8"]                    # default: every rule
  ignore = ["unused-data"]
  severity = "warning"                 # the exit code's threshold
  severities = { RMC807 = "warning" }  # a rule's severity
  ```

  The command line's `--select` replaces the file's `select`; `--ignore` adds to its
  `ignore`; `--severity` replaces its `severity`.
* **Backups**: a controller backup folder is linted task by task (`--task NAME`: one task).
* **Codes**: RMC801-RMC840, registered with every other diagnostic code
  (docs/diagnostics.md). From Python: `rapidmc.findings.lint.lint_program(program, config)`
  returns the findings as `Diagnostic` values (the language server uses it).

Unchecked input flows (RMC820) are found by a taint analysis of the syntax tree; `rapidmc
check --flows` verifies the same flows on the state graph, where a check that really guards
the use clears the mark (docs/checking.md, "Unchecked input flows").

This page is generated from the rules' registry: `python -m rapidmc.findings.lint.documentation`.
"""


def document() -> str:
    parts = [INTRODUCTION, "\n| code | name | severity | what |\n|---|---|---|---|\n"]
    for code, rule in sorted(RULES.items()):
        parts.append(f"| [{code}](#{code.lower()}-{rule.code.name}) | {rule.code.name} | "
                     f"{rule.severity} | {rule.summary} |\n")
    for code, rule in sorted(RULES.items()):
        parts.append(f"\n## {code} {rule.code.name}\n\n{rule.summary[0].upper()}"
                     f"{rule.summary[1:]} (default severity: {rule.severity}).")
        if rule.why:
            parts.append(f" {rule.why}")
        parts.append(f"\n\nBad:\n\n```rapid\n{rule.bad}```\n\nGood:\n\n```rapid\n{rule.good}```\n")
    return "".join(parts)


def main(argv: list[str]) -> int:
    return write_or_check(DOC, document(), "rapidmc.findings.lint.documentation", argv)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
