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
from dataclasses import replace
from pathlib import Path

from .. import api
from ..check import Progress
from ..check.result import VIOLATED
from ..report.results import format_json, format_json_entries, format_text
from ..report.results import format_json_errors
from ..diagnostics import NEVER_REACHED, USAGE, UserError, error, render, render_all
from ..ltl import BACKENDS
from ..load.backup import add_program_arguments
from ..model.properties import Property, check_unique, read_property_file
from ..model import reduction
from .interrupts import stop_on_interrupt
from . import cluster_options, entries, storage_options
from ..diagnostics.quoting import quoted, routine_name
from .report_file import check_report_target, unwritable_reason, write_report
from . import baseline_options
from ..report.ci_findings import from_results

DEFAULT_MAX_STATES = 1_000_000


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser)
    parser.add_argument("--format", choices=("text", "json", "sarif", "codeclimate"),
                        default="text",
                        help="output format (default: text); sarif: SARIF 2.1.0 for CI and "
                             "code-scanning tools, input errors included; codeclimate: GitLab's "
                             "Code Quality report")
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
    parser.add_argument("--all-warnings", action="store_true",
                        help=f"text: every warning and note in full (default: the first "
                             f"{WARNINGS_SHOWN}, warnings before notes, unreached code last, then a "
                             f"count per code; "
                             f"json, sarif, codeclimate, --html and --junit always keep all)")
    baseline_options.add_arguments(parser)
    cluster_options.add_arguments(parser)


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
                        help="procedure to start from (default: main); check: 'all' checks "
                             "from the entry and from each procedure without parameters that "
                             "no routine calls (service routines), a verdict table each")
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
    parser.add_argument("--exact-input-domains", action="store_true",
                        help="refuse (RMC502) a free analog or group input whose values the "
                             "program does not fix exactly (default: it takes the numbers the "
                             "code compares it with, their neighbours and its configured ends, "
                             "and the verdicts say so under assumes:)")
    parser.add_argument("--socket-messages", action="append", default=[], metavar="TEXT",
                        help="a message SocketReceive may deliver (repeatable; default: one "
                             "empty message)")
    parser.add_argument("--socket-closures", action="store_true",
                        help="the peer may close a socket at any receive or send "
                             "(ERR_SOCK_CLOSED)")
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
    parser.add_argument("--fixed-outside-data", action="store_true",
                        help="PERS data no loaded code writes keeps its initial value, and so do "
                             "outputs only the controller or a task not loaded sets (default: "
                             "each read takes any value of its domain, as another task, an "
                             "encrypted module or a PC may write it)")
    parser.add_argument("--outside-writes-anytime", action="store_true",
                        help="PERS data only the outside writes may change between any two "
                             "reads (default: where a wait of the loaded code reads it, it "
                             "changes only while a task waits or polls for it, and other reads "
                             "take the value the last wait took)")
    parser.add_argument("--track-robot", action="store_true",
                        help="keep the robot's position in every state (default: where nothing "
                             "but moves reads it, moves leave the robot where it is, and the "
                             "verdicts say so under assumes:)")
    parser.add_argument("--exact-edges", action="store_true",
                        help="store the value of every input an interrupt watches (default: an "
                             "input that only interrupts watch may give an edge at any step, "
                             "and the verdicts say so under assumes:; an input no active "
                             "interrupt watches is not stored)")
    parser.add_argument("--inputs-every-step", action="store_true",
                        help="every step chooses the value of every stored input (default: a "
                             "step that reads no signal leaves the inputs no active interrupt "
                             "watches unchosen, at rest)")
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
        exact_input_domains=getattr(args, "exact_input_domains", False),
        socket_messages=tuple(args.socket_messages), socket_closures=args.socket_closures,
        socket_timeouts=not args.no_socket_timeouts, file_lines=tuple(args.file_lines),
        automata=_pairs(args.automaton, "--automaton"), backend=args.backend,
        max_states=args.max_states, max_seconds=args.max_seconds,
        reductions=reduction.from_arguments(args),
        storage=storage_options.storage_from_arguments(args),
        fairness=not args.no_fairness,
        track_robot=args.track_robot,
        edge_inputs=not args.exact_edges,
        inputs_where_read=not args.inputs_every_step,
        cluster=cluster_options.cluster_from_arguments(args))


