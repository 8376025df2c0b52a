"""``rapidmc lint FILE... | BACKUP``: static rules and unchecked input flows.

Loads the modules (a controller backup: each of its tasks, linted as a program of its
own), runs the rules of ``rapidmc.findings.lint`` with the configuration of
``[tool.rapidmc.lint]`` in the nearest pyproject.toml and the options, and prints the
findings: text (``file:line:col: warning: message [RMC8nn]``, source line, caret),
``--format json``, ``sarif`` or ``codeclimate``; ``--baseline`` leaves out the findings a
baseline records (docs/ci.md).  Exit 0 when no finding at or above ``--severity``
(default: warning) remains, 1 when one does, 2 for input errors (syntax, files,
configuration).  Rules are listed in docs/lint.md.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .. import ast
from ..diagnostics import EXIT_OK, EXIT_VIOLATED, UserError, render_all
from ..findings.lint import failing, lint_tasks
from ..findings.lint.config import make_config, read_pyproject
from ..findings.lint.registry import SEVERITIES
from ..load.backup import every_task, is_backup
from ..load.source import program_paths
from ..report.ci_findings import from_diagnostics
from ..report.codeclimate import format_codeclimate, format_codeclimate_errors
from ..report.lint import format_lint_json, format_lint_sarif, format_lint_text
from ..syntax import load_program
from . import baseline_options


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="RAPID module files (.mod, .sys, .pgf ...) linted as one program, "
                             "or a controller backup folder (each task is linted)")
    parser.add_argument("--format", choices=("text", "json", "sarif", "codeclimate"),
                        default="text",
                        help="output format (default: text); codeclimate: GitLab's Code Quality "
                             "report")
    parser.add_argument("--select", action="append", default=[], metavar="CODES",
                        help="only these rules: codes, code prefixes or names, comma-separated "
                             "(repeatable; default: every rule, or the configuration's)")
    parser.add_argument("--ignore", action="append", default=[], metavar="CODES",
                        help="leave these rules out (codes, prefixes or names, comma-separated)")
    parser.add_argument("--severity", choices=SEVERITIES, default=None,
                        help="the lowest severity of a finding that makes the exit code 1 "
                             "(default: warning, or the configuration's)")
    parser.add_argument("--task", metavar="NAME",
                        help="with a backup: lint only this task")
    baseline_options.add_arguments(parser)


def execute(args: argparse.Namespace) -> int:
    try:
        return _lint(args)
    except UserError as exc:
        if args.format == "text":
            raise
        # a machine-readable report is always written, so that a CI step that uploads it
        # finds a valid file: input errors are findings in it (blocker issues in Code Quality)
        print(render_all(exc.diagnostics), file=sys.stderr)
        if args.format == "codeclimate":
            sys.stdout.write(format_codeclimate_errors(exc.diagnostics, args.files[0]))
        elif args.format == "sarif":
            sys.stdout.write(format_lint_sarif(exc.diagnostics, exc.exit_code))
        else:
            sys.stdout.write(format_lint_json(exc.diagnostics, exc.exit_code, 0))
        return exc.exit_code


def _lint(args: argparse.Namespace) -> int:
    table, origin = read_pyproject(Path.cwd())
    config = make_config(table, str(origin or "pyproject.toml"), _split(args.select),
                         _split(args.ignore), args.severity)
    baseline_options.refuse_unwritable_target(args)
    known = baseline_options.read_known(args, "lint")
    findings, lines, files = [], 0, 0
    for controller in _programs(args):
        programs = [load_program(paths) for _, paths in controller]
        for (task, _), program, found in zip(controller, programs, lint_tasks(programs, config)):
            if args.task is not None and task is not None and task.upper() != args.task.upper():
                continue
            findings.extend(found)
            lines += _line_count(program)
            files += len({module.span.file for module in program.modules})
    gated = from_diagnostics(findings, args.files[0])
    new, _ = baseline_options.new_findings(args, "lint", gated, list(zip(gated, findings)),
                                           known)
    findings = [finding for _, finding in new]
    exit_code = EXIT_VIOLATED if failing(findings, config.severity) else EXIT_OK
    if args.format == "json":
        sys.stdout.write(format_lint_json(findings, exit_code, lines))
    elif args.format == "sarif":
        sys.stdout.write(format_lint_sarif(findings, exit_code))
    elif args.format == "codeclimate":
        sys.stdout.write(format_codeclimate([gate for gate, _ in new]))
    else:
        sys.stdout.write(format_lint_text(findings, lines, files))
    return exit_code


def _split(values: list[str]) -> tuple[str, ...]:
    return tuple(part.strip() for value in values for part in value.split(",") if part.strip())


def _programs(args) -> list[list[tuple]]:
    """The controllers to lint, each a list of (task name or None, the program's files): the
    loose files as one program, each backup's tasks (all of them are read, for the PERS
    data they change; ``--task`` keeps the findings of one)."""
    loose, controllers = [], []
    for name in args.files:
        if is_backup(Path(name)):
            controllers.append(list(every_task(Path(name))))
        else:
            loose.append(name)
    if loose:
        controllers.insert(0, [(None, program_paths(loose))])
    return controllers


def _line_count(program: ast.Program) -> int:
    from ..diagnostics import SourceCache
    files = {module.span.file for module in program.modules}
    return sum(len(SourceCache.lines(file) or ()) for file in files)
