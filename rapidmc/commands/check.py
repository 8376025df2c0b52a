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
from typing import Optional

from .. import ast
from ..check import (HOLDS, UNKNOWN, VIOLATED, Progress, PropertyResult, check_property,
                     find_reachable, format_json, format_text)
from ..check.sarif import format_sarif, format_sarif_diagnostics
from ..diagnostics import (AUTOMATON, DOMAIN, ENVIRONMENT, EXIT_OK, EXIT_UNKNOWN,
                           EXIT_VIOLATED, TRACE_REPLAY, USAGE, SourceCache, UserError, error,
                           render_all)
from ..ltl import BACKENDS, read_hoa, to_buchi, to_text
from ..ltl.syntax import Not
from ..backup import add_program_arguments, load_tasks, resolve_program_files
from ..model import RapidDescriber, RapidSystem, replay, with_final_loop
from .. import reduction
from ..properties import (AtomCompiler, Property, check_unique, parse_property,
                          read_property_file)
from ..semantics.link import build
from ..semantics.step import CheckConfig, EnvironmentFault
from ..syntax import load_program
from . import storage_options
from .quoting import one_line, quoted, routine_name

DEFAULT_MAX_STATES = 1_000_000
BUILTIN_RUNTIME = "no_runtime_error"
BUILTIN_DEADLOCK = "no_deadlock"


def add_arguments(parser: argparse.ArgumentParser) -> None:
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
    parser.add_argument("--format", choices=("text", "json", "sarif"), default="text",
                        help="output format (default: text); sarif: SARIF 2.1.0 for CI and "
                             "code-scanning tools, input errors included")
    parser.add_argument("--quiet", action="store_true", help="no progress line on stderr")
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
    parser.add_argument("--automaton", action="append", default=[], metavar="NAME=FILE.hoa",
                        help="use this Büchi automaton (HOA) for the NEGATION of property NAME")
    parser.add_argument("--backend", choices=BACKENDS, default=None,
                        help="LTL translator (default: spot when installed, else builtin)")
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
        name = f"<formula-{number}>"   # no space: diagnostics open with FILE:LINE:COL
        SourceCache.remember(name, text)
        properties.append(parse_property(text, name, 1))
    check_unique(properties)
    return properties


def execute(args: argparse.Namespace) -> int:
    if args.format != "sarif":
        return _check(args)
    try:
        return _check(args)
    except UserError as exc:
        print(render_all(exc.diagnostics), file=sys.stderr)
        print(format_sarif_diagnostics(exc.diagnostics, exc.exit_code), end="")
        return exc.exit_code


def _check(args: argparse.Namespace) -> int:
    properties = gather_properties(args)
    automata = _pairs(args.automaton, "--automaton")
    domains = {name.upper(): _numbers(values, "--input-domain")
               for name, values in _pairs(args.input_domain, "--input-domain").items()}
    files = resolve_program_files(args)
    program_ast = load_program(files.modules)
    environment = load_program(args.env) if args.env else None
    program = build(program_ast, entry=args.entry, environment=environment,
                    options={"configured_signals": files.signals}, tasks=load_tasks(files))
    _check_domains(program, domains)
    atoms = AtomCompiler(program)
    jobs = [_prepare(prop, atoms, automata, args.backend) for prop in properties]
    config = CheckConfig(program, _numbers(args.tp_answers, "--tp-answers"),
                         _numbers(args.fk_answers, "--fk-answers"), domains,
                         observed=_observed_inputs(program_ast, atoms))
    if args.socket_messages:
        config.socket_messages = tuple(args.socket_messages)
    config.socket_closures = args.socket_closures
    config.socket_timeouts = not args.no_socket_timeouts
    if args.file_lines:
        config.file_lines = tuple(args.file_lines)
    plan = reduction.plan_reductions(
        program, config, [atom for _, buchi, _ in jobs for atom in buchi.atoms],
        [None if prop.name in automata else prop.formula for prop in properties],
        reduction.from_arguments(args))
    system = RapidSystem(program, config, plan)
    describer = RapidDescriber(program, config)
    unknown = set(automata) - {p.name for p in properties}
    if unknown:
        raise error(USAGE, f"--automaton names no property: "
                    f"{', '.join(quoted(name) for name in sorted(unknown))}")
    bounds = dict(max_states=args.max_states, max_seconds=args.max_seconds,
                  storage=storage_options.storage_from_arguments(args))
    results = []
    try:
        results.append(_builtin(system, BUILTIN_RUNTIME, "no reachable uncaught run-time error",
                                system.failed, bounds, args.quiet))
        results.append(_builtin(system, BUILTIN_DEADLOCK, "no reachable state where the program "
                                "waits forever", system.stuck, bounds, args.quiet))
        for prop, buchi, valuation in jobs:
            result = check_property(system, buchi, valuation, progress=_progress(args.quiet),
                                    **bounds)
            _replayed(system, result)
            results.append(PropertyResult(prop.name, prop.text, result))
    except EnvironmentFault as exc:
        raise error(ENVIRONMENT, f"environment model: {one_line(str(exc))}") from None
    verdicts = [r.result.verdict for r in results]
    exit_code = EXIT_VIOLATED if VIOLATED in verdicts else (
        EXIT_UNKNOWN if UNKNOWN in verdicts else EXIT_OK)
    if args.format == "json":
        print(format_json(results, describer))
    elif args.format == "sarif":
        print(format_sarif(results, describer, exit_code), end="")
    else:
        print(format_text(results, describer))
    return exit_code


