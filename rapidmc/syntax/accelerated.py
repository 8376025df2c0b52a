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
import sys
from typing import Callable, Iterable, Iterator

from lark.parsers.lalr_analysis import Reduce, Shift

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
        self.expansion, self.rule = tuple(rule.expansion), rule
        self.origin = Symbol(rule.origin.name)


class Symbol:
    """A grammar symbol's name, interned (``sys.intern``) as the table's keys and the
    scanner's terminal names are: the loop's look-ups by name then find the very key
    object and compare no text."""

    __slots__ = ("name",)

    def __init__(self, name: str):
        self.name = sys.intern(str(name))


class CompiledTable:
    """Lark's parse table with the reductions of ``pass_through`` rules taken as
    shortcuts (``shortcuts``) and each rule replaced by its ``Reduction``."""

    def __init__(self, table, pass_through: frozenset = frozenset()):
        states = with_shortcuts(table.states, pass_through.__contains__,
                                table.end_states.values()) if pass_through else table.states
        reductions: dict[int, tuple] = {}
        for actions in states.values():
            for kind, rule in actions.values():
                if kind is Reduce and id(rule) not in reductions:
                    reductions[id(rule)] = (Reduce, Reduction(rule))
        number = _state_numbers(states)
        self.states = {number[state]: {sys.intern(str(symbol)): reductions[id(entry[1])]
                                       if entry[0] is Reduce
                                       else (Shift, number[entry[1]])
                                       for symbol, entry in actions.items()}
                       for state, actions in states.items()}
        self.start_states = {start: number[state] for start, state in table.start_states.items()}
        self.end_states = {start: number[state] for start, state in table.end_states.items()}
        self.reductions = tuple(reduction for _, reduction in reductions.values())


# CPython keeps one object for each int up to this; the compiled loop turns the state
# number into a Python int and back at every action, and looks it up in ``states``.
SHARED_INTS = 257


def _state_numbers(states: dict[int, dict]) -> dict[int, int]:
    """A new number for each state: those entered by shifting a token most often in the
    table (where the parser reads the next token) below ``SHARED_INTS``, so that their
    numbers are neither allocated nor compared by value in the loop (3% of the parse
    time).  Each number is one object, in the keys and in the actions alike."""
    entered = dict.fromkeys(states, 0)
    for actions in states.values():
        for symbol, (kind, argument) in actions.items():
            if kind is Shift and symbol.isupper():
                entered[argument] += 1
    order = sorted(states, key=lambda state: (-entered[state], state))
    return {state: number for number, state in enumerate(order)}


@functools.cache
def compiled_table(table, pass_through: frozenset = frozenset()) -> CompiledTable:
    return CompiledTable(table, pass_through)


def parse(table, callbacks: dict, tokens: "TokenFeed", start: str,
          pass_through: frozenset = frozenset()):
    """Run the compiled loop over ``table`` (Lark's), with ``callbacks`` keyed by Lark's
    rules, on the tokens of ``tokens``; the reductions of the ``pass_through`` rules,
    whose callbacks give their one entry back, are skipped."""
    return compiled_parser(table, callbacks, pass_through).parse(tokens, start)


def compiled_parser(table, callbacks: dict, pass_through: frozenset = frozenset()):
    """The compiled loop over ``table`` with ``callbacks`` keyed by its reductions (it
    keeps no state between parses: a parser may keep it with the callbacks)."""
    compiled = compiled_table(table, pass_through)
    by_reduction = {reduction: callbacks[reduction.rule] for reduction in compiled.reductions}
    return CompiledParser(compiled, by_reduction)


class TokenFeed:
    """The tokens of a text as the compiled loop asks for them: ``next_token(parser_state)``,
    then ``EOFError`` after the last one.

    Like ``RapidLexer`` it tells the last token the parser has shifted
    (``previous``, which ends the text of the rule being reduced) and calls
    ``on_too_deep`` when the parser stack is deeper than ``max_depth`` as a
    token is read."""

    def __init__(self, tokens: Iterable, max_depth: int, on_too_deep: Callable[[], None]):
        self.tokens, self.max_depth, self.on_too_deep = tokens, max_depth, on_too_deep
        self.previous = None
        self.next_token = self.first_token

    def first_token(self, parser_state):
        feed = self.feed(parser_state.state_stack)
        self.next_token = feed.send          # one C call per token; the value sent is unused
        return next(feed)

    def feed(self, state_stack: list) -> Iterator:
        max_depth, current = self.max_depth, None
        for token in self.tokens:
            if len(state_stack) > max_depth:
                self.on_too_deep()
            self.previous = current
            current = token
            yield token
        self.previous = current
        raise EOFError
