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
from operator import attrgetter
from typing import Callable, Iterator, Optional, Union

# Node class -> the fields ``==`` compares (and ``hash`` hashes), read as one tuple.
_COMPARED: dict[type, Callable[[object], tuple]] = {}
_SHOWN: dict[type, tuple[str, ...]] = {}


def node(cls: type) -> type:
    """A frozen dataclass with slots, whose ``==``, ``hash`` and ``repr`` are those
    ``dataclass`` would generate for it (same results, same hash values) but shared by
    every node class: generating them per class was half the cost of importing this
    module.  ``dataclasses.fields``, ``replace`` and pattern matching see a dataclass."""
    cls.__eq__, cls.__hash__, cls.__repr__ = _node_eq, _node_hash, _node_repr
    made = dataclass(frozen=True, slots=True, eq=False, repr=False)(cls)
    compared = [f.name for f in fields(made) if f.compare]
    assert compared == [f.name for f in fields(made)
                        if (f.compare if f.hash is None else f.hash)], "hash differs from =="
    _COMPARED[made] = attrgetter(*compared) if len(compared) > 1 else _one_tuple(compared[0])
    _SHOWN[made] = tuple(f.name for f in fields(made) if f.repr)
    return made


def _one_tuple(name: str) -> Callable[[object], tuple]:
    read = attrgetter(name)
    return lambda value: (read(value),)


def _node_eq(self, other):
    if other.__class__ is self.__class__:
        key = _COMPARED[self.__class__]
        return key(self) == key(other)
    return NotImplemented


def _node_hash(self) -> int:
    return hash(_COMPARED[self.__class__](self))


def _node_repr(self) -> str:
    shown = ", ".join(f"{name}={getattr(self, name)!r}" for name in _SHOWN[self.__class__])
    return f"{self.__class__.__qualname__}({shown})"


@node
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


@node
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


@node
class NumLiteral:
    """A numeric literal; ``value`` is an exact int or a float, ``text`` as written."""

    value: Union[int, float]
    text: str
    span: Span


@node
class StringLiteral:
    """A string literal with escapes (``""``, ``\\\\``, ``\\hh``) already decoded."""

    value: str
    span: Span


@node
class BoolLiteral:
    value: bool
    span: Span


@node
class NameRef:
    """A reference to a data object, parameter, constant or signal by name."""

    name: Name
    span: Span


@node
class Index:
    """Array element ``base{i, j}``."""

    base: "Expr"
    indices: tuple["Expr", ...]
    span: Span


@node
class Component:
    """Record component ``base.name``."""

    base: "Expr"
    name: Name
    span: Span


@node
class FunctionCall:
    """``name(args)``: a predefined or user function."""

    name: Name
    args: tuple["Argument", ...]
    span: Span


@node
class Unary:
    """``op operand`` where op is ``'-'``, ``'+'`` or ``'NOT'``."""

    op: str
    operand: "Expr"
    span: Span


@node
class Binary:
    """``left op right``; op is upper case: ``+ - * / DIV MOD < <= = > >= <> AND OR XOR``."""

    op: str
    left: "Expr"
    right: "Expr"
    span: Span


@node
class Aggregate:
    """``[e1, e2, ...]``: its type comes from the context."""

    items: tuple["Expr", ...]
    span: Span


@node
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


@node
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


@node
class Assignment:
    target: Expr
    value: Expr
    span: Span


@node
class ProcedureCall:
    name: Name
    args: tuple[Argument, ...]
    span: Span


@node
class LateBindingCall:
    """``%expr% args;``: the string ``expr`` names the procedure at run time."""

    name_expr: Expr
    args: tuple[Argument, ...]
    span: Span


@node
class Goto:
    label: Name
    span: Span


@node
class Label:
    name: Name
    span: Span


@node
class Return:
    value: Optional[Expr]
    span: Span


@node
class Raise:
    value: Optional[Expr]
    span: Span


@node
class Exit:
    span: Span


@node
class Retry:
    span: Span


@node
class TryNext:
    span: Span


@node
class Connect:
    """``CONNECT target WITH trap;``"""

    target: Expr
    trap: Name
    span: Span


@node
class IfBranch:
    condition: Expr
    body: tuple["Statement", ...]
    span: Span


