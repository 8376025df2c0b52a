"""Typed abstract syntax of RAPID programs.

Every node is a frozen dataclass carrying a ``Span``.  The front end
(``rapidmc.syntax``) builds them while Lark's LALR parser reduces, and does
nothing else; name resolution, typing and execution live in
``rapidmc.semantics``.

Identifiers are ``Name`` values: ``text`` keeps the spelling for messages,
``key`` is the canonical (upper-cased) form used for every lookup, because
RAPID is case-insensitive.

Example::

    >>> Name.of("MoveL", Span("a.mod", 3, 5)).key
    'MOVEL'
"""
from __future__ import annotations

from dataclasses import dataclass, field, fields, is_dataclass
from typing import Iterator, Optional, Union


@dataclass(frozen=True, slots=True)
class Span:
    """A position in a source file (1-based line and column)."""

    file: str
    line: int
    column: int
    end_line: int = 0
    end_column: int = 0

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


NO_SPAN = Span("<builtin>", 0, 0)


def canonical(text: str) -> str:
    """The lookup key of a RAPID identifier (RAPID ignores case)."""
    return text.upper()


@dataclass(frozen=True, slots=True)
class Name:
    """An identifier as written, with its canonical key."""

    text: str
    key: str
    span: Span = field(compare=False, hash=False)

    @staticmethod
    def of(text: str, span: Span = NO_SPAN) -> "Name":
        return Name(text, canonical(text), span)

    def __str__(self) -> str:
        return self.text


# --------------------------------------------------------------------------
# Expressions
# --------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class NumLiteral:
    """A numeric literal; ``value`` is an exact int or a float, ``text`` as written."""

    value: Union[int, float]
    text: str
    span: Span


@dataclass(frozen=True, slots=True)
class StringLiteral:
    """A string literal with escapes (``""``, ``\\\\``, ``\\hh``) already decoded."""

    value: str
    span: Span


@dataclass(frozen=True, slots=True)
class BoolLiteral:
    value: bool
    span: Span


@dataclass(frozen=True, slots=True)
class NameRef:
    """A reference to a data object, parameter, constant or signal by name."""

    name: Name
    span: Span


