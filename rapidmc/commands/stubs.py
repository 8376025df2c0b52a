"""``rapidmc stubs FILE... [-o Missing.mod]``: declare the names nobody declares.

Writes a RAPID module (to ``-o`` or stdout) declaring every name the
program uses and no given module declares, typed from the uses
(``rapidmc.load.stubs``).  Then loads the program with that module, as ``check``
and ``run`` would: exit 0 when it loads (or nothing was missing), 2 with
the remaining static errors when it does not (for instance a name whose
type the uses do not tell, or a mistake that is not a missing name).
"""
from __future__ import annotations

import argparse
import re
from dataclasses import replace
import sys
from collections import Counter
from pathlib import Path

from .. import ast
from ..diagnostics import (EXIT_INPUT_ERROR, EXIT_OK, NO_ENTRY, USAGE, UserError, error,
                           render_all)
from ..load.backup import resolve_program_files
from ..semantics.link import build
from ..load.source import program_paths
from ..load.stubs import Stubs, stub_module
from ..syntax import load_program, parse_text

DEFAULT_MODULE = "Missing"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="the program's RAPID module files (.mod, .sys, .pgf ...) or a "
                             "controller backup folder")
    parser.add_argument("--task", metavar="NAME",
                        help="the task to take from a controller backup")
    parser.add_argument("--eio", metavar="EIO.cfg",
                        help="I/O configuration: its signals are declared there, not missing")
    parser.add_argument("-o", "--output", metavar="FILE",
                        help="write the module here (default: stdout); its name is the file's "
                             "stem")


def module_name(output, modules) -> str:
    stem = Path(output).stem if output else DEFAULT_MODULE
    name = stem if re.fullmatch(r"[A-Za-z][A-Za-z0-9_]{0,31}", stem) else DEFAULT_MODULE
    taken = {module.name.key for module in modules}
    while name.upper() in taken:
        name = (name + "_stubs")[:32]
    return name


def execute(args: argparse.Namespace) -> int:
    files = resolve_program_files(args)
    paths = program_paths(list(files.modules))
    if args.output and any(Path(p).resolve() == Path(args.output).resolve() for p in paths):
        raise error(USAGE, f"the output file '{args.output}' is one of the program's files: "
                    "choose another name (it would be overwritten)")
    program = load_program(paths)
    signals = tuple(files.signals)
    stubs = stub_module(program.modules, module_name(args.output, program.modules),
                        {signal.name.upper() for signal in signals})
    if not stubs.declared and not stubs.undeclared:
        print("nothing to declare: every name the program uses is declared")
        return _verify(program, None, "", signals)
    target = args.output or "<stdout>"
    if args.output:
        Path(args.output).write_text(stubs.text, encoding="latin-1")
    else:
        sys.stdout.write(stubs.text)
    print(summary(target, stubs), file=sys.stderr if not args.output else sys.stdout)
    return _verify(program, stubs, args.output or "<stubs>", signals)


def summary(target: str, stubs: Stubs) -> str:
    kinds = Counter(item.kind for item in stubs.declared)
    parts = ", ".join(f"{count} {kind}" for kind, count in sorted(kinds.items()))
    text = f"{target}: {len(stubs.declared)} declarations ({parts or 'none'})"
    if stubs.undeclared:
        names = ", ".join(item.name.text for item in stubs.undeclared)
        text += f"; left to you (type not inferred, or an array too large to write): {names}"
    return text


def _in_written_module(diagnostic, filename: str):
    """An error inside the module stubs wrote says it is rapidmc's fault: the module is
    meant to load whatever the program (tests/test_stubs_always_load.py)."""
    if diagnostic.span is None or diagnostic.span.file != filename:
        return diagnostic
    return replace(diagnostic, notes=diagnostic.notes + (
        "this error lies in the module 'rapidmc stubs' wrote, which should always load: a "
        "fault of rapidmc; please report it with the program",))


def _verify(program: ast.Program, stubs, filename: str, signals: tuple) -> int:
    """Load the program with the stubs as check and run do; report what still fails."""
    modules = program.modules
    if stubs is not None:
        modules = modules + parse_text(stubs.text, filename)
    try:
        build(ast.Program(modules), options={"configured_signals": signals})
    except UserError as failure:
        remaining = [_in_written_module(d, filename) for d in failure.diagnostics
                     if d.code is not NO_ENTRY]
        if remaining:
            print(render_all(remaining), file=sys.stderr)
            return EXIT_INPUT_ERROR
    return EXIT_OK