def _progress(quiet: bool) -> Progress:
    return Progress(sys.stderr, quiet=quiet)


def _prepare(prop: Property, atoms: AtomCompiler, automata: dict, backend):
    """The automaton of the property's negation and the valuation of its atoms."""
    where = ast.Span(prop.file, prop.line, 1)
    path = automata.get(prop.name)
    if path is not None:
        try:
            with open(path, encoding="latin-1") as handle:
                buchi = read_hoa(handle.read(), path)
        except OSError as exc:
            raise error(AUTOMATON, f"cannot read automaton file '{path}': {exc.strerror}") from None
    else:
        buchi = to_buchi(Not(prop.formula), backend=backend)
    spans = {atom: _atom_span(prop, atom) for atom in buchi.atoms}
    return prop, buchi, atoms.valuation(buchi.atoms, spans)


def _atom_span(prop: Property, atom: str) -> ast.Span:
    """Where the atom is written in the property (its column within the line)."""
    from ..diagnostics import SourceCache as cache
    line = cache.line(prop.file, prop.line) or prop.text
    for written in (f'"{atom}"', atom):
        column = line.find(written)
        if column >= 0:
            return ast.Span(prop.file, prop.line, column + 1, prop.line,
                            column + 1 + len(written))
    return ast.Span(prop.file, prop.line, 1)


def _builtin(system: RapidSystem, name: str, description: str, predicate, bounds,
             quiet: bool) -> PropertyResult:
    result = find_reachable(system, predicate, progress=_progress(quiet), **bounds)
    if result.verdict == VIOLATED:
        with_final_loop(system, result)
        _replayed(system, result)
    return PropertyResult(name, description, result)


def _replayed(system: RapidSystem, result) -> None:
    if result.verdict != VIOLATED:
        return
    try:
        replay(system, result)
    except AssertionError as exc:
        raise RuntimeError(f"internal error: {exc} [{TRACE_REPLAY.code}]") from None


INTERRUPT_ORDERS = {"ISIGNALDI", "ISIGNALDO", "ISIGNALAI", "ISIGNALAO", "ISIGNALGI", "ISIGNALGO"}


def _observed_inputs(program_ast, atoms: AtomCompiler):
    """The free inputs whose values states must keep (None: all of them).

    Inputs that no atom reads are chosen when the program reads them; an atom
    that reads signal data (bound at run time) or an interrupt ordered on a
    signal makes every input observed.
    """
    from ..semantics.configured_signals import signal_uses
    if atoms.observes_signal_data:
        return None
    for module in program_ast.modules:
        for routine in module.routines:
            from ..semantics.configured_signals import _walk_statements
            for node in _walk_statements(routine.body):
                if isinstance(node, ast.ProcedureCall) and node.name.key in INTERRUPT_ORDERS:
                    return None
    return set(atoms.observed)


def _check_domains(program, domains: dict) -> None:
    for key in domains:
        signal = program.signal(key)
        if signal is None:
            raise error(USAGE, f"--input-domain names unknown signal {quoted(key)}")
        if signal.kind not in ("AI", "GI"):
            raise error(USAGE, f"--input-domain is for analog and group inputs; {signal.name} is "
                        f"a {signal.kind}")
    for signal in program.signals:
        if signal.kind in ("AI", "GI") and not signal.driven and signal.key not in domains:
            raise error(DOMAIN, f"free {signal.kind} input '{signal.name}' needs a finite set of "
                        f"values: give --input-domain {signal.name}=v1,v2,... (or drive it from "
                        "an environment model)", signal.span)
