"""Which data can matter to a check: a cone-of-influence analysis over the routines.

A data object is *relevant* when its value can influence, directly or
through other data, something the check observes:

* control flow (IF, WHILE, FOR and TEST conditions and bounds, compact IF);
* any call (predefined or user routine): every argument counts, because a
  call may do I/O, wait, order interrupts, move the robot or raise;
* RETURN, RAISE, CONNECT and every statement the analysis does not know;
* the atoms of the properties checked (any data an atom names);
* whether a statement raises a run-time error: an expression the analysis
  cannot prove *total* (never raising, see ``Totality``) makes every
  data object it reads relevant, and so does every array index;
* data written by environment code (its reaction runs after every step;
  a change there must stay visible to deadlock detection).

An assignment ``x := e`` whose ``e`` is total only passes influence on:
the data ``e`` reads are relevant when ``x`` is (``Incr x`` and the other
numeric updates are read as their assignments, ``numeric_updates``).  The result is the least
set closed under these rules; every other value-typed data object of the
program and of its tasks (never parameters, FOR variables or temporaries)
is *sliced*: no relevant computation reads it and no computation that reads
it can fail, choose or wait, so it can be dropped from stored states
without changing any verdict.  Sliced data is read only by such total
assignments ``x := e`` to sliced data (``Slicing.total_writes``): a step
whose state is then projected may skip them (``semantics.fused_step``).

Names resolve as the linker resolves them (``routine.scope``); a name it
cannot resolve (a FOR variable, system data) never denotes sliceable data.
The analysis is flow-insensitive and keeps data whenever in doubt.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterable, Iterator, Optional

from ... import ast
from ...semantics.program import ENVIRONMENT_NAMESPACE, Program
from ...semantics.scope import GLOBAL_DATA, LOCAL_DATA, Symbol
from ...semantics.types import ArrayType, RapidType
from .counters import NO_COUNTERS, Counters
from .numeric_updates import as_assignment
from .totality import Totality

# A data key: ("G", slot) for global data, ("L", routine index, slot) for routine data.
Key = tuple

# Routines that reach data by its name at run time: with them nothing is sliced.
DATA_BY_NAME = frozenset({"GETDATAVAL", "SETDATAVAL", "SETALLDATAVAL", "GETNEXTSYM"})

_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@dataclass(frozen=True)
class Slicing:
    """The data dropped from stored states: global slots and, per routine, local slots."""

    globals: tuple[int, ...]
    locals: dict                     # routine index -> tuple of local slots
    # the spans of the assignments ``x := e`` to sliced data named directly whose ``e``
    # is total: skipped, they change only sliced values
    total_writes: frozenset = frozenset()
    # the sliced data that only shape moves' targets (``move_shaping``): sliced on the
    # assumption that their arithmetic stays within num's range, each (name, span)
    move_shaping: tuple = ()
    # the sliced counters that only fill bytes sent (``sent_counters``), each (name, span),
    # and the rawbytes data they are packed into, whose contents the projection resets
    sent_counters: tuple = ()
    sent_bytes: frozenset = frozenset()
    # ((file, line) of a sliced counter's guard, (file, line) in its body): the reduced
    # search decides the guard on the reset value, so it says nothing of the body's reach
    # (``counters``); coverage counts the body reached where the guard ran
    undecided_lines: frozenset = frozenset()

    @property
    def empty(self) -> bool:
        return not self.globals and not any(self.locals.values())


NO_SLICING = Slicing((), {})


def atom_keys_of(atom_texts: Iterable[str]) -> set[str]:
    """Every identifier in the atoms, upper case (the names they may read)."""
    return {token.upper() for text in atom_texts for token in _IDENTIFIER.findall(text)}


def find_slicing(program: Program, atom_texts: Iterable[str] = (),
                 moves_unobserved: bool = False, counters: Counters = NO_COUNTERS) -> Slicing:
    """The data no check of ``program`` against atoms ``atom_texts`` can observe;
    ``moves_unobserved``: the check leaves the robot's position out (moves do not change
    the state), so data that only shapes moves' targets is sliced too, on the assumption
    ``move_shaping`` states; ``counters``: indices proven in bounds and the guards that
    wrap them (``counters``), which pass their data on instead of being observed."""
    analysis = _Analysis(program, counters)
    if not analysis.run():
        return NO_SLICING
    atom_keys = atom_keys_of(atom_texts)
    analysis.observe(atom_keys)
    relevant = analysis.closure()
    shaping = set()
    if moves_unobserved:
        from .move_shaping import MoveShaping   # (a refinement of this module's analysis)
        moves = MoveShaping(program)
        if moves.run():
            moves.observe(atom_keys)
            shaping = relevant - moves.closure()
            relevant = relevant - shaping
    sent, sent_bytes = _sent_counters(program, atom_keys, relevant)
    relevant = relevant - sent
    sliced_globals = tuple(
        data.slot for data in program.globals
        if ("G", data.slot) not in relevant and data.key not in atom_keys
        and data.namespace != ENVIRONMENT_NAMESPACE and is_value(data.type))
    sliced_locals = {}
    for routine in program.routines:
        slots = tuple(slot for slot in routine_data(routine)
                      if ("L", routine.index, slot) not in relevant
                      and routine.local_names[slot].upper() not in atom_keys)
        if slots:
            sliced_locals[routine.index] = slots
    sliced = {("G", slot) for slot in sliced_globals} | \
        {("L", routine, slot) for routine, slots in sliced_locals.items() for slot in slots}
    total_writes = frozenset(span for span, key in analysis.total_writes.items()
                             if key in sliced)
    undecided = frozenset((guard, line) for slot, guard, line in counters.arm_lines
                          if ("G", slot) in sliced)
    return Slicing(sliced_globals, sliced_locals, total_writes,
                   tuple(_named(program, key) for key in sorted(shaping & sliced)),
                   tuple(_named(program, key) for key in sorted(sent & sliced)),
                   sent_bytes, undecided)


def _sent_counters(program: Program, atom_keys: set[str], relevant: set) -> tuple:
    """(the ``relevant`` counters that only fill bytes sent, the rawbytes data they are
    packed into): ``sent_counters``."""
    from .sent_counters import SentCounters   # (a refinement of this module's analysis)
    analysis = SentCounters(program)
    if not analysis.sent_bytes or not analysis.run():
        return set(), frozenset()
    analysis.observe(atom_keys)
    found = {key for key in analysis.sent_counters()
             if not any(_data_key(program, into) in atom_keys for into in analysis.packed[key])}
    counters = (found - analysis.closure()) & relevant
    return counters, frozenset(into for key in counters for into in analysis.packed[key])


def _data_key(program: Program, key: Key) -> str:
    """The upper-case name of the data ``key`` stands for (as atoms name it)."""
    if key[0] == "G":
        return program.globals[key[1]].key
    return program.routines[key[1]].local_names[key[2]].upper()


def _named(program: Program, key: Key) -> tuple:
    """(name, declaration span) of sliced data: ``h``, or ``Place.x`` for routine data."""
    if key[0] == "G":
        data = program.globals[key[1]]
        return data.name, data.span
    routine = program.routines[key[1]]
    return f"{routine.name}.{routine.local_names[key[2]]}", routine.span


def is_value(rapid_type) -> bool:
    if isinstance(rapid_type, ArrayType):
        rapid_type = rapid_type.element
    return isinstance(rapid_type, RapidType) and rapid_type.is_value


def routine_data(routine) -> list[int]:
    """Local slots that may be reset: routine VAR data (not parameters, FOR, temporaries)."""
    decl: ast.Routine = routine.ast
    slots = []
    for data in decl.data:
        symbol = routine.scope.names.get(data.name.key)
        if symbol is not None and symbol.kind == LOCAL_DATA and symbol.storage == "VAR" \
                and is_value(symbol.type):
            slots.append(symbol.slot)
    return slots


class Resolver:
    """Data keys of the names written in one routine, resolved as the linker does."""

    def __init__(self, routine):
        self.routine = routine

    def symbol(self, name: ast.Name) -> Optional[Symbol]:
        return self.routine.scope.lookup(name.key)

    def key(self, name: ast.Name) -> Optional[Key]:
        symbol = self.symbol(name)
        if symbol is None:
            return None
        if symbol.kind == GLOBAL_DATA:
            return ("G", symbol.slot)
        if symbol.kind == LOCAL_DATA:
            return ("L", self.routine.index, symbol.slot)
        return None

    def keys(self, node) -> set:
        """Every data key ``node`` reads or passes."""
        return {key for key in map(self.key, _names(node)) if key is not None}

    def by_reference(self, name: ast.Name) -> bool:
        symbol = self.symbol(name)
        return symbol is None or symbol.by_reference or symbol.optional


class _Analysis:
    """Seeds (data that matter by themselves) and flows (target <- sources)."""

    totality_type = Totality        # which expressions never fail

    def __init__(self, program: Program, counters: Counters = NO_COUNTERS):
        self.program = program
        self.counters = counters
        self.relevant: set[Key] = set()
        self.flows: dict[Key, set[Key]] = {}
        self.total_writes: dict = {}     # span of ``x := e`` with ``e`` total -> x's key
        self.routine = None

    # ------------------------------------------------------------- results
    def run(self) -> bool:
        """Analyse every routine; False when the program defeats the analysis."""
        for routine in self.program.routines:
            if routine.ast is None or getattr(routine, "scope", None) is None:
                return False
            self.routine = routine
            self.resolver = Resolver(routine)
            self.totality = self.totality_type(self.symbol)
            decl: ast.Routine = routine.ast
            for data in decl.data:
                for expr in (*data.dims, data.init):
                    self.seed(expr)
            if decl.error is not None:          # ERROR (booked_errnum, ...) reads its data
                for expr in decl.error.numbers or ():
                    self.seed(expr)
            bodies = [decl.body, decl.backward, decl.undo,
                      decl.error.body if decl.error is not None else None]
            for body in bodies:
                if body is None:
                    continue
                for statement in body:
                    if not self.statement(statement):
                        return False
        return True

    def observe(self, keys: set[str]) -> None:
        """Data an atom may name are relevant (and so is everything that flows into them)."""
        for data in self.program.globals:
            if data.key in keys:
                self.relevant.add(("G", data.slot))
        for routine in self.program.routines:
            for slot, name in enumerate(routine.local_names):
                if name.upper() in keys:
                    self.relevant.add(("L", routine.index, slot))

    def closure(self) -> set[Key]:
        """The relevant data: the seeds and everything that flows into them."""
        return self.sources(self.relevant)

    def sources(self, keys) -> set[Key]:
        """``keys`` and every key that flows into them."""
        found = set(keys)
        work = list(found)
        while work:
            for source in self.flows.get(work.pop(), ()):
                if source not in found:
                    found.add(source)
                    work.append(source)
        return found

    # -------------------------------------------------------------- names
    def symbol(self, name: ast.Name) -> Optional[Symbol]:
        return self.resolver.symbol(name)

    def key(self, name: ast.Name) -> Optional[Key]:
        return self.resolver.key(name)

    def keys_read(self, node) -> Iterator[Key]:
        for name in _names(node):
            key = self.key(name)
            if key is not None:
                yield key

    def seed(self, node) -> None:
        if node is not None:
            self.relevant.update(self.keys_read(node))

    # --------------------------------------------------------- statements
    def statement(self, statement) -> bool:
        kind = type(statement).__name__
        if kind == "Assignment":
            self.assignment(statement)
        elif kind == "If" and statement.span in self.counters.guards:
            written = {self.key(inner.target.name) for inner in statement.branches[0].body
                       if isinstance(inner, ast.Assignment)
                       and isinstance(inner.target, ast.NameRef)}
            for inner in statement.branches[0].body:       # Incr x: the counter too
                update = as_assignment(inner, self.routine.scope.lookup)
                if update is not None:
                    written.add(self.key(update.target.name))
            for key in written - {None}:
                self.flows.setdefault(key, set()).update(self.keys_read(
                    statement.branches[0].condition))
            self.block(statement.branches[0].body)
        elif kind in ("If",):
            for branch in statement.branches:
                self.seed(branch.condition)
                self.block(branch.body)
            self.block(statement.else_body)
        elif kind == "CompactIf":
            self.seed(statement.condition)
            self.statement(statement.statement)
        elif kind == "While":
            self.seed(statement.condition)
            self.block(statement.body)
        elif kind == "For":
            for expr in (statement.start, statement.stop, statement.step):
                self.seed(expr)
            self.block(statement.body)
        elif kind == "Test":
            self.seed(statement.subject)
            for case in statement.cases:
                for value in case.values:
                    self.seed(value)
                self.block(case.body)
            self.block(statement.default)
        elif kind in ("Label", "Goto", "Exit", "Retry", "TryNext"):
            pass
        elif kind == "ProcedureCall" and statement.name.key in DATA_BY_NAME:
            return False
        elif kind == "ProcedureCall" and \
                (update := as_assignment(statement, self.routine.scope.lookup)) is not None:
            self.assignment(update)                  # Incr x: x := x + 1
        else:                              # calls, RETURN, RAISE, CONNECT, anything else
            self.seed(statement)
        return True

    def block(self, statements) -> None:
        for statement in statements or ():
            self.statement(statement)

    def assignment(self, statement: ast.Assignment) -> None:
        target = statement.target
        root = target
        bounded = statement.span in self.counters.bounded_writes
        passed: set = set()                # indices proven in bounds: they choose the element
        while isinstance(root, (ast.Index, ast.Component)):
            if isinstance(root, ast.Index):
                for index in root.indices:
                    if bounded:
                        passed.update(self.keys_read(index))
                    else:
                        self.seed(index)   # an index may be out of bounds
            root = root.base
        sources = set(self.keys_read(statement.value)) | passed
        symbol = self.symbol(root.name) if isinstance(root, ast.NameRef) else None
        target_key = self.key(root.name) if symbol is not None else None
        if self.routine.namespace == ENVIRONMENT_NAMESPACE or target_key is None or \
                symbol.by_reference or symbol.optional:
            # the environment's writes, writes through references: keep everything
            self.relevant.update(sources)
            if target_key is not None:
                self.relevant.add(target_key)
            return
        if target is not root or not self.totality.assignable(statement.value, symbol.type):
            # whether the assignment fails depends on them (not on an index in bounds)
            self.relevant.update(sources - passed)
        else:
            self.total_writes[statement.span] = target_key
        if target_key is not None:
            self.flows.setdefault(target_key, set()).update(sources)


def _names(node) -> Iterator[ast.Name]:
    """Every data name a node reads or passes (not routine or component names)."""
    if node is None:
        return
    if isinstance(node, ast.NameRef):
        yield node.name
        return
    if isinstance(node, ast.Component):
        yield from _names(node.base)
        return
    if isinstance(node, ast.FunctionCall):
        for arg in node.args:
            yield from _names(arg)
        return
    if isinstance(node, ast.Argument):
        if node.source is not None:
            yield node.source
        yield from _names(node.value)
        return
    if isinstance(node, (ast.ProcedureCall,)):
        for arg in node.args:
            yield from _names(arg)
        return
    if isinstance(node, (tuple, list)):
        for item in node:
            yield from _names(item)
        return
    fields = getattr(node, "__dataclass_fields__", None)
    if fields is None:
        return
    for field in fields:
        if field in ("span", "name", "label", "trap"):
            continue
        yield from _names(getattr(node, field))
