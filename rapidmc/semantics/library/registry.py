"""The registry of predefined RAPID routines and their signatures.

Each entry pairs a ``Signature`` (parsed once, from a RAPID-like declaration
string, when the routine is first looked up: a check looks up the few it
calls, not the six hundred the library registers) with a plain Python
implementation::

    @function("num Round(num Val \\\\num Dec)")
    def round_num(val, dec): ...

    @procedure("Incr(INOUT anynum Name)")
    def incr(name): return {"Name": name + 1}

Signature strings follow RAPID's parameter-list syntax: a function starts
with its return type, parameters are ``[VAR|PERS|INOUT|REF] type name
[{*}]`` separated by commas; ``\\`` makes a parameter optional, ``\\switch
Name`` declares a switch, ``\\a | b | c`` is a group of mutually exclusive
optional parameters and ``a | b`` (without backslash) a group of required
alternatives of which exactly one must be given (SetGO's ``Value | Dvalue``).
Type names: any RAPID type, ``anytype`` (every type) and ``anynum`` (num
or dnum).  The comma before a ``\\`` parameter may be left out.  ``(...)``
declares a routine whose parameter list rapidmc has no evidence for (it
knows the name from ABB's reference only): calls with any arguments load,
their arguments are not matched to parameters (``Signature.open_parameters``),
and the entry's factory must not bind them (``arguments.unknown_parameters``).

Calling convention (what the interpreter does after binding arguments):

* ``entry.impl(*args)`` with exactly one Python value per declared
  parameter, in declaration order: the argument's value, ``None`` for an
  absent optional parameter (and for the unused members of an alternative
  group), ``True``/``False`` for a switch.  By-reference parameters
  (VAR, PERS, INOUT, REF) receive the current value of the referenced data.
* A function returns its value.  A procedure returns ``None`` or a dict
  mapping the *name as written in the signature* (``"Name"``) of each
  by-reference parameter it changes to the new value; the interpreter
  stores it back through the reference.
* Recoverable failures raise ``RapidError``.
* Routines with an ``anynum`` parameter whose result depends on whether
  the argument is num or dnum (Incr, Add, TryInt, BitSet ...) also carry
  ``dnum_impl``; the interpreter picks ``entry.implementation(type_name)``
  once, at link time, from the static type of that argument (the first
  anynum parameter).  Results are already rounded to the chosen type.
* Routines that read or change the program state (I/O, motion, the
  FlexPendant, clocks, interrupts ...) have ``impl=None`` and a ``factory``
  instead, registered with ``@compiled(signature, ...)``: the factory
  receives each call site once, at link time (already checked against the
  signature), and returns a compiled closure (functions) or an
  instruction (procedures)::

      @compiled("Set(VAR signaldo Signal)", "Reset(VAR signaldo Signal)")
      def set_or_reset(calls, compiler, call, entry): ...

* Every entry says how rapidmc models it (``modelled``): ``EXACT`` (the
  documented result or effect), ``CHOICE`` (the controller or the world
  decides: each outcome is a nondeterministic choice), ``ROBOT_STATE``
  (only the modelled robot position, tool, work object or load change),
  ``FIXED`` (a function whose controller-dependent result is one fixed
  value, e.g. the date), ``NO_EFFECT`` (checked against its signature,
  changes nothing rapidmc observes) or ``NOT_MODELLED`` (the program loads;
  reaching the call stops with RMC305).  docs/predefined.md lists them (``rapidmc.semantics.library.documentation``).

Lookups are by canonical (upper-case) name: ``lookup_function("ROUND")``.
"""
from __future__ import annotations

import importlib
import re
import sys
from dataclasses import dataclass
from typing import Callable, Iterator, NamedTuple, Optional

from ... import ast
from ..values import DNUM, NUM, NumericKind

FUNCTION = "function"
PROCEDURE = "procedure"

IN, VAR, PERS, INOUT, REF = "IN", "VAR", "PERS", "INOUT", "REF"
MODES = (VAR, PERS, INOUT, REF)


def mode_may_write(mode: Optional[str]) -> bool:
    """Whether an argument bound to a parameter of ``mode`` may be written by the call.
    REF is the manuals' reference that a predefined routine only reads (``Present``,
    ``Dim``, a ``TaskRef``, WaitSyncTask's task list); an unknown mode (None: a routine
    not declared) may write."""
    return mode is None or mode.upper() not in (IN, REF)
ANYTYPE = "anytype"
ANYNUM = "anynum"
SWITCH = "switch"

