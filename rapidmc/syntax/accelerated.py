"""Lark's LALR loop compiled (``lark_cython``): the fast path of the front end.

``lark_cython`` runs Lark's LALR table, with the same callbacks, in compiled
code; the table has the reductions that only pass a child on taken as
shortcuts (``shortcuts``).  Two things differ from Lark's driver: the loop
asks for one token at a time (``next_token(parser_state)``, ``EOFError`` at
the end) and takes only lark_cython's own ``Token`` class.  The tokens come
from ``scanner``, which reads the whole text at once; ``TokenFeed`` hands
them over.  The rules in the table are replaced by ``Reduction`` records
hashed by identity: Lark's ``Rule`` hashes and compares in Python, once per
reduction.

Only a parse that succeeds is taken from here.  When the text has an error,
or the scanner cannot read it, ``parser`` parses it again with Lark's own
driver and ``RapidLexer``, so every exception and every diagnostic is
exactly the one Lark's driver gives.  Without lark_cython installed,
``AVAILABLE`` is False and Lark's driver does all.
"""
from __future__ import annotations

import functools
import itertools
from typing import Callable, Iterator

from lark.parsers.lalr_analysis import Reduce

from .shortcuts import with_shortcuts

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
    """Lark's parse table with the reductions of ``pass_through`` rules taken as
    shortcuts (``shortcuts``) and each rule replaced by its ``Reduction``."""

    def __init__(self, table, pass_through: frozenset = frozenset()):
        reductions: dict[int, Reduction] = {}

        def action(entry):
            kind, argument = entry
            if kind is not Reduce:
                return entry
            if id(argument) not in reductions:
                reductions[id(argument)] = Reduction(argument)
            return kind, reductions[id(argument)]
        states = with_shortcuts(table.states, pass_through.__contains__,
                                table.end_states.values()) if pass_through else table.states
        self.states = {state: {symbol: action(entry) for symbol, entry in actions.items()}
                       for state, actions in states.items()}
        self.start_states, self.end_states = table.start_states, table.end_states
        self.reductions = tuple(reductions.values())


@functools.cache
def compiled_table(table, pass_through: frozenset = frozenset()) -> CompiledTable:
    return CompiledTable(table, pass_through)


def parse(table, callbacks: dict, tokens: "TokenFeed", start: str,
          pass_through: frozenset = frozenset()):
    """Run the compiled loop over ``table`` (Lark's), with ``callbacks`` keyed by Lark's
    rules, on the tokens of ``tokens``; the reductions of the ``pass_through`` rules,
    whose callbacks give their one entry back, are skipped."""
    compiled = compiled_table(table, pass_through)
    by_reduction = {reduction: callbacks[reduction.rule] for reduction in compiled.reductions}
    return CompiledParser(compiled, by_reduction).parse(tokens, start)


@functools.cache
def depth_growth(table, pass_through: frozenset = frozenset()) -> int:
    """How much deeper the parser stack of the compiled loop can be when it asks for a
    token than when it asked for the one before: one shift, and the reductions by
    empty rules (``body`` with no statements) it can make in a row on one lookahead.
    An empty rule pops nothing, so the state it goes to is known from the table alone."""
    states = compiled_table(table, pass_through).states
    longest = 0
    for start, actions in states.items():
        for symbol in actions:
            state, in_a_row = start, 0
            kind, argument = states[state][symbol]
            while kind is Reduce and not argument.expansion:
                in_a_row += 1
                if in_a_row > len(states):
                    raise ValueError("empty rules reduce in a cycle")  # pragma: no cover
                state = states[state][argument.origin.name][1]
                kind, argument = states[state].get(symbol, (None, None))
            longest = max(longest, in_a_row)
    return 1 + longest


class TokenFeed:
    """The tokens of a text (a list) as the compiled loop asks for them:
    ``next_token(parser_state)``, then ``EOFError`` after the last one.

    Like ``RapidLexer`` it tells the last token the parser has shifted
    (``previous``, which ends the text of the rule being reduced) and calls
    ``on_too_deep`` when the parser stack is deeper than ``max_depth`` as a
    token is read.

    No Python code runs per token: the tokens are handed over by C iterators
    (``next`` on a chain of slices of one list iterator).  The stack depth is
    checked where a slice begins; a slice is as long as the stack, growing
    by at most ``growth`` entries per token (``depth_growth``), cannot pass
    ``max_depth`` within it, so the checks skipped would all have passed.
    ``previous`` is found from how many tokens the list iterator has left."""

    def __init__(self, tokens: list, max_depth: int, on_too_deep: Callable[[], None],
                 growth: int):
        self.tokens, self.max_depth, self.on_too_deep = tokens, max_depth, on_too_deep
        self.growth = growth
        self.remaining = iter(tokens)
        self.finished = False
        self.next_token = self.first_token

    def first_token(self, parser_state):
        self.next_token = functools.partial(
            next, itertools.chain.from_iterable(self.slices(parser_state.state_stack)))
        return self.next_token(parser_state)

    def slices(self, state_stack: list) -> Iterator:
        remaining, max_depth, growth = self.remaining, self.max_depth, self.growth
        while remaining.__length_hint__():
            depth = len(state_stack)
            if depth > max_depth:
                self.on_too_deep()
            yield itertools.islice(remaining, 1 + max(0, max_depth - depth) // growth)
        self.finished = True
        raise EOFError

    @property
    def previous(self):
        """The token before the one the parser is looking at (the last at the end)."""
        tokens = self.tokens
        if self.finished:
            return tokens[-1] if tokens else None
        index = len(tokens) - self.remaining.__length_hint__() - 2
        return tokens[index] if index >= 0 else None
