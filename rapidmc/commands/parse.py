"""``rapidmc parse FILE... [--json]``: syntax-check RAPID files.

Prints ``FILE: ok: N routines, M data`` for each file that parses, and the
diagnostics (on stderr) for each that does not; exit status 0 when every file
parsed, 2 otherwise.  ``--json`` writes the syntax trees to stdout instead:
``{"files": [{"file": ..., "ok": true, "modules": [...], "diagnostics": []}]}`` with every
node as an object ``{"node": "<class name>", <fields>..., "span": {...}}``.
"""
from __future__ import annotations

import argparse
import dataclasses
import json
import sys
from typing import Optional, Union

from .. import ast
from ..diagnostics import EXIT_INPUT_ERROR, EXIT_OK, Diagnostic, UserError, render_all
from ..load.source import program_paths
from ..syntax import parse_file


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="RAPID module files (.mod, .modx, .sys, .prg) or .pgf program files")
    parser.add_argument("--json", action="store_true",
                        help="write the syntax trees as JSON to stdout")


@dataclasses.dataclass(frozen=True)
class FileOutcome:
    """What parsing one file gave: its modules, or the diagnostics."""

    file: Optional[str]
    modules: tuple[ast.Module, ...] = ()
    diagnostics: tuple[Diagnostic, ...] = ()

    @property
    def ok(self) -> bool:
        return not self.diagnostics


def execute(args: argparse.Namespace) -> int:
    outcomes = [parse_outcome(path) for path in _module_paths(args.files)]
    for outcome in outcomes:
        if not outcome.ok:
            print(render_all(outcome.diagnostics), file=sys.stderr)
    if args.json:
        json.dump({"files": [outcome_json(o) for o in outcomes]}, sys.stdout, indent=1)
        sys.stdout.write("\n")
    else:
        for outcome in outcomes:
            if outcome.ok:
                print(f"{outcome.file}: ok: {summary(outcome.modules)}")
    return EXIT_OK if all(outcome.ok for outcome in outcomes) else EXIT_INPUT_ERROR


def _module_paths(paths: list[str]) -> list[Union[str, UserError]]:
    """Each argument's module files; a bad ``.pgf`` stands for its error."""
    result: list[Union[str, UserError]] = []
    for path in paths:
        try:
            result.extend(program_paths([path]))
        except UserError as failure:
            result.append(failure)
    return result


def parse_outcome(path: Union[str, UserError]) -> FileOutcome:
    if isinstance(path, UserError):
        return FileOutcome(None, diagnostics=tuple(path.diagnostics))
    try:
        return FileOutcome(path, modules=parse_file(path))
    except UserError as failure:
        return FileOutcome(path, diagnostics=tuple(failure.diagnostics))


def outcome_json(outcome: FileOutcome) -> dict:
    return {"file": outcome.file, "ok": outcome.ok,
            "modules": [to_json(module) for module in outcome.modules],
            "diagnostics": [diagnostic_json(d) for d in outcome.diagnostics]}


def summary(modules) -> str:
    routines = sum(len(m.routines) for m in modules)
    data = sum(len(m.data) for m in modules)
    return f"{routines} routines, {data} data"


def diagnostic_json(diagnostic) -> dict:
    return {"code": diagnostic.code.code, "severity": diagnostic.severity,
            "message": diagnostic.message,
            "span": to_json(diagnostic.span)}


def to_json(value):
    """An AST value as JSON-ready data: node type name, fields and span."""
    if isinstance(value, ast.Span):
        return {"file": value.file, "line": value.line, "column": value.column,
                "end_line": value.end_line, "end_column": value.end_column}
    if dataclasses.is_dataclass(value):
        result = {"node": type(value).__name__}
        for field in dataclasses.fields(value):
            result[field.name] = to_json(getattr(value, field.name))
        return result
    if isinstance(value, tuple):
        return [to_json(item) for item in value]
    return value
