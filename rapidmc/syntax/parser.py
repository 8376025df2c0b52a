"""RAPID text to ``rapidmc.ast`` in one pass; Lark's errors become rapidmc diagnostics.

The grammar (``rapidmc.grammar/rapid.lark``) is compiled by Lark once per
process (Lark caches the LALR tables on disk).  Parsing runs the LALR
tables on tokens -- first lark_cython's compiled loop on the whole text's
tokens from ``scanner``, and for a text that fails there Lark's own driver
fed by ``RapidLexer`` -- and builds AST nodes as rules are reduced
(``reductions``, ``lower``): no parse tree is built.

Example::

    >>> [module.name.text for module in parse_modules("MODULE m ENDMODULE", "m.mod")]
    ['m']
"""
from __future__ import annotations

import contextlib
import functools
import re
import threading

from lark import Lark
from lark.exceptions import UnexpectedCharacters, UnexpectedInput, UnexpectedToken
from lark.lexer import LexerState, LexerThread, TextSlice
from lark.parsers.lalr_analysis import Reduce
from lark.parsers.lalr_parser import _Parser

from .. import ast
from ..ast import Span
from ..diagnostics import (BAD_CHARACTER, BAD_STRING, FILE_EMPTY, PLACEHOLDER,
                           SYNTAX, UNEXPECTED_EOF, UserError, error)
from . import accelerated, call_statement, recovery
from .lexer import RapidLexer
from .lower import Lowering
from .reductions import passes_child_on, rule_callbacks
from .scanner import Scanner
from .tokens import CompiledToken, describe_expected, describe_token

PLACEHOLDER_MEANINGS = {
    "TDN": "a type definition", "DDN": "a data declaration", "RDN": "a routine declaration",
    "PAR": "a parameter", "ALT": "an optional parameter", "DIM": "an array dimension",
    "SMT": "a statement", "VAR": "a data reference", "EIT": "an ELSEIF clause",
    "CSE": "a CASE clause", "EXP": "an expression", "ARG": "an argument", "ID": "an identifier",
}
_PLACEHOLDER_TEXT = re.compile(r"<(%s)>" % "|".join(PLACEHOLDER_MEANINGS))
# Text that is not code: whitespace, ! comments and %%% header blocks.
TOKEN_START_PUNCTUATION = frozenset('{}()[],.=<>+-*/:;\\?|%!"')
_TOKEN_START_WORD = re.compile(r"[0-9a-zA-Z\xc0-\xd6\xd8-\xf6\xf8-\xff]")
_NOT_CODE = re.compile(r"%%%(?:.|\n)*?%%%|![^\n]*")
START_RULE = "start"
# Parser stack entries beyond which a file counts as nested too deeply: the
# later stages walk the AST recursively.  That allows 490 nested NOT, 240
# nested -( ), 160 nested a + ( or IF; ordinary code stays below 50 entries.
MAX_STACK_DEPTH = 500


@functools.cache
def rapid_parser() -> Lark:
    """The grammar compiled by Lark (LALR tables and the contextual lexer), built on first use."""
    return Lark.open_from_package(
        "rapidmc.grammar", "rapid.lark", parser="lalr", lexer="contextual",
        maybe_placeholders=True, cache=True)


@functools.cache
def _reduced_rules() -> tuple:
    """The rule objects the parse table reduces by (callbacks are keyed by them)."""
    table = rapid_parser().parser.parser._parse_table
    rules = {id(rule): rule for actions in table.states.values()
             for action, rule in actions.values() if action is Reduce}
    return tuple(rules.values())


def parse_modules(text: str, filename: str) -> tuple[ast.Module, ...]:
    """The modules in RAPID source text, or a ``UserError`` with every syntax error found.

    After a syntax error inside a statement or declaration, that statement
    is blanked out and the file parsed again, so that one run reports the
    errors of the other statements too (``recovery``).

    The scanner and the compiled LALR loop (``accelerated``) parse first
    when lark_cython is installed; a text they fail on is parsed again by
    Lark's own driver, whose exceptions the diagnostics are made from.
    """
    if accelerated.AVAILABLE:
        try:
            return _parse(text, filename, compiled=True)
        except (UnexpectedInput, UserError, NotScanned):
            pass
    try:
        return _parse(text, filename)
    except UnexpectedInput as exc:
        raise UserError(_all_syntax_errors(text, filename, exc)) from None


