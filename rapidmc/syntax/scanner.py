"""The whole text to tokens at once, for the compiled LALR loop (``accelerated``).

``RapidLexer`` reads one token at a time, asking the parser state whether
it accepts each one.  This scanner reads every token of the text with one
``findall`` (the regular expression takes most of the time); the Python
loop that follows only counts lines and columns, and the terminal of each
*distinct* token text is looked up once.  It does not ask the parser state:
it reads each word that spells a keyword as that keyword.  The compiled
loop looks every token up in the parser state, at the very point where
``RapidLexer`` does, and fails when the state does not take it; the text is
then parsed again by Lark's driver (``parser``).  So a parse that succeeds
from these tokens is one in which ``RapidLexer`` reads the same tokens.

The pattern is ``RapidLexer``'s (ignored text, then the terminals in Lark's
order), with a last alternative that takes any one character: a place no
token starts from becomes a token of no terminal, which makes ``scan``
answer None, rather than a place ``findall`` would skip silently.  One
difference: the identifier is matched without its ``i`` flag (case-folding
every character costs an eighth of the scan).  Its character classes hold
both cases of each Latin-1 letter in them (checked when the scanner is
built), so the flag only adds characters beyond Latin-1 (``\u017f``, the
Kelvin sign): where the text has one in code, the scanner finds a token of
no terminal and answers None, and Lark's driver reads the text.

Example::

    >>> from rapidmc.syntax.parser import rapid_parser
    >>> lexer_conf = rapid_parser().parser.lexer_conf
    >>> scanner = Scanner(lexer_conf.terminals, frozenset(lexer_conf.ignore))
    >>> [(t.type, t.value, t.line, t.column) for t in scanner.scan("x := 1;\\n  ENDIF", Token)]
    [('NAME', 'x', 1, 1), ('_ASSIGN', ':=', 1, 3), ('NUMBER', '1', 1, 6), ('SEMICOLON', ';', 1, 7), ('_ENDIF', 'ENDIF', 2, 3)]
    >>> scanner.scan("x := 1 $ 2;", Token) is None
    True
    >>> [t.value for t in scanner.scan("ENDMODULE\n! the end", Token)]
    ['ENDMODULE']
"""
from __future__ import annotations

import re
import sys
from typing import Iterator, Optional

from lark import Token
from lark.lexer import PatternStr, TerminalDef

from .lexer import IDENTIFIER, keyword_spellings, ordered_terminals

class Scanner:
    """Tokens of a whole text; ``scan`` answers None where ``RapidLexer`` must decide."""

    def __init__(self, terminals: list[TerminalDef], ignore: frozenset[str]):
        self.keywords = keyword_spellings(terminals)
        ordered = ordered_terminals(terminals, self.keywords)
        skipped = "|".join(t.pattern.to_regexp() for t in ordered if t.name in ignore)
        tokens = [(t.name, _case_sensitive(t) if t.name == IDENTIFIER else t.pattern.to_regexp())
                  for t in ordered if t.name not in ignore]
        alternatives = "|".join(f"(?:{regexp})" for _, regexp in tokens)
        # Two groups: the ignored text, then the token (or one stray character, or the end
        # of the text after ignored text such as a last comment: an empty token, dropped).
        self.pattern = re.compile(f"((?>(?:{skipped})*))({alternatives}|(?s:.)|\\Z)")
        assert self.pattern.groups == 2, "a terminal's pattern has a capturing group"
        self.terminal_of = re.compile(
            "|".join(f"(?P<{name}>{regexp})" for name, regexp in tokens)).match

    def scan(self, text: str, make_token: type) -> Optional[Iterator]:
        """The tokens of ``text`` (made by ``make_token``, called as ``Token`` is), each
        made as it is asked for; None, before any token, when some text is no token of
        the grammar."""
        # ``split`` gives the text before the first match, then for each match its two
        # groups and the text up to the next match: a flat list of strings, cheaper
        # than ``findall``'s tuples.  Every place of the text matches, so the text
        # between matches is always empty.
        parts = self.pattern.split(text)
        del parts[0]
        while parts and not parts[-2]:
            del parts[-3:]      # the ignored text at the end (and the empty last match)
        terminal = self.terminals(set(parts[1::3]))
        if terminal is None:
            return None
        return _tokens(parts, terminal, make_token)

    def terminals(self, values: set[str]) -> Optional[dict[str, str]]:
        """Token text -> terminal, or None when a text is no token or spans lines."""
        terminal = {}
        for value in values:
            found = self.terminal_of(value)
            if found is None or found.end() != len(value) or "\n" in value:
                return None
            kind = found.lastgroup
            if kind == IDENTIFIER:
                kind = self.keywords.get(value.upper(), IDENTIFIER)
            terminal[value] = sys.intern(kind)     # the compiled table's keys are interned
        return terminal


_LATIN_1 = [chr(code) for code in range(256)]


def _case_sensitive(terminal: TerminalDef) -> str:
    """The regular expression of ``terminal`` without its ``i`` flag, when that matches the
    same Latin-1 text (a character class and a repeated one, each holding both cases of
    its letters); else the one Lark gives."""
    folded, plain = terminal.pattern.to_regexp(), terminal.pattern.value
    if isinstance(terminal.pattern, PatternStr) or set(terminal.pattern.flags) != {"i"}:
        return folded
    folded_match, plain_match = re.compile(folded).fullmatch, re.compile(plain).fullmatch
    first = [c for c in _LATIN_1 if folded_match(c)]
    if not first or first != [c for c in _LATIN_1 if plain_match(c)]:
        return folded
    start = first[0]
    later = [c for c in _LATIN_1 if folded_match(start + c)]
    return plain if later == [c for c in _LATIN_1 if plain_match(start + c)] else folded


def _tokens(parts: list[str], terminal: dict[str, str], make_token: type) -> Iterator:
    """The tokens of ``parts`` (ignored text, token text and empty text, for each token),
    with their lines and columns counted (Lark counts lines at \\n only).  Their offsets
    in the text are left out (``start_pos`` 0, ``end_pos`` None): the AST is built from
    lines and columns, and a text that fails is parsed again by Lark's driver."""
    line, column = 1, 1
    each = iter(parts)
    for skipped, value, _ in zip(each, each, each):
        if skipped:
            if "\n" in skipped:
                line += skipped.count("\n")
                column = len(skipped) - skipped.rindex("\n")
            else:
                column += len(skipped)
        end_column = column + len(value)
        yield make_token(terminal[value], value, 0, line, column, line, end_column, None)
        column = end_column