def prepare_model(args: argparse.Namespace) -> api.Model:
    """The program and properties named by ``check``'s arguments, ready to search."""
    storage_options.select_engine(args)
    properties = gather_properties(args)
    options = check_options(args)
    flows = getattr(args, "flows", False)
    program = api.load_program(args.files, args.env, entry=args.entry, task=args.task,
                               all_tasks=args.all_tasks, add_tasks=args.add_task, eio=args.eio,
                               flows=flows,
                               outside_data=not getattr(args, "fixed_outside_data", False),
                               outside_writes_anytime=getattr(args, "outside_writes_anytime",
                                                              False),
                               properties=properties, stubs=getattr(args, "stubs", False))
    if flows:
        properties.append(api.flow_property(program))
    return api.prepare(program, properties, options)


def execute(args: argparse.Namespace) -> int:
    try:
        with stop_on_interrupt():
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
        elif args.format == "codeclimate":
            from ..report.codeclimate import format_codeclimate_errors
            print(format_codeclimate_errors(exc.diagnostics, args.files[0]), end="")
        else:
            from ..report.sarif import format_sarif_diagnostics
            print(format_sarif_diagnostics(exc.diagnostics, exc.exit_code), end="")
        return exc.exit_code


def _check(args: argparse.Namespace) -> int:
    _refuse_unwritable_targets(args)
    if entries.every_entry(args):
        return _check_every_entry(args)
    known = baseline_options.read_known(args, "check")
    try:
        model = prepare_model(args)
    except UserError as exc:       # a library (no main): each routine is an entry
        if args.entry != "main" or not entries.missing_main(exc) or not entries.is_library(args):
            raise
        return _check_every_entry(args)
    report = api.check_model(model, progress=lambda: _progress(args.quiet))
    results, describer, warnings = report.results, report.describer, report.warnings
    gated, known_sources = _new_findings(args, report, known)
    # the gates (exit code, SARIF, Code Quality, JUnit) leave out what the baseline records;
    # text, JSON and HTML show every verdict
    gated_results = [checked for checked in results if id(checked) not in known_sources]
    gated_warnings = [warning for warning in warnings if id(warning) not in known_sources]
    exit_code = replace(report, results=gated_results).exit_code(args.fail_on_vacuous)
    if args.html:
        from ..report.html import write_html          # (reports load on demand)
        write_html(args.html, results, describer, warnings)
    if args.format == "json":
        print(format_json(results, describer, warnings, getattr(args, "command_line", None)))
    elif args.format == "sarif":
        from ..report.sarif import format_sarif
        print(format_sarif(gated_results, describer, exit_code, gated_warnings), end="")
    elif args.format == "codeclimate":
        from ..report.codeclimate import format_codeclimate
        print(format_codeclimate(gated), end="")
    else:
        print(format_text(results, describer, args.full_trace))
        sys.stdout.flush()
        if warnings:
            print(warnings_text(warnings, _beside_counterexample(args, results),
                                args.all_warnings), file=sys.stderr)
    if args.junit:
        from ..report.junit import format_junit
        write_report(args.junit, format_junit(gated_results, describer, *_suite(args),
                                              warnings), "JUnit report")
    return exit_code


def _check_every_entry(args: argparse.Namespace) -> int:
    """``--entry all``: a verdict table per entry routine, in every format."""
    if args.baseline or args.write_baseline:
        raise error(USAGE, "--entry all gives a verdict table per entry; it does not combine "
                    "with baselines (check each entry with --entry NAME for those)")
    checked = entries.check_every_entry(args, prepare_model, lambda: _progress(args.quiet))
    try:
        return _report_every_entry(args, checked)
    finally:
        checked.remove_drivers()


def _report_every_entry(args: argparse.Namespace, checked: "entries.EntryChecks") -> int:
    """The reports of ``--entry all``, in every format asked for; the exit code."""
    tables, warnings = checked.tables(), checked.warnings
    exit_code = checked.exit_code(args.fail_on_vacuous)
    if args.html:
        from ..report.html import write_html
        for path, (_, results, describer) in zip(
                entries.html_paths(args.html, [entry for entry, *_ in tables]), tables):
            write_html(path, results, describer, warnings)
    if args.format == "json":
        print(format_json_entries(tables, warnings, getattr(args, "command_line", None)), end="")
    elif args.format == "sarif":
        from ..report.sarif import format_sarif_entries
        print(format_sarif_entries(tables, exit_code, warnings), end="")
    elif args.format == "codeclimate":
        from ..report.codeclimate import format_codeclimate
        print(format_codeclimate(_entry_findings(args, tables, warnings)), end="")
    else:
        print("\n".join(f"entry {entry}:\n{format_text(results, describer, args.full_trace)}"
                        for entry, results, describer in tables))
        sys.stdout.flush()
        if warnings:
            every = [checked for _, results, _ in tables for checked in results]
            print(warnings_text(warnings, _beside_counterexample(args, every),
                                args.all_warnings), file=sys.stderr)
    if args.junit:
        from ..report.junit import format_junit_entries
        write_report(args.junit, format_junit_entries(tables, *_suite(args), warnings),
                     "JUnit report")
    return exit_code


