"""LTL formulas: the abstract syntax and a parser for Spot's LTL syntax.

Precedence follows Spot's grammar (``parsetl.yy``), weakest first:

=====================  ==========================  ===============
operators              spellings                   associativity
=====================  ==========================  ===============
implication, equiv.    ``->`` ``=>`` ``<->`` ``<=>``  right
or                     ``|`` ``||``                left
exclusive or           ``xor`` ``^``               left
and                    ``&`` ``&&``                left
U W R M                                            right
unary                  ``!`` ``~`` ``G`` ``F`` ``X`` ``[]`` ``<>``
=====================  ==========================  ===============

Atoms are double-quoted strings (``"c_in = 0 AND s1 = 1"``, the text inside
kept verbatim, ``\\"`` and ``\\\\`` escaped) or bare identifiers (letters,
digits, ``_``, ``.``, not starting with a digit).  An identifier is read as
a whole, so ``Go`` is an atom while ``G o`` is ``G`` applied to ``o``; a word
made only of the unary operator letters ``F G X`` is those operators, so
``GF p`` is ``G F p``.

Example::

    >>> parse_formula('G(a -> F "x = 1")')
    Globally(operand=Implies(left=Atom(name='a'), right=Finally(operand=Atom(name='x = 1'))))
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Union

from ..ast import Span
from ..diagnostics import LTL_SYNTAX, error


# --------------------------------------------------------------------------
# Abstract syntax
# --------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Atom:
    name: str


@dataclass(frozen=True, slots=True)
class TrueF:
    pass


@dataclass(frozen=True, slots=True)
class FalseF:
    pass


@dataclass(frozen=True, slots=True)
class Not:
    operand: "Formula"


@dataclass(frozen=True, slots=True)
class Next:
    operand: "Formula"


@dataclass(frozen=True, slots=True)
class Globally:
    operand: "Formula"


@dataclass(frozen=True, slots=True)
class Finally:
    operand: "Formula"


@dataclass(frozen=True, slots=True)
class And:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Or:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Implies:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Equiv:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Xor:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Until:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class WeakUntil:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class Release:
    left: "Formula"
    right: "Formula"


@dataclass(frozen=True, slots=True)
class StrongRelease:
    """Spot's ``M``: ``a M b`` is ``b U (a & b)``."""

    left: "Formula"
    right: "Formula"


Unary = Union[Not, Next, Globally, Finally]
Binary = Union[And, Or, Implies, Equiv, Xor, Until, WeakUntil, Release, StrongRelease]
Formula = Union[Atom, TrueF, FalseF, Unary, Binary]

UNARY_TYPES = (Not, Next, Globally, Finally)
BINARY_TYPES = (And, Or, Implies, Equiv, Xor, Until, WeakUntil, Release, StrongRelease)


PROPOSITIONAL_TYPES = (Atom, TrueF, FalseF, Not, And, Or, Implies, Equiv, Xor)


def is_propositional(formula: Formula) -> bool:
    """Whether ``formula`` speaks of one state only (no temporal operator in it)."""
    if not isinstance(formula, PROPOSITIONAL_TYPES):
        return False
    if isinstance(formula, Not):
        return is_propositional(formula.operand)
    if isinstance(formula, BINARY_TYPES):
        return is_propositional(formula.left) and is_propositional(formula.right)
    return True


def atoms_of(formula: Formula) -> tuple[str, ...]:
    """The atom names of ``formula`` in order of first appearance (left to right)."""
    seen: dict[str, None] = {}
    stack = [formula]
    while stack:
        node = stack.pop()
        if isinstance(node, Atom):
            seen.setdefault(node.name, None)
        elif isinstance(node, UNARY_TYPES):
            stack.append(node.operand)
        elif isinstance(node, BINARY_TYPES):
            stack.append(node.right)
            stack.append(node.left)
    return tuple(seen)


# --------------------------------------------------------------------------
# Tokens
# --------------------------------------------------------------------------

KEYWORDS = {"G": "G", "F": "F", "X": "X", "U": "U", "R": "R", "W": "W", "M": "M",
            "true": "true", "false": "false", "xor": "xor"}

SYMBOLS = [  # longest spellings first
    ("<->", "<->"), ("<=>", "<->"), ("->", "->"), ("=>", "->"), ("<>", "F"), ("[]", "G"),
    ("&&", "&"), ("||", "|"), ("&", "&"), ("|", "|"), ("^", "xor"), ("!", "!"), ("~", "!"),
    ("(", "("), (")", ")"), ("1", "true"), ("0", "false"),
]

IDENTIFIER = re.compile(r"[A-Za-z_.][A-Za-z0-9_.]*")
UNARY_RUN = re.compile(r"[FGX]+")
NUMBER = re.compile(r"[0-9]+")


@dataclass(frozen=True, slots=True)
class Token:
    kind: str      # operator kind, "atom", or "end"
    text: str      # atom name (decoded) or the spelling
    offset: int    # index into the formula text
    length: int


