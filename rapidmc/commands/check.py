"""``rapidmc check PROGRAM... --ltl FILE [--env PLANT.mod]``: model-check a RAPID program.

Explores every run of the program for every sequence of inputs (free
digital inputs, FlexPendant answers, environment choices), on the fly,
against the Büchi automaton of each property's negation.

Exit codes: 0 every property (and the built-in checks) holds; 1 some
property is violated or a run-time error / deadlock is reachable; 2 bad
input or usage; 3 no violation found but some search was bounded (UNKNOWN).
"""
from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

from .. import api
from ..check import Progress
from ..report.results import format_json, format_text
from ..report.results import format_json_errors
from ..diagnostics import USAGE, UserError, error, render_all
from ..ltl import BACKENDS
from ..load.backup import add_program_arguments
from ..model.properties import Property, check_unique, read_property_file
from ..model import reduction
from . import storage_options
from ..diagnostics.quoting import quoted, routine_name
from .report_file import check_report_target, unwritable_reason, write_report

DEFAULT_MAX_STATES = 1_000_000


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser)
    parser.add_argument("--format", choices=("text", "json", "sarif"), default="text",
                        help="output format (default: text); sarif: SARIF 2.1.0 for CI and "
                             "code-scanning tools, input errors included")
    parser.add_argument("--html", metavar="FILE", default=None,
                        help="also write a self-contained HTML report: verdicts, and each "
                             "counterexample as a player with the source and a timeline")
    parser.add_argument("--junit", metavar="FILE", default=None,
                        help="also write a JUnit XML report to FILE (one test case per property)")
    parser.add_argument("--fail-on-vacuous", action="store_true",
                        help="exit 1 when a property holds only because its trigger is never true")
    parser.add_argument("--full-trace", action="store_true",
                        help="text counterexamples in full: every initial value, values not "
                             "shortened, repeated steps not folded")
    parser.add_argument("--quiet", action="store_true", help="no progress line on stderr")


def add_model_arguments(parser: argparse.ArgumentParser) -> None:
    """The options that say what to search: program, properties, inputs, bounds (``graph`` too)."""
    parser.add_argument("files", nargs="+", metavar="FILE",
                        help="RAPID module files of the program (.mod, .sys, .pgf ...), or a "
                             "controller backup folder")
    add_program_arguments(parser)
    parser.add_argument("--ltl", action="append", default=[], metavar="FILE",
                        help="property file: one 'NAME: FORMULA' per line (repeatable)")
    parser.add_argument("--formula", action="append", default=[], metavar="'NAME: FORMULA'",
                        help="an inline property (repeatable)")
    parser.add_argument("--env", action="append", default=[], metavar="FILE",
                        help="environment (plant) model module in RAPID (repeatable)")
    parser.add_argument("--entry", default="main", metavar="NAME", type=routine_name,
                        help="procedure to start from (default: main)")
    parser.add_argument("--max-states", type=int, default=DEFAULT_MAX_STATES, metavar="N",
                        help=f"bound on stored states per search (default {DEFAULT_MAX_STATES:,})")
    parser.add_argument("--max-seconds", type=float, default=None, metavar="S",
                        help="bound on the time of each search")
    parser.add_argument("--tp-answers", default="1,2,3", metavar="LIST",
                        help="answers TPReadNum/TPReadDnum may get (default: 1,2,3)")
    parser.add_argument("--fk-answers", default="1,2,3,4,5", metavar="LIST",
                        help="function keys TPReadFK may get (default: 1,2,3,4,5)")
    parser.add_argument("--input-domain", action="append", default=[], metavar="NAME=LIST",
                        help="finite values a free analog or group input may take, e.g. "
                             "AI1=0,5,10 (repeatable)")
    parser.add_argument("--socket-messages", action="append", default=[], metavar="TEXT",
                        help="a message SocketReceive may deliver (repeatable; default: one "
                             "empty message)")
    parser.add_argument("--socket-closures", action="store_true",
                        help="the peer may close a socket at any receive (ERR_SOCK_CLOSED)")
    parser.add_argument("--no-socket-timeouts", action="store_true",
                        help="receives with a finite \\Time never time out")
    parser.add_argument("--file-lines", action="append", default=[], metavar="TEXT",
                        help="a line a file or serial read may deliver (repeatable)")
    parser.add_argument("--flows", action="store_true",
                        help="also check no_unchecked_input: no run takes input from a socket, "
                             "file, the FlexPendant or an analog/group input to a move, file "
                             "path, late-bound call or output without a bounding check")
    parser.add_argument("--automaton", action="append", default=[], metavar="NAME=FILE.hoa",
                        help="use this Büchi automaton (HOA) for the NEGATION of property NAME")
    parser.add_argument("--backend", choices=BACKENDS, default=None,
                        help="LTL translator (default: spot when installed, else builtin)")
    parser.add_argument("--no-fairness", action="store_true",
                        help="with several tasks: also search runs in which a task that could "
                             "go on never runs again (default: weak fairness between tasks; "
                             "graph draws the same graph either way)")
    reduction.add_arguments(parser)
    storage_options.add_arguments(parser)


