"""Wrapping counters: a num that only numbers the entries of a log no check reads.

A message log (``ncycle1 := ncycle1 + 1; recstring{ncycle1} := message;
IF ncycle1 > 98 THEN ncycle1 := 1; ENDIF``) keeps its counter in every
state, so a program that loops forever has as many states as the log has
entries times everything else.  Whether the log's index is in bounds is a
run-time error a check must find, so the counter is relevant as an index
(``relevance``) and as a condition.  This module proves, for such a
counter, that every index it gives is within its array's bounds; then the
counter decides nothing a check observes unless the array is relevant:

* ``bounded_writes``: the spans of ``A{x} := e`` whose index ``x`` is
  within ``A``'s bounds in every run: ``x`` flows into ``A`` (it chooses
  the element written) instead of being relevant by itself;
* ``guards``: the spans of ``IF x <op> c THEN ... ENDIF`` (one branch, no
  ELSE) whose body only assigns ``x``: the condition flows into ``x``
  instead of being relevant by itself.

A *counter* is a global num of a program of one task (no environment
model, no further task, not written from outside the loaded code) that
only the entry routine names, every write of it ``x := c`` or ``x := x
+ k`` / ``x - k`` / ``Incr x`` / ``Decr x`` with whole numbers, every read
one of those, a guard's condition or the whole index of such an array
write.  The proof is an interval analysis over the entry routine's
instructions (a jump, an error to the handler, RETRY and TRYNEXT
anywhere, ExitCycle back to the start, which a TRAP may also run at any
step: the start's value is any number), with widening and then narrowing
steps.  Sliced, the counter is reset to its initial value in every stored
state, and a step computes from there (or skips the total writes): the
initial value is therefore joined into the value at every instruction,
so the reduced model's indices are within the bounds too.

The reduced model decides a guard on the reset value: a run of the
program whose guard holds (the counter past the log's end) is the reduced
run with the guard's body left out, whose steps change only the program
counter and sliced data.  That keeps verdicts of properties blind to
stuttering (no X) that name no location; ``find_slicing`` asks for the
counters only then.  The guard's body is then never run by the reduced
search: its lines are not reported as unreached (``arm_lines``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterator, Optional

from ... import ast
from ...semantics.instructions import Branch
from ...semantics.library.program_control import CALLS_BY_NAME
from ...semantics.program import Program
from ...semantics.scope import GLOBAL_DATA, LOCAL_DATA
from ...semantics.types import ArrayType, RapidType
from .merging import nodes_by_span
from .numeric_updates import as_assignment

Interval = Optional[tuple]       # (low, high), infinities allowed; None: no value (unreached)
ANY = (-math.inf, math.inf)
WIDEN_AFTER = 24                 # updates of one pc before a moving bound is widened
NARROWINGS = 24                  # steps of the decreasing iteration after the fixed point
COMPARISONS = {"<", "<=", ">", ">=", "=", "<>"}
MIRRORED = {"<": ">", "<=": ">=", ">": "<", ">=": "<=", "=": "=", "<>": "<>"}
NEGATED = {"<": ">=", "<=": ">", ">": "<=", ">=": "<", "=": "<>", "<>": "="}


@dataclass(frozen=True)
class Counters:
    """What the counters proven in bounds let ``relevance`` pass on instead of seed."""

    bounded_writes: frozenset = frozenset()    # spans of ``A{x} := e``
    guards: frozenset = frozenset()            # spans of ``IF x op c THEN x := ... ENDIF``
    # (slot, (file, line) of a guard, (file, line) in its body)
    arm_lines: tuple = ()

    @property
    def empty(self) -> bool:
        return not self.bounded_writes and not self.guards


NO_COUNTERS = Counters()


def find_counters(program: Program) -> Counters:
    """The counters of ``program`` whose every index is proven within its array."""
    if program.task_entries or program.environment_react is not None or \
            program.environment_init is not None:
        return NO_COUNTERS
    entry = program.routines[program.entry]
    if entry.ast is None or getattr(entry, "scope", None) is None:
        return NO_COUNTERS
    uses = _Uses(program, entry)
    if not uses.run():
        return NO_COUNTERS
    writes, guards, lines = set(), set(), set()
    for slot, found in sorted(uses.found.items()):
        if found is None or not found.indexes:
            continue
        data = program.globals[slot]
        initial = data.initial
        if not _whole(initial):
            continue
        values = _intervals(entry, slot, float(initial),
                            uses.thresholds | {float(size) for _, size in found.indexes})
        if values is None:
            continue
        places = found.index_pcs(entry)
        if places is not None and all(_within(values[pc], dims) for pc, dims in places):
            writes |= {span for span, _ in found.indexes}
            guards |= found.guards
            lines |= {(slot, *pair) for pair in found.arm_lines}
    return Counters(frozenset(writes), frozenset(guards), tuple(sorted(lines)))


def _whole(value) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool) and \
        math.isfinite(value) and float(value).is_integer()


def _within(interval: Interval, size: int) -> bool:
    return interval is None or interval[0] >= 1 and interval[1] <= size


class _Found:
    """One counter's places: its array writes (span, size) and guards."""

    def __init__(self):
        self.indexes: list[tuple] = []
        self.guards: set = set()
        self.arm_lines: set = set()

    def index_pcs(self, routine) -> Optional[list[tuple[int, int]]]:
        """(pc, array size) of each instruction that writes an array at the counter; None
        when one of the writes is not found among the instructions."""
        sizes = dict(self.indexes)
        places = [(pc, sizes[instruction.span]) for pc, instruction in enumerate(routine.code)
                  if instruction.span in sizes]
        if {routine.code[pc].span for pc, _ in places} != set(sizes):
            return None
        return places


