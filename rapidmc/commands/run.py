"""``rapidmc run FILE... [--entry main] [--io NAME=VALUE]``: execute a RAPID program.

FlexPendant text goes to stdout, diagnostics to stderr.  Exit codes: 0 the
program ended (end of main, EXIT) or stays stopped (Stop, Break: the
operator's restart is a line of stdin, see ``--no-restart``), 1 uncaught RAPID run-time error
or deadlock, 2 static error (nothing ran).
"""
from __future__ import annotations

import argparse
import math
import sys

from ..diagnostics import (BAD_INPUT_VALUE, EXIT_OK, EXIT_RUNTIME_ERROR, USAGE, UserError, error, render)
from .console import fault_diagnostic, run_program
from ..load.backup import (add_program_arguments, link_options, resolve_program_files,
                           with_interfaces)
from ..semantics.link import build
from ..semantics.state import FAILED
from ..syntax import load_program
from ..diagnostics.quoting import quoted, routine_name


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="RAPID module files (.mod, .modx, .sys, .prg), .pgf program files, "
                             "or a controller backup folder")
    add_program_arguments(parser)
    parser.add_argument("--entry", default="main", metavar="NAME", type=routine_name,
                        help="procedure to start from (default: main)")
    parser.add_argument("--io", action="append", default=[], metavar="NAME=VALUE",
                        help="value of an input signal for the whole run (repeatable; "
                             "inputs are 0 otherwise)")
    parser.add_argument("--inputs", metavar="FILE",
                        help="input script: lines 'SECONDS NAME=VALUE ...' setting inputs at "
                             "virtual times (time passes in waits: WaitTime, or a wait that only "
                             "a later input change can end)")
    parser.add_argument("--max-steps", type=int, default=None, metavar="N",
                        help="stop with an error after N steps (default: no limit)")
    parser.add_argument("--no-restart", action="store_true",
                        help="the operator never restarts a program stopped by Stop or Break: "
                             "the run ends there (by default a line of standard input restarts "
                             "it at the next instruction; the end of input also ends the run)")
    parser.add_argument("--trace", action="store_true",
                        help="print the source position of every step to stderr")


def parse_io(assignments: list[str]) -> dict[str, float]:
    values = {}
    for text in assignments:
        name, sep, value = text.partition("=")
        if not sep or not name.strip():
            raise error(USAGE, f"--io expects NAME=VALUE, got {quoted(text)}")
        try:
            number = float(value)
        except ValueError:
            raise error(USAGE, f"--io {quoted(name)}: {quoted(value)} is not a number") from None
        if not math.isfinite(number):
            raise error(BAD_INPUT_VALUE, f"--io {quoted(name)}: {quoted(value)} is not a finite "
                        "number")
        values[name.strip().upper()] = number
    return values


def check_io_values(program, io_values: dict[str, float]) -> None:
    """Every --io name is a signal, and digital signals get 0 or 1."""
    unknown = [name for name in io_values if program.signal(name) is None]
    if unknown:
        raise error(USAGE, f"--io names unknown signal(s): "
                    f"{', '.join(quoted(name) for name in unknown)}")
    for name, value in io_values.items():
        check_signal_value(program.signal(name), value)


def check_signal_value(signal, value: float, where=None) -> None:
    """A digital signal is 0 or 1."""
    if signal.kind in ("DI", "DO") and value not in (0, 1):
        raise error(BAD_INPUT_VALUE, f"{signal.name}: a digital signal is 0 or 1, not "
                    f"{value:g}", where)


def read_input_script(path: str, program) -> tuple:
    """``SECONDS NAME=VALUE ...`` lines -> (seconds, signal index, value) in time order."""
    from pathlib import Path
    from .. import ast
    from ..diagnostics import FILE_NOT_FOUND, SourceCache
    file = Path(path)
    if not file.is_file():
        raise error(FILE_NOT_FOUND, f"input script '{path}' does not exist")
    text = file.read_bytes().decode("latin-1")
    SourceCache.remember(path, text)
    changes = []
    for number, line in enumerate(text.splitlines(), start=1):
        words = line.split("#", 1)[0].split()
        if not words:
            continue
        where = ast.Span(path, number, 1)
        try:
            seconds = float(words[0])
        except ValueError:
            raise error(USAGE, f"an input script line starts with a time in seconds, not "
                        f"{quoted(words[0])}", where) from None
        if not 0 <= seconds < math.inf or len(words) < 2:
            raise error(USAGE, "expected 'SECONDS NAME=VALUE ...' with SECONDS >= 0", where)
        for assignment in parse_io(words[1:]).items():
            name, value = assignment
            signal = program.signal(name)
            if signal is None:
                raise error(USAGE, f"the input script names unknown signal {quoted(name)}", where)
            check_signal_value(signal, value, where)
            changes.append((seconds, signal.index, value))
    return tuple(sorted(changes, key=lambda change: change[0]))


def execute(args: argparse.Namespace) -> int:
    io_values = parse_io(args.io)
    files = resolve_program_files(args)
    parsed, tasks = with_interfaces(load_program(files.modules), files)
    program = build(parsed, entry=files.main_entry if args.entry == "main" else args.entry,
                    options=dict(link_options(files), io_names=tuple(io_values)), tasks=tasks)
    check_io_values(program, io_values)
    changes = read_input_script(args.inputs, program) if args.inputs else ()
    result = run_program(program, io_values, sys.stdin, sys.stdout, args.max_steps,
                         sys.stderr if args.trace else None, changes,
                         None if args.no_restart else sys.stderr)
    if result.state.status == FAILED:
        sys.stdout.flush()
        print(render(fault_diagnostic(program, result.state)), file=sys.stderr)
        return EXIT_RUNTIME_ERROR
    return EXIT_OK