def _numbers(text: str, option: str) -> tuple[float, ...]:
    try:
        values = tuple(float(v) for v in text.split(",") if v.strip())
    except ValueError:
        raise error(USAGE, f"{option} expects numbers separated by commas, got {quoted(text)}") from None
    if not values:
        raise error(USAGE, f"{option} needs at least one value")
    if not all(math.isfinite(v) for v in values):
        raise error(USAGE, f"{option} expects finite numbers, got {quoted(text)}")
    return values


def _pairs(items: list[str], option: str) -> dict[str, str]:
    result = {}
    for item in items:
        name, sep, value = item.partition("=")
        if not sep or not name.strip() or not value.strip():
            raise error(USAGE, f"{option} expects NAME=VALUE, got {quoted(item)}")
        result[name.strip()] = value.strip()
    return result


def gather_properties(args) -> list[Property]:
    properties: list[Property] = []
    for path in args.ltl:
        properties.extend(read_property_file(path))
    for number, text in enumerate(args.formula, start=1):
        properties.append(api.property_from_text(text, number))
    check_unique(properties)
    return properties


def check_options(args: argparse.Namespace) -> api.CheckOptions:
    """The options of ``check`` as the API takes them."""
    return api.CheckOptions(
        tp_answers=_numbers(args.tp_answers, "--tp-answers"),
        fk_answers=_numbers(args.fk_answers, "--fk-answers"),
        input_domains={name.upper(): _numbers(values, "--input-domain")
                       for name, values in _pairs(args.input_domain, "--input-domain").items()},
        socket_messages=tuple(args.socket_messages), socket_closures=args.socket_closures,
        socket_timeouts=not args.no_socket_timeouts, file_lines=tuple(args.file_lines),
        automata=_pairs(args.automaton, "--automaton"), backend=args.backend,
        max_states=args.max_states, max_seconds=args.max_seconds,
        reductions=reduction.from_arguments(args),
        storage=storage_options.storage_from_arguments(args),
        fairness=not args.no_fairness)


def prepare_model(args: argparse.Namespace) -> api.Model:
    """The program and properties named by ``check``'s arguments, ready to search."""
    storage_options.select_engine(args)
    properties = gather_properties(args)
    options = check_options(args)
    flows = getattr(args, "flows", False)
    program = api.load_program(args.files, args.env, entry=args.entry, task=args.task,
                               all_tasks=args.all_tasks, add_tasks=args.add_task, eio=args.eio,
                               flows=flows)
    if flows:
        properties.append(api.flow_property(program))
    return api.prepare(program, properties, options)


def execute(args: argparse.Namespace) -> int:
    try:
        return _check(args)
    except UserError as exc:
        if args.junit:
            from ..report.junit import format_junit_diagnostics   # (reports load on demand)
            write_report(args.junit, format_junit_diagnostics(exc.diagnostics, *_suite(args)),
                         "JUnit report")
        if args.format == "text":
            raise
        print(render_all(exc.diagnostics), file=sys.stderr)
        if args.format == "json":
            print(format_json_errors(exc.diagnostics, getattr(args, "command_line", None)), end="")
        else:
            from ..report.sarif import format_sarif_diagnostics
            print(format_sarif_diagnostics(exc.diagnostics, exc.exit_code), end="")
        return exc.exit_code


def _check(args: argparse.Namespace) -> int:
    _refuse_unwritable_targets(args)
    report = api.check_model(prepare_model(args), progress=lambda: _progress(args.quiet))
    results, describer, warnings = report.results, report.describer, report.warnings
    exit_code = report.exit_code(args.fail_on_vacuous)
    if args.html:
        from ..report.html import write_html          # (reports load on demand)
        write_html(args.html, results, describer, warnings)
    if args.format == "json":
        print(format_json(results, describer, warnings, getattr(args, "command_line", None)))
    elif args.format == "sarif":
        from ..report.sarif import format_sarif
        print(format_sarif(results, describer, exit_code, warnings), end="")
    else:
        print(format_text(results, describer, args.full_trace))
        sys.stdout.flush()
        if warnings:
            print(warnings_text(warnings), file=sys.stderr)
    if args.junit:
        from ..report.junit import format_junit
        write_report(args.junit, format_junit(results, describer, *_suite(args), warnings),
                     "JUnit report")
    return exit_code


def warnings_text(warnings) -> str:
    """The warnings as the counterexamples name files: relative to the current folder when
    it holds them all, else to the folder that does, named once."""
    from ..report.counterexample import display_root
    root, named = display_root([w.span.file for w in warnings if w.span and w.span.file])
    text = render_all(warnings, root)
    return f"(files relative to {root})\n{text}" if named else text


def _refuse_unwritable_targets(args: argparse.Namespace) -> None:
    """A report file that cannot be written is an input error before the search, not after it."""
    reason = unwritable_reason(args.html) if args.html else None
    if reason is not None:
        from ..report.html import html_unwritable
        raise html_unwritable(args.html, reason)
    if args.junit:
        check_report_target(args.junit, "JUnit report")


def _suite(args: argparse.Namespace) -> tuple[str, str]:
    """The JUnit suite name (the program's files) and class name (the first file's stem)."""
    return " ".join(args.files), Path(args.files[0].rstrip("/\\")).stem or "program"


def _progress(quiet: bool) -> Progress:
    return Progress(sys.stderr, quiet=quiet)