def _new_findings(args: argparse.Namespace, report: api.CheckReport, known):
    """The findings a baseline does not record (the Code Quality issues), and the ids of the
    properties and warnings it does record."""
    if not (known is not None or args.write_baseline or args.format == "codeclimate"):
        # nothing reads them: each VIOLATED property's finding would build its trace once
        # more than the report does
        return [], set()
    pairs = from_results(report.results, report.describer, report.warnings, args.files[0],
                         args.fail_on_vacuous)
    new, old = baseline_options.new_findings(args, "check", [f for f, _ in pairs], pairs, known)
    return [finding for finding, _ in new], {id(source) for _, source in old}


COVERAGE_SHOWN = 5      # unreached-code warnings beside a counterexample (then a count)
# warnings and notes the text report shows in full after the verdicts (then a count per code):
# a whole backup gave 31 KB of them, and the verdicts are what a cell engineer reads first
WARNINGS_SHOWN = 10
SEVERITY_ORDER = {"error": 0, "warning": 1, "note": 2}


def warnings_text(warnings, brief_coverage: bool = False, every: bool = False) -> str:
    """The warnings with their files named as the counterexamples name them
    (``trace_text.file_names``).  ``brief_coverage`` (beside a counterexample, which is what
    the reader needs first): the unreached-code warnings (RMC701) one line each, without
    their source line, at most ``COVERAGE_SHOWN``, then a count.  Unless ``every``
    (``--all-warnings``): at most ``WARNINGS_SHOWN`` in all, warnings before notes,
    unreached code (RMC701) after both, then how many of each code are left out."""
    from ..report.line_width import wrapped
    from ..report.trace_text import file_names
    names = file_names([w.span.file for w in warnings if w.span and w.span.file])
    lines = names.legend()
    if not every:
        # what the verdicts rest on first; unreached code, the many, last
        warnings = sorted(warnings, key=lambda w: (w.code is NEVER_REACHED,
                                                   SEVERITY_ORDER.get(w.severity, 1)))
    shown, left_out = 0, {}
    coverage = 0
    for warning in warnings:
        if not every and shown >= WARNINGS_SHOWN:
            left_out[warning.code.code] = left_out.get(warning.code.code, 0) + 1
        elif not (brief_coverage and warning.code is NEVER_REACHED):
            lines.append(render(warning, names.shown))
            shown += 1
        else:
            coverage += 1
            if coverage <= COVERAGE_SHOWN:
                lines.append(render(warning, names.shown, source=False))
                shown += 1
    if coverage > COVERAGE_SHOWN:
        lines.append(f"rapidmc: and {coverage - COVERAGE_SHOWN} more unreached-code warnings "
                     "[RMC701] (--full-trace, --format json or --html shows each)")
    if left_out:
        counts = ", ".join(f"{count} {code}" for code, count in sorted(left_out.items()))
        lines.append(f"rapidmc: and {sum(left_out.values())} more warnings and notes ({counts}): "
                     "--all-warnings shows each; --format json or sarif and --html list them all")
    return wrapped("\n".join(lines))


def _beside_counterexample(args: argparse.Namespace, results) -> bool:
    """Whether the text report shows a counterexample (a violation, no ``--full-trace``)."""
    return not args.full_trace and any(checked.result.verdict == VIOLATED for checked in results)


def _entry_findings(args: argparse.Namespace, tables, warnings) -> list:
    """The Code Quality issues of ``--entry all``: each entry's properties, their messages
    naming the entry, then the warnings of the whole check."""
    found = []
    for entry, results, describer in tables:
        for finding, _ in from_results(results, describer, (), args.files[0],
                                       args.fail_on_vacuous):
            found.append(replace(finding, message=f"entry {entry}: {finding.message}"))
    return found + [finding for finding, _ in from_results((), None, warnings, args.files[0])]


def _refuse_unwritable_targets(args: argparse.Namespace) -> None:
    """A report file that cannot be written is an input error before the search, not after it."""
    reason = unwritable_reason(args.html) if args.html else None
    if reason is not None:
        from ..report.html import html_unwritable
        raise html_unwritable(args.html, reason)
    if args.junit:
        check_report_target(args.junit, "JUnit report")
    baseline_options.refuse_unwritable_target(args)


def _suite(args: argparse.Namespace) -> tuple[str, str]:
    """The JUnit suite name (the program's files) and class name (the first file's stem)."""
    return " ".join(args.files), Path(args.files[0].rstrip("/\\")).stem or "program"


def _progress(quiet: bool) -> Progress:
    return Progress(sys.stderr, quiet=quiet)
