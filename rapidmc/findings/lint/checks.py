"""What counts as a check of a datum: a comparison that bounds it.

A datum is *compared* by a condition that holds ``<``, ``<=``, ``>``, ``>=`` or ``=``
with the datum on either side (or a TEST of it).  A use is *checked* when a condition
around it compares the datum, or an earlier IF of its routine compares it and the
branch for that comparison *handles* it: leaves the routine (RETURN, RAISE, EXIT ...)
or gives the datum a new value, so what follows runs only with a bounded value.
RMC809 (shared indices), RMC820 (flows) and ``check --flows``'s marks share it.
"""
from __future__ import annotations

from ... import ast
from .context import subexpressions
from .unreachable import ends_block

COMPARISONS = ("<", "<=", ">", ">=", "=")


def compares(condition, key: str) -> bool:
    """Does ``condition`` compare the data ``key`` (on either side) with something?"""
    if type(condition) is ast.Test:
        return any(type(e) is ast.NameRef and e.name.key == key
                   for e in subexpressions(condition.subject))
    return key in compared_names(condition)


def compared_names(condition) -> set[str]:
    """The keys of the data a condition compares."""
    found = set()
    for expression in subexpressions(condition):
        if type(expression) is ast.Binary and expression.op in COMPARISONS:
            for side in (expression.left, expression.right):
                found.update(e.name.key for e in subexpressions(side) if type(e) is ast.NameRef)
    return found


def handles(body, key: str) -> bool:
    """Does a branch deal with an out-of-bounds datum ``key``: leave, or assign it whole?"""
    if body and ends_block(body[-1]):
        return True
    return any(type(s) is ast.Assignment and type(s.target) is ast.NameRef
               and s.target.name.key == key for s in body)


def checked(context, site, key: str) -> bool:
    """Is the datum ``key`` checked where ``site`` uses it?"""
    if any(compares(guard, key) for guard in site.guards):
        return True
    line = _leaving_checks(context, site.routine).get(key)
    return line is not None and line < site.statement.span.line


def _leaving_checks(context, routine) -> dict[str, int]:
    """Datum key -> the line of the first IF of ``routine`` that compares it in a branch
    that handles it (computed once per routine)."""
    table = context.memo.setdefault("leaving_checks", {})
    found = table.get(id(routine))
    if found is None:
        found = {}
        for site in context.sites_by_routine.get(id(routine), ()):
            statement = site.statement
            if type(statement) is ast.CompactIf:
                branches = ((statement.condition, (statement.statement,)),)
            elif type(statement) is ast.If:
                branches = tuple((b.condition, b.body) for b in statement.branches)
            else:
                continue
            for condition, body in branches:
                for key in compared_names(condition):
                    if key not in found and handles(body, key):
                        found[key] = statement.span.line
        table[id(routine)] = found
    return found
