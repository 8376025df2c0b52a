"""Lark's LALR loop compiled (``lark_cython``): the fast path of the front end.

``lark_cython`` runs the same LALR table as Lark, with the same callbacks, in
compiled code.  Two things differ from Lark's driver: the loop asks its
lexer for one token at a time (``next_token(parser_state)``, ``EOFError``
at the end) and takes only lark_cython's own ``Token`` class, which
``RapidLexer`` makes when told to.  The rules in the table are replaced by
``Reduction`` records hashed by identity: Lark's ``Rule`` hashes and
compares in Python, once per reduction.

Only a parse that succeeds is taken from here.  When the text has an error,
``parser`` parses it again with Lark's own driver, so every exception and
every diagnostic is exactly the one Lark's driver gives.  Without
lark_cython installed, ``AVAILABLE`` is False and Lark's driver does all.
"""
from __future__ import annotations

import functools
from typing import Callable, Iterator

from lark.parsers.lalr_analysis import Reduce

try:
    from lark_cython.lark_cython import _Parser as CompiledParser
except ImportError:                     # pragma: no cover - lark_cython is a dependency
    CompiledParser = None

AVAILABLE = CompiledParser is not None


class Reduction:
    """A grammar rule as the compiled loop reads it: how many entries it pops
    (``len(expansion)``) and what it reduces to (``origin.name``)."""

    __slots__ = ("expansion", "origin", "rule")

    def __init__(self, rule):
        self.expansion, self.origin, self.rule = tuple(rule.expansion), rule.origin, rule


class CompiledTable:
    """Lark's parse table with each rule replaced by its ``Reduction``."""

    def __init__(self, table):
        reductions: dict[int, Reduction] = {}

        def action(entry):
            kind, argument = entry
            if kind is not Reduce:
                return entry
            if id(argument) not in reductions:
                reductions[id(argument)] = Reduction(argument)
            return kind, reductions[id(argument)]
        self.states = {state: {symbol: action(entry) for symbol, entry in actions.items()}
                       for state, actions in table.states.items()}
        self.start_states, self.end_states = table.start_states, table.end_states
        self.reductions = tuple(reductions.values())


@functools.cache
def compiled_table(table) -> CompiledTable:
    return CompiledTable(table)


def parse(table, callbacks: dict, tokens: Callable[[object], Iterator], start: str):
    """Run the compiled loop over ``table`` (Lark's), with ``callbacks`` keyed by Lark's
    rules; ``tokens(parser_state)`` gives the token generator (``RapidLexer.lex``), which
    raises ``EOFError`` after the last token."""
    compiled = compiled_table(table)
    by_reduction = {reduction: callbacks[reduction.rule] for reduction in compiled.reductions}
    return CompiledParser(compiled, by_reduction).parse(TokenThread(tokens), start)


class TokenThread:
    """``next_token(parser_state)`` over a token iterator made on the first call
    (the iterator needs the parser state, which the compiled loop creates)."""

    def __init__(self, tokens: Callable[[object], Iterator]):
        self.tokens = tokens
        self.next_token = self.first_token

    def first_token(self, parser_state):
        tokens = self.tokens(parser_state)
        self.next_token = tokens.send        # one C call per token; the value sent is unused
        return next(tokens)
