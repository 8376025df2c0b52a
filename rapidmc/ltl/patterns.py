"""Specification patterns: properties written without LTL, translated to LTL.

The patterns and scopes of Dwyer, Avrunin and Corbett ("Patterns in Property
Specifications for Finite-State Verification", ICSE 1999), written as a call
and an optional scope after it::

    response(!C_IN & S_1 & S_2, S_3 & !S_4)          # globally, as P1 of the sorter
    absence(AtLine(42)) between(door_open, door_closed)

=========================  =================================================
pattern                    meaning (arguments in the order they happen)
=========================  =================================================
``absence(P)``             P never holds
``existence(P)``           P holds at some point
``universality(P)``        P always holds
``precedence(S, P)``       S precedes P: P does not hold before S has held
``response(P, S)``         S responds to P: every P is followed by S (then or later)
=========================  =================================================

Scopes: ``globally`` (the default), ``before(R)`` (up to the first R),
``after(Q)`` (from the first Q on), ``between(Q, R)`` (each stretch from a Q
to the next R, when that R comes) and ``after_until(Q, R)`` (each stretch
from a Q to the next R, or to the end when no R comes).  The arguments are
conditions on one state: LTL formulas without temporal operators, so atoms
(``C_IN``, ``"x > 3"``, ``InRoutine("Grip")``) joined by ``!``, ``&``,
``|``, ``->``.  The translation is the catalogue's LTL mapping for each
pattern and scope (``pattern_formula``); a malformed pattern is RMC860.

Example::

    >>> from rapidmc.ltl.printing import to_text
    >>> to_text(pattern_formula(parse_pattern("response(req, ack) after_until(on, off)")))
    'G (on & !off -> (req -> !off U (ack & !off)) W off)'
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable

from ..diagnostics import PATTERN, error
from .printing import to_text
from .syntax import (And, Finally, Formula, Globally, Implies, Not, Or, Until, WeakUntil,
                     _Locator, is_propositional, parse_formula)

# pattern -> the names of its arguments, in the order they are written
PATTERNS = {"absence": ("P",), "existence": ("P",), "universality": ("P",),
            "precedence": ("S", "P"), "response": ("P", "S")}
SCOPES = {"globally": (), "before": ("R",), "after": ("Q",), "between": ("Q", "R"),
          "after_until": ("Q", "R")}

_START = re.compile(r"\s*(" + "|".join(PATTERNS) + r")\s*\(", re.IGNORECASE)
_WORD = re.compile(r"\s*([A-Za-z_]+)")


@dataclass(frozen=True)
class Pattern:
    """A pattern with its scope; ``arguments`` and ``bounds`` (Q, R) as formulas."""

    kind: str
    arguments: tuple[Formula, ...]
    scope: str = "globally"
    bounds: tuple[Formula, ...] = ()

    def __str__(self) -> str:
        call = f"{self.kind}({', '.join(to_text(f) for f in self.arguments)})"
        if not self.bounds:
            return f"{call} {self.scope}"
        return f"{call} {self.scope}({', '.join(to_text(f) for f in self.bounds)})"


def is_pattern(text: str) -> bool:
    """Whether ``text`` is written as a pattern (it starts with a pattern's name and '(';
    no LTL formula does)."""
    return _START.match(text) is not None


def parse_pattern(text: str, file: str = "<formula>", line: int = 1,
                  column: int = 1) -> Pattern:
    """The pattern written in ``text``; errors point into the file (RMC860, or RMC401
    inside an argument)."""
    where = _Locator(text, file, line, column)
    kind, arguments, end = _call(text, 0, where, PATTERNS)
    scope, bounds = "globally", []
    word = _WORD.match(text, end)
    if word is not None:
        scope = word.group(1).lower()
        if scope == "globally":
            end = word.end()
        else:
            scope, bounds, end = _call(text, end, where, SCOPES)
    if text[end:].strip():
        offset = end + len(text[end:]) - len(text[end:].lstrip())
        raise _error(where, "expected a scope (globally, before(R), after(Q), "
                     "between(Q, R), after_until(Q, R)) or the end of the pattern",
                     offset, len(text) - offset)
    return Pattern(kind, tuple(arguments), scope, tuple(bounds))


def _error(where: _Locator, message: str, offset: int, length: int):
    return error(PATTERN, message, where.span(offset, length))


def _call(text: str, start: int, where: _Locator, known: dict) -> tuple[str, list, int]:
    """``name(argument, ...)`` at ``start``: the name (lower case), the arguments as
    formulas, and where the call ends."""
    word = _WORD.match(text, start)
    name = word.group(1).lower() if word else ""
    if name not in known:
        offset = word.start(1) if word else start
        choices = ", ".join(known)
        raise _error(where, f"expected one of {choices}", offset,
                     len(word.group(1)) if word else 1)
    opening = len(text) - len(text[word.end():].lstrip())
    if not text.startswith("(", opening):
        raise _error(where, f"expected '(' after {word.group(1)}", opening, 1)
    pieces, end = _arguments(text, opening, where)
    expected = known[name]
    if len(pieces) != len(expected):
        raise _error(where, f"{name} takes {len(expected)} condition"
                     f"{'s' * (len(expected) != 1)} ({', '.join(expected)}), "
                     f"found {len(pieces)}", word.start(1), end - word.start(1))
    return name, [_condition(piece, offset, where) for piece, offset in pieces], end


def _arguments(text: str, opening: int, where: _Locator) -> tuple[list, int]:
    """The comma-separated texts (and their offsets) between ``(`` at ``opening`` and its
    ``)``, and the offset after the ``)``; quoted atoms may hold commas and parentheses."""
    pieces, depth, quoted, piece_start, i = [], 0, False, opening + 1, opening + 1
    while i < len(text):
        char = text[i]
        if quoted:
            if char == "\\":
                i += 1
            elif char == '"':
                quoted = False
        elif char == '"':
            quoted = True
        elif char == "(":
            depth += 1
        elif char == ")" and depth:
            depth -= 1
        elif char in ",)":
            if text[piece_start:i].strip() or char == "," or pieces:
                pieces.append((text[piece_start:i], piece_start))
            if char == ")":
                return pieces, i + 1
            piece_start = i + 1
        i += 1
    raise _error(where, "expected ')' to close the '('", opening, 1)


def _condition(piece: str, offset: int, where: _Locator) -> Formula:
    """One argument: a formula without temporal operators."""
    lead = len(piece) - len(piece.lstrip())
    if not piece.strip():
        raise _error(where, "expected a condition", offset, max(len(piece), 1))
    span = where.span(offset + lead, 1)
    formula = parse_formula(piece.strip(), where.file, span.line, span.column)
    if not is_propositional(formula):
        raise _error(where, "a pattern's conditions hold in one state: write "
                     "no temporal operator (X F G U W R M) in them",
                     offset + lead, len(piece.strip()))
    return formula


# --- the catalogue's LTL mappings ----------------------------------------------------------

def _between(q: Formula, r: Formula) -> Formula:
    """``Q & !R & F R``: a stretch that opens at Q and closes at a later R."""
    return And(And(q, Not(r)), Finally(r))


def _opened(q: Formula, r: Formula) -> Formula:
    """``Q & !R``: a stretch opens at Q (and may never close)."""
    return And(q, Not(r))


# (pattern, scope) -> fn(P or S..., Q, R) -> formula; the arguments as the pattern names them
MAPPINGS: dict[tuple[str, str], Callable[..., Formula]] = {
    ("absence", "globally"): lambda p, q, r: Globally(Not(p)),
    ("absence", "before"): lambda p, q, r: Implies(Finally(r), Until(Not(p), r)),
    ("absence", "after"): lambda p, q, r: Globally(Implies(q, Globally(Not(p)))),
    ("absence", "between"): lambda p, q, r: Globally(Implies(_between(q, r), Until(Not(p), r))),
    ("absence", "after_until"):
        lambda p, q, r: Globally(Implies(_opened(q, r), WeakUntil(Not(p), r))),
    ("existence", "globally"): lambda p, q, r: Finally(p),
    ("existence", "before"): lambda p, q, r: WeakUntil(Not(r), And(p, Not(r))),
    ("existence", "after"):
        lambda p, q, r: Or(Globally(Not(q)), Finally(And(q, Finally(p)))),
    ("existence", "between"):
        lambda p, q, r: Globally(Implies(_opened(q, r), WeakUntil(Not(r), And(p, Not(r))))),
    ("existence", "after_until"):
        lambda p, q, r: Globally(Implies(_opened(q, r), Until(Not(r), And(p, Not(r))))),
    ("universality", "globally"): lambda p, q, r: Globally(p),
    ("universality", "before"): lambda p, q, r: Implies(Finally(r), Until(p, r)),
    ("universality", "after"): lambda p, q, r: Globally(Implies(q, Globally(p))),
    ("universality", "between"): lambda p, q, r: Globally(Implies(_between(q, r), Until(p, r))),
    ("universality", "after_until"):
        lambda p, q, r: Globally(Implies(_opened(q, r), WeakUntil(p, r))),
    ("precedence", "globally"): lambda s, p, q, r: WeakUntil(Not(p), s),
    ("precedence", "before"): lambda s, p, q, r: Implies(Finally(r), Until(Not(p), Or(s, r))),
    ("precedence", "after"):
        lambda s, p, q, r: Or(Globally(Not(q)), Finally(And(q, WeakUntil(Not(p), s)))),
    ("precedence", "between"):
        lambda s, p, q, r: Globally(Implies(_between(q, r), Until(Not(p), Or(s, r)))),
    ("precedence", "after_until"):
        lambda s, p, q, r: Globally(Implies(_opened(q, r), WeakUntil(Not(p), Or(s, r)))),
    ("response", "globally"): lambda p, s, q, r: Globally(Implies(p, Finally(s))),
    ("response", "before"):
        lambda p, s, q, r: Implies(Finally(r), Until(_answered_before(p, s, r), r)),
    ("response", "after"):
        lambda p, s, q, r: Globally(Implies(q, Globally(Implies(p, Finally(s))))),
    ("response", "between"):
        lambda p, s, q, r: Globally(Implies(_between(q, r), Until(_answered_before(p, s, r), r))),
    ("response", "after_until"):
        lambda p, s, q, r: Globally(Implies(_opened(q, r),
                                            WeakUntil(_answered_before(p, s, r), r))),
}


def _answered_before(p: Formula, s: Formula, r: Formula) -> Formula:
    """``P -> (!R U (S & !R))``: a P here is answered by an S before the next R."""
    return Implies(p, Until(Not(r), And(s, Not(r))))


def pattern_formula(pattern: Pattern) -> Formula:
    """The pattern's LTL formula (the catalogue's mapping for its scope)."""
    bounds = dict(zip(SCOPES[pattern.scope], pattern.bounds))
    return MAPPINGS[(pattern.kind, pattern.scope)](*pattern.arguments, bounds.get("Q"),
                                                  bounds.get("R"))