def _all_syntax_errors(text: str, filename: str, first: UnexpectedInput) -> list:
    diagnostics = []
    attempt, failure = text, first
    while True:
        diagnostics.extend(syntax_error(failure, attempt, filename).diagnostics)
        blanked = recovery.without_failed_statement(attempt, failure)
        if blanked is None or len(diagnostics) >= recovery.MAX_SYNTAX_ERRORS:
            return diagnostics
        try:
            _parse(blanked, filename)
            return diagnostics
        except UnexpectedInput as later:
            if recovery.offset(later) <= recovery.offset(failure):
                return diagnostics
            attempt, failure = blanked, later
        except UserError:            # a lexical problem further on: shown once this is fixed
            return diagnostics


@functools.cache
def _pass_through() -> frozenset:
    """The rules whose reductions the compiled loop skips (``shortcuts``)."""
    return frozenset(rule for rule in _reduced_rules() if passes_child_on(rule))


class NotScanned(Exception):
    """The scanner cannot read the text alone: Lark's driver and ``RapidLexer`` must."""


@functools.cache
def _scanner() -> Scanner:
    lexer_conf = rapid_parser().parser.lexer_conf
    return Scanner(lexer_conf.terminals, frozenset(lexer_conf.ignore))


def _parse(text: str, filename: str, compiled: bool = False) -> tuple[ast.Module, ...]:
    """Parse with Lark's driver, or with the scanner and lark_cython's compiled loop when
    ``compiled`` (``NotScanned`` when the scanner cannot read the text)."""
    lark = rapid_parser()
    frontend = lark.parser
    table = frontend.parser._parse_table
    with _parsing(filename) as parsing:
        lowering = parsing.lowering
        if compiled:
            tokens = _scanner().scan(text, CompiledToken)
            if tokens is None:
                raise NotScanned(filename)
            lowering.lexer = feed = accelerated.TokenFeed(tokens, MAX_STACK_DEPTH,
                                                          lowering.too_deep)
            modules = parsing.compiled(table).parse(feed, START_RULE)
        else:
            lowering.lexer = lexer = RapidLexer(
                frontend.lexer_conf.terminals, frozenset(frontend.lexer_conf.ignore),
                frontend.lexer, MAX_STACK_DEPTH, lowering.too_deep)
            lexer_state = LexerState(TextSlice.cast_from(text))
            modules = _Parser(table, parsing.callbacks).parse(LexerThread(lexer, lexer_state),
                                                              START_RULE)
        if lowering.problem is not None:
            raise lowering.problem
    return modules


class _Parsing:
    """A ``Lowering``, its rule callbacks and the compiled loop over them, for one parse
    after another (``_parsing``)."""

    def __init__(self) -> None:
        self.lowering = Lowering("", None)
        self.callbacks = rule_callbacks(_reduced_rules(), self.lowering)
        self._compiled = None

    def compiled(self, table):
        if self._compiled is None:
            self._compiled = accelerated.compiled_parser(table, self.callbacks,
                                                         _pass_through())
        return self._compiled


class _Spare(threading.local):
    """A thread's ``_Parsing`` between parses."""

    parsing: _Parsing | None = None


_SPARE = _Spare()


@contextlib.contextmanager
def _parsing(filename: str):
    """A ``_Parsing`` for one parse of ``filename``.  Making the callbacks (a closure for
    each of the table's rules) and keying them by the compiled table's reductions took
    longer than parsing a short text (an atom of a property, a small module: some 0.7 ms
    each time), so each thread keeps one and starts its lowering afresh for the next
    parse; a parse while it is in use makes its own."""
    parsing, _SPARE.parsing = _SPARE.parsing or _Parsing(), None
    parsing.lowering.for_file(filename, None)
    try:
        yield parsing
    finally:
        parsing.lowering.for_file("", None)      # (lets go of the parse's nodes and tokens)
        _SPARE.parsing = parsing


