"""The RAPID tokenizer: one compiled regular expression, Lark's contextual lexer as referee.

Lark's contextual lexer scans every token with a pattern made only of the
terminals the parser state accepts, so a reserved word is read as an
identifier where no keyword fits.  Doing that per token is slow; this lexer
scans with one pattern: the ignored text (white space, comments, headers),
then one of all terminals (in Lark's order: the first alternative that
matches wins), and resolves identifiers against the keywords with a
dictionary.  When the token it finds is one the parser state
accepts, the contextual lexer would have found the same token (its pattern
is a sub-list of the same alternatives).  Otherwise -- a keyword used as a
name, a character no token starts with, an overlap such as ``<`` against
``<EXP>`` -- the contextual lexer reads that one token, so every token and
every lexical error is exactly Lark's.

This lexer feeds Lark's own driver, which parses a text the fast path
(``scanner`` and the compiled loop, see ``parser``) fails on.

The lexer also remembers the last token the parser has shifted: when the
parser reduces a rule, that token ends the rule's text (see ``lower``).
"""
from __future__ import annotations

import re
from typing import Iterator, Optional

from lark import Token
from lark.lexer import ContextualLexer, Lexer, LexerState, PatternStr, TerminalDef

IDENTIFIER = "NAME"
# Lark counts line breaks only in tokens whose pattern can hold one.
_MAY_HOLD_NEWLINE = re.compile(r"\\n|\n|\\s|\[\^|\(\?s")


class ScannedToken(Token):
    """A Lark token built directly (``Token()`` sorts out deprecated keywords first,
    which costs a third of the time it takes to scan a token)."""

    __slots__ = ()

    def __new__(cls, type, value, start_pos=None, line=None, column=None, end_line=None,
                end_column=None, end_pos=None):
        token = str.__new__(cls, value)
        token.type, token.value, token.start_pos, token.end_pos = type, value, start_pos, end_pos
        token.line, token.column = line, column
        token.end_line, token.end_column = end_line, end_column
        return token


class RapidLexer(Lexer):
    """Tokens for Lark's LALR parser; ``previous`` is the last token shifted."""

    def __init__(self, terminals: list[TerminalDef], ignore: frozenset[str],
                 contextual: ContextualLexer, max_depth: int, on_too_deep):
        self.keywords = keyword_spellings(terminals)
        self.pattern = _scanning_pattern(terminals, self.keywords, ignore)
        self.multiline = frozenset(t.name for t in terminals
                                   if _MAY_HOLD_NEWLINE.search(t.pattern.to_regexp()))
        self.contextual = contextual
        self.max_depth = max_depth
        self.on_too_deep = on_too_deep
        self.previous: Optional[Token] = None

    def lex(self, lexer_state: LexerState, parser_state) -> Iterator[Token]:
        text, end = lexer_state.text.text, lexer_state.text.end
        counter = lexer_state.line_ctr
        pos, line, line_start = counter.char_pos, counter.line, counter.line_start_pos
        states, state_stack = parser_state.parse_conf.parse_table.states, parser_state.state_stack
        keywords, multiline, match = self.keywords, self.multiline, self.pattern.match
        max_depth = self.max_depth
        current = None
        while True:
            found = match(text, pos, end)
            token = None
            if found is not None:
                kind = found.lastgroup
                start, stop = found.span(kind)
                value = text[start:stop]
                if kind == IDENTIFIER:
                    kind = keywords.get(value.upper(), IDENTIFIER)
                if kind in states[state_stack[-1]] and not (kind in multiline and "\n" in value):
                    if start != pos:                # skipped white space and comments
                        breaks = text.count("\n", pos, start)
                        if breaks:
                            line += breaks
                            line_start = text.rindex("\n", pos, start) + 1
                    column = start - line_start + 1
                    token = ScannedToken(kind, value, start, line, column, line,
                                       column + stop - start, stop)
                    pos = stop
            if token is None:
                counter.char_pos, counter.line, counter.line_start_pos = pos, line, line_start
                counter.column = pos - line_start + 1
                lexer_state.last_token = current    # Lark's lexers read it in their errors
                token = self._contextual_token(lexer_state, parser_state)
                pos, line, line_start = counter.char_pos, counter.line, counter.line_start_pos
                if token is None:
                    break
            if len(state_stack) > max_depth:
                self.on_too_deep()
            self.previous = current
            current = token
            yield token
        self.previous = lexer_state.last_token = current

    def _contextual_token(self, lexer_state: LexerState, parser_state) -> Optional[Token]:
        """The next token as Lark's contextual lexer reads it (None at the end of the text)."""
        return next(iter(self.contextual.lex(lexer_state, parser_state)), None)


def keyword_spellings(terminals: list[TerminalDef]) -> dict[str, str]:
    """Upper-case spelling -> terminal name, for the keywords an identifier can spell."""
    identifier = next(t for t in terminals if t.name == IDENTIFIER)
    pattern = re.compile(identifier.pattern.to_regexp())
    keywords = {}
    for terminal in terminals:
        spelling = terminal.pattern.value
        if (isinstance(terminal.pattern, PatternStr) and "i" in terminal.pattern.flags
                and pattern.fullmatch(spelling)):
            keywords[spelling.upper()] = terminal.name
    return keywords


def ordered_terminals(terminals: list[TerminalDef],
                      keywords: dict[str, str]) -> list[TerminalDef]:
    """The terminals other than keywords, in the order Lark's lexers try them."""
    keyword_names = set(keywords.values())
    return sorted((t for t in terminals if t.name not in keyword_names),
                  key=lambda t: (-t.priority, -t.pattern.max_width, -len(t.pattern.value), t.name))


def _scanning_pattern(terminals: list[TerminalDef], keywords: dict[str, str],
                      ignore: frozenset[str]) -> re.Pattern:
    """Ignored text, then one token: an alternation of the terminals in the order
    Lark's lexers try them (the first alternative that matches wins)."""
    ordered = ordered_terminals(terminals, keywords)
    skipped = "|".join(t.pattern.to_regexp() for t in ordered if t.name in ignore)
    tokens = "|".join(f"(?P<{t.name}>{t.pattern.to_regexp()})"
                      for t in ordered if t.name not in ignore)
    return re.compile(f"(?>(?:{skipped})*)(?:{tokens})")
