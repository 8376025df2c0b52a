"""What the LALR parser does when it reduces a grammar rule: build the AST at once.

Lark normally builds a parse tree (dropping punctuation and ``_`` terminals,
inlining ``?rule`` and ``_rule`` nodes, filling ``[optional]`` gaps with
None) and a Transformer lowers it afterwards.  Here the same shaping is done
on the parser's value stack: each rule gets one callback that selects its
children exactly as Lark's tree builder would and hands them, with the raw
stack slice (for positions), to the lowering method named like the rule.
No tree is built.

Example::

    >>> from rapidmc.syntax.parser import rapid_parser
    >>> plan = ChildPlan.of(next(r for r in rapid_parser().rules if r.origin.name == "goto"))
    >>> plan.kept
    ((1, False, 0),)
"""
from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Callable, Optional

from lark.grammar import Rule

Callback = Callable[[list], object]


@dataclass(frozen=True)
class ChildPlan:
    """Which stack entries of a rule become children.

    ``kept`` holds ``(index, splice, nones_before)``: the entry at ``index``
    is kept (its items spliced in when it is a ``_rule``), after inserting
    ``nones_before`` Nones for absent ``[optional]`` parts; ``nones_after``
    Nones end the list.
    """

    size: int
    kept: tuple[tuple[int, bool, int], ...]
    nones_after: int

    @staticmethod
    def of(rule: Rule) -> "ChildPlan":
        expansion = rule.expansion
        empty = rule.options.empty_indices
        nones = _nones_per_gap(empty, len(expansion)) if empty else [0] * (len(expansion) + 1)
        kept = []
        pending = 0
        for index, symbol in enumerate(expansion):
            pending += nones[index]
            if not (symbol.is_term and symbol.filter_out):
                splice = not symbol.is_term and symbol.name.startswith("_")
                kept.append((index, splice, pending))
                pending = 0
        return ChildPlan(len(expansion), tuple(kept), pending + nones[len(expansion)])

    def selector(self) -> Optional[Callback]:
        """A function from stack slice to children; None when the slice is the children."""
        plain = not self.nones_after and not any(splice or nones for _, splice, nones in self.kept)
        if plain:
            indices = [index for index, _, _ in self.kept]
            if indices == list(range(self.size)):
                return None
            if len(indices) == 1:
                (only,) = indices
                return lambda entries: [entries[only]]
            return lambda entries: [entries[index] for index in indices]
        kept, nones_after = self.kept, self.nones_after

        def select(entries: list) -> list:
            children: list = []
            for index, splice, nones in kept:
                if nones:
                    children += [None] * nones
                if not splice:
                    children.append(entries[index])
                elif children:
                    children += entries[index]
                else:
                    children = entries[index]   # a left-recursive list grows in place
            if nones_after:
                children += [None] * nones_after
            return children
        return select


def _nones_per_gap(empty_indices: list[bool], length: int) -> list[int]:
    """How many Nones Lark inserts before each symbol (and after the last)."""
    text = "".join(str(int(flag)) for flag in empty_indices)
    counts = [len(ones) for ones in text.split("0")]
    assert len(counts) == length + 1, (counts, length)
    return counts


def rule_callbacks(rules, lowering) -> dict[Rule, Callback]:
    """The parser callbacks: one per rule, calling ``lowering``'s method of the rule's name.

    A lowering method receives ``(children, entries)``; ``lowering.enclose``
    is told when a ``?rule`` passes on its only child with other tokens
    around it (a parenthesised expression), since the enclosing text counts
    for the positions of the rules above.
    """
    return {rule: _callback(rule, lowering) for rule in rules}


@functools.cache
def _selector(rule: Rule) -> Optional[Callback]:
    return ChildPlan.of(rule).selector()


def _callback(rule: Rule, lowering) -> Callback:
    name = rule.alias or rule.options.template_source or rule.origin.name
    select = _selector(rule)
    if name.startswith("_"):
        return select or _same
    method = getattr(lowering, name, None) or _missing(name)
    if rule.options.expand1 and not rule.alias:
        return _inlining(select, method, lowering.enclose)
    if select is None:
        return lambda entries: method(entries, entries)
    return lambda entries: method(select(entries), entries)


def _inlining(select: Optional[Callback], method, enclose) -> Callback:
    if select is None:
        def inline_plain(entries: list):
            return entries[0] if len(entries) == 1 else method(entries, entries)
        return inline_plain

    def inline(entries: list):
        children = select(entries)
        if len(children) != 1:
            return method(children, entries)
        child = children[0]
        if len(entries) > 1:
            enclose(child, entries)
        return child
    return inline


def _same(entries: list) -> list:
    return entries


def _missing(name: str):
    def fail(children, entries):
        raise AssertionError(f"no lowering for grammar rule '{name}'")
    return fail
