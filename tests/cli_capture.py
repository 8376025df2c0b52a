"""``rapidmc ARGV`` run in this process, its output captured: the tests' one way to do it.

A test that asks for what a user sees (exit code, report, diagnostics) calls ``rapidmc.cli.main``
in the test's own process, which is much cheaper than starting a fresh interpreter, with
standard output and standard error read into strings.  Optionally it gives the command a
standard input (``rapidmc run`` reads socket messages and file lines from it) or a working
folder (a case's ``args`` name files relative to its folder); both are restored afterwards,
also when the command raises.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import sys
from pathlib import Path
from typing import NamedTuple

from rapidmc.cli import main


class Captured(NamedTuple):
    code: int
    out: str
    err: str


def run_cli(argv, *, stdin: str | None = None, cwd: Path | str | None = None) -> Captured:
    """Exit code, standard output and standard error of ``rapidmc ARGV`` (each argument made a
    string), run with ``stdin`` as standard input and from inside ``cwd`` when given."""
    out, err = io.StringIO(), io.StringIO()
    saved_stdin, saved_cwd = sys.stdin, os.getcwd()
    if stdin is not None:
        sys.stdin = io.StringIO(stdin)
    if cwd is not None:
        os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main([str(argument) for argument in argv])
    finally:
        sys.stdin = saved_stdin
        if cwd is not None:
            os.chdir(saved_cwd)
    return Captured(code, out.getvalue(), err.getvalue())


def verdicts_and_states(argv, *, cwd: Path | str | None = None) -> dict:
    """Property -> (verdict, model states) of ``rapidmc check ARGV --format json --quiet``."""
    document = json.loads(run_cli(["check", *argv, "--format", "json", "--quiet"], cwd=cwd).out)
    return {p["name"]: (p["verdict"], p["stats"]["model_states"])
            for p in document["properties"]}


def other_task_module(lines: list) -> str:
    """A second task for generated two-task programs: PERS ``flag`` and ``n`` shared with
    the first task, its own ``m``, and ``lines`` run in an endless loop."""
    return ("MODULE Other\n  PERS bool flag := FALSE;\n  PERS num n := 0;\n"
            "  VAR num m := 0;\n  PROC main()\n    WHILE TRUE DO\n" +
            "".join(f"      {line}\n" for line in lines) +
            "    ENDWHILE\n  ENDPROC\nENDMODULE\n")


def two_task_verdicts(tmp_path: Path, program: tuple, formulas: list, *flags: str,
                      bound: int | None = None) -> dict:
    """``verdicts_and_states`` of a two-task ``program`` (the texts of ``prog.mod`` and of
    the task ``--add-task other.mod``) against ``formulas``, at ``--max-states bound`` when
    given."""
    (tmp_path / "prog.mod").write_text(program[0])
    (tmp_path / "other.mod").write_text(program[1])
    options = [word for formula in formulas for word in ("--formula", formula)]
    if bound is not None:
        options += ["--max-states", str(bound)]
    return verdicts_and_states(["prog.mod", "--add-task", "other.mod", *options, *flags],
                               cwd=tmp_path)


def differing_verdicts(found: dict, exact: dict) -> list:
    """The properties (of two ``verdicts_and_states`` results) whose verdicts differ where
    the ``exact`` search ended: a reduction's differential test expects none."""
    assert found.keys() == exact.keys(), (found.keys(), exact.keys())
    return [name for name, (verdict, _) in exact.items()
            if verdict != "UNKNOWN" and found[name][0] != verdict]


def assert_reduction_keeps_verdicts(reduced: dict, exact: dict, names: set, text: str) -> None:
    """The differential of a reduction: both searches report the properties ``names``, and
    every verdict the exact search reaches (not UNKNOWN) is the reduced search's too."""
    assert exact.keys() == names
    assert not differing_verdicts(reduced, exact), text