# How a predefined routine is modelled (docs/predefined.md)
EXACT = "exact"
CHOICE = "nondeterministic outcomes"
ROBOT_STATE = "robot state only"
NO_EFFECT = "no effect"
FIXED = "fixed value"
NOT_MODELLED = "stops the run: not modelled"
MODELLED_AS = (EXACT, CHOICE, ROBOT_STATE, FIXED, NO_EFFECT, NOT_MODELLED)


def matched_parameters(args, parameters) -> Iterator[tuple]:
    """(argument, its parameter or None) for a call's arguments: a positional one takes the
    next required parameter, a named one (``\\Name:=`` or ``Name:=``) the parameter of that
    name.  ``parameters``: objects with ``key`` and ``optional`` (a ``ParameterSpec``, a
    user routine's ``Parameter``)."""
    required = [p for p in parameters if not p.optional]
    position = 0
    for arg in args:
        if arg.kind == ast.REQUIRED and arg.name is None:
            yield arg, required[position] if position < len(required) else None
            position += 1
        else:
            key = arg.name.key if arg.name is not None else None
            yield arg, next((p for p in parameters if p.key == key), None)


class SignatureSyntaxError(ValueError):
    """A malformed signature string (a bug in a registration, not user input)."""


@dataclass(frozen=True, slots=True)
class ParameterSpec:
    """One declared parameter of a predefined routine.

    ``type_name`` as written (lower case: ``num``, ``anytype``, ``anynum``,
    ``switch``); ``accepted_types`` the type names an argument may have
    (empty for anytype); ``alternative_group`` numbers a ``|`` group within
    the signature (None outside groups); ``array_rank`` counts the ``*`` of
    ``{*}``/``{*,*}``.
    """

    name: str
    key: str
    type_name: str
    mode: str
    optional: bool
    alternative_group: Optional[int]
    array_rank: int

    @property
    def is_switch(self) -> bool:
        return self.type_name == SWITCH

    @property
    def by_reference(self) -> bool:
        return self.mode != IN

    @property
    def accepted_types(self) -> tuple[str, ...]:
        if self.type_name == ANYTYPE:
            return ()
        if self.type_name == ANYNUM:
            return ("num", "dnum")
        return (self.type_name,)


@dataclass(frozen=True, slots=True)
class Signature:
    """Name, kind, return type and parameters of a predefined routine."""

    name: str
    key: str
    kind: str                       # FUNCTION or PROCEDURE
    return_type: Optional[str]      # None for procedures
    parameters: tuple[ParameterSpec, ...]
    open_parameters: bool = False   # ``(...)``: the parameter list is not known

    def parameter(self, key: str) -> Optional[ParameterSpec]:
        """The parameter with canonical name ``key``, or None."""
        for spec in self.parameters:
            if spec.key == key:
                return spec
        return None

    @property
    def required(self) -> tuple[ParameterSpec, ...]:
        """Parameters that take positional arguments (not optional)."""
        return tuple(p for p in self.parameters if not p.optional)


@dataclass(frozen=True, slots=True)
class RoutineEntry:
    """A registered predefined routine."""

    signature: Signature
    impl: Optional[Callable[..., object]]
    special: bool = False
    dnum_impl: Optional[Callable[..., object]] = None
    factory: Optional[Callable[..., object]] = None
    modelled: str = EXACT
    topic: str = ""                 # the library module that defines it

    @property
    def key(self) -> str:
        return self.signature.key

    def implementation(self, numeric_type: str = "num") -> Optional[Callable[..., object]]:
        """The implementation for an anynum argument of type ``numeric_type``."""
        if numeric_type == "dnum" and self.dnum_impl is not None:
            return self.dnum_impl
        return self.impl


# canonical name -> entry (a ``_Declared`` until first looked up: see ``_entry``)
FUNCTIONS: dict[str, "RoutineEntry | _Declared"] = {}
PROCEDURES: dict[str, "RoutineEntry | _Declared"] = {}


# --------------------------------------------------------------------------
# Signature parsing
# --------------------------------------------------------------------------

_TOKEN = re.compile(r"\s*(?:(?P<word>[A-Za-z_][A-Za-z0-9_]*)|(?P<array>\{\s*\*(?:\s*,\s*\*)*\s*\})"
                    r"|(?P<punct>[\\|,()]|\.\.\.))")
OPEN = "..."


def _tokens(text: str) -> list[str]:
    tokens, position = [], 0
    text = text.rstrip()
    while position < len(text):
        match = _TOKEN.match(text, position)
        if not match:
            raise SignatureSyntaxError(f"bad character at {position} in {text!r}")
        tokens.append(match.group(match.lastgroup))
        position = match.end()
    return tokens


