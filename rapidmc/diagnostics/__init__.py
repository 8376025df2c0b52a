"""Diagnostics: one registry of codes, diagnostic values, and their rendering.

A diagnostic is data (code, message, span); rendering is separate.  User
errors travel as ``UserError`` carrying diagnostics; anything else that
escapes is an internal bug and is reported as such by the CLI.

Rendered form (like mypy and compilers)::

    sorter.mod:12:5: error: unknown name 'flag_9' [RMC201]
        flag_9 := TRUE;
        ^

Exit codes of the ``rapidmc`` command (documented in README):
0 success / all properties hold, 1 violation or uncaught RAPID run-time
error, 2 bad input or usage, 3 search incomplete (UNKNOWN), 4 internal error, 5 a
distributed search lost a worker (no verdict).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Iterable, Optional

from ..ast import Span

EXIT_OK = 0
EXIT_VIOLATED = 1
EXIT_RUNTIME_ERROR = 1
EXIT_INPUT_ERROR = 2
EXIT_UNKNOWN = 3
EXIT_INTERNAL_ERROR = 4
EXIT_WORKER_LOST = 5


@dataclass(frozen=True)
class ErrorCode:
    code: str        # "RMC101"
    name: str        # short slug, e.g. "syntax"
    summary: str     # what the code is about


REGISTRY: dict[str, ErrorCode] = {}


def _code(code: str, name: str, summary: str) -> ErrorCode:
    assert code not in REGISTRY, code
    entry = ErrorCode(code, name, summary)
    REGISTRY[code] = entry
    return entry


# --- input files (0xx) -------------------------------------------------------
FILE_NOT_FOUND = _code("RMC001", "file-not-found", "the file does not exist")
FILE_IS_DIRECTORY = _code("RMC002", "file-is-directory", "a directory was given where a file is needed")
FILE_UNREADABLE = _code("RMC003", "file-unreadable", "the file cannot be read")
FILE_BINARY = _code("RMC004", "file-binary", "the file is binary, not RAPID source text")
FILE_ENCRYPTED = _code("RMC005", "file-encrypted", "the module is encrypted and cannot be analysed (every module given is)")
FILE_EMPTY = _code("RMC006", "file-empty", "the file holds no module")
FILE_TOO_LARGE = _code("RMC007", "file-too-large", "the file exceeds the size limit")
PROGRAM_FILE = _code("RMC008", "program-file", "a .pgf program file is malformed or names a missing module")

# --- lexical and syntax (1xx) -------------------------------------------------
SYNTAX = _code("RMC101", "syntax", "the text does not follow RAPID syntax")
BAD_CHARACTER = _code("RMC102", "bad-character", "a character that cannot start any RAPID token")
BAD_STRING = _code("RMC103", "bad-string", "malformed string literal (escape, newline, or longer than 80 characters)")
BAD_NUMBER = _code("RMC104", "bad-number", "malformed or out-of-range numeric literal")
IDENTIFIER_TOO_LONG = _code("RMC105", "identifier-too-long", "identifier longer than 32 characters")
PLACEHOLDER = _code("RMC106", "placeholder", "an editor placeholder where no construct can stand in for it (<ID> as a declared name, <PAR>)")
UNEXPECTED_EOF = _code("RMC107", "unexpected-eof", "the file ends inside a construct")

# --- static semantics (2xx) ---------------------------------------------------
UNKNOWN_NAME = _code("RMC201", "unknown-name", "a name that is not declared")
UNKNOWN_TYPE = _code("RMC202", "unknown-type", "a data type that is not declared")
UNKNOWN_ROUTINE = _code("RMC203", "unknown-routine", "a routine that is not declared")
DUPLICATE = _code("RMC204", "duplicate", "two declarations of one name in one scope")
ARGUMENT = _code("RMC205", "argument", "wrong number, kind or name of arguments")
TYPE_MISMATCH = _code("RMC206", "type-mismatch", "a value of the wrong type")
ASSIGN_CONST = _code("RMC207", "assign-const", "assignment to a constant or a read-only object")
NOT_A_REFERENCE = _code("RMC208", "not-a-reference", "a data reference is required here")
BAD_DECLARATION = _code("RMC209", "bad-declaration", "a declaration RAPID does not allow")
BAD_CONTROL = _code("RMC210", "bad-control", "a statement in a place where RAPID does not allow it")
NO_ENTRY = _code("RMC211", "no-entry", "the entry routine is missing or has parameters")
UNKNOWN_LABEL = _code("RMC212", "unknown-label", "GOTO to a label that does not exist")
NOT_CONSTANT = _code("RMC213", "not-constant", "a constant expression is required")
ENV_ONLY = _code("RMC214", "env-only", "a model-only routine used outside an environment module")
MORE_ERRORS = _code("RMC215", "more-errors", "further errors left out of the report (it is capped)")

# --- run time (3xx) ------------------------------------------------------------
RUNTIME_ERROR = _code("RMC301", "runtime-error", "an uncaught RAPID run-time error stopped the program")
INPUT_EXHAUSTED = _code("RMC302", "input-exhausted", "the program read from the FlexPendant but stdin has no more answers")
BAD_INPUT_VALUE = _code("RMC303", "bad-input-value", "an answer or --io value cannot be used")
STEP_LIMIT = _code("RMC304", "step-limit", "the run exceeded --max-steps")
UNSUPPORTED = _code("RMC305", "unsupported", "a feature rapidmc does not model")

# --- properties and LTL (4xx) ----------------------------------------------------
LTL_SYNTAX = _code("RMC401", "ltl-syntax", "the LTL formula is malformed")
ATOM = _code("RMC402", "atom", "an atomic proposition does not type-check as bool")
PROPERTY_FILE = _code("RMC403", "property-file", "a property file line is malformed")
AUTOMATON = _code("RMC404", "automaton", "a supplied automaton (HOA) is malformed or does not fit")
DUPLICATE_PROPERTY = _code("RMC405", "duplicate-property", "two properties with one name")
AMBIGUOUS_NAME = _code("RMC406", "ambiguous-name",
                       "an atom names data or a place several tasks have, or a robot of a "
                       "controller with several motion tasks, without naming the task")

# --- model checking (5xx) ---------------------------------------------------------
STATE_LIMIT = _code("RMC501", "state-limit", "the search reached --max-states or --max-seconds")
DOMAIN = _code("RMC502", "domain", "a nondeterministic input has no finite domain (free AI/GI "
               "inputs: with `--exact-input-domains` only)")
DOMAIN_ASSUMED = _code("RMC515", "domain-assumed",
                       "a free input's values were derived (its width, or the numbers it is "
                       "compared with), or, not exact, singled out from the program (named "
                       "under `assumes:` too)")
ENVIRONMENT = _code("RMC503", "environment", "the environment model is invalid")
TRACE_REPLAY = _code("RMC504", "trace-replay", "a counterexample did not replay (internal)")
OUTPUT_FILE = _code("RMC506", "output-file", "a report file (--junit, graph -o) cannot be written")
TRACE_DIVERGED = _code("RMC507", "trace-diverged", "the program no longer follows a saved counterexample (replay)")
TRACE_FILE = _code("RMC508", "trace-file", "a trace file is not a usable report of check --format json")
BASELINE_FILE = _code("RMC509", "baseline-file", "a --baseline file cannot be read or is not a rapidmc baseline")
HTML_OUTPUT = _code("RMC520", "html-output", "the HTML report file cannot be written")

# --- usage (6xx) --------------------------------------------------------------------
USAGE = _code("RMC601", "usage", "bad command-line usage")

# --- warnings (7xx): reported beside the verdicts, never a failure on their own ------
NEVER_REACHED = _code("RMC701", "never-reached", "a statement no input sequence reaches (after a complete search)")
FIXED_READING = _code("RMC702", "fixed-reading", "a controller reading the check takes as a fixed or sampled value")
TASKS_LOADED = _code("RMC730", "tasks-loaded", "which tasks of a controller backup are checked together (or left out, and why)")
PERS_UNWRITTEN = _code("RMC731", "pers-unwritten", "a task checked alone reads PERS data it never writes: another task or a PC may write it")
ORDER_REDUCTION = _code("RMC732", "order-reduction", "partial-order reduction is off for a property with X (next)")
EDGES_REPLAYED = _code("RMC733", "edges-replayed", "a counterexample needed an input that only interrupts watch to rise in two steps in a row: the check ran again with its value stored")
ENCRYPTED_SKIPPED = _code("RMC735", "encrypted-skipped", "an encrypted module beside readable ones (or a backup's task of encrypted modules only) is checked as the interface its uses show")
MODULE_UNLISTED = _code("RMC737", "module-unlisted", "a module file in a backup's task folder that backinfo.txt does not list among the task's modules: the task is checked without it")
NO_PROGRAM = _code("RMC736", "no-program", "a controller backup, or the task --task names, holds no program (system modules only): nothing to check, exit 0")

# --- the search engine (750-759) ---------------------------------------------------------
NATIVE_ENGINE = _code("RMC750", "native-engine",
                      "--engine native asked for, and the compiled search core is not built")
RAY_UNAVAILABLE = _code("RMC751", "ray-unavailable",
                        "--workers, --ray or --swarm asked for, and Ray (the 'ray' extra) is not installed")
WORKER_LOST = _code("RMC752", "worker-lost",
                    "a worker of a distributed search died or ran out of memory: no verdict (exit 5)")
RAY_UNREACHABLE = _code("RMC754", "ray-unreachable",
                        "--ray ADDRESS names no Ray cluster this process can join (exit 2)")
RAY_START = _code("RMC755", "ray-start",
                  "the local Ray cluster for --workers or --swarm did not start: no verdict (exit 5)")
DISTRIBUTED_SCOPE = _code("RMC753", "distributed-scope",
                          "what a distributed check did not distribute or report: fair cycles, "
                          "waiting tasks and a swarm's LTL run in one process; no coverage or "
                          "vacuity")

# --- lint (80x-84x): `rapidmc lint` rules (rapidmc.findings.lint, docs/lint.md) ---------
NOT_CHAIN = _code("RMC801", "not-chain", "NOT over an AND/OR/XOR chain without parentheses")
TOOL_NOT_PERS = _code("RMC802", "tool-not-pers", "tooldata, wobjdata or loaddata given to a move instruction is not PERS")
OPTIONAL_CASE = _code("RMC803", "optional-case", "an optional argument's name is spelt in another case than declared")
IO_UNGUARDED = _code("RMC804", "io-unguarded", "a socket or file operation with neither \\Time nor an ERROR handler for its errors")
BUSY_LOOP = _code("RMC805", "busy-loop", "a background task's endless loop that never waits")
UNUSED_DATA = _code("RMC806", "unused-data", "data declared and never used")
UNUSED_ROUTINE = _code("RMC807", "unused-routine", "a routine never called")
UNREACHABLE = _code("RMC808", "unreachable", "a statement after RETURN, EXIT, RAISE, ExitCycle, GOTO or a WHILE TRUE loop that no jump reaches")
SHARED_INDEX = _code("RMC809", "shared-index", "a PERS number indexes an array without a bound check")
EMPTY_KEY = _code("RMC810", "empty-key", "TPReadFK offers an empty key the program waits for")
UNCHECKED_INPUT = _code("RMC820", "unchecked-input", "input from outside reaches a motion, file, late-bound call or output argument unchecked")
LINT_CONFIG = _code("RMC840", "lint-config", "the [tool.rapidmc.lint] configuration is malformed")

# --- editors (85x) --------------------------------------------------------------------
LSP_UNAVAILABLE = _code("RMC850", "lsp-unavailable", "'rapidmc lsp' needs pygls, which is not installed")

# --- specification patterns (86x) ------------------------------------------------------
PATTERN = _code("RMC860", "pattern", "a specification pattern is malformed")


@dataclass(frozen=True)
class Diagnostic:
    """One message about the input, with an optional position."""

    code: ErrorCode
    message: str
    span: Optional[Span] = None
    severity: str = "error"
    notes: tuple[str, ...] = field(default_factory=tuple)
    subject: str = ""        # canonical name an unknown-name diagnostic is about
    omitted: int = 0         # a capped report's last diagnostic (RMC215): how many it leaves out
    flow: tuple = ()         # a lint flow (RMC820): (span, what happens there) from source to sink
    places: tuple = ()       # a finding given once per cause: the spans of its other places


class UserError(Exception):
    """Bad input: carries diagnostics and the exit code to use."""

    def __init__(self, diagnostics: Iterable[Diagnostic] | Diagnostic,
                 exit_code: int = EXIT_INPUT_ERROR):
        if isinstance(diagnostics, Diagnostic):
            diagnostics = [diagnostics]
        self.diagnostics = list(diagnostics)
        self.exit_code = exit_code
        super().__init__("; ".join(d.message for d in self.diagnostics))


def error(code: ErrorCode, message: str, span: Optional[Span] = None,
          *notes: str, exit_code: int = EXIT_INPUT_ERROR, subject: str = "") -> UserError:
    """Shorthand: ``raise error(UNKNOWN_NAME, "unknown name 'x'", span)``."""
    return UserError([Diagnostic(code, message, span, notes=tuple(notes), subject=subject)],
                     exit_code)


class SourceCache:
    """Source lines by file name, for showing the offending line."""

    _lines: dict[str, list[str]] = {}

    @classmethod
    def remember(cls, file: str, text: str) -> None:
        cls._lines[file] = text.splitlines()

    @classmethod
    def line(cls, file: str, line: int) -> Optional[str]:
        lines = cls._lines.get(file)
        if lines is None or not 1 <= line <= len(lines):
            return None
        return lines[line - 1]

    @classmethod
    def lines(cls, file: str) -> Optional[tuple[str, ...]]:
        """Every line of a remembered file (None when it was never read)."""
        lines = cls._lines.get(file)
        return None if lines is None else tuple(lines)


def render(diagnostic: Diagnostic, file_name: Optional[Callable[[str], str]] = None,
           source: bool = True) -> str:
    """Render one diagnostic as text: location, message, code, source line, caret (unless
    not ``source``), notes; the file named by ``file_name`` when one is given (else as
    given)."""
    span = diagnostic.span
    if span is None or span.line <= 0:
        out = head_lines("rapidmc", diagnostic)
    else:
        file = file_name(span.file) if file_name else span.file
        out = head_lines(f"{file}:{span.line}:{span.column}", diagnostic)
        line = SourceCache.line(span.file, span.line) if source else None
        if line is not None:
            width = 1
            if span.end_line == span.line and span.end_column > span.column:
                width = span.end_column - span.column
            shown, column = source_window(line.expandtabs(1).rstrip(), span.column - 1)
            width = max(1, min(width, len(shown) - column))
            out.append("    " + shown)
            out.append("    " + " " * column + "^" + "~" * (width - 1))
    out.extend(f"  note: {note}" for note in diagnostic.notes)
    if diagnostic.places:
        out.append(f"  note: {places_text(diagnostic.places, file_name)}")
    return "\n".join(out)


HEAD_WIDTH = 300       # a text report's longest line (``report.line_width.LONGEST_LINE``)
HEAD_BREAKS = ";, "     # where a message too long for its head line is broken


def head_lines(where: str, diagnostic: Diagnostic) -> list[str]:
    """``where: severity: message [CODE]``, one line when it fits ``HEAD_WIDTH``; else the
    message broken after a ``;``, ``,`` or space so that the head line still ends with its
    code, and the rest on the lines after it, indented and marked ``...``: nothing lost,
    and every head line keeps the shape tools parse."""
    start, code = f"{where}: {diagnostic.severity}: ", f" [{diagnostic.code.code}]"
    message = diagnostic.message
    if len(start) + len(message) + len(code) <= HEAD_WIDTH:
        return [start + message + code]
    room = HEAD_WIDTH - len(start) - len(code) - len(" ...")
    cut = max(message.rfind(char, room // 2, room) for char in HEAD_BREAKS) + 1 \
        if room > 1 else 0
    if cut <= 0:
        cut = max(room, 1)
    lines = [start + message[:cut].rstrip() + " ..." + code]
    rest, width = message[cut:].lstrip(), HEAD_WIDTH - len("    ... ")
    while rest:
        piece = rest if len(rest) <= width else rest[:max(
            rest.rfind(char, width // 2, width) for char in HEAD_BREAKS) + 1 or width]
        lines.append("    ... " + piece.rstrip())
        rest = rest[len(piece):].lstrip()
    return lines


SOURCE_SHOWN = 200     # a longer source line is shown around its caret, cut with "..."


def source_window(source: str, column: int) -> tuple[str, int]:
    """The part of a source line a diagnostic shows and the caret's column in it: the line
    itself when it has at most ``SOURCE_SHOWN`` characters, else ``SOURCE_SHOWN`` of them
    from a little before the caret, with ``...`` where it is cut.

    >>> source_window("x := 1;", 0)
    ('x := 1;', 0)
    >>> shown, at = source_window("a" * 300 + " := 1;", 300)
    >>> len(shown), shown[at:], shown[:3]
    (203, ' := 1;', '...')
    """
    column = max(column, 0)
    if len(source) <= SOURCE_SHOWN:
        return source, column
    first = max(0, min(column - SOURCE_SHOWN // 4, len(source) - SOURCE_SHOWN))
    lead = "..." if first else ""
    tail = "..." if first + SOURCE_SHOWN < len(source) else ""
    return lead + source[first:first + SOURCE_SHOWN] + tail, column - first + len(lead)


def places_text(places, file_name: Optional[Callable[[str], str]] = None) -> str:
    """The other places of a finding given once per cause, by file, a place of several
    lines as its first and last: ``3 more places: m.mod lines 14-16, 22; n.mod line 5``."""
    by_file: dict[str, list[str]] = {}
    for span in places:
        lines = by_file.setdefault(file_name(span.file) if file_name else span.file, [])
        shown = f"{span.line}-{span.end_line}" if span.end_line > span.line else f"{span.line}"
        if shown not in lines:
            lines.append(shown)
    parts = [f"{file} line{'s' if len(lines) > 1 or '-' in lines[0] else ''} {', '.join(lines)}"
             for file, lines in by_file.items()]
    count = len(places)
    return f"{count} more place{'s' if count != 1 else ''}: {'; '.join(parts)}"


def render_all(diagnostics: Iterable[Diagnostic],
               file_name: Optional[Callable[[str], str]] = None) -> str:
    return "\n".join(render(d, file_name) for d in diagnostics)
