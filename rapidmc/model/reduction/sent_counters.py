"""Counters that only fill bytes sent: left out of states, with the bytes they fill.

A message header often carries a count of the messages sent::

    Incr msg_send_counter;
    PackRawBytes msg_send_counter, buffer, 17 \\IntX:=UDINT;
    ...
    SocketSend client_socket \\RawData:=buffer;

The count grows by one per message, so the check never ends, although nothing the
program does depends on it: its only read packs it into bytes that are only sent.

**Bytes only sent.**  A rawbytes data object (a VAR of a routine, or of the program when
it has one task) is *sent only* when every place the program names it is one of:
``PackRawBytes``'s RawData, ``CopyRawBytes``'s ToRawData, ``ClearRawBytes``'s RawData,
``RawBytesLen``'s RawData or ``SocketSend``'s ``\\RawData``.  Its contents then reach
nothing but the message sent (``SocketSend`` only shows them in the transition's
output); only its length can decide an error (a pack past the bytes held plus one).

**A counter only sent.**  A num data object named directly (not through a reference;
not a PERS when several tasks are loaded) whose

* every write is ``x := c`` with ``c`` an integer literal 0..2^24, or ``x := x + k``
  (``Incr x``, ``Add x, k``) with ``k`` an integer literal 1..32,
* initial value is an integer 0..2^24,
* only read outside those writes is as the Value of ``PackRawBytes ... \\IntX:=s``
  into bytes only sent, with ``s`` a constant size of 4 or 8 bytes (UDINT, DINT,
  ULINT, LINT),

never makes ``PackRawBytes`` raise: num is single precision, and ``x + k`` with
``k <= 32`` rounds back to ``x`` once ``x`` reaches 2^30 (the gap between floats there
is 128), so the counter stays an integer in 0..2^30, inside every such size's range.
Only the bytes it fills depend on its value.  So it is sliced (``relevance``: the
analysis reads such a pack as not reading the Value), and the projection resets the
contents of the bytes it is packed into to zeros of the same length
(``Projection``): the reduced states are then the projections of the plain ones, and a
counterexample is rebuilt on the plain program as for any sliced data.

A PERS counter may also be written by code not loaded (another task, a PC): that code
is assumed to keep it within the same range, and the verdicts say so under
``assumes:`` (``findings.assumptions``).
"""
from __future__ import annotations

from typing import Optional

from ... import ast
from ...semantics.library.arguments import argument_expression
from ...semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA
from ...semantics.types import ArrayType
from .merging import _walk
from .relevance import Key, _Analysis

COUNT_START_MAX = 2 ** 24          # an initial or assigned count: an exact float32 integer
STEP_MAX = 32                      # x + k with k <= 32 stops growing at 2^30
WIDE_SIZES = frozenset({4.0, -4.0, 8.0, -8.0})   # UDINT, DINT, ULINT, LINT

# predefined routine -> (parameter, its position among the positional arguments, or -1):
# where naming a rawbytes object neither reads nor passes on its contents
_CONTENT_BLIND = {
    "PACKRAWBYTES": ("RAWDATA", 1),
    "COPYRAWBYTES": ("TORAWDATA", 2),
    "CLEARRAWBYTES": ("RAWDATA", 0),
    "RAWBYTESLEN": ("RAWDATA", 0),
    "SOCKETSEND": ("RAWDATA", -1),
}


def _bodies(decl: ast.Routine) -> tuple:
    return (decl.data, decl.body, decl.backward, decl.undo,
            decl.error.body if decl.error is not None else None)


def sent_only_bytes(program) -> set[Key]:
    """The rawbytes data whose contents reach nothing but messages sent (module docstring)."""
    if not _declares_bytes(program):
        return set()
    candidates: set = set()
    named_elsewhere: set = set()
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            return set()
        scope = routine.scope
        blind: set = set()
        nodes = list(_walk(_bodies(routine.ast)))
        for node in nodes:
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                    isinstance(node.name, ast.Name) and node.name.key in _CONTENT_BLIND and \
                    scope.lookup(node.name.key) is None:
                named = argument_expression(node, *_CONTENT_BLIND[node.name.key])
                if isinstance(named, ast.NameRef):
                    blind.add(id(named))
        for node in nodes:
            if not isinstance(node, ast.NameRef):
                continue
            key = _bytes_key(program, scope.lookup(node.name.key), routine.index)
            if key is None:
                continue
            (candidates if id(node) in blind else named_elsewhere).add(key)
    return candidates - named_elsewhere


def _declares_bytes(program) -> bool:
    """Whether the program declares rawbytes data (else there is nothing to look for)."""
    if any(getattr(data.type, "key", None) == "RAWBYTES" for data in program.globals):
        return True
    for routine in program.routines:
        scope = getattr(routine, "scope", None)
        if routine.ast is None or scope is None:
            return True                    # (sent_only_bytes answers for it)
        for data in routine.ast.data:
            symbol = scope.names.get(data.name.key)
            if symbol is not None and getattr(symbol.type, "key", None) == "RAWBYTES":
                return True
    return False