@dataclass(frozen=True, slots=True)
class Index:
    """Array element ``base{i, j}``."""

    base: "Expr"
    indices: tuple["Expr", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Component:
    """Record component ``base.name``."""

    base: "Expr"
    name: Name
    span: Span


@dataclass(frozen=True, slots=True)
class FunctionCall:
    """``name(args)``: a predefined or user function."""

    name: Name
    args: tuple["Argument", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Unary:
    """``op operand`` where op is ``'-'``, ``'+'`` or ``'NOT'``."""

    op: str
    operand: "Expr"
    span: Span


@dataclass(frozen=True, slots=True)
class Binary:
    """``left op right``; op is upper case: ``+ - * / DIV MOD < <= = > >= <> AND OR XOR``."""

    op: str
    left: "Expr"
    right: "Expr"
    span: Span


@dataclass(frozen=True, slots=True)
class Aggregate:
    """``[e1, e2, ...]``: its type comes from the context."""

    items: tuple["Expr", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Placeholder:
    """An editor placeholder such as ``<EXP>``; executing one raises ERR_EXECPHR."""

    kind: str
    span: Span


Expr = Union[
    NumLiteral, StringLiteral, BoolLiteral, NameRef, Index, Component,
    FunctionCall, Unary, Binary, Aggregate, Placeholder,
]


# --------------------------------------------------------------------------
# Arguments of procedure and function calls
# --------------------------------------------------------------------------

REQUIRED = "required"        # expr   or   Name:=expr
OPTIONAL = "optional"        # \Name:=expr
SWITCH = "switch"            # \Name          (no value)
CONDITIONAL = "conditional"  # \Name?Source


@dataclass(frozen=True, slots=True)
class Argument:
    """One argument.

    ``kind`` is one of REQUIRED, OPTIONAL, SWITCH, CONDITIONAL.  ``name`` is
    the parameter name (None for a positional required argument), ``value``
    the expression (None for SWITCH and CONDITIONAL), ``source`` the caller's
    optional parameter passed on by a CONDITIONAL argument.
    """

    kind: str
    name: Optional[Name]
    value: Optional[Expr]
    span: Span
    source: Optional[Name] = None


# --------------------------------------------------------------------------
# Statements
# --------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Assignment:
    target: Expr
    value: Expr
    span: Span


@dataclass(frozen=True, slots=True)
class ProcedureCall:
    name: Name
    args: tuple[Argument, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class LateBindingCall:
    """``%expr% args;``: the string ``expr`` names the procedure at run time."""

    name_expr: Expr
    args: tuple[Argument, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Goto:
    label: Name
    span: Span


@dataclass(frozen=True, slots=True)
class Label:
    name: Name
    span: Span


@dataclass(frozen=True, slots=True)
class Return:
    value: Optional[Expr]
    span: Span


@dataclass(frozen=True, slots=True)
class Raise:
    value: Optional[Expr]
    span: Span


@dataclass(frozen=True, slots=True)
class Exit:
    span: Span


@dataclass(frozen=True, slots=True)
class Retry:
    span: Span


@dataclass(frozen=True, slots=True)
class TryNext:
    span: Span


@dataclass(frozen=True, slots=True)
class Connect:
    """``CONNECT target WITH trap;``"""

    target: Expr
    trap: Name
    span: Span


@dataclass(frozen=True, slots=True)
class IfBranch:
    condition: Expr
    body: tuple["Statement", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class If:
    """IF/ELSEIF/ELSE; ``branches[0]`` is the IF, the rest are ELSEIFs."""

    branches: tuple[IfBranch, ...]
    else_body: Optional[tuple["Statement", ...]]
    span: Span


@dataclass(frozen=True, slots=True)
class CompactIf:
    """``IF cond statement;`` with exactly one simple statement."""

    condition: Expr
    statement: "Statement"
    span: Span


@dataclass(frozen=True, slots=True)
class For:
    variable: Name
    start: Expr
    stop: Expr
    step: Optional[Expr]
    body: tuple["Statement", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class While:
    condition: Expr
    body: tuple["Statement", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class TestCase:
    values: tuple[Expr, ...]
    body: tuple["Statement", ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Test:
    subject: Expr
    cases: tuple[TestCase, ...]
    default: Optional[tuple["Statement", ...]]
    span: Span


@dataclass(frozen=True, slots=True)
class PlaceholderStatement:
    kind: str
    span: Span


Statement = Union[
    Assignment, ProcedureCall, LateBindingCall, Goto, Label, Return, Raise,
    Exit, Retry, TryNext, Connect, If, CompactIf, For, While, Test,
    PlaceholderStatement,
]


# --------------------------------------------------------------------------
# Declarations
# --------------------------------------------------------------------------

VAR = "VAR"
PERS = "PERS"
CONST = "CONST"
IN = "IN"          # parameter without mode keyword: by value
INOUT = "INOUT"

GLOBAL = "GLOBAL"
LOCAL = "LOCAL"
TASK = "TASK"


@dataclass(frozen=True, slots=True)
class TypeRef:
    """A data type named in a declaration or parameter."""

    name: Name
    span: Span


@dataclass(frozen=True, slots=True)
class DataDeclaration:
    """``[LOCAL|TASK] VAR|PERS|CONST type name[{dims}] [:= init];``

    ``dims`` holds one expression per array dimension (empty for scalars).
    """

    storage: str
    scope: str
    type: TypeRef
    name: Name
    dims: tuple[Expr, ...]
    init: Optional[Expr]
    span: Span


@dataclass(frozen=True, slots=True)
class Parameter:
    """One routine parameter.

    ``mode`` is IN, VAR, PERS or INOUT.  ``array_rank`` counts the ``*`` of a
    ``{*,*}`` conformant array (0 for scalars).  Optional parameters have
    ``optional=True``; parameters written ``\\a | b`` share one
    ``alternative_group`` number (None for a parameter outside a group of
    alternatives).  A ``switch`` parameter has ``type.name.key == 'SWITCH'``.
    """

    mode: str
    type: TypeRef
    name: Name
    array_rank: int
    optional: bool
    alternative_group: Optional[int]
    span: Span


@dataclass(frozen=True, slots=True)
class ErrorHandler:
    """``ERROR [(n1, n2)]`` section; ``numbers`` None when no list is given."""

    numbers: Optional[tuple[Expr, ...]]
    body: tuple[Statement, ...]
    span: Span


PROC = "PROC"
FUNC = "FUNC"
TRAP = "TRAP"


@dataclass(frozen=True, slots=True)
class Routine:
    kind: str                      # PROC, FUNC or TRAP
    local: bool
    name: Name
    return_type: Optional[TypeRef]
    parameters: tuple[Parameter, ...]
    data: tuple[DataDeclaration, ...]
    body: tuple[Statement, ...]
    backward: Optional[tuple[Statement, ...]]
    error: Optional[ErrorHandler]
    undo: Optional[tuple[Statement, ...]]
    span: Span
    end_span: Span = NO_SPAN      # position of ENDPROC/ENDFUNC/ENDTRAP


@dataclass(frozen=True, slots=True)
class RecordComponent:
    type: TypeRef
    name: Name
    span: Span


@dataclass(frozen=True, slots=True)
class RecordDefinition:
    local: bool
    name: Name
    components: tuple[RecordComponent, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class AliasDefinition:
    local: bool
    base: TypeRef
    name: Name
    span: Span


TypeDefinition = Union[RecordDefinition, AliasDefinition]


@dataclass(frozen=True, slots=True)
class Module:
    name: Name
    attributes: tuple[str, ...]    # upper case: SYSMODULE, NOSTEPIN, ...
    types: tuple[TypeDefinition, ...]
    data: tuple[DataDeclaration, ...]
    routines: tuple[Routine, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class Program:
    """A task's program: the modules loaded together."""

    modules: tuple[Module, ...]


def children(node) -> tuple:
    """The nodes directly inside ``node`` (fields that are nodes or tuples of nodes)."""
    found = []
    for slot in getattr(type(node), "__slots__", ()):
        value = getattr(node, slot, None)
        if isinstance(value, tuple):
            found.extend(item for item in value if hasattr(item, "__slots__"))
        elif hasattr(value, "__slots__") and not isinstance(value, (Span, Name)):
            found.append(value)
    return tuple(found)


def referenced_names(node) -> frozenset:
    """The keys of every name ``node`` refers to as data or routine (at any depth)."""
    keys = set()
    pending = [node]
    while pending:
        current = pending.pop()
        if isinstance(current, NameRef):
            keys.add(current.name.key)
        elif isinstance(current, (FunctionCall, ProcedureCall)):
            keys.add(current.name.key)
        pending.extend(children(current))
    return frozenset(keys)


STATEMENT_TYPES = Statement.__args__


def names_used(statement) -> list:
    """``(name, use)`` for each name a statement refers to, in source order, without
    looking into the statements nested in it; ``use`` is "data", "function" or "procedure"."""
    found = []
    pending = [statement]
    while pending:
        current = pending.pop()
        if isinstance(current, NameRef):
            found.append((current.name, "data"))
        elif isinstance(current, FunctionCall):
            found.append((current.name, "function"))
        elif isinstance(current, ProcedureCall):
            found.append((current.name, "procedure"))
        pending.extend(child for child in children(current)
                       if not isinstance(child, STATEMENT_TYPES))
    return sorted(found, key=lambda item: (item[0].span.line, item[0].span.column))


def walk(node, parents: tuple = ()) -> Iterator[tuple[object, tuple]]:
    """(node, its ancestors) for every syntax node under ``node`` (itself included), in
    source order; spans and names are leaves, not nodes."""
    yield node, parents
    inner = parents + (node,)
    for f in fields(node):
        yield from _walk_value(getattr(node, f.name), inner)


def _walk_value(value, parents: tuple) -> Iterator[tuple[object, tuple]]:
    if isinstance(value, (tuple, list)):
        for item in value:
            yield from _walk_value(item, parents)
    elif is_dataclass(value) and not isinstance(value, (Span, Name, type)):
        yield from walk(value, parents)
