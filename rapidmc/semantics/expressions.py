"""Type checking of RAPID expressions and their compilation into closures.

``ExpressionCompiler.value(expr, expected)`` returns a ``Compiled``: a
function ``fn(machine) -> value`` plus the static type (None when it cannot
be known statically).  Compiling once into closures, instead of walking the
AST at every step, is what makes the step function fast.

Calls of user FUNCs cannot run inside one step (a function body takes
steps), so they are *hoisted*: the statement compiler provides ``hoist``,
which emits a call instruction before the statement and gives back the
frame slot where the result will be; the expression just reads that slot.
"""
from __future__ import annotations

import itertools
import operator
from dataclasses import dataclass, replace
from typing import Any, Callable, Optional

from .. import ast
from ..diagnostics import (ARGUMENT, NOT_A_REFERENCE, TYPE_MISMATCH, UNKNOWN_NAME,
                           UNKNOWN_ROUTINE, error)
from . import values
from .errors import RapidError, placeholder_reached
from .index_reads import reads_only_index
from .instructions import called_from_wait
from .machine import ABSENT, GLOBAL, read_at, replace_at
from .wait_outcomes import WaitRead, by_outcome, note_writes
from .scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE, SIGNAL, Symbol
from .types import (ATOMIC, BOOL, DNUM, NUM, ORIENT, POS, RECORD, SEMI_VALUE, STRING, AnyType,
                    ArrayType, RapidType, is_numeric, same_type)

# a whole array of data written from outside is chosen element by element up to this many
# combinations of values (ExpressionCompiler._outside_whole); a larger one keeps its value,
# but in a wait or a poll, where up to WAIT_CHOICES are tried (the wait keeps the state it
# tried only where it ends, so the successors stay few); beyond that the assumption says so
WHOLE_ARRAY_CHOICES = 64
WAIT_CHOICES = 4096
# a WaitUntil's reads of outside data compared with constants choose one value per outcome
# (``wait_outcomes``; off: every value, the reference the differential tests compare with)
BY_OUTCOME = True

NOT_CONSTANT = object()


@dataclass
class Compiled:
    """A compiled expression: ``fn(machine)`` computes it; ``type`` is static (or None)."""

    fn: Callable[[Any], Any]
    type: Optional[AnyType]
    constant: Any = NOT_CONSTANT
    # the same computation as a Python expression for fused steps (``fused_step``), over
    # ``store``, ``locals_`` and the signal reader's context ``cx``; None when not available
    source: Optional[str] = None
    names: Optional[dict] = None          # the values the source names (constants)
    # a read of data written from outside that chooses afresh and stores nothing
    # (``ExpressionCompiler._outside_read_as``): (the stored read, the choice's name, its
    # domain), so that a comparison with a constant can choose among fewer values
    # (``decisive_read``)
    free_choice: Optional[tuple] = None
    # a wait's read of outside data that stores what it takes (``_outside_read_as``):
    # what a comparison with a constant needs to choose per outcome (``wait_outcomes``)
    wait_read: Optional[WaitRead] = None

    @property
    def is_constant(self) -> bool:
        return self.constant is not NOT_CONSTANT


_CONSTANT_NAMES = itertools.count()


def constant(value: Any, rapid_type: Optional[AnyType]) -> Compiled:
    name = f"_k{next(_CONSTANT_NAMES)}"
    return Compiled(lambda m: value, rapid_type, value, name, {name: value})


def with_source(compiled: Compiled, template: str, *operands: Compiled) -> Compiled:
    """``compiled`` with the source ``template`` filled with the operands' sources,
    when every operand has one (``template`` computes what ``compiled.fn`` does, in
    the same order, with the same helpers: see ``fused_step.HELPERS``)."""
    if any(operand.source is None for operand in operands):
        return compiled
    names = {}
    for operand in operands:
        names.update(operand.names)
    compiled.source = template.format(*(operand.source for operand in operands))
    compiled.names = names
    return compiled


def type_name(t: Optional[AnyType]) -> str:
    return "unknown" if t is None else str(t)


def _num_result(fn: Callable, both_num: bool) -> Callable:
    return fn


def _check_index(value: tuple, index: float, span: ast.Span) -> int:
    if index != index or index != int(index):
        raise RapidError("ERR_OUTOFBND", f"array index {values.format_num(index)} is not an integer")
    i = int(index)
    if not 1 <= i <= len(value):
        raise RapidError("ERR_OUTOFBND", f"array index {i} outside 1..{len(value)}")
    return i - 1


def _binary(combine: Callable, left: Compiled, right: Compiled) -> Callable:
    """``fn(m) = combine(left(m), right(m))``; a constant right operand is not called."""
    lf = left.fn
    if right.is_constant:
        value = right.constant
        return lambda m: combine(lf(m), value)
    rf = right.fn
    return lambda m: combine(lf(m), rf(m))


# the sources of the operators (``with_source``; ROUND: the arithmetic's rounding)
COMPARISON_SOURCES = {"=": "({0} == {1})", "<>": "({0} != {1})", "<": "({0} < {1})",
                      "<=": "({0} <= {1})", ">": "({0} > {1})", ">=": "({0} >= {1})"}
LOGICAL_SOURCES = {"AND": "bool({0} & {1})", "OR": "bool({0} | {1})", "XOR": "({0} != {1})"}
ARITHMETIC_SOURCES = {"+": "ROUND({0} + {1})", "-": "ROUND({0} - {1})",
                      "*": "ROUND({0} * {1})", "/": "ROUND(_divide({0}, {1}))",
                      "DIV": "_int_div({0}, {1})", "MOD": "_int_mod({0}, {1})"}

# operators with a variable left and a constant right operand that ``_constant_right`` serves
ARITHMETIC = ("+", "-", "*", "DIV", "MOD")


