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
  configuration: RMC840). With `--format json`, `sarif` or `codeclimate` an input error is
  still a report on standard output, with the error as its finding (and the usual text on
  standard error), so a CI step that uploads the report always finds a valid file.
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

# The survey behind the defaults (docs/realworld-survey.md, "Lint defaults judged on real
# code"): 771 files of 44 public repositories, backups linted task by task as `rapidmc lint
# BACKUP` does.  code -> (findings, sample size, judged true, what the sample showed).
JUDGED = {
    "RMC801": (2, 2, 2, "both read differently from what their layout suggests"),
    "RMC803": (651, 10, 0, "`\\Wobj` for `\\WObj`: RAPID names are not case-sensitive, so the "
               "program is right as written: opt-in"),
    "RMC804": (130, 8, 7, "an `Open`, `SocketBind` or `SocketSend` whose failure stops "
               "production for want of a handler; one `ReadStr` of a file already guarded by "
               "EOF tests"),
    "RMC805": (5, 5, 5, "a background task's `WHILE TRUE` polling with no wait (five copies "
               "of one cell)"),
    "RMC806": (2207, 10, 3, "teach points, CONST targets and track data a backup keeps "
               "unused; three leftover routine variables: opt-in"),
    "RMC807": (87, 10, 10, "functions and procedures with parameters nothing calls; a trap "
               "never connected (service routines without parameters are no longer reported)"),
    "RMC808": (58, 8, 8, "moves after a debugging `RETURN`, statements after `ExitCycle`"),
    "RMC809": (44, 10, 9, "step counters and ring-buffer pointers other tasks advance; one "
               "counter wrapped just after its use"),
    "RMC810": (25, 6, 5, "menu keys with empty labels whose answers are tested"),
    "RMC820": (68, 10, 9, "socket, FlexPendant, file and group-input values reaching moves "
               "unchecked; one encoder count echoed to a group output"),
}


def document() -> str:
    parts = [INTRODUCTION,
             "\n| code | name | severity | by default | what |\n|---|---|---|---|---|\n"]
    for code, rule in sorted(RULES.items()):
        parts.append(f"| [{code}](#{code.lower()}-{rule.code.name}) | {rule.code.name} | "
                     f"{rule.severity} | {'on' if rule.default else 'opt-in'} | "
                     f"{rule.summary} |\n")
    parts.append(_judged())
    for code, rule in sorted(RULES.items()):
        parts.append(f"\n## {code} {rule.code.name}\n\n{rule.summary[0].upper()}"
                     f"{rule.summary[1:]} (default severity: {rule.severity}).")
        if rule.why:
            parts.append(f" {rule.why}")
        parts.append(f"\n\nBad:\n\n```rapid\n{rule.bad}```\n\nGood:\n\n```rapid\n{rule.good}```\n")
    return "".join(parts)


def _judged() -> str:
    """The table of the rules' judged samples: a rule is on by default only when at least
    80 % of its sample was a real problem a cell engineer would look at."""
    rows = ["\n## Defaults judged on real code\n\n"
            "Each rule was run on public RAPID code (771 files of 44 repositories, backups "
            "task by task), a sample of its findings read and each judged: a real problem a "
            "cell engineer would look at, or noise. A rule is on by default only when at "
            "least 80 % of its sample was judged true; the others are opt-in (`--select "
            "unused-data`, or `select` in the configuration). Figures: "
            "docs/realworld-survey.md.\n\n"
            "| rule | findings | sample | judged true | by default | the sample |\n"
            "|---|---:|---:|---:|---|---|\n"]
    for code, (found, sample, true, what) in sorted(JUDGED.items()):
        rule = RULES[code]
        rows.append(f"| {code} {rule.code.name} | {found} | {sample} | {true} "
                    f"({round(100 * true / sample)} %) | {'on' if rule.default else 'opt-in'} "
                    f"| {what} |\n")
    return "".join(rows)


def main(argv: list[str]) -> int:
    return write_or_check(DOC, document(), "rapidmc.findings.lint.documentation", argv)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
