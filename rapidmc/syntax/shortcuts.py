"""The LALR table with the reductions that only pass a child on taken as shortcuts.

An operand alone, ``x`` in ``MoveL x, v100``, is reduced ``postfix`` ->
``term`` -> ``sum`` -> ``expression``: three reductions whose callbacks hand
their one stack entry back unchanged (``reductions.passes_child_on``).  They
are two fifths of all reductions in ordinary code.  This module rewrites the
table so that the compiled loop skips them and gives the same results.

Take a state ``below`` whose goto on a symbol leads to a state ``first``
that reduces such a rule on some lookahead.  After the reduction the parser
is back in ``below`` and takes its goto on the rule's left side; the next
state may pass the entry on again, and so on, until some state does
something else with the lookahead: shift it, reduce another rule, or fail.
The shortcut state for (``below``, ``first``) takes, on each lookahead, the
action that ends this chain, and the gotos of every state of the chains
(the shortcut stands in the stack for whichever of them the original parser
would have reached).  The goto of ``below`` leads to the shortcut instead.
Where two states of the chains go to different states on the same symbol,
no shortcut is made for that pair and the table keeps the chain.

The shortcut table accepts the same token sequences, fails on the same
token, and its callbacks receive the same values, since every skipped
callback would have returned its argument.  Shifts still lead to the
original states, whose actions are unchanged, so each token is first looked
up in the same state as before (the scanner's reading rests on that).

Example::

    >>> from rapidmc.syntax.parser import rapid_parser
    >>> from rapidmc.syntax.reductions import passes_child_on
    >>> table = rapid_parser().parser.parser._parse_table
    >>> states = with_shortcuts(table.states, passes_child_on, table.end_states.values())
    >>> len(states) > len(table.states)
    True
"""
from __future__ import annotations

from typing import Callable, Iterable, Optional

from lark.parsers.lalr_analysis import Reduce, Shift

# More shortcut states than this means an unexpected grammar: the table is left alone.
MAX_SHORTCUTS = 20_000


def with_shortcuts(states: dict[int, dict], passes_on: Callable[[object], bool],
                   end_states: Iterable[int]) -> dict[int, dict]:
    """``states`` (Lark's: state -> symbol -> (Shift, state) or (Reduce, rule)) with
    the reductions of the rules ``passes_on`` accepts taken as shortcuts."""
    passing = {id(argument) for actions in states.values() for kind, argument in actions.values()
               if kind is Reduce and passes_on(argument)}
    starts = {state for state, actions in states.items()
              if any(id(argument) in passing for _, argument in actions.values())}
    ends = frozenset(end_states)
    # What each state does, split into actions on terminals and gotos, as in the
    # original table (a chain is read from these).
    meaning = {state: _split(actions) for state, actions in states.items()}
    result = {state: dict(actions) for state, actions in states.items()}
    made: dict[tuple[int, int], Optional[int]] = {}
    new_state = max(states, default=-1) + 1
    work = sorted(states)
    while work:
        below = work.pop()
        for symbol, (kind, first) in meaning[below][1].items():
            if first not in starts:
                continue
            if (below, first) not in made:
                made[(below, first)] = shortcut = None
                actions = _shortcut(meaning, below, first, passing, ends)
                if actions is not None:
                    if len(meaning) - len(states) >= MAX_SHORTCUTS:
                        return {state: dict(actions) for state, actions in states.items()}
                    made[(below, first)] = shortcut = new_state
                    new_state += 1
                    meaning[shortcut], result[shortcut] = actions, {**actions[0], **actions[1]}
                    work.append(shortcut)
            if made[(below, first)] is not None:
                result[below][symbol] = (Shift, made[(below, first)])
    return result


def _split(actions: dict) -> tuple[dict, dict]:
    """A state's actions on terminals, and its gotos."""
    on_terminals, gotos = {}, {}
    for symbol, entry in actions.items():
        (on_terminals if _is_terminal(symbol) else gotos)[symbol] = entry
    return on_terminals, gotos


def _shortcut(meaning: dict[int, tuple[dict, dict]], below: int, first: int,
              passing: set[int], ends: frozenset[int]) -> Optional[tuple[dict, dict]]:
    """The actions and gotos of the shortcut state for (``below``, ``first``), or None."""
    actions, reached = {}, {first: None}
    below_gotos = meaning[below][1]
    for symbol, entry in meaning[first][0].items():
        kind, argument = entry
        while kind is Reduce and id(argument) in passing:
            goto = below_gotos.get(argument.origin.name)
            if goto is None or goto[1] in ends:
                return None
            reached[goto[1]] = None
            entry = meaning[goto[1]][0].get(symbol)
            if entry is None:
                break                           # the chain fails on this lookahead
            kind, argument = entry
        if entry is not None:
            actions[symbol] = entry
    gotos: dict = {}
    for state in reached:
        for symbol, entry in meaning[state][1].items():
            if gotos.setdefault(symbol, entry) != entry:
                return None                     # two continuations: keep the chain
    return actions, gotos


def _is_terminal(symbol: str) -> bool:
    """Terminal names are upper case in Lark's tables (``$END`` too), rules lower case."""
    return symbol.isupper()