def has_code(text: str) -> bool:
    """Whether ``text`` holds anything besides whitespace, comments and headers."""
    return _NOT_CODE.sub("", text).strip() != ""


def syntax_error(exc: UnexpectedInput, text: str, filename: str) -> UserError:
    """The diagnostic for a Lark parse failure."""
    if isinstance(exc, UnexpectedToken) and exc.token.type == "$END":
        return _end_of_file_error(exc, text, filename)
    placeholder = _PLACEHOLDER_TEXT.match(text, exc.pos_in_stream or 0)
    if placeholder:
        return _placeholder_error(placeholder, exc, filename)
    if isinstance(exc, UnexpectedToken):
        called = call_statement.called_name(exc)
        if called is not None:
            return error(SYNTAX, call_statement.message(str(called), text),
                         _token_span(called, filename))
        return _unexpected_token_error(exc, filename)
    if isinstance(exc, UnexpectedCharacters):
        return _unexpected_character_error(exc, text, filename)
    return error(SYNTAX, str(exc), Span(filename, exc.line, exc.column))


def _token_span(token, filename: str) -> Span:
    """Where a token of the failed parse is: the caret's place."""
    return Span(filename, token.line, token.column, token.end_line, token.end_column)


def _unexpected_token_error(exc: UnexpectedToken, filename: str) -> UserError:
    token = exc.token
    span = _token_span(token, filename)
    message = f"unexpected {describe_token(token)}; expected one of: {describe_expected(_acceptable(exc))}"
    return error(SYNTAX, message, span)


def _acceptable(exc: UnexpectedToken) -> set[str]:
    """The terminals the parser could take where it failed.

    Lark's own ``expected`` leaves out keywords when the contextual lexer
    failed first, so the parser state is asked instead.
    """
    if exc.interactive_parser is None:
        return set(exc.expected)
    return set(exc.interactive_parser.accepts()) or set(exc.expected)


def _unexpected_character_error(exc: UnexpectedCharacters, text: str,
                                filename: str) -> UserError:
    span = Span(filename, exc.line, exc.column, exc.line, exc.column + 1)
    character = exc.char
    if character == '"':
        return error(BAD_STRING, "unterminated string (a string must end on the line it starts)", span)
    if _starts_a_token(character):
        message = f"unexpected {character!r}; expected one of: {describe_expected(exc.allowed)}"
        return error(SYNTAX, message, span)
    shown = character if character.isprintable() else f"\\x{ord(character):02x}"
    return error(BAD_CHARACTER, f"character '{shown}' cannot start any RAPID token", span)


def _starts_a_token(character: str) -> bool:
    """Whether some RAPID token can begin with ``character`` (reference 1.3, 1.9)."""
    return character in TOKEN_START_PUNCTUATION or _TOKEN_START_WORD.match(character) is not None


def _placeholder_error(match: re.Match, exc: UnexpectedInput, filename: str) -> UserError:
    kind = match.group(1)
    span = Span(filename, exc.line, exc.column, exc.line, exc.column + len(match.group(0)))
    return error(PLACEHOLDER,
                 f"placeholder {match.group(0)} ({PLACEHOLDER_MEANINGS[kind]}) cannot be "
                 "analysed here; complete the program first", span)


def _end_of_file_error(exc: UnexpectedToken, text: str, filename: str) -> UserError:
    if not has_code(text):
        return error(FILE_EMPTY, "the file holds no module (only comments or white space)",
                     Span(filename, 1, 1))
    lines = text.splitlines() or [""]
    last = len(lines)
    span = Span(filename, last, len(lines[-1]) + 1)
    message = f"the file ends too early; expected one of: {describe_expected(_acceptable(exc))}"
    return error(UNEXPECTED_EOF, message, span)