class _Uses:
    """Where each global num is named: ``found[slot]`` is its places, None when a use is
    not one a counter may have."""

    def __init__(self, program: Program, entry):
        self.program = program
        self.entry = entry
        self.found: dict[int, Optional[_Found]] = {}
        self.lookup = entry.scope.lookup
        # the numbers the entry routine names: the steps a widened bound may stop at
        self.thresholds = {float(node.value) for node, _ in ast.walk(entry.ast)
                           if isinstance(node, ast.NumLiteral) and _whole(node.value)}

    def run(self) -> bool:
        program = self.program
        for data in program.globals:
            if data.slot not in program.outside_data and _is_num(data.type):
                self.found[data.slot] = _Found()
        for routine in program.routines:
            if routine.ast is None or getattr(routine, "scope", None) is None:
                return False
            for node, _ in ast.walk(routine.ast):     # main called again: not followed
                if isinstance(node, ast.LateBindingCall) or \
                        isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                        isinstance(node.name, ast.Name) and \
                        node.name.key in CALLS_BY_NAME | {self.entry.key}:
                    return False
            if routine is not self.entry:
                self._forbid(routine, routine.ast)
                continue
            decl = routine.ast
            self._forbid(routine, (decl.data, decl.error.numbers if decl.error else None))
            for body in (decl.body, decl.backward, decl.undo,
                         decl.error.body if decl.error is not None else None):
                self._block(body or ())
        return True

    def _forbid(self, routine, node) -> None:
        """Every global num ``node`` names is no counter."""
        for name in _names(node):
            symbol = routine.scope.lookup(name.key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.slot in self.found:
                self.found[symbol.slot] = None

    def _counter(self, expr) -> Optional[int]:
        """The slot of a global num candidate ``expr`` names alone."""
        if isinstance(expr, ast.NameRef):
            symbol = self.lookup(expr.name.key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and \
                    self.found.get(symbol.slot) is not None:
                return symbol.slot
        return None

    def _block(self, statements) -> None:
        for statement in statements:
            self._statement(statement)

    def _statement(self, statement) -> None:
        entry = self.entry
        update = as_assignment(statement, self.lookup) \
            if isinstance(statement, ast.ProcedureCall) else None
        if update is not None:
            statement = update
        if isinstance(statement, ast.Assignment):
            slot = self._counter(statement.target)
            if slot is not None and _update(statement.value, slot, self._counter) is not None:
                return
            array = _array_write(statement.target, self._counter, self.lookup)
            if array is not None:
                slot, size = array
                self.found[slot].indexes.append((statement.span, size))
                self._forbid(entry, (statement.target.base, statement.value))
                return
            self._forbid(entry, statement)
        elif isinstance(statement, ast.If):
            slot = self._guard(statement)
            if slot is not None:
                found = self.found[slot]
                found.guards.add(statement.span)
                guard = (statement.span.file, statement.span.line)
                for inner in statement.branches[0].body:
                    for node, _ in ast.walk(inner):
                        if getattr(node, "span", None) is not None:
                            found.arm_lines.add((guard, (node.span.file, node.span.line)))
                return
            for branch in statement.branches:
                self._forbid(entry, branch.condition)
                self._block(branch.body)
            self._block(statement.else_body or ())
        elif isinstance(statement, ast.While):
            self._forbid(entry, statement.condition)
            self._block(statement.body)
        elif isinstance(statement, ast.For):
            self._forbid(entry, (statement.start, statement.stop, statement.step))
            self._block(statement.body)
        elif isinstance(statement, ast.Test):
            self._forbid(entry, (statement.subject,
                                 [case.values for case in statement.cases]))
            for case in statement.cases:
                self._block(case.body)
            self._block(statement.default or ())
        else:                          # CompactIf, calls, RETURN, RAISE, CONNECT, ...
            self._forbid(entry, statement)

    def _guard(self, statement: ast.If) -> Optional[int]:
        """The counter of ``IF x op c THEN x := ...; ENDIF`` (one branch, no ELSE)."""
        if len(statement.branches) != 1 or statement.else_body:
            return None
        branch = statement.branches[0]
        slot = _compared(branch.condition, self._counter)
        if slot is None or not branch.body:
            return None
        for inner in branch.body:
            update = as_assignment(inner, self.lookup) \
                if isinstance(inner, ast.ProcedureCall) else inner
            if not isinstance(update, ast.Assignment) or \
                    self._counter(update.target) != slot or \
                    _update(update.value, slot, self._counter) is None:
                return None
        return slot


def _is_num(rapid_type) -> bool:
    return isinstance(rapid_type, RapidType) and rapid_type.key == "NUM"


def _names(node) -> Iterator[ast.Name]:
    """Every data name inside ``node`` (as ``relevance`` reads them)."""
    from .relevance import _names as names
    return names(node)


def _update(value, slot: int, counter) -> Optional[tuple]:
    """('set', c) for a whole number ``c``, ('add', k) for ``x + k`` / ``k + x`` /
    ``x - k`` with ``k`` whole; None for any other value."""
    if isinstance(value, ast.NumLiteral) and _whole(value.value):
        return "set", float(value.value)
    if isinstance(value, ast.Binary) and value.op in ("+", "-"):
        left, right = value.left, value.right
        if counter(left) == slot and isinstance(right, ast.NumLiteral) and _whole(right.value):
            return "add", float(right.value) * (1 if value.op == "+" else -1)
        if value.op == "+" and counter(right) == slot and \
                isinstance(left, ast.NumLiteral) and _whole(left.value):
            return "add", float(left.value)
    return None


def _compared(condition, counter) -> Optional[int]:
    """The counter of ``x op c`` / ``c op x`` (c a number)."""
    parts = _comparison(condition, counter)
    return parts[0] if parts is not None else None


def _comparison(condition, counter) -> Optional[tuple]:
    """(slot, op, c) with the counter on the left, or None."""
    if not isinstance(condition, ast.Binary) or condition.op not in COMPARISONS:
        return None
    left, right = condition.left, condition.right
    if counter(left) is not None and isinstance(right, ast.NumLiteral):
        return counter(left), condition.op, float(right.value)
    if counter(right) is not None and isinstance(left, ast.NumLiteral):
        return counter(right), MIRRORED[condition.op], float(left.value)
    return None


def _array_write(target, counter, lookup) -> Optional[tuple]:
    """(counter slot, array size) of ``A{x}`` (A one-dimensional data named directly)."""
    if not isinstance(target, ast.Index) or len(target.indices) != 1 or \
            not isinstance(target.base, ast.NameRef):
        return None
    slot = counter(target.indices[0])
    symbol = lookup(target.base.name.key)
    if slot is None or symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA) or \
            symbol.by_reference or symbol.optional:
        return None
    array = symbol.type
    if not isinstance(array, ArrayType) or array.rank != 1 or array.dims[0] is None:
        return None
    return slot, array.dims[0]


# ------------------------------------------------------------------ intervals
def _intervals(routine, slot: int, initial: float, thresholds: set) -> Optional[list]:
    """The counter's interval before each pc of ``routine`` (the entry routine), or None
    when the analysis does not settle.  A bound that keeps moving jumps to the next of
    ``thresholds`` (the numbers the routine names, and the arrays' sizes), then to
    infinity."""
    steps = sorted({value + offset for value in thresholds | {initial}
                    for offset in (-1.0, 0.0, 1.0)})
    from .liveness import _successors
    code = routine.code
    nodes = nodes_by_span(routine.ast)
    lookup = routine.scope.lookup
    size = len(code)
    handler, undo = routine.handler_pc, routine.undo_pc
    body_end = min(pc for pc in (handler, undo, size) if pc >= 0)

    def counter(expr) -> Optional[int]:
        if isinstance(expr, ast.NameRef):
            symbol = lookup(expr.name.key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.slot == slot:
                return slot
        return None

    edges: list[list] = []            # per pc: (target, transfer) pairs
    for pc, instruction in enumerate(code):
        node = nodes.get(instruction.span)
        if isinstance(node, ast.ProcedureCall):
            node = as_assignment(node, lookup) or node
        following = _successors(routine, pc, instruction, nodes.get(instruction.span), True)
        compared = _comparison(getattr(node, "condition", None), counter) \
            if isinstance(instruction, Branch) else None
        effect = None
        if isinstance(node, ast.Assignment) and counter(node.target) == slot:
            effect = _update(node.value, slot, counter)
            if effect is None:
                return None
        targets: list = []
        for target in following:
            if compared is not None and instruction.target_true != instruction.target_false:
                holds = target == instruction.target_true
                targets.append((target, ("test", compared[1] if holds
                                         else NEGATED[compared[1]], compared[2])))
            else:
                targets.append((target, effect))
        if pc < body_end and handler >= 0:
            targets.append((handler, None))        # an error before the write
        if undo >= 0:
            targets.append((undo, None))
        edges.append(targets)

    start = [None] * size
    start[0] = ANY                                   # any value when main starts (again)
    floor = (initial, initial)                       # the value a reset stores

    def transfer(value: Interval, effect) -> Interval:
        if value is None:
            return None
        if effect is None:
            return value
        kind = effect[0]
        if kind == "set":
            return (effect[1], effect[1])
        if kind == "add":
            return (value[0] + effect[1], value[1] + effect[1])
        return _refine(value, effect[1], effect[2])

    def step(values: list) -> list:
        new = [_join(start[pc], floor) for pc in range(size)]
        for pc, targets in enumerate(edges):
            for target, effect in targets:
                new[target] = _join(new[target], transfer(values[pc], effect))
        return new

    values = [_join(start[pc], floor) for pc in range(size)]
    updates = [0] * size
    for _ in range(WIDEN_AFTER * (size + 2)):
        new = [_join(old, value) for old, value in zip(values, step(values))]
        if new == values:
            break                                    # a post-fixed point: F(values) <= values
        for pc in range(size):
            if new[pc] != values[pc]:
                updates[pc] += 1
                if updates[pc] > WIDEN_AFTER:
                    new[pc] = _widen(values[pc], new[pc], steps)
        values = new
    else:
        return None
    for _ in range(NARROWINGS):                      # each step keeps a post-fixed point
        new = step(values)
        if new == values:
            break
        values = new
    return values


def _join(a: Interval, b: Interval) -> Interval:
    if a is None:
        return b
    if b is None:
        return a
    return (min(a[0], b[0]), max(a[1], b[1]))


def _widen(old: Interval, new: Interval, steps: list) -> Interval:
    if old is None or new is None:
        return new
    low = old[0] if new[0] >= old[0] else max((t for t in steps if t <= new[0]),
                                              default=-math.inf)
    high = old[1] if new[1] <= old[1] else min((t for t in steps if t >= new[1]),
                                               default=math.inf)
    return (low, high)


def _refine(value: Interval, op: str, c: float) -> Interval:
    """``value`` where ``x op c`` holds (x a whole number)."""
    low, high = value
    if op in (">", ">="):
        bound = math.floor(c) + 1 if op == ">" or not float(c).is_integer() else c
        low = max(low, bound)
    elif op in ("<", "<="):
        bound = math.ceil(c) - 1 if op == "<" or not float(c).is_integer() else c
        high = min(high, bound)
    elif op == "=":
        if not float(c).is_integer():
            return None
        low, high = max(low, c), min(high, c)
    return (low, high) if low <= high else None