def _constant_right(op: str, lf: Callable, value, round_: Callable) -> Callable:
    """``lf(m) op value``, rounded as the general arithmetic rounds (the common
    ``n + 1``, ``n MOD k``: one call less per evaluation)."""
    if op == "+":
        return lambda m: round_(lf(m) + value)
    if op == "-":
        return lambda m: round_(lf(m) - value)
    if op == "*":
        return lambda m: round_(lf(m) * value)
    if op == "DIV":
        return lambda m: values.int_div(lf(m), value)
    return lambda m: values.int_mod(lf(m), value)


def _bound_signal_reader(slot: int) -> Callable:
    """The value of the signal that global signal data in ``slot`` is bound to
    (``read_signal`` of the slot's value, in one call)."""
    def read_bound_signal(m):
        index = m.store[slot]
        if index < 0:
            return read_signal(m, index)
        return m.io[index]
    return read_bound_signal


def read_signal(m, index: int) -> float:
    if index < 0:
        raise RapidError("ERR_NO_ALIASIO_DEF", "the signal data is not connected to a signal (AliasIO)")
    return m.io[index]


def _component_positions(record_type, names: tuple) -> Optional[tuple]:
    """The positions of the components ``names`` (upper-case) inside a value of
    ``record_type``, or None when the types do not have them."""
    positions = []
    for key in names:
        components = getattr(record_type, "components", None) or ()
        index = next((i for i, c in enumerate(components) if c.key == key), None)
        if index is None:
            return None
        positions.append(index)
        record_type = components[index].type
    return tuple(positions)


def free_read(stored: Callable, name: str, domain: tuple, rapid_type) -> Compiled:
    """A read of data written from outside that takes any value of ``domain``, chosen
    afresh and stored nowhere; ``stored`` reads the stored value for its own errors (an
    index out of range)."""
    def chosen(m):
        stored(m)
        return m.choose(name, domain)
    return Compiled(chosen, rapid_type, free_choice=(stored, name, domain))


def decisive_read(compare: Callable, left: Compiled, right: Compiled) -> tuple:
    """The operands of ``compare`` (a comparison), where one is a ``free_read`` and the other
    a constant: the read chooses only the first value of its domain for each outcome of
    the comparison.  Its value goes nowhere but into the comparison, so every value left
    out gives the same outcome, and the step the same successor, as the one kept (the
    labels differ: a counterexample names the value kept)."""
    for read, other, flipped in ((left, right, False), (right, left, True)):
        if read.free_choice is None or not other.is_constant:
            continue
        stored, name, domain = read.free_choice
        value = other.constant
        try:
            outcomes = {}
            for candidate in domain:
                outcome = compare(value, candidate) if flipped else compare(candidate, value)
                outcomes.setdefault(outcome, candidate)
        except (RapidError, TypeError):
            return left, right
        kept = tuple(outcomes.values())          # (in the domain's order)
        if len(kept) == len(domain):
            return left, right
        narrowed = free_read(stored, name, kept, read.type)
        return (other, narrowed) if flipped else (narrowed, other)
    return left, right


def _varying_leaves(value_type, outside, path: tuple) -> list:
    """(positions in a value of ``value_type``, ``.component`` names, domain, the component's
    path in the data object) of each value component under ``path`` of outside data
    (``load.outside_data``) whose reads may take several values."""
    leaves = []
    for leaf_path, domain in outside.domains.items():
        if leaf_path[:len(path)] != path or domain is None or len(domain) < 2:
            continue
        positions = _component_positions(value_type, leaf_path[len(path):])
        if positions is not None:
            leaves.append((positions, "".join("." + p.lower() for p in leaf_path[len(path):]),
                           domain, leaf_path))
    return leaves


ORDERS_KEPT = 256        # stored values whose choice order one read remembers


def stored_first(domain: tuple) -> Callable:
    """fn(stored) -> the values a wait's read of data another party writes too may take:
    the stored value first, then the others of ``domain``.  The order is the order of the
    successors: a shortest counterexample then shows the value the data kept (the command
    a wait before saw) wherever that value alone leads there, not one the other party
    wrote again.  Each order is made once per stored value (a wait reads at every poll)."""
    orders: dict = {}

    def order(stored) -> tuple:
        found = orders.get(stored)
        if found is None:
            found = (stored,) + tuple(value for value in domain if value != stored)
            if len(orders) < ORDERS_KEPT:
                orders[stored] = found
        return found
    return order


