"""The LALR table with pass-through reductions taken as shortcuts parses exactly as the
table it comes from: the same results and the same failing token, on every short token
sequence of a small grammar with chains of such rules, and on the RAPID grammar."""
from __future__ import annotations

import itertools
from operator import itemgetter

import pytest
from lark import Lark
from lark.exceptions import UnexpectedInput

from rapidmc.syntax import accelerated, parser
from rapidmc.syntax.reductions import passes_child_on
from rapidmc.syntax.tokens import CompiledToken

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

needs_compiled = pytest.mark.skipif(not accelerated.AVAILABLE, reason="lark_cython not installed")

# Unit chains (comparison -> sum -> product -> factor), operators that start and continue
# them, a rule that continues after a chain (the call's arguments) and one that starts
# with the chain's symbol on its own.
CHAINS = r"""
start: comparison (";" comparison)*
?comparison: sum | sum "<" sum -> less
?sum: product | sum "+" product -> plus | "-" product -> minus
?product: factor | product "*" factor -> times
?factor: NAME | NAME "(" [arguments] ")" -> call | "(" comparison ")" | factor "!" -> bang
arguments: comparison ("," comparison)*
NAME: "a" | "b"
%ignore " "
"""
# After ``b`` and after ``a`` the empty ``e`` leads to different states: a shortcut
# state would not know which, so none is made.
TWO_CONTINUATIONS = r"""
start: a ";"
?a: b | a e "+"
?b: c | b e "*"
e:
c: "c"
"""
GRAMMARS = {
    "chains": (CHAINS, ["NAME", "SEMICOLON", "LESSTHAN", "PLUS", "MINUS", "STAR", "LPAR",
                        "RPAR", "BANG", "COMMA"], 5, 50),
    "two continuations": (TWO_CONTINUATIONS, ["C", "PLUS", "STAR", "SEMICOLON"], 8, 20),
}


class Tokens:
    """``next_token`` over a list of lark_cython tokens, then ``EOFError``."""

    def __init__(self, kinds: tuple[str, ...]):
        self.tokens = iter([CompiledToken(kind, kind, number, 1, number + 1)
                            for number, kind in enumerate(kinds)])

    def next_token(self, parser_state):
        for token in self.tokens:
            return token
        raise EOFError


def outcome(table, callbacks: dict, kinds: tuple[str, ...]):
    try:
        return accelerated.CompiledParser(table, callbacks).parse(Tokens(kinds), "start")
    except UnexpectedInput as failure:            # the kind of failure and the token
        return type(failure).__name__, failure.token.start_pos


def tables(grammar: str):
    """The plain and the shortcut compiled table of ``grammar``, each with callbacks that
    build (rule, *entries) tuples, or pass the entry on for the pass-through rules."""
    table = Lark(grammar, parser="lalr").parser.parser.parser.parse_table
    rules = {rule for actions in table.states.values()
             for kind, rule in actions.values() if kind.name == "Reduce"}
    passing = frozenset(rule for rule in rules if passes_child_on(rule))
    assert passing

    def with_callbacks(compiled):
        return compiled, {
            reduction: itemgetter(0) if reduction.rule in passing else
            (lambda entries, name=reduction.rule.alias or reduction.rule.origin.name:
             (name, *entries)) for reduction in compiled.reductions}
    return (with_callbacks(accelerated.CompiledTable(table)),
            with_callbacks(accelerated.CompiledTable(table, passing)))


@needs_compiled
@pytest.mark.parametrize("name", GRAMMARS)
def test_shortcuts_parse_every_short_sequence_as_the_chains_do(name):
    grammar, alphabet, longest, least_accepted = GRAMMARS[name]
    (plain, plain_callbacks), (shortcut, shortcut_callbacks) = tables(grammar)
    assert (len(shortcut.states) > len(plain.states)) == (name == "chains")
    accepted = 0
    for length in range(1, longest + 1):
        for kinds in itertools.product(alphabet, repeat=length):
            expected = outcome(plain, plain_callbacks, kinds)
            assert outcome(shortcut, shortcut_callbacks, kinds) == expected, kinds
            accepted += expected[0] != "UnexpectedToken"
    assert accepted >= least_accepted


@needs_compiled
def test_rapid_table_skips_two_fifths_of_the_reductions():
    """On ordinary code (bench/parse.py's routine) most operand chains are skipped."""
    text = ("MODULE m\n PROC p()\n  MoveL Offs(p1, 0, 0, n MOD 100), v1000, z50, tool0;\n"
            "  x := x + i * 2 - (i DIV 3);\n  IF x > 100 AND NOT done THEN done := TRUE; ENDIF\n"
            " ENDPROC\nENDMODULE\n")
    counts, results = [], []
    for pass_through in (frozenset(), parser._pass_through()):
        lowering = parser.Lowering("m.mod", None)
        calls = []
        counting = {rule: (lambda entries, callback=callback: calls.append(1) or callback(entries))
                    for rule, callback in parser.rule_callbacks(parser._reduced_rules(),
                                                                lowering).items()}
        lowering.lexer = feed = accelerated.TokenFeed(
            parser._scanner().scan(text, CompiledToken), parser.MAX_STACK_DEPTH, None)
        results.append(accelerated.parse(parser.rapid_parser().parser.parser._parse_table,
                                         counting, feed, parser.START_RULE, pass_through))
        counts.append(len(calls))
    assert results[0] == results[1]
    assert counts[1] < 0.7 * counts[0]


@needs_compiled
def test_compiled_table_is_the_shortcut_table_renumbered():
    """The compiled table numbers its states anew (the states entered most often by a
    token get CPython's shared small ints): one to one, every action kept."""
    from lark.parsers.lalr_analysis import Shift
    from rapidmc.syntax.shortcuts import with_shortcuts
    table = parser.rapid_parser().parser.parser._parse_table
    pass_through = parser._pass_through()
    shortcut = with_shortcuts(table.states, pass_through.__contains__, table.end_states.values())
    compiled = accelerated.compiled_table(table, pass_through)
    number = accelerated._state_numbers(shortcut)
    assert sorted(number.values()) == list(range(len(shortcut))) == sorted(compiled.states)
    for state, actions in shortcut.items():
        renumbered = compiled.states[number[state]]
        assert renumbered.keys() == actions.keys()
        for symbol, (kind, argument) in actions.items():
            expected = number[argument] if kind is Shift else argument
            assert renumbered[symbol][0] is kind
            assert (renumbered[symbol][1] if kind is Shift else renumbered[symbol][1].rule) \
                == expected
    assert compiled.start_states == {start: number[s] for start, s in table.start_states.items()}
    assert compiled.end_states == {start: number[s] for start, s in table.end_states.items()}
    entered = dict.fromkeys(shortcut, 0)
    for actions in shortcut.values():
        for symbol, (kind, argument) in actions.items():
            if kind is Shift and symbol.isupper():
                entered[argument] += 1
    by_number = sorted(shortcut, key=number.__getitem__)
    counts = [entered[state] for state in by_number]
    assert counts == sorted(counts, reverse=True) and counts[0] > counts[accelerated.SHARED_INTS]
