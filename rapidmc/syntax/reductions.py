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
from operator import itemgetter
from typing import Callable, Optional

from lark.grammar import Rule

# The callback of a rule that passes on its only child: the one entry of its stack slice.
_ONLY_ENTRY = itemgetter(0)

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

    def is_identity(self) -> bool:
        """Whether the stack slice is the children as it stands."""
        return (not self.nones_after and [(index, False, 0) for index in range(self.size)]
                == list(self.kept))

    def selector(self) -> Optional[Callback]:
        """A function from stack slice to children; None when the slice is the children."""
        return None if self.is_identity() else self.function(None)

    def function(self, method) -> Callback:
        """A function of the stack slice giving the children, or with ``method`` the
        result of ``method(children, entries)``."""
        return _reducer_maker(self, method is not None)(method)

    def reducer_source(self, calls_method: bool) -> str:
        """The source of ``make(method)``, which gives the function of the stack slice:
        straight-line code written for this plan, so that nothing loops over the plan
        once per reduction."""
        lines = self.children_source() if not self.is_identity() else ["children = entries"]
        result = "method(children, entries)" if calls_method else "children"
        body = "\n        ".join(lines)
        return (f"def make(method):\n    def reduce(entries):\n        {body}\n"
                f"        return {result}\n    return reduce\n")

    def children_source(self) -> list[str]:
        """Statements that set ``children`` as Lark's tree builder would (a spliced
        ``_rule`` list that comes first is extended in place, so that a left-recursive
        list grows without being copied)."""
        parts: list[tuple[str, int]] = []          # ("one", index), ("splice", index), ("none", 0)
        for index, splice, nones in self.kept:
            parts += [("none", 0)] * nones
            parts.append(("splice" if splice else "one", index))
        parts += [("none", 0)] * self.nones_after
        lines: list[str] = []
        pending: list[str] = []                    # single children not yet added

        def flush():
            if not lines:
                lines.append(f"children = [{', '.join(pending)}]")
            elif len(pending) == 1:
                lines.append(f"children.append({pending[0]})")
            elif pending:
                lines.append(f"children += [{', '.join(pending)}]")
            pending.clear()
        for kind, index in parts:
            if kind != "splice":
                pending.append("None" if kind == "none" else f"entries[{index}]")
            elif not lines and not pending:
                lines.append(f"children = entries[{index}]")
            else:
                flush()
                lines.append(f"children += entries[{index}]")
        if pending or not lines:
            flush()
        return lines


@functools.cache
def _reducer_maker(plan: ChildPlan, calls_method: bool) -> Callable:
    namespace: dict = {}
    exec(plan.reducer_source(calls_method), namespace)
    return namespace["make"]


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
    return {rule: _callback_maker(rule)(lowering) for rule in rules}


@functools.cache
def _callback_maker(rule: Rule) -> Callable[[object], Callback]:
    """What a rule's callback is, decided once: a function of the lowering giving it."""
    name = _callback_name(rule)
    plan = ChildPlan.of(rule)
    if passes_child_on(rule):
        return lambda lowering: _ONLY_ENTRY
    if name.startswith("_"):
        reduce = _passing_on(plan) or plan.function(None)
        return lambda lowering: reduce
    if rule.options.expand1 and not rule.alias:
        if not plan.is_identity():
            select = plan.selector()
            return lambda lowering: _inlining(select, _method(lowering, name), lowering.enclose)
    make, identity = _reducer_maker(plan, True), plan.is_identity()

    def callback(lowering) -> Callback:
        method = _method(lowering, name)
        if identity and getattr(method, "children_only", False):
            return method           # called with the stack slice, which is the children
        return make(method)
    return callback


@functools.cache
def passes_child_on(rule: Rule) -> bool:
    """Whether the rule's callback gives its one stack entry back unchanged: a ``?rule``
    with one child (``term: postfix``), or a ``_rule`` of one spliced child.  The
    compiled loop may skip such reductions (``shortcuts``)."""
    plan = ChildPlan.of(rule)
    if plan.size != 1:
        return False
    if _callback_name(rule).startswith("_"):
        return plan.kept == ((0, True, 0),) and not plan.nones_after
    return bool(rule.options.expand1) and not rule.alias and plan.is_identity()


def _callback_name(rule: Rule) -> str:
    return rule.alias or rule.options.template_source or rule.origin.name


def children_only(method):
    """Marks a lowering method that reads only the children (``entries`` may be left
    out): a rule whose stack slice is its children calls it with no function between."""
    method.children_only = True
    return method


def _passing_on(plan: ChildPlan) -> Optional[Callback]:
    """A built-in function for a ``_rule`` whose children are its stack slice (a copy of
    it serves) or one spliced entry, or None."""
    if plan.is_identity():
        return list
    if len(plan.kept) == 1 and plan.kept[0][1:] == (True, 0) and not plan.nones_after:
        return itemgetter(plan.kept[0][0])
    return None


def _method(lowering, name: str):
    return getattr(lowering, name, None) or _missing(name)


def _inlining(select: Callback, method, enclose) -> Callback:
    def inline(entries: list):
        children = select(entries)
        if len(children) != 1:
            return method(children, entries)
        child = children[0]
        if len(entries) > 1:
            enclose(child, entries)
        return child
    return inline


def _missing(name: str):
    def fail(children, entries):
        raise AssertionError(f"no lowering for grammar rule '{name}'")
    return fail