class ExpressionCompiler:
    """Compiles expressions in one scope (a routine body, a data initialiser, an atom)."""

    def __init__(self, linker, scope, *, hoist=None, constant_only: bool = False,
                 routine=None):
        self.linker = linker
        self.scope = scope
        self.hoist = hoist                  # callable(FunctionCall, routine) -> slot, or None
        self.constant_only = constant_only  # CONST/VAR initialisers: no variables, no calls
        self.routine = routine
        self.io_reader = None               # callable noting that the code reads signals
        self.choice_noter = None            # callable noting a read of outside data that chooses
        self.in_wait = False                # compiling a WaitUntil or polling condition (_outside_read)
        # a read compiled while ``in_wait`` chose a value another writer wrote and stores it
        # (``_outside_read``; WaitUntil keeps it only where the wait ends: library.waits)
        self.wait_choices = False
        # compiling a WaitUntil's condition: the list its reads by outcome note what they
        # chose in (``wait_outcomes``), else None
        self.wait_outcomes: Optional[list] = None
        # user FUNC call node (id) -> the slot of its hoisted result: an expression compiled
        # twice (a read and the reference it stores to) calls the function once
        self._hoisted: dict[int, int] = {}
        # expression node (id) whose value indexes an array -> that dimension's length: a read
        # of outside data there takes only that array's indexes (``_outside_index``)
        self.index_lengths: dict[int, int] = {}

    def note_io_read(self, index: Optional[int] = None) -> None:
        """The code reads signal ``index`` (None: one not known at compile time)."""
        if self.io_reader is not None:
            self.io_reader(index)

    # ------------------------------------------------------------------ entry
    def value(self, expr: ast.Expr, expected: Optional[AnyType] = None) -> Compiled:
        method = getattr(self, "_" + type(expr).__name__)
        compiled = method(expr, expected)
        if self.routine is not None and self.linker.outside_data and \
                isinstance(expr, (ast.NameRef, ast.Component, ast.Index)):
            read = self._outside_read(expr, compiled)
            if read is not compiled and self.choice_noter is not None:
                self.choice_noter()
            compiled = read
        if expected is not None and compiled.type is not None:
            self.check_assignable(compiled.type, expected, expr.span)
            compiled = self.convert(compiled, expected)
        return compiled

    def base_value(self, expr: ast.Expr) -> Compiled:
        """The record or array a component or element is read from: compiled as ``value``
        does, but never a read of outside data of its own (the component or element read
        makes the one choice, ``_outside_read``)."""
        return getattr(self, "_" + type(expr).__name__)(expr, None)

    def _outside_read(self, expr, compiled: Compiled) -> Compiled:
        """A read of outside data (``_outside_read_as``).  In a FUNC, which a WaitUntil or
        polling condition may call, the read is the one such a condition makes when the
        function runs for one (``called_from_wait``), else the one of other code."""
        plain = self._outside_read_as(expr, compiled)
        if self.in_wait or getattr(self.routine, "kind", None) != "FUNC":
            return plain
        saved = self.wait_choices
        self.in_wait = True
        try:
            waited = self._outside_read_as(expr, compiled)
        finally:
            self.in_wait = False
            self.wait_choices = saved
        if waited is plain or waited.fn is plain.fn:
            return plain
        in_wait, other = waited.fn, plain.fn
        return Compiled(lambda m: in_wait(m) if called_from_wait(m) else other(m), plain.type)

    def _outside_read_as(self, expr, compiled: Compiled) -> Compiled:
        """A read of a value component of PERS data written from outside the loaded code
        (``load.outside_data``): any value of its domain, chosen afresh by each read, as
        the outside may write between any two (merged steps expand read by read); data a
        wait reads as well changes only in waits (``load.waited_data``), as data the loaded
        code writes too does: a wait's read chooses and stores, others read it.  A read
        of a whole record (``target``, ``rec.sub``) takes its components' choices together
        (``_outside_whole``), a whole array its elements' likewise."""
        whole_array = isinstance(compiled.type, ArrayType)
        if not whole_array and (not isinstance(compiled.type, RapidType) or
                                compiled.type.kind not in (ATOMIC, RECORD)):
            return compiled
        path, indexed, node = [], False, expr
        while isinstance(node, (ast.Component, ast.Index)):
            if isinstance(node, ast.Component):
                path.append(node.name.key)
            else:
                indexed = True
            node = node.base
        if not isinstance(node, ast.NameRef):
            return compiled
        symbol = self.scope.lookup(node.name.key)
        if symbol is None or symbol.kind != GLOBAL_DATA:
            return compiled
        outside = self.linker.outside_data.get(symbol.slot)
        if outside is None:
            return compiled
        path = tuple(reversed(path))
        name = symbol.name + "".join("." + part.lower() for part in path)
        if whole_array:
            array_type = compiled.type
            if any(d is None for d in array_type.dims):
                return compiled
            elements = list(itertools.product(*(range(d) for d in array_type.dims)))
            return self._outside_whole(expr, compiled, outside, path, name,
                                       array_type.element, elements)
        domain = outside.domain(path)
        if domain is None and compiled.type.kind != RECORD:
            return compiled
        name += "{*}" if indexed else ""
        if compiled.type.kind == RECORD:
            return self._outside_whole(expr, compiled, outside, path, name, compiled.type, [()])
        stored = compiled.fn
        if outside.stored_by_waits(path):
            if not self.in_wait:
                return compiled          # elsewhere the value stored (the last wait's)
            # a wait or a poll: the value stored, or one the other writer wrote just
            # before; a value it wrote stays, so the code after the wait or in the loop's
            # body reads what the condition saw (data only the outside writes that a wait
            # reads changes only there: ``load.waited_data``)
            # (the reference's indexes are evaluated once: the value is read through it)
            ref_fn = self.reference(expr, "read")[0]
            self.wait_choices = True
            ordered = stored_first(domain)
            pending = self.wait_outcomes

            def either(m):
                ref = ref_fn(m)
                value = m.read_ref(ref)
                taken = m.choose(name, ordered(value))
                if taken != value:
                    m.write_ref(ref, taken)
                note_writes(pending, ref, ((),))
                return taken
            return Compiled(either, compiled.type,
                            wait_read=WaitRead(ref_fn, [((), name, domain, ordered, True)]))

        if outside.observed:
            # a property names it: the value taken is stored, for the atoms to read
            ref_fn = self.reference(expr, "read")[0]

            def kept(m):
                ref = ref_fn(m)          # (the stored read's own errors: an index out of range)
                taken = m.choose(name, domain)
                if taken != m.read_ref(ref):
                    m.write_ref(ref, taken)
                return taken
            return Compiled(kept, compiled.type)

        length = self.index_lengths.get(id(expr))
        if length is not None and outside.written_by_tasks is None:
            domain = self._outside_index(domain, length, outside.slot, expr.span)
        return free_read(stored, name, domain, compiled.type)

    def outside_read_only_as_index(self, expr) -> bool:
        """Whether ``expr`` reads data that the routine compiled reads only as whole array
        indexes (``index_reads``; a routine that also tests it races with its writer)."""
        root = expr
        while isinstance(root, (ast.Component, ast.Index)):
            root = root.base
        routine_ast = getattr(self.routine, "ast", None)
        if not isinstance(root, ast.NameRef) or routine_ast is None:
            return False
        symbol = self.scope.lookup(root.name.key)
        if symbol is None or symbol.kind != GLOBAL_DATA or \
                symbol.slot not in self.linker.outside_data:
            return False
        memo = self.linker.index_only_reads
        key = (id(routine_ast), root.name.key)
        if key not in memo:
            memo[key] = reads_only_index(routine_ast, root.name.key)
        return memo[key]

    def _outside_index(self, domain: tuple, length: int, slot: int, span) -> tuple:
        """The values of ``domain`` a read of outside data takes where its value indexes an
        array of ``length`` elements (directly, or through a local that only indexes:
        ``statements``): the whole numbers 1 .. ``length`` among them.  The party that
        writes the data is taken to write an index there, as code that indexes with it
        unguarded expects (a PC's step number); the assumption names each such read
        (``Linker.outside_indexes``).  A domain with no such value is kept whole, and so is
        one of data whose writers are known tasks left out (``written_by_tasks``): the values
        their code writes, 0 included, may reach the read (a guard read apart from it)."""
        valid = tuple(v for v in domain if isinstance(v, float) and v.is_integer() and
                      1 <= v <= length)
        if not valid or len(valid) == len(domain):
            return domain
        self.linker.outside_indexes.setdefault(slot, set()).add(span)
        return valid

    def _outside_whole(self, expr, compiled: Compiled, outside, path: tuple, name: str,
                       value_type, elements: list) -> Compiled:
        """A whole record or array of outside data read at once (``elements``: the index
        tuples of an array's elements, ``[()]`` for a record): each value component that a
        read of the component alone may choose (a domain of several values) is chosen here
        too, element by element, so the whole and its parts tell the same story.

        Components of data only the outside writes that no wait reads: every read chooses
        afresh, as the component reads do; an array whose combinations exceed
        ``WHOLE_ARRAY_CHOICES`` keeps the stored value outside a wait (choosing would
        multiply every step's successors), but not in a wait, where the stored value alone
        would make a wait the other writer ends look like a deadlock (``WAIT_CHOICES``
        there).  Components of data the loaded code writes too, or that a wait reads
        (``OutsideData.stored_by_waits``): a wait or a poll takes the stored value or one
        the other writer wrote just before, and keeps what it took (``_outside_read``);
        other reads, the stored value."""
        leaves = [(positions, leaf_name, domain, outside.stored_by_waits(leaf_path))
                  for positions, leaf_name, domain, leaf_path
                  in _varying_leaves(value_type, outside, path)]
        if not self.in_wait:             # (elsewhere a stored component is read as stored)
            leaves = [leaf for leaf in leaves if not leaf[3]]
        if not leaves:
            return compiled
        choices = [(element + positions,
                    name + (f"{{{','.join(str(i + 1) for i in element)}}}" if element else "")
                    + leaf_name, domain, keeps)
                   for element in elements for positions, leaf_name, domain, keeps in leaves]
        combinations = 1
        for _, _, domain, keeps in choices:
            combinations *= len(domain) + keeps
        if self.in_wait and combinations > WAIT_CHOICES:
            self.linker.whole_reads_fixed.add(outside.slot)     # the assumption says so
            return compiled
        if not self.in_wait and elements != [()] and combinations > WHOLE_ARRAY_CHOICES:
            return compiled
        stores = any(keeps for _, _, _, keeps in choices)
        if not stores and not outside.observed:
            stored = compiled.fn

            def chosen(m):
                value = stored(m)
                for positions, leaf_name, domain, _ in choices:
                    value = replace_at(value, positions, m.choose(leaf_name, domain))
                return value
            # (what it reads goes nowhere but into the value: a comparison with a constant
            # chooses per outcome anywhere, ``_by_outcome``)
            ref_fn = self.reference(expr, "read")[0]
            leaves = [(positions, leaf_name, domain, lambda current, domain=domain: domain,
                       False) for positions, leaf_name, domain, _ in choices]
            return Compiled(chosen, compiled.type, wait_read=WaitRead(ref_fn, leaves))
        if not stores:                   # a property names it: the values taken are stored
            ref_fn = self.reference(expr, "read")[0]

            def kept(m):
                ref = ref_fn(m)
                value = old = m.read_ref(ref)
                for positions, leaf_name, domain, _ in choices:
                    value = replace_at(value, positions, m.choose(leaf_name, domain))
                if value != old:
                    m.write_ref(ref, value)
                return value
            return Compiled(kept, compiled.type)
        # a wait or a poll: a stored component takes the stored value or another, and keeps
        # it; any other one is chosen afresh (and kept where a property names the data)
        ref_fn = self.reference(expr, "read")[0]
        self.wait_choices = True
        observed = outside.observed
        ordered_choices = [(positions, leaf_name, stored_first(domain) if keeps else domain,
                            keeps) for positions, leaf_name, domain, keeps in choices]
        pending = self.wait_outcomes
        written = tuple(positions for positions, _, _, keeps in choices if keeps or observed)

        def either(m):
            ref = ref_fn(m)
            value = old = keep = m.read_ref(ref)
            for positions, leaf_name, domains, keeps in ordered_choices:
                if keeps:
                    current = read_at(keep, positions)
                    taken = m.choose(leaf_name, domains(current))
                    if taken != current:
                        keep = replace_at(keep, positions, taken)
                else:
                    taken = m.choose(leaf_name, domains)
                    if observed and taken != read_at(keep, positions):
                        keep = replace_at(keep, positions, taken)
                if taken != read_at(value, positions):
                    value = replace_at(value, positions, taken)
            if keep is not old:
                m.write_ref(ref, keep)
            note_writes(pending, ref, written)
            return value
        leaves = [(positions, leaf_name, domain,
                   stored_first(domain) if keeps else (lambda current, domain=domain: domain),
                   keeps or observed) for positions, leaf_name, domain, keeps in choices]
        return Compiled(either, compiled.type, wait_read=WaitRead(ref_fn, leaves))

    def condition(self, expr: ast.Expr) -> Compiled:
        compiled = self.value(expr)
        if compiled.type is not None and compiled.type is not BOOL:
            raise error(TYPE_MISMATCH, f"condition must be bool, not {type_name(compiled.type)}",
                        expr.span)
        return compiled

    def check_assignable(self, actual: AnyType, expected: AnyType, span: ast.Span) -> None:
        if isinstance(expected, RapidType) and expected.kind == SEMI_VALUE:
            expected = expected.value_type
        if not same_type(actual, expected):
            raise error(TYPE_MISMATCH, f"expected {type_name(expected)}, found {type_name(actual)}",
                        span)

    @staticmethod
    def convert(compiled: Compiled, target: AnyType) -> Compiled:
        """Round to num when a dnum value goes into a num."""
        if target is NUM and compiled.type is DNUM:
            fn = compiled.fn
            # A constant too large for num fails when it runs (ERR_NUM_LIMIT), not here.
            return ExpressionCompiler._fold(lambda m: values.to_num(fn(m)), NUM, compiled,
                                            template="_to_num({0})")
        return compiled

    # --------------------------------------------------------------- literals
    def _NumLiteral(self, expr: ast.NumLiteral, expected) -> Compiled:
        if expected is DNUM:
            return constant(values.to_dnum(expr.value), DNUM)
        try:
            return constant(values.to_num(expr.value), NUM)
        except RapidError:
            return constant(values.to_dnum(expr.value), DNUM)

    def _StringLiteral(self, expr: ast.StringLiteral, expected) -> Compiled:
        return constant(expr.value, STRING)

    def _BoolLiteral(self, expr: ast.BoolLiteral, expected) -> Compiled:
        return constant(expr.value, BOOL)

    def _Placeholder(self, expr: ast.Placeholder, expected) -> Compiled:
        """An editor placeholder (``<EXP>``): any type; evaluating it raises ERR_EXECPHR."""
        kind = expr.kind
        return Compiled(lambda m: placeholder_reached(kind), None)

    # ------------------------------------------------------------------ names
    def lookup(self, name: ast.Name, expected=None) -> Symbol:
        symbol = self.scope.lookup(name.key)
        if symbol is None:
            symbol = self.linker.system_symbol(name)
        if symbol is None:
            raise error(UNKNOWN_NAME, f"unknown name '{name.text}'", name.span,
                        *_unknown_name_notes(name, expected), subject=name.key)
        return symbol

    def _NameRef(self, expr: ast.NameRef, expected) -> Compiled:
        key = expr.name.key
        if key == "ERRNO" and self.scope.lookup(key) is None:
            self._no_variables(expr)
            return Compiled(lambda m: m.errno, NUM)
        if key == "INTNO" and self.scope.lookup(key) is None:
            self._no_variables(expr)
            return Compiled(lambda m: m.intno, NUM)
        symbol = self.lookup(expr.name, expected)
        kind = symbol.kind
        if kind == CONSTANT:
            return constant(symbol.value, symbol.type)
        if kind == ROUTINE:
            raise error(TYPE_MISMATCH, f"'{expr.name.text}' is a routine, not data", expr.span)
        self._no_variables(expr)
        slot = symbol.slot
        rapid_type = symbol.type
        if kind == SIGNAL:
            self.note_io_read(slot)
            self.linker.note_signal_named(slot)
            return Compiled(lambda m: m.io[slot], NUM, source=f"_read(cx, {slot})", names={})
        is_signal = isinstance(rapid_type, RapidType) and rapid_type.kind == SEMI_VALUE
        if is_signal:
            self.note_io_read()
        if kind == GLOBAL_DATA:
            if is_signal:
                return Compiled(_bound_signal_reader(slot), NUM,
                                source=f"_read(cx, store[{slot}])", names={})
            return Compiled(lambda m: m.store[slot], rapid_type, source=f"store[{slot}]",
                            names={})
        # routine data and parameters
        if is_signal:    # a signal parameter holds the physical index its caller bound
            index = self._local_reader(replace(symbol, by_reference=False), expr.name)
            return Compiled(lambda m: read_signal(m, index(m)), NUM)
        reader = self._local_reader(symbol, expr.name)
        if symbol.by_reference or symbol.optional:
            return Compiled(reader, rapid_type)
        return Compiled(reader, rapid_type, source=f"locals_[{slot}]", names={})

    def _local_reader(self, symbol: Symbol, name: ast.Name) -> Callable:
        slot = symbol.slot
        if symbol.by_reference:
            if symbol.optional:
                def read_optional_ref(m):
                    ref = m.frames[-1].locals[slot]
                    if ref is ABSENT:
                        raise RapidError("ERR_NOTPRES", f"optional parameter {name.text} not present")
                    return m.read_ref(ref)
                return read_optional_ref
            return lambda m: m.read_ref(m.frames[-1].locals[slot])
        if symbol.optional:
            def read_optional(m):
                value = m.frames[-1].locals[slot]
                if value is ABSENT:
                    raise RapidError("ERR_NOTPRES", f"optional parameter {name.text} not present")
                return value
            return read_optional
        return lambda m: m.frames[-1].locals[slot]

    def _no_variables(self, expr) -> None:
        if self.constant_only:
            from ..diagnostics import NOT_CONSTANT as CODE
            raise error(CODE, "a constant expression is required here "
                        "(no variables, persistents or function calls)", expr.span)

    # ------------------------------------------------------- index, component
    def _Index(self, expr: ast.Index, expected) -> Compiled:
        base = self.base_value(expr.base)
        base_type = base.type
        if base_type is not None and not isinstance(base_type, ArrayType):
            raise error(TYPE_MISMATCH, f"'{type_name(base_type)}' is not an array", expr.span)
        if base_type is not None and len(expr.indices) > base_type.rank:
            raise error(TYPE_MISMATCH, f"too many indices: the array has {base_type.rank} "
                        f"dimension(s)", expr.span)
        if isinstance(base_type, ArrayType):
            for index, length in zip(expr.indices, base_type.dims):
                if length is not None and self.outside_read_only_as_index(index):
                    self.index_lengths[id(index)] = length
        indices = [self.value(i, NUM) for i in expr.indices]
        result_type = None
        if base_type is not None:
            rest = base_type.dims[len(indices):]
            result_type = ArrayType(base_type.element, rest) if rest else base_type.element
        base_fn = base.fn
        span = expr.span
        index_fns = [i.fn for i in indices]
        if len(index_fns) == 1:
            index_fn = index_fns[0]

            def element(m):
                array = base_fn(m)
                return array[_check_index(array, index_fn(m), span)]
            return Compiled(element, result_type)

        def element_n(m):
            value = base_fn(m)
            for fn in index_fns:
                value = value[_check_index(value, fn(m), span)]
            return value
        return Compiled(element_n, result_type)

    def _Component(self, expr: ast.Component, expected) -> Compiled:
        base = self.base_value(expr.base)
        offset, component_type = self.component_offset(base.type, expr.name)
        base_fn = base.fn
        if base.is_constant:
            return constant(base.constant[offset], component_type)
        return Compiled(lambda m: base_fn(m)[offset], component_type)

    def component_offset(self, record: Optional[AnyType], name: ast.Name):
        if record is None:
            raise error(TYPE_MISMATCH, f"cannot tell the type that has component "
                        f"'{name.text}'", name.span)
        if not isinstance(record, RapidType) or record.kind != RECORD:
            raise error(TYPE_MISMATCH, f"'{type_name(record)}' has no component "
                        f"'{name.text}' (not a record)", name.span)
        offset = record.component_index(name.key)
        if offset < 0:
            names = ", ".join(c.name for c in record.components)
            raise error(UNKNOWN_NAME, f"record type {record.name} has no component "
                        f"'{name.text}' (components: {names})", name.span)
        return offset, record.components[offset].type

    # -------------------------------------------------------------- aggregate
    def _Aggregate(self, expr: ast.Aggregate, expected) -> Compiled:
        item_types: list[Optional[AnyType]]
        if isinstance(expected, ArrayType):
            if expected.dims[0] is not None and expected.dims[0] != len(expr.items):
                raise error(TYPE_MISMATCH, f"aggregate has {len(expr.items)} elements, the "
                            f"array dimension is {expected.dims[0]}", expr.span)
            inner = ArrayType(expected.element, expected.dims[1:]) if expected.rank > 1 \
                else expected.element
            item_types = [inner] * len(expr.items)
        elif isinstance(expected, RapidType) and expected.kind == RECORD:
            if len(expected.components) != len(expr.items):
                raise error(TYPE_MISMATCH, f"aggregate has {len(expr.items)} components, "
                            f"{expected.name} has {len(expected.components)}", expr.span)
            item_types = [c.type for c in expected.components]
        elif expected is None:
            item_types = [None] * len(expr.items)
        else:
            raise error(TYPE_MISMATCH, f"an aggregate cannot be a {type_name(expected)}",
                        expr.span)
        items = [self.value(item, t) for item, t in zip(expr.items, item_types)]
        result_type = expected
        if all(i.is_constant for i in items):
            return constant(tuple(i.constant for i in items), result_type)
        fns = [i.fn for i in items]
        return with_source(Compiled(lambda m: tuple(fn(m) for fn in fns), result_type),
                           "(" + "".join(f"{{{i}}}, " for i in range(len(items))) + ")",
                           *items)

    # ------------------------------------------------------------------ unary
    def _Unary(self, expr: ast.Unary, expected) -> Compiled:
        if expr.op == "NOT":
            operand = self.condition(expr.operand)
            fn = operand.fn
            if operand.is_constant:
                return constant(not operand.constant, BOOL)
            return with_source(Compiled(lambda m: not fn(m), BOOL), "(not {0})", operand)
        operand = self.value(expr.operand,
                             expected if is_numeric(expected) or expected is POS else None)
        rapid_type = operand.type
        if rapid_type is None and isinstance(expr.operand, ast.Aggregate):
            raise error(TYPE_MISMATCH, f"cannot tell the type of the aggregate after unary "
                        f"{expr.op}", expr.span)
        if rapid_type is not None and not is_numeric(rapid_type) and rapid_type is not POS:
            raise error(TYPE_MISMATCH, f"unary {expr.op} needs num, dnum or pos, not "
                        f"{type_name(rapid_type)}", expr.span)
        if expr.op == "+":
            return operand
        fn = operand.fn
        # ``- x + 0.0``: negation never makes -0.0 (values.py: no value holds it)
        if rapid_type is POS:
            return self._fold(lambda m: tuple(-c + 0.0 for c in fn(m)), POS, operand)
        if operand.is_constant:
            return constant(-operand.constant + 0.0, rapid_type)
        return with_source(Compiled(lambda m: -fn(m) + 0.0, rapid_type), "(-{0} + 0.0)",
                           operand)

    # ----------------------------------------------------------------- binary
    def _Binary(self, expr: ast.Binary, expected) -> Compiled:
        op = expr.op
        if op in ("AND", "OR", "XOR"):
            return self._logical(expr)
        hint = expected if is_numeric(expected) else None
        left, right = self._operands(expr, hint)
        if op in ("=", "<>"):
            return self._equality(expr, left, right)
        if op in ("<", "<=", ">", ">="):
            return self._ordering(expr, left, right)
        return self._arithmetic(expr, left, right)

    def _operands(self, expr: ast.Binary, hint) -> tuple[Compiled, Compiled]:
        """Both operands; an aggregate beside a pos (or another record) in ``+``, ``-``, ``=``
        or ``<>`` takes the other operand's type (``[10,10,30] + p.trans``, which controllers
        load), as an aggregate assigned to data takes the data's; so does one beside a pos or
        an orient in ``*`` (the cross product ``[0,0,1] * v``, the quaternion product)."""
        aggregate_left = isinstance(expr.left, ast.Aggregate)
        if aggregate_left != isinstance(expr.right, ast.Aggregate) and \
                expr.op in ("+", "-", "=", "<>", "*"):
            other = self.value(expr.right if aggregate_left else expr.left, hint)
            record = isinstance(other.type, RapidType) and other.type.kind == RECORD and \
                (expr.op != "*" or other.type in (POS, ORIENT))
            shaped = other.type if record else hint
            aggregate = self.value(expr.left if aggregate_left else expr.right, shaped)
            return (aggregate, other) if aggregate_left else (other, aggregate)
        return self.value(expr.left, hint), self.value(expr.right, hint)

    def _logical(self, expr: ast.Binary) -> Compiled:
        left = self.condition(expr.left)
        right = self.condition(expr.right)
        lf, rf = left.fn, right.fn
        # RAPID documents no short-circuit: both operands are evaluated.
        if expr.op == "AND":
            fn = lambda m: bool(lf(m) & rf(m))  # noqa: E731
        elif expr.op == "OR":
            fn = lambda m: bool(lf(m) | rf(m))  # noqa: E731
        else:
            fn = lambda m: lf(m) != rf(m)  # noqa: E731
        return self._fold(fn, BOOL, left, right, template=LOGICAL_SOURCES[expr.op])

    @staticmethod
    def _fold(fn: Callable, rapid_type, *operands: Compiled,
              template: Optional[str] = None) -> Compiled:
        """A constant when every operand is one (and it computes), else ``fn``
        (with the source ``template`` of the operands' sources, see ``with_source``)."""
        if all(o.is_constant for o in operands):
            try:
                return constant(fn(None), rapid_type)
            except RapidError:
                pass
        compiled = Compiled(fn, rapid_type)
        return compiled if template is None else with_source(compiled, template, *operands)

    def _equality(self, expr, left: Compiled, right: Compiled) -> Compiled:
        if left.type is not None and right.type is not None:
            if not same_type(left.type, right.type):
                raise error(TYPE_MISMATCH, f"cannot compare {type_name(left.type)} with "
                            f"{type_name(right.type)}", expr.span)
            if isinstance(left.type, ArrayType):
                raise error(TYPE_MISMATCH, "arrays cannot be compared with = or <>", expr.span)
        compare = operator.eq if expr.op == "=" else operator.ne
        left, right = decisive_read(compare, left, right)
        left, right = self._by_outcome(compare, left, right)
        return self._fold(_binary(compare, left, right), BOOL, left, right,
                          template=COMPARISON_SOURCES[expr.op])

    def _ordering(self, expr, left: Compiled, right: Compiled) -> Compiled:
        for side in (left, right):
            if side.type is not None and not is_numeric(side.type):
                raise error(TYPE_MISMATCH, f"'{expr.op}' compares num or dnum values, not "
                            f"{type_name(side.type)}", expr.span)
        compare = {"<": operator.lt, "<=": operator.le, ">": operator.gt, ">=": operator.ge}[expr.op]
        left, right = decisive_read(compare, left, right)
        left, right = self._by_outcome(compare, left, right)
        return self._fold(_binary(compare, left, right), BOOL, left, right,
                          template=COMPARISON_SOURCES[expr.op])

    def _by_outcome(self, compare: Callable, left: Compiled, right: Compiled) -> tuple:
        """The operands of ``compare``, where one is a read of outside data that chooses
        (a wait's, or a whole record's or array's that stores nothing) and the other a
        constant: the read chooses one value per outcome of the comparison
        (``wait_outcomes``); a read that keeps what it took, only in a WaitUntil's
        condition."""
        pending = self.wait_outcomes
        if not BY_OUTCOME:
            return left, right
        for read, other, flipped in ((left, right, False), (right, left, True)):
            if read.wait_read is None or not other.is_constant:
                continue
            if pending is None and any(leaf[4] for leaf in read.wait_read.leaves):
                return left, right      # (it keeps what it took: only a WaitUntil settles it)
            fn = by_outcome(read.wait_read, compare, other.constant, flipped, pending)
            if fn is None:
                return left, right
            chosen = Compiled(fn, read.type)
            return (other, chosen) if flipped else (chosen, other)
        return left, right

    def _arithmetic(self, expr, left: Compiled, right: Compiled) -> Compiled:
        op = expr.op
        lt, rt = left.type, right.type
        lf, rf = left.fn, right.fn
        if lt is STRING or rt is STRING:
            if op != "+" or not (same_type(lt, STRING) and same_type(rt, STRING)):
                raise error(TYPE_MISMATCH, f"'{op}' cannot combine {type_name(lt)} and "
                            f"{type_name(rt)}", expr.span)
            return self._fold(lambda m: values.concat(lf(m), rf(m)), STRING, left, right,
                              template="_concat({0}, {1})")
        if lt is POS or rt is POS or lt is ORIENT or rt is ORIENT:
            return self._vector(expr, left, right)
        self._typed_aggregates(expr)
        for side in (lt, rt):
            if side is not None and not is_numeric(side):
                raise error(TYPE_MISMATCH, f"'{op}' needs num or dnum operands, not "
                            f"{type_name(side)}", expr.span)
        result_type = DNUM if (lt is DNUM or rt is DNUM) else (NUM if lt is not None or rt is not None else None)
        round_ = values.to_dnum if result_type is DNUM else values.to_num
        if right.is_constant and op in ARITHMETIC:
            fn = _constant_right(op, lf, right.constant, round_)
        elif op == "+":
            fn = lambda m: round_(lf(m) + rf(m))  # noqa: E731
        elif op == "-":
            fn = lambda m: round_(lf(m) - rf(m))  # noqa: E731
        elif op == "*":
            fn = lambda m: round_(lf(m) * rf(m))  # noqa: E731
        elif op == "/":
            fn = lambda m: round_(values.divide(lf(m), rf(m)))  # noqa: E731
        elif op == "DIV":
            fn = lambda m: values.int_div(lf(m), rf(m))  # noqa: E731
        elif op == "MOD":
            fn = lambda m: values.int_mod(lf(m), rf(m))  # noqa: E731
        else:
            raise error(TYPE_MISMATCH, f"unknown operator {op}", expr.span)
        template = ARITHMETIC_SOURCES[op].replace("ROUND", "_to_dnum" if result_type is DNUM
                                                   else "_to_num")
        return self._fold(fn, result_type, left, right, template=template)

    @staticmethod
    def _typed_aggregates(expr: ast.Binary) -> None:
        """An aggregate operand whose type nothing tells (``[1,2,3] + [4,5,6]``) is an error."""
        for side in (expr.left, expr.right):
            if isinstance(side, ast.Aggregate):
                raise error(TYPE_MISMATCH, f"cannot tell the type of the aggregate operand of "
                            f"'{expr.op}'", side.span)

    def _vector(self, expr, left: Compiled, right: Compiled) -> Compiled:
        from .library import geometry_ops
        fn, result_type = geometry_ops.operator_for(expr.op, left.type, right.type)
        if fn is None:
            raise error(TYPE_MISMATCH, f"'{expr.op}' cannot combine {type_name(left.type)} "
                        f"and {type_name(right.type)}", expr.span)
        lf, rf = left.fn, right.fn
        return self._fold(lambda m: fn(lf(m), rf(m)), result_type, left, right)

    # ------------------------------------------------------------------ calls
    def _FunctionCall(self, expr: ast.FunctionCall, expected) -> Compiled:
        symbol = self.scope.lookup(expr.name.key)
        if symbol is not None and symbol.kind == ROUTINE:
            routine = self.linker.routine_by_index(symbol.slot)
            if routine.kind != "FUNC":
                raise error(TYPE_MISMATCH, f"'{expr.name.text}' is a {routine.kind}, not a "
                            "function", expr.span)
            self._no_variables(expr)
            if self.hoist is None:
                raise error(ARGUMENT, f"user function '{expr.name.text}' cannot be called "
                            "here (only predefined functions)", expr.span)
            slot = self._hoisted.get(id(expr))
            if slot is None:
                pending, self.wait_outcomes = self.wait_outcomes, None   # (run before the wait)
                try:
                    slot = self._hoisted[id(expr)] = self.hoist(expr, routine)
                finally:
                    self.wait_outcomes = pending
            return Compiled(lambda m: m.frames[-1].locals[slot], routine.return_type)
        if symbol is not None:
            raise error(TYPE_MISMATCH, f"'{expr.name.text}' is data, not a function", expr.span)
        return self.linker.calls.predefined_function(self, expr)

    # ------------------------------------------------------------- references
    def reference(self, expr: ast.Expr, purpose: str):
        """Compile a data reference: ``fn(machine) -> (space, index, path)``.

        Returns (fn, type, symbol) where ``symbol`` is the root data object.
        """
        if isinstance(expr, ast.NameRef):
            symbol = self.scope.lookup(expr.name.key)
            if symbol is None:
                symbol = self.linker.system_symbol(expr.name)
            if symbol is None:
                raise error(UNKNOWN_NAME, f"unknown name '{expr.name.text}'", expr.span,
                            subject=expr.name.key)
            if symbol.kind == GLOBAL_DATA:
                ref = (GLOBAL, symbol.slot, ())
                return (lambda m: ref), symbol.type, symbol
            if symbol.kind == LOCAL_DATA:
                slot = symbol.slot
                if symbol.by_reference:
                    name = expr.name.text

                    def param_ref(m):
                        ref = m.frames[-1].locals[slot]
                        if ref is ABSENT:
                            raise RapidError("ERR_NOTPRES", f"optional parameter {name} not present")
                        return ref
                    return param_ref, symbol.type, symbol
                return (lambda m: (len(m.frames) - 1, slot, ())), symbol.type, symbol
            raise error(NOT_A_REFERENCE, f"'{expr.name.text}' is not a variable or persistent "
                        f"and cannot be {purpose}", expr.span)
        if isinstance(expr, ast.Index):
            base_fn, base_type, symbol = self.reference(expr.base, purpose)
            if base_type is not None and not isinstance(base_type, ArrayType):
                raise error(TYPE_MISMATCH, f"'{type_name(base_type)}' is not an array", expr.span)
            index_fns = [self.value(i, NUM).fn for i in expr.indices]
            result_type = None
            if base_type is not None:
                rest = base_type.dims[len(index_fns):]
                result_type = ArrayType(base_type.element, rest) if rest else base_type.element
            span = expr.span

            def element_ref(m):
                space, index, path = base_fn(m)
                value = m.read_ref((space, index, path))
                offsets = []
                for fn in index_fns:
                    offset = _check_index(value, fn(m), span)
                    offsets.append(offset)
                    value = value[offset]
                return (space, index, path + tuple(offsets))
            return element_ref, result_type, symbol
        if isinstance(expr, ast.Component):
            base_fn, base_type, symbol = self.reference(expr.base, purpose)
            offset, component_type = self.component_offset(base_type, expr.name)

            def component_ref(m):
                space, index, path = base_fn(m)
                return (space, index, path + (offset,))
            return component_ref, component_type, symbol
        if isinstance(expr, ast.Placeholder):      # <VAR>: an error only when executed
            kind = expr.kind
            return (lambda m: placeholder_reached(kind)), None, None
        raise error(NOT_A_REFERENCE, f"a variable or persistent is required here ({purpose})",
                    expr.span)


# Data a robot station defines outside the program's main modules (CalibData.mod, a data module).
STATION_DATA_TYPES = ("TOOLDATA", "WOBJDATA", "ROBTARGET", "JOINTTARGET", "LOADDATA")


def _unknown_name_notes(name: ast.Name, expected) -> tuple[str, ...]:
    """Why a tool, work object or target may be unknown: its module was not given."""
    if getattr(expected, "key", None) in STATION_DATA_TYPES:
        return (f"'{name.text}' would be {expected.name}: tools, work objects and targets are often "
                "declared in another module of the task (CalibData.mod or a data module); "
                "give that module too",)
    return ()