class _Parser:
    """Recursive descent over the tokens of one signature string."""

    def __init__(self, text: str):
        self.text = text
        self.tokens = _tokens(text)
        self.index = 0
        self.groups = 0

    def peek(self) -> Optional[str]:
        return self.tokens[self.index] if self.index < len(self.tokens) else None

    def take(self, expected: Optional[str] = None) -> str:
        token = self.peek()
        if token is None or (expected is not None and token != expected):
            raise SignatureSyntaxError(f"expected {expected or 'more'} in {self.text!r}")
        self.index += 1
        return token

    def word(self) -> str:
        token = self.take()
        if not re.match(r"[A-Za-z_]", token):
            raise SignatureSyntaxError(f"expected a name, got {token!r} in {self.text!r}")
        return token

    def signature(self) -> Signature:
        first = self.word()
        if self.peek() == "(":
            return_type, name = None, first
        else:
            return_type, name = first.lower(), self.word()
        self.take("(")
        parameters: list[ParameterSpec] = []
        open_parameters = self.peek() == OPEN
        if open_parameters:
            self.take(OPEN)
        while self.peek() != ")":
            if parameters and self.peek() == ",":
                self.take(",")
            parameters.extend(self.group())
        self.take(")")
        if self.peek() is not None:
            raise SignatureSyntaxError(f"text after ')' in {self.text!r}")
        if open_parameters and parameters:
            raise SignatureSyntaxError(f"'...' stands for the whole parameter list in {self.text!r}")
        kind = PROCEDURE if return_type is None else FUNCTION
        return Signature(name, name.upper(), kind, return_type, tuple(parameters),
                         open_parameters)

    def group(self) -> list[ParameterSpec]:
        optional = self.peek() == "\\"
        if optional:
            self.take("\\")
        members = [self.parameter(optional)]
        while self.peek() == "|":
            self.take("|")
            if optional and self.peek() == "\\":
                self.take("\\")
            members.append(self.parameter(optional))
        if len(members) == 1:
            return members
        self.groups += 1
        return [_with_group(m, self.groups) for m in members]

    def parameter(self, optional: bool) -> ParameterSpec:
        mode = IN
        if self.peek() is not None and self.peek().upper() in MODES:
            mode = self.take().upper()
        type_name = self.word().lower()
        name = self.word()
        rank = 0
        if self.peek() is not None and self.peek().startswith("{"):
            rank = self.take().count("*")
        if type_name == SWITCH and not optional:
            raise SignatureSyntaxError(f"switch {name} must be optional in {self.text!r}")
        return ParameterSpec(name, name.upper(), type_name, mode, optional, None, rank)


def _with_group(spec: ParameterSpec, group: int) -> ParameterSpec:
    return ParameterSpec(spec.name, spec.key, spec.type_name, spec.mode, spec.optional,
                         group, spec.array_rank)


def parse_signature(text: str) -> Signature:
    """Parse a RAPID-like routine declaration.

    >>> s = parse_signature("num Round(num Val \\\\num Dec)")
    >>> s.key, s.return_type, [(p.name, p.optional) for p in s.parameters]
    ('ROUND', 'num', [('Val', False), ('Dec', True)])
    """
    return _Parser(text).signature()


# --------------------------------------------------------------------------
# Registration and lookup
# --------------------------------------------------------------------------


def register(text: str, impl: Optional[Callable[..., object]], special: bool = False,
             dnum_impl: Optional[Callable[..., object]] = None,
             factory: Optional[Callable[..., object]] = None, modelled: str = EXACT,
             topic: str = "") -> RoutineEntry:
    """Add one routine; a second registration of a name is a bug."""
    table, key = _declare(_Declared(text, impl, special, dnum_impl, factory, modelled, topic))
    try:
        return _entry(table, key)           # parsed now: a bad signature is refused here
    except SignatureSyntaxError:
        del table[key]
        raise


class _Declared(NamedTuple):
    """A registered routine whose signature is not parsed yet (``register``'s arguments)."""

    text: str
    impl: Optional[Callable[..., object]]
    special: bool
    dnum_impl: Optional[Callable[..., object]]
    factory: Optional[Callable[..., object]]
    modelled: str
    topic: str


# what registering needs of a signature before it is parsed: its name, and whether a
# return type comes first (a function) or the name is followed by "(" (a procedure)
_HEAD = re.compile(r"\s*([A-Za-z_][A-Za-z0-9_]*)\s*(?:\(|([A-Za-z_][A-Za-z0-9_]*)\s*\()")