def tokenize(text: str, where: "_Locator") -> list[Token]:
    tokens: list[Token] = []
    i = 0
    while i < len(text):
        char = text[i]
        if char.isspace():
            i += 1
        elif char == '"':
            token = _quoted_atom(text, i, where)
            tokens.append(token)
            i += token.length
        elif IDENTIFIER.match(text, i):
            word = IDENTIFIER.match(text, i).group()
            tokens.extend(_word_tokens(word, i))
            i += len(word)
        else:
            number = NUMBER.match(text, i)
            if number and number.group() not in ("0", "1"):
                raise where.error(f"'{number.group()}' is not a formula (only 0 and 1 are constants)",
                                  i, len(number.group()))
            for spelling, kind in SYMBOLS:
                if text.startswith(spelling, i):
                    tokens.append(Token(kind, spelling, i, len(spelling)))
                    i += len(spelling)
                    break
            else:
                raise where.error(f"unexpected character {char!r} in formula", i, 1)
    tokens.append(Token("end", "", len(text), 0))
    return tokens


def _word_tokens(word: str, offset: int) -> list[Token]:
    """A keyword, an atom, or (like Spot) a run of unary operators such as ``GF``."""
    if UNARY_RUN.fullmatch(word):
        return [Token(letter, letter, offset + k, 1) for k, letter in enumerate(word)]
    return [Token(KEYWORDS.get(word, "atom"), word, offset, len(word))]


def _quoted_atom(text: str, start: int, where: "_Locator") -> Token:
    name: list[str] = []
    i = start + 1
    while i < len(text):
        char = text[i]
        if char == "\\" and i + 1 < len(text) and text[i + 1] in '"\\':
            name.append(text[i + 1])
            i += 2
        elif char == '"':
            return Token("atom", "".join(name), start, i + 1 - start)
        else:
            name.append(char)
            i += 1
    raise where.error("unterminated quoted atom", start, len(text) - start)


# --------------------------------------------------------------------------
# Parser (precedence climbing)
# --------------------------------------------------------------------------


class _Locator:
    """Turns offsets in the formula text into spans of the enclosing file."""

    def __init__(self, text: str, file: str, line: int, column: int):
        self.text, self.file, self.line, self.column = text, file, line, column

    def span(self, offset: int, length: int) -> Span:
        before = self.text[:offset]
        line = self.line + before.count("\n")
        if "\n" in before:
            column = offset - before.rfind("\n")
        else:
            column = self.column + offset
        return Span(self.file, line, column, line, column + max(length, 1))

    def error(self, message: str, offset: int, length: int):
        return error(LTL_SYNTAX, message, self.span(offset, length))


UNARY_OPERATORS = {"!": Not, "G": Globally, "F": Finally, "X": Next}
TEMPORAL_BINARY = {"U": Until, "W": WeakUntil, "R": Release, "M": StrongRelease}
IMPLICATIONS = {"->": Implies, "<->": Equiv}


class _Parser:
    def __init__(self, tokens: list[Token], where: _Locator):
        self.tokens, self.where, self.position = tokens, where, 0

    @property
    def current(self) -> Token:
        return self.tokens[self.position]

    def advance(self) -> Token:
        token = self.current
        self.position += 1
        return token

    def formula(self) -> Formula:
        left = self.disjunction()
        if self.current.kind in IMPLICATIONS:
            node = IMPLICATIONS[self.advance().kind]
            return node(left, self.formula())
        return left

    def disjunction(self) -> Formula:
        return self._left_associative("|", Or, self.exclusive_or)

    def exclusive_or(self) -> Formula:
        return self._left_associative("xor", Xor, self.conjunction)

    def conjunction(self) -> Formula:
        return self._left_associative("&", And, self.temporal)

    def _left_associative(self, kind: str, node, operand) -> Formula:
        left = operand()
        while self.current.kind == kind:
            self.advance()
            left = node(left, operand())
        return left

    def temporal(self) -> Formula:
        left = self.unary()
        if self.current.kind in TEMPORAL_BINARY:
            node = TEMPORAL_BINARY[self.advance().kind]
            return node(left, self.temporal())
        return left

    def unary(self) -> Formula:
        if self.current.kind in UNARY_OPERATORS:
            node = UNARY_OPERATORS[self.advance().kind]
            return node(self.unary())
        return self.primary()

    def primary(self) -> Formula:
        token = self.advance()
        if token.kind == "atom":
            return Atom(token.text)
        if token.kind == "true":
            return TrueF()
        if token.kind == "false":
            return FalseF()
        if token.kind == "(":
            inner = self.formula()
            if self.current.kind != ")":
                raise self._unexpected(self.current, f"expected ')' to close the '(' at column "
                                                     f"{self.where.span(token.offset, 1).column}")
            self.advance()
            return inner
        raise self._unexpected(token, "expected a formula")

    def _unexpected(self, token: Token, expectation: str):
        found = "the end of the formula" if token.kind == "end" else f"'{token.text}'"
        return self.where.error(f"{expectation}, found {found}", token.offset, token.length)


def parse_formula(text: str, file: str = "<formula>", line: int = 1, column: int = 1) -> Formula:
    """Parse ``text`` in Spot's LTL syntax; errors are ``UserError`` [LTL_SYNTAX].

    ``file``, ``line`` and ``column`` say where ``text`` starts, so that
    diagnostics point into the file the formula came from.
    """
    where = _Locator(text, file, line, column)
    parser = _Parser(tokenize(text, where), where)
    formula = parser.formula()
    if parser.current.kind != "end":
        raise parser._unexpected(parser.current, "expected an operator or the end of the formula")
    return formula