@node
class If:
    """IF/ELSEIF/ELSE; ``branches[0]`` is the IF, the rest are ELSEIFs."""

    branches: tuple[IfBranch, ...]
    else_body: Optional[tuple["Statement", ...]]
    span: Span


@node
class CompactIf:
    """``IF cond statement;`` with exactly one simple statement."""

    condition: Expr
    statement: "Statement"
    span: Span


@node
class For:
    variable: Name
    start: Expr
    stop: Expr
    step: Optional[Expr]
    body: tuple["Statement", ...]
    span: Span


@node
class While:
    condition: Expr
    body: tuple["Statement", ...]
    span: Span


@node
class TestCase:
    values: tuple[Expr, ...]
    body: tuple["Statement", ...]
    span: Span


@node
class Test:
    subject: Expr
    cases: tuple[TestCase, ...]
    default: Optional[tuple["Statement", ...]]
    span: Span


@node
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


@node
class TypeRef:
    """A data type named in a declaration or parameter."""

    name: Name
    span: Span


@node
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


@node
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


@node
class ErrorHandler:
    """``ERROR [(n1, n2)]`` section; ``numbers`` None when no list is given."""

    numbers: Optional[tuple[Expr, ...]]
    body: tuple[Statement, ...]
    span: Span


PROC = "PROC"
FUNC = "FUNC"
TRAP = "TRAP"


@node
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


@node
class RecordComponent:
    type: TypeRef
    name: Name
    span: Span


@node
class RecordDefinition:
    local: bool
    name: Name
    components: tuple[RecordComponent, ...]
    span: Span


@node
class AliasDefinition:
    local: bool
    base: TypeRef
    name: Name
    span: Span


TypeDefinition = Union[RecordDefinition, AliasDefinition]


@node
class Module:
    name: Name
    attributes: tuple[str, ...]    # upper case: SYSMODULE, NOSTEPIN, ...
    types: tuple[TypeDefinition, ...]
    data: tuple[DataDeclaration, ...]
    routines: tuple[Routine, ...]
    span: Span


@node
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


def statement_lists(statements: tuple) -> Iterator[tuple]:
    """``statements`` and every statement list nested in them (IF, ELSEIF and ELSE bodies,
    FOR and WHILE bodies, TEST cases and DEFAULT), in source order."""
    yield tuple(statements)
    for statement in statements:
        for node, _ in walk(statement):
            for name in ("body", "else_body", "default"):
                inner = getattr(node, name, None)
                if isinstance(inner, tuple) and not isinstance(node, Routine):
                    yield inner


def walk(node, parents: tuple = ()) -> Iterator[tuple[object, tuple]]:
    """(node, its ancestors) for every syntax node under ``node`` (itself included), in
    source order; spans and names are leaves, not nodes."""
    # Depth first with a stack of pending nodes, the next one last: every analysis walks
    # the program, and a generator per node and per field cost a fifth of a check's time.
    pending = [(node, parents)]
    while pending:
        current, above = pending.pop()
        yield current, above
        inner = above + (current,)
        found: list = []
        for name in _field_names(type(current)):
            _collect_nodes(getattr(current, name), inner, found)
        found.reverse()
        pending.extend(found)


# class -> its dataclass field names, or None for a class that is not a node to walk into
_FIELD_NAMES: dict[type, Optional[tuple[str, ...]]] = {}


def _field_names(kind: type) -> tuple[str, ...]:
    names = _walked_fields(kind)
    if names is None:
        return tuple(f.name for f in fields(kind))      # (raises for a non-dataclass)
    return names


def _walked_fields(kind: type) -> Optional[tuple[str, ...]]:
    try:
        return _FIELD_NAMES[kind]
    except KeyError:
        walked = (is_dataclass(kind) and not issubclass(kind, (Span, Name, type)))
        names = tuple(f.name for f in fields(kind)) if walked else None
        _FIELD_NAMES[kind] = names
        return names


def _collect_nodes(value, parents: tuple, found: list) -> None:
    if isinstance(value, (tuple, list)):
        for item in value:
            _collect_nodes(item, parents, found)
    elif _walked_fields(type(value)) is not None:
        found.append((value, parents))
