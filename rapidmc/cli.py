"""The ``rapidmc`` command line: subcommands, exit codes, diagnostics on stderr.

Each subcommand lives in ``rapidmc.commands.<name>`` and offers
``add_arguments(parser)`` and ``execute(args) -> int``.  This module only
dispatches and turns errors into diagnostics and exit codes:

* 0 success (program ended normally, all properties hold, files parsed)
* 1 a property is violated, or the program stopped on an uncaught RAPID error
* 2 bad input or usage (syntax, static errors, malformed LTL, missing files)
* 3 no violation found but the search was bounded (UNKNOWN)
* 4 internal error in rapidmc (a bug: please report it)
* 5 a distributed search gave no verdict: a worker was lost, or Ray did not start
"""
from __future__ import annotations

import argparse
import functools
import gc
import importlib
import os
import sys
from typing import Optional, Sequence

from . import __version__
from .diagnostics import (EXIT_INPUT_ERROR, EXIT_INTERNAL_ERROR, USAGE,
                          Diagnostic, UserError, render_all)

SUBCOMMANDS = {
    "parse": "parse RAPID files and report routines and data, or syntax errors",
    "run": "execute a RAPID program with the FlexPendant on the console",
    "check": "model-check a RAPID program against LTL properties",
    "ltl": "translate an LTL formula to a Büchi automaton (HOA format)",
    "replay": "re-execute a counterexample saved by 'check --format json'",
    "graph": "write the reachable state graph (GraphML, GEXF or DOT)",
    "stubs": "write a module declaring the names the program uses and no module declares",
    "lint": "report mistakes visible without a search, and unchecked input flows",
    "lsp": "a Language Server over stdio: diagnostics, hover and go to definition in editors",
}


class _ArgumentParser(argparse.ArgumentParser):
    """argparse that reports usage errors as rapidmc diagnostics (exit 2)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        from .diagnostics.quoting import one_line   # user text stays on the diagnostic's line
        raise UserError([Diagnostic(USAGE, f"{one_line(message)} (see '{self.prog} --help')")])


class _VersionAction(argparse.Action):
    """``--version``: the version and the search engine (``check.native``, imported only
    here: the other commands need not load the search engine)."""

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        from .check.native import description
        print(f"rapidmc {__version__} ({description()})")
        parser.exit()


def build_parser(command: Optional[str] = None) -> argparse.ArgumentParser:
    """The parser of every subcommand; with ``command``, only that one's arguments (the
    others' modules, some slow to import, are not loaded: their parsers take no options)."""
    parser = _ArgumentParser(prog="rapidmc", description="rapidmc: an LTL model checker and "
                             "reference interpreter for ABB RAPID robot programs")
    parser.add_argument("--version", action=_VersionAction, nargs=0,
                        help="show the version and the search engine, and exit")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_ArgumentParser)
    for name, help_text in SUBCOMMANDS.items():
        if command is not None and name != command:
            sub.add_parser(name, help=help_text, description=help_text)
            continue
        module = _command_module(name)
        if module is None:
            continue
        sub_parser = sub.add_parser(name, help=help_text, description=help_text)
        module.add_arguments(sub_parser)
    return parser


@functools.cache
def _parser_of(command: Optional[str]) -> argparse.ArgumentParser:
    """``build_parser(command)``, built once per process: ``main`` may run many times in
    one (in-process checks: the API's callers, the tests), building the arguments took a
    fifth of a small check's time, and parsing leaves the parser as it was."""
    return build_parser(command)


def _command_module(name: str):
    """The module of a subcommand, imported the first time with the cycle collector
    paused: what an import makes (modules, classes, functions) lives as long as the
    process, so the collector's passes over it at every few hundred objects are work for
    nothing (``check``: some 50 passes, a few milliseconds of start-up).  Afterwards the
    new objects join the oldest generation at once (freeze, then unfreeze), as parsing's
    do (``syntax._garbage_collection_paused``): only full collections see them."""
    module = f"rapidmc.commands.{name}"
    paused = module not in sys.modules and gc.isenabled()
    if paused:
        gc.disable()
    try:
        return importlib.import_module(module)
    except ModuleNotFoundError as exc:
        if exc.name == module:
            return None
        raise
    finally:
        if paused:
            gc.freeze()
            gc.unfreeze()
            gc.enable()


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Entry point of the console script; returns the exit code."""
    try:
        arguments = list(sys.argv[1:] if argv is None else argv)
        parser = _parser_of(arguments[0] if arguments and arguments[0] in SUBCOMMANDS
                            else None)
        args = parser.parse_args(arguments)
        args.command_line = arguments   # recorded in reports
        if args.command is None:
            parser.print_help(sys.stderr)
            return EXIT_INPUT_ERROR
        command = _command_module(args.command)
        if getattr(args, "engine", None) is None:
            return command.execute(args)
        # --engine holds for this command only: a caller in this process (a test, an
        # editor's server) keeps the engine it had
        from .check import native
        with native.engine_kept():
            return command.execute(args)
    except UserError as exc:
        sys.stdout.flush()
        print(render_all(exc.diagnostics), file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("rapidmc: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader of our output went away (e.g. `| head`): stop quietly, as Unix tools do
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return 141
    except RecursionError:
        print("rapidmc: error: nesting too deep to analyse [RMC305]", file=sys.stderr)
        return EXIT_INPUT_ERROR
    except Exception as exc:  # an internal bug, not bad input
        if os.environ.get("RAPIDMC_DEBUG"):
            import traceback
            traceback.print_exc()
        print(f"rapidmc: internal error: {type(exc).__name__}: {exc} "
              "(set RAPIDMC_DEBUG=1 for details; please report this)", file=sys.stderr)
        return EXIT_INTERNAL_ERROR


def console_main() -> None:
    code = main()
    # The process ends: the collector's last full pass, at interpreter exit, would walk
    # every object still alive for garbage nobody needs freed (``check`` on the counters,
    # N=6: some 20 ms, a twentieth of the time to verdict).  Reports are written and
    # closed by now; standard streams are flushed at exit as always.
    gc.freeze()
    sys.exit(code)