def _declare(declared: _Declared) -> tuple[dict, str]:
    """Check what can be checked without parsing the signature and file the routine
    under its name; the table and the key."""
    head = _HEAD.match(declared.text)
    if head is None:
        parse_signature(declared.text)            # raises the syntax error
        raise SignatureSyntaxError(f"expected a routine name in {declared.text!r}")
    name = head.group(2) or head.group(1)
    if declared.impl is None and not declared.special:
        raise SignatureSyntaxError(f"{name} has no implementation and is not special")
    if OPEN in declared.text and declared.factory is None:
        raise SignatureSyntaxError(f"{name}: an open parameter list needs a factory")
    if declared.modelled not in MODELLED_AS:
        raise SignatureSyntaxError(f"{name}: unknown modelling {declared.modelled!r}")
    table = FUNCTIONS if head.group(2) else PROCEDURES
    key = name.upper()
    if key in table:
        raise SignatureSyntaxError(f"{name} registered twice")
    table[key] = declared
    return table, key


def _entry(table: dict, key: str) -> Optional[RoutineEntry]:
    """The entry filed under ``key``, its signature parsed on first use."""
    found = table.get(key)
    if type(found) is _Declared:
        signature = parse_signature(found.text)
        if signature.key != key or (table is FUNCTIONS) != (signature.kind == FUNCTION):
            raise SignatureSyntaxError(f"{found.text!r} does not parse as it was filed")
        found = table[key] = RoutineEntry(signature, *found[1:])
    return found


def _topic(code: Callable) -> str:
    return code.__module__.rsplit(".", 1)[-1]


def function(text: str) -> Callable[[Callable[..., object]], Callable[..., object]]:
    """Decorator: register a predefined function with signature ``text``."""
    def decorate(impl: Callable[..., object]) -> Callable[..., object]:
        table, _ = _declare(_Declared(text, impl, False, None, None, EXACT, _topic(impl)))
        if table is not FUNCTIONS:
            raise SignatureSyntaxError(f"{text!r} declares no return type")
        return impl
    return decorate


def procedure(text: str) -> Callable[[Callable[..., object]], Callable[..., object]]:
    """Decorator: register a predefined procedure (instruction) with signature ``text``."""
    def decorate(impl: Callable[..., object]) -> Callable[..., object]:
        table, _ = _declare(_Declared(text, impl, False, None, None, EXACT, _topic(impl)))
        if table is not PROCEDURES:
            raise SignatureSyntaxError(f"{text!r} declares a return type")
        return impl
    return decorate


def numeric(text: str) -> Callable[[Callable[[NumericKind], Callable[..., object]]], object]:
    """Decorator for a factory ``make(kind)`` of a routine with an anynum parameter.

    ``make(NUM)`` becomes ``impl`` and ``make(DNUM)`` becomes ``dnum_impl``::

        @numeric("Incr(INOUT anynum Name)")
        def incr(kind):
            return lambda name: {"Name": kind.convert(name + 1)}
    """
    def decorate(make: Callable[[NumericKind], Callable[..., object]]) -> object:
        _declare(_Declared(text, make(NUM), False, make(DNUM), None, EXACT, _topic(make)))
        return make
    return decorate


def compiled(*texts: str, modelled: str = EXACT) -> Callable:
    """Decorator: register routines whose calls ``factory`` compiles (they use the state).

    ``factory(calls, compiler, call, entry)`` returns a ``Compiled`` closure for a
    function, an ``Instruction`` for a procedure; several signatures may share it, and
    a shared factory (``no_effect``, ``fixed(value)``) may come from another module:
    the topic is the module that registers.
    """
    topic = sys._getframe(1).f_globals["__name__"].rsplit(".", 1)[-1]

    def decorate(factory: Callable[..., object]) -> Callable[..., object]:
        for text in texts:
            _declare(_Declared(text, None, True, None, factory, modelled, topic))
        return factory
    return decorate


_loaded = False


def _load() -> None:
    """Import the topic modules once; importing registers their routines."""
    global _loaded
    if not _loaded:
        _loaded = True
        from . import TOPICS
        for topic in TOPICS:
            importlib.import_module(f"{__package__}.{topic}")


def lookup_function(key: str) -> Optional[RoutineEntry]:
    """The predefined function with canonical name ``key``, or None."""
    if not _loaded:
        _load()
    return _entry(FUNCTIONS, key)


def lookup_procedure(key: str) -> Optional[RoutineEntry]:
    """The predefined procedure with canonical name ``key``, or None."""
    if not _loaded:
        _load()
    return _entry(PROCEDURES, key)


def all_entries() -> Iterator[RoutineEntry]:
    """Every registered routine, functions first, each group in name order."""
    _load()
    for table in (FUNCTIONS, PROCEDURES):
        for key in sorted(table):
            yield _entry(table, key)