def _bytes_key(program, symbol, routine: int) -> Optional[Key]:
    if symbol is None or symbol.by_reference or symbol.optional or symbol.storage != "VAR" or \
            getattr(symbol.type, "key", None) != "RAWBYTES":
        return None
    if symbol.kind == LOCAL_DATA:
        return ("L", routine, symbol.slot)
    if symbol.kind == GLOBAL_DATA and not program.task_entries:
        return ("G", symbol.slot)
    return None


def _count_literal(expr, low: int, high: int) -> bool:
    return isinstance(expr, ast.NumLiteral) and float(expr.value).is_integer() and \
        low <= expr.value <= high


class SentCounters(_Analysis):
    """``relevance``'s analysis with a pack of a counter into bytes only sent read as not
    reading the counter; ``sent_counters()`` then tells which such counters the rest of the
    program leaves irrelevant (module docstring)."""

    def __init__(self, program):
        super().__init__(program)
        self.sent_bytes = sent_only_bytes(program)
        self.packed: dict[Key, set] = {}      # counter -> the bytes it is packed into
        self.packs: dict[Key, list] = {}      # counter -> the spans of those packs
        self.not_counting: set = set()        # data written otherwise than as a count

    def assignment(self, statement: ast.Assignment) -> None:
        target = statement.target
        if isinstance(target, ast.NameRef):
            key = self.key(target.name)
            if key is not None and not self._counts(key, target, statement.value):
                self.not_counting.add(key)
        super().assignment(statement)

    def _counts(self, key: Key, target: ast.NameRef, value) -> bool:
        if _count_literal(value, 0, COUNT_START_MAX):
            return True
        if isinstance(value, ast.Binary) and value.op == "+":
            for data, step in ((value.left, value.right), (value.right, value.left)):
                if isinstance(data, ast.NameRef) and self.key(data.name) == key and \
                        _count_literal(step, 1, STEP_MAX):
                    return True
        return False

    def statement(self, statement) -> bool:
        if type(statement).__name__ == "ProcedureCall" and \
                isinstance(statement.name, ast.Name) and statement.name.key == "PACKRAWBYTES" \
                and self.routine.scope.lookup("PACKRAWBYTES") is None:
            counter = self._sent_counter(statement)
            if counter is not None:
                key, value, into = counter
                for argument in statement.args:
                    if argument.value is not value:
                        self.seed(argument)
                self.packed.setdefault(key, set()).add(into)
                self.packs.setdefault(key, []).append(statement.span)
                return True
        return super().statement(statement)

    def _sent_counter(self, call) -> Optional[tuple]:
        """(counter key, its Value expression, the bytes' key) of a pack of a num named
        directly, at a constant wide \\IntX size, into bytes only sent; else None."""
        value = argument_expression(call, "VALUE", 0)
        into = argument_expression(call, "RAWDATA", 1)
        size = argument_expression(call, "INTX", -1)
        if not isinstance(value, ast.NameRef) or not isinstance(into, ast.NameRef) or \
                size is None or self._size(size) is None:
            return None
        bytes_key = self.key(into.name)
        if bytes_key not in self.sent_bytes:
            return None
        symbol = self.symbol(value.name)
        if symbol is None or symbol.by_reference or symbol.optional or \
                isinstance(symbol.type, ArrayType) or getattr(symbol.type, "key", None) != "NUM" \
                or symbol.storage == "PERS" and self.program.task_entries:
            return None          # (a PERS of several loaded tasks: each task has its own)
        key = self.key(value.name)
        return (key, value, bytes_key) if key is not None else None

    def _size(self, expr) -> Optional[float]:
        if isinstance(expr, ast.NumLiteral):
            size = float(expr.value)
        elif isinstance(expr, ast.NameRef):
            symbol = self.symbol(expr.name)
            if symbol is None or symbol.kind != CONSTANT or \
                    not isinstance(symbol.value, (int, float)) or isinstance(symbol.value, bool):
                return None
            size = float(symbol.value)
        else:
            return None
        return size if size in WIDE_SIZES else None

    def sent_counters(self) -> set[Key]:
        """The packed counters that count as the module docstring says: the others are
        seeded (their packs read them after all)."""
        found = set()
        for key in self.packed:
            if key in self.not_counting or not self._starts_as_count(key):
                self.relevant.add(key)
            else:
                found.add(key)
        return found

    def _starts_as_count(self, key: Key) -> bool:
        if key[0] == "G":
            initial = self.program.globals[key[1]].initial
        else:
            initial = self.program.routines[key[1]].initial_locals[key[2]]
        return isinstance(initial, float) and initial.is_integer() and \
            0 <= initial <= COUNT_START_MAX
