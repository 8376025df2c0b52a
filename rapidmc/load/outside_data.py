"""PERS data written from outside the loaded code, and the values it may take (issue 28).

A persistent that some loaded task reads and no loaded code can write (see
``shared_data.data_uses``) is written, if at all, by something rapidmc does
not load: another task checked apart (``--task``), an encrypted module, a PC
through its interfaces.  Keeping its initial value makes a ``WaitUntil
startRob`` wait forever although the controller's PLC sets it.  So, like a
free input, each read of such data in the program's code takes any value of a
finite domain (``semantics.expressions`` compiles the read as a choice); the
stored value never changes.  The domain is per component (records) and per
element type (arrays), for the value types only:

* bool: both values;
* num, dnum and string: the initial values and the constants the code
  compares the component with (``= <>``, TEST ... CASE; a string compared
  through ``StrPart(data, start, n) = "text"``: the text at that start; one
  cut at a separator with StrFind: a text of that many fields, ``_note_fields``),
  plus one other value; with an ordering comparison (``< <= > >=``), one value per place
  among those numbers (each number, one between each two, one beyond each
  end), as for the free analog inputs of ``input_domains``.  A component the
  code never compares with anything keeps its initial value: no branch of the
  program can tell its values apart, and inventing values for an index or a
  divisor would report errors the data never causes.  In an array, each element
  keeps its own (its stored value is read), never a mix of the elements' values.

Data only the outside writes that is declared without a value, in the loaded
code and in the tasks of the backup left out (``Linker._values_declared_elsewhere``
takes such a task's value first), holds zeros no writer gave: it starts with a valid
value instead (``unset_value``: 1 for each number, the identity rotation for each
orientation), so that no index 0, divisor 0 or zero quaternion is reported that
rests only on the missing value; ``--fixed-outside-data`` keeps the zeros.  Data
the loaded code writes is its own: declared without a value, it starts at zero.

PERS data the loaded code writes too, when a party left out may also write it
(``other_writers``: a task not loaded, a task's encrypted modules), is chosen
as well, where a wait reads it: a WaitUntil condition, and the condition of a
polling loop (WHILE; IF ... GOTO back, in a branch or the ELSE:
``statements.branch``), takes the stored
value or any value of the same domain, so the wait may end, and stores a value
other than the stored one (the other party wrote it just before: the code after the
wait reads what the wait saw; a WaitUntil keeps it only where it ends, so a wait no
value ends stays a deadlock: ``library.waits``); the stored value comes first among the
choices (``expressions.stored_first``), and where the other party is only assumed from a
wait no loaded write ends (``awaited_from_outside``), its values leave out the constants
the loaded code writes (``_client_writes``: a client fills the mailbox, the task empties
it); every other read takes the
stored value (the loaded code's own protocol), so no branch runs on values the
other writer's protocol may never produce together with the rest of the data.

A read of a whole record (an argument, an assignment from it) chooses each of its
components that has several values, together, so the record passed on holds what
reads of its components could give (``ExpressionCompiler._outside_whole``); a
whole array chooses each element's components likewise when their combinations are
at most ``WHOLE_ARRAY_CHOICES`` (64), else it reads the stored value (choosing
would multiply the successors by the elements' domains); in a wait or a poll, up to
``WAIT_CHOICES`` (4096: the wait keeps no state for the values that do not end
it), beyond which the assumption says the wait reads the stored value.  The
properties' atoms read stored values: a read of data only the outside writes that
a property names (``observed``) stores the value it took, so the program runs as it
does unobserved and the atoms see the value its last read took (the assumption says
so).  ``check --fixed-outside-data`` keeps every such data object at its initial
value, as before.  The verdicts name each object and its
values under ``assumes:`` (``findings.assumptions``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

from .. import ast
from ..semantics.configured_signals import COMPARISONS
from ..semantics.program import ENVIRONMENT_NAMESPACE
from ..semantics.scope import CONSTANT, GLOBAL_DATA
from ..semantics.types import RECORD, ArrayType, RapidType, default_value
from ..semantics.values import format_value, to_dnum
from .awaited_from_outside import VALUE_KEYS, awaited_from_outside
from .other_writers import Counting
from .call_graph import TaskRoutines
from .encrypted import from_encrypted_interface
from .input_domains import analog_points, number_value
from .shared_data import data_uses, writes_data_by_name
from .waited_data import waited_reads

ORDERINGS = frozenset({"<", "<=", ">", ">="})
MANY_COMPONENTS = 6              # a record with more is described by its varying components
AWAITED_WRITER = "a PC or an HMI"      # assumed where no loaded write ends a wait
IDENTITY_ROTATION = (1.0, 0.0, 0.0, 0.0)
# what the verdicts say of data written only outside and declared without a value
UNSET_VALUE_TEXT = ("it starts with 1 for each number and identity rotations, not zeros "
                    "(--fixed-outside-data keeps zeros)")


@dataclass(frozen=True)
class OutsideData:
    """One PERS data object written from outside: the domain of each value component.

    ``domains``: component path (upper-case component names from the data object,
    array indices left out) -> the values a read of that component may give (None: the
    stored value, ``domain``)."""

    slot: int
    name: str
    span: object
    domains: dict
    # who else writes it when loaded code writes it too (load.other_writers), else None:
    # then a read takes the stored value or any value of the domain
    also_written_by: Optional[str] = None
    # a property's formula names it: a read of data only the outside writes keeps the value
    # it took, so the atoms read the value the program last read (``observed_names``)
    observed: bool = False
    # the WaitUntil or poll (``WaitUntil at file:line``) that no write of the loaded code
    # ends, when the other writer is only assumed from it (``awaited_from_outside``), else None
    awaited_at: Optional[str] = None
    # declared without a value (here and in every task read) and written only outside:
    # it starts with ``unset_value`` instead of the type's zeros (the linker stores it)
    unset: bool = False
    initial: object = None
    # (file, line, column) of the IF conditions in loops that poll it, when the other writer
    # is only assumed (``awaited_from_outside.polled``): read there as in a wait
    polled_at: frozenset = frozenset()
    # the tasks left out that write it, when each of their writes is a constant or a FOR
    # loop's count (``other_writers.written_constants``): its domain holds only what they
    # write, so the verdicts assume that no other party (a PC, an HMI) writes it
    written_by_tasks: Optional[str] = None
    # data only the outside writes that a wait of the loaded code reads (``waited_data``):
    # the first such wait (``WaitUntil at file:line``), and the component paths the waits
    # read.  Those change only while a task waits or polls for them: a wait's read chooses
    # and stores, other reads take the stored value (``check --outside-writes-anytime``:
    # None, every read chooses)
    waited_at: Optional[str] = None
    waited_paths: frozenset = frozenset()

    @property
    def written_by_waits(self) -> bool:
        """Whether some wait's read stores the value it takes: data the loaded code
        writes too, or data a wait of it reads."""
        return self.also_written_by is not None or bool(self.waited_paths)

    def stored_by_waits(self, path: tuple) -> bool:
        """Whether a wait's read of the component at ``path`` stores the value it takes,
        and other reads take the stored value (else every read chooses afresh)."""
        return self.also_written_by is not None or \
            any(path[:len(waited)] == waited for waited in self.waited_paths)

    def domain(self, path: tuple) -> Optional[tuple]:
        """The values a read of the component may take; None: the stored value (a
        component no code compares, whose elements hold different values)."""
        return self.domains.get(path)

    def describe(self) -> str:
        """``FALSE or TRUE`` / ``rec.a: 0 or 1; rec.b: ...`` per component; a record of
        many components names only those that may take several values."""
        parts = []
        shown_paths = self.domains
        if len(self.domains) > MANY_COMPONENTS:
            shown_paths = {path: values for path, values in self.domains.items()
                           if values is not None and len(values) > 1}
        for path, values in shown_paths.items():
            shown = "each element's initial value" if values is None else \
                " or ".join(format_value(v) for v in values) if len(values) <= 8 else \
                f"{len(values)} values from {format_value(values[0])} to {format_value(values[-1])}"
            parts.append(f"{self.name}{''.join('.' + p.lower() for p in path)}: {shown}"
                         if path else shown)
        left = len(self.domains) - len(shown_paths)
        if left and not parts:
            return "its initial value"
        if left:
            parts.append(f"{left} other components: their initial values")
        return "; ".join(parts)


def outside_data(linker) -> dict:
    """Slot -> ``OutsideData`` for each PERS some loaded task reads and no loaded code writes
    (the linker's routines prepared, not yet compiled).  Data a property's atom may name
    (the linker's option ``observed_names``) is marked ``observed``: atoms read stored
    values, so its reads store the value they take, and the program runs as it does when
    no property names it.  Empty when the code writes data named by a string
    (``SetDataVal``): then any persistent may be written."""
    routines = [r for r in linker.routines if r.namespace != ENVIRONMENT_NAMESPACE]
    if writes_data_by_name(routines):
        return {}
    read, written = set(), set()
    for namespace in sorted({routine.namespace for routine in routines}):
        task_read, task_written = data_uses(linker, namespace)
        read |= task_read
        written |= task_written
    observed = linker.options.get("observed_names", frozenset())
    writers = linker.options.get("outside_writers") or {}
    task_writes = linker.options.get("written_constants") or {}
    awaited = awaited_from_outside(linker, routines)      # a wait only a client ends
    # data only the outside writes that a wait reads: it changes only in waits and polls
    waited = {} if linker.options.get("outside_writes_anytime") else \
        waited_reads(routines, read - written)
    chosen = {data.slot: data for data in linker.globals
              if data.storage == "PERS" and data.namespace != ENVIRONMENT_NAMESPACE
              and data.slot in read
              and (data.slot not in written or (data.key in writers and _shared(data))
                   or (data.slot in awaited and _shared(data)))
              and data.span is not None
              and (not _is_stub(data.span) or _flag_like(data))}
    if not chosen:
        return {}
    compared = _compared_constants(routines, chosen)
    chosen = {slot: data for slot, data in chosen.items()
              if not _is_stub(data.span) or _awaits_values(data, compared.get((slot, ())))}
    found = {}
    for slot, data in chosen.items():
        domains = {}
        # the tasks left out write only these values; not for a wait no loaded write ends
        # (``awaited_from_outside``): where their constants are all the loaded code's are
        # too (a command word both tasks clear), the value that ends it comes from a client
        known = task_writes.get(data.key) if slot not in awaited else None
        writes = _written_leaves(data.type, known.pairs) if known is not None else {}
        start = unset_value(data.type) if data.declared_without_value \
            and slot not in written and known is None else data.initial
        unset = start != data.initial          # (numbers or orientations in place of zeros)
        for path, leaf_type, initial in _leaves(data.type, start):
            if known is not None and writes.get(path, ((), (), False))[2] is False:
                domains[path] = _written_domain(leaf_type, initial, compared.get((slot, path)),
                                                writes.get(path, ((), (), False)), not path)
            else:
                domains[path] = _domain(leaf_type, initial, compared.get((slot, path)))
        if domains:
            # a known writer left out names itself; else a wait only a client ends names one
            awaited_at, polled_at = None, frozenset()
            if slot in written and data.key not in writers and slot in awaited:
                awaited_at, own, polled_at = awaited[slot]
                domains = _client_writes(domains, own)
            writer = writers.get(data.key) or (AWAITED_WRITER if awaited_at else None)
            waited_at, waited_paths = None, frozenset()
            # (not data a task of the backup left out writes: a task writes at any time)
            if slot not in written and slot in waited and data.key not in writers:
                waited_at, waited_paths, polled_at = waited[slot]
            found[slot] = OutsideData(slot, data.name, data.span, domains,
                                      writer if slot in written else None,
                                      data.key in observed, awaited_at, unset,
                                      start if unset else None, polled_at,
                                      known.writers() if known is not None else None,
                                      waited_at, waited_paths)
    return found


def _client_writes(domains: dict, own: frozenset) -> dict:
    """The domain of data a client is only assumed to write (a wait no loaded write ends,
    ``awaited_from_outside``): not the constants the loaded code writes to it itself (the
    mailbox's "empty", which the task writes back once it has taken a command).  A wait's
    read still takes the stored value, which may be one of those; without them a wait
    after another (``WaitUntil cmd <> ""; WaitUntil StrPart(cmd, 1, 10) = "workoffset"``)
    no longer sees the client empty the data in between, which no client filling a
    mailbox does (the value the first wait saw stays a choice: ``stored_first``)."""
    kept = {path: tuple(v for v in values if v not in own) if values is not None else None
            for path, values in domains.items()}
    return kept if all(values is None or values for values in kept.values()) else domains


def unset_value(rapid_type):
    """The value data written only from outside and declared without a value starts with:
    a valid value of its type, not its zeros.  The zeros are no value the writer gave
    (the backup holds none), and an index 0, a divisor 0 or a zero quaternion fails where
    the written data would not: each number is 1 (an index of every array, a non-zero
    divisor, a positive mass), each orientation the identity rotation; bool and string
    keep FALSE and ""."""
    if isinstance(rapid_type, ArrayType):
        return _unset_array(rapid_type.element, rapid_type.dims)
    if not isinstance(rapid_type, RapidType):
        return default_value(rapid_type)
    if rapid_type.key == "ORIENT":
        return IDENTITY_ROTATION
    if rapid_type.key == "NUM":
        return 1.0
    if rapid_type.key == "DNUM":
        return to_dnum(1.0)
    if rapid_type.kind == RECORD and rapid_type.components:
        return tuple(unset_value(component.type) for component in rapid_type.components)
    return default_value(rapid_type)


def _unset_array(element, dims: tuple) -> tuple:
    if len(dims) == 1:
        return tuple(unset_value(element) for _ in range(dims[0] or 0))
    return tuple(_unset_array(element, dims[1:]) for _ in range(dims[0] or 0))


def _shared(data) -> bool:
    """Whether other tasks see the data object: neither TASK PERS nor LOCAL to its module."""
    return not data.task_local and not data.local


def _flag_like(data) -> bool:
    """A stub's PERS of type bool, num, dnum or string: a handshake flag or a command
    another task or a PC writes (held-out survey, issue 28: ``IF newTarget = TRUE`` polled
    in a loop, declared by the stubs since the task that sets it is not loaded).  A stub's
    record (a tooldata, a wobjdata, a robtarget) is the cell's configuration: it keeps its
    neutral value, or every bool component would double the states."""
    return getattr(data.type, "key", None) in VALUE_KEYS


def _awaits_values(data, compared: Optional[list]) -> bool:
    """Whether a stub's flag-like PERS is data another party writes rather than a named
    constant of a module not given: a bool, or a num or string the code compares with a
    constant (``smIndx = "d"``, ``TEST pathChoice CASE 1``).  One compared only with other
    data (``IF nAxis = axisX``, ``CASE STATION_LOAD:``) stands for a constant: it keeps the
    value the stubs gave it (``stubs``: distinct numbers for names compared in turn)."""
    return getattr(data.type, "key", None) == "BOOL" or bool(compared and compared[0])


def _is_stub(span) -> bool:
    """Data a user's ``rapidmc stubs`` module declares: its own assumption (neutral value).
    The interface of encrypted modules is no such module: the encrypted code may write
    its PERS (``encrypted``)."""
    from .stubs.module_text import STUB_MARKER
    from ..diagnostics import SourceCache
    if from_encrypted_interface(span.file):
        return False
    return any(STUB_MARKER in (SourceCache.line(span.file, n) or "") for n in range(1, 4))


def data_path(expr) -> Optional[tuple]:
    """(root NameRef, component path) of a read ``name``, ``name.c``, ``name{i}.c`` ...
    (None for any other expression)."""
    path = []
    while isinstance(expr, (ast.Component, ast.Index)):
        if isinstance(expr, ast.Component):
            path.append(expr.name.key)
        expr = expr.base
    if not isinstance(expr, ast.NameRef):
        return None
    return expr, tuple(reversed(path))


def _leaves(rapid_type, value, path: tuple = ()):
    """(component path, leaf type, the set of its initial values) per value component."""
    if isinstance(rapid_type, ArrayType):
        values = _elements(value, len(rapid_type.dims))
        merged: dict = {}
        for element in values:
            for leaf_path, leaf_type, initial in _leaves(rapid_type.element, element, path):
                merged.setdefault((leaf_path, leaf_type), set()).update(initial)
        for (leaf_path, leaf_type), initial in merged.items():
            yield leaf_path, leaf_type, initial
        return
    if not isinstance(rapid_type, RapidType):
        return
    if rapid_type.key in VALUE_KEYS:
        yield path, rapid_type, ({value} if value is not None else set())
    elif rapid_type.components and isinstance(value, (tuple, list)):
        for component, part in zip(rapid_type.components, value):
            yield from _leaves(component.type, part, path + (component.key,))


def _elements(value, rank: int) -> list:
    items = [value]
    for _ in range(rank):
        items = [item for outer in items if isinstance(outer, (tuple, list)) for item in outer]
    return items


def _compared_constants(routines, chosen: dict) -> dict:
    """(slot, path) -> [constants, ordered?, compared with a non-constant?] from the code."""
    found: dict = {}
    words: dict = {}            # (slot, path) -> the words StrPart compares at the start
    passed = _passed_whole(routines, chosen)
    for routine in routines:
        if routine.ast is None:
            continue
        scope = routine.scope
        held = {name: slot for (key, name), slots in passed.items() if key == routine.key
                for slot in slots}
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.Binary) and node.op in COMPARISONS:
                for side, other in ((node.left, node.right), (node.right, node.left)):
                    _note(found, chosen, scope, side, [other], node.op in ORDERINGS)
                    _note_part(found, words, chosen, scope, side, other)
                    _note_held(found, chosen, held, scope, side, [other], node.op in ORDERINGS)
            elif isinstance(node, ast.Test):
                cases = [value for case in node.cases for value in case.values]
                _note(found, chosen, scope, node.subject, cases, False)
                _note_held(found, chosen, held, scope, node.subject, cases, False)
    _note_fields(found, words, routines, chosen)
    return found


def _passed_whole(routines, chosen: dict) -> dict:
    """(routine key, parameter key) -> slots of chosen value data (bool, num, dnum,
    string) passed whole to that parameter, directly or through parameters of other
    routines (``executeState pathChoice, stateChoice, ...``, then ``findState(stateChoice)``
    compares it with 1 and 2): each such comparison is one with the data."""
    own = TaskRoutines(routines)
    held: dict = {}
    changed = True
    while changed:
        changed = False
        for routine in own.routines:            # every task's (each has its own main)
            mine = {name: slots for (key, name), slots in held.items() if key == routine.key}
            for node, _ in ast.walk(routine.ast):
                callee = own.called(routine, node.name.key) \
                    if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) else None
                if callee is None:
                    continue
                required = [p.name.key for p in callee.ast.parameters if not p.optional]
                positional = [a for a in node.args if a.name is None]
                for position, arg in enumerate(positional[:len(required)]):
                    slots = _whole_slots(arg.value, routine.scope, chosen) \
                        | mine.get(getattr(getattr(arg.value, "name", None), "key", None),
                                   frozenset())
                    key = (node.name.key, required[position])
                    if slots - held.get(key, frozenset()):
                        held[key] = held.get(key, frozenset()) | slots
                        changed = True
    return held


def _whole_slots(expr, scope, chosen: dict) -> frozenset:
    if not isinstance(expr, ast.NameRef):
        return frozenset()
    symbol = scope.lookup(expr.name.key)
    if symbol is None or symbol.kind != GLOBAL_DATA or symbol.slot not in chosen \
            or getattr(chosen[symbol.slot].type, "key", None) not in VALUE_KEYS:
        return frozenset()
    return frozenset({symbol.slot})


def _note_held(found: dict, chosen: dict, held: dict, scope, side, others: list,
               ordered: bool) -> None:
    """A comparison of a parameter that holds chosen data (``_passed_whole``)."""
    if not isinstance(side, ast.NameRef) or side.name.key not in held:
        return
    symbol = scope.lookup(side.name.key)
    if symbol is None or symbol.kind == GLOBAL_DATA:
        return
    slot = held[side.name.key]
    for other in others:
        _spread(found, slot, (), chosen[slot].type, other, scope, ordered)


def _note(found: dict, chosen: dict, scope, side, others: list, ordered: bool) -> None:
    located = data_path(side)
    if located is None:
        return
    ref, path = located
    symbol = scope.lookup(ref.name.key)
    if symbol is None or symbol.slot not in chosen or symbol.kind != GLOBAL_DATA:
        return
    part_type = _part_type(chosen[symbol.slot].type, path)
    for other in others:
        _spread(found, symbol.slot, path, part_type, other, scope, ordered)


def _note_part(found: dict, words: dict, chosen: dict, scope, side, other) -> None:
    """``StrPart(data, start, length) = "text"`` with constant numbers and a text of that
    length: the data holding the text at ``start`` (spaces before it) is one value to
    offer, the value that makes the part equal (``WaitUntil StrPart(SocketStr,1,10) =
    "workoffset"``: a command with its parameters after the word)."""
    if not (isinstance(side, ast.FunctionCall) and side.name.key == "STRPART"):
        return
    values = [a.value for a in side.args if a.kind == ast.REQUIRED]
    if len(values) != 3:
        return
    start, length = number_value(values[1], scope), number_value(values[2], scope)
    text = _constant(other, scope)
    if not isinstance(text, str) or start is None or length is None or start < 1 \
            or start != int(start) or len(text) != length:
        return
    _note(found, chosen, scope, values[0], [" " * (int(start) - 1) + text], False)
    located = data_path(values[0])
    symbol = scope.lookup(located[0].name.key) if located is not None else None
    if start == 1 and symbol is not None and symbol.slot in chosen:
        words.setdefault((symbol.slot, located[1]), set()).add(text)


MAX_FIELDS = 12           # the most separators a value offered for a parsed text holds


def _note_fields(found: dict, words: dict, routines, chosen: dict) -> None:
    """A string the code cuts into fields (``StrFind(data, start, ",")``, then StrPart
    and StrToVal at the positions found) also takes a text of that many fields: "1"
    after each separator, as many as the routine that searches most for it looks for
    (a search in a FOR loop of constant bounds counts once per round), after each word
    a StrPart compares at the start (``workoffset,1,1,1,1,1,1``) and alone
    (``1,1,1``).  Without it every value of the domain lacks the separators, and the
    parse after a wait raises where a PC's message would not."""
    searched: dict = {}              # (slot, path, separator) -> most searches in a routine
    for routine in routines:
        if routine.ast is None:
            continue
        counts: dict = {}
        for node, parents in ast.walk(routine.ast):
            key = _field_search(node, chosen, routine.scope)
            if key is not None:
                rounds = 1
                for parent in parents:
                    if isinstance(parent, ast.For):
                        rounds *= _rounds(parent, routine.scope)
                counts[key] = counts.get(key, 0) + rounds
        for key, count in counts.items():
            searched[key] = max(searched.get(key, 0), count)
    for (slot, path, separator), count in searched.items():
        entry = found.setdefault((slot, path), [set(), False, False])
        fields = (separator + "1") * min(count, MAX_FIELDS)
        entry[0].update({"1" + fields} | {word + fields for word in words.get((slot, path), ())
                                          if separator not in word})


def _field_search(node, chosen: dict, scope) -> Optional[tuple]:
    """(slot, path, separator) for ``StrFind(data, start, "c")`` on chosen string data."""
    if not (isinstance(node, ast.FunctionCall) and node.name.key == "STRFIND"):
        return None
    values = [a.value for a in node.args if a.kind == ast.REQUIRED]
    if len(values) != 3:
        return None
    separator = _constant(values[2], scope)
    located = data_path(values[0])
    if not isinstance(separator, str) or len(separator) != 1 or located is None:
        return None
    ref, path = located
    symbol = scope.lookup(ref.name.key)
    if symbol is None or symbol.slot not in chosen or symbol.kind != GLOBAL_DATA:
        return None
    return symbol.slot, path, separator


def _rounds(loop, scope) -> int:
    """The rounds of a FOR loop with constant bounds (1 when not constant)."""
    start, stop = number_value(loop.start, scope), number_value(loop.stop, scope)
    step = number_value(loop.step, scope) if loop.step is not None else 1.0
    if start is None or stop is None or not step:
        return 1
    return max(1, int((stop - start) / step) + 1)


def _part_type(rapid_type, path: tuple):
    """The type of the part of a data object under a component path (indices left out)."""
    for key in path:
        while isinstance(rapid_type, ArrayType):
            rapid_type = rapid_type.element
        components = getattr(rapid_type, "components", None) or ()
        rapid_type = next((c.type for c in components if c.key == key), None)
    return rapid_type


def _spread(found: dict, slot: int, path: tuple, rapid_type, other, scope,
            ordered: bool) -> None:
    """Note what a part of type ``rapid_type`` is compared with, component by component:
    ``other`` is an expression, an aggregate (``stReact = ["Ready", "Ready"]``: each element
    is compared with its element) or a constant's value; None, unknown (a non-constant)."""
    if isinstance(other, ast.NameRef) and isinstance(_constant(other, scope), (tuple, list)):
        other = _constant(other, scope)          # a CONST aggregate: its value
    if isinstance(rapid_type, ArrayType):
        items = [other]                  # (an element read, ``a{i} = 1``, is compared whole)
        if isinstance(other, (ast.Aggregate, tuple, list)):
            for _ in rapid_type.dims:
                items = [item for outer in items for item in _items(outer, None)]
        for item in items:
            _spread(found, slot, path, rapid_type.element, item, scope, ordered)
        return
    components = getattr(rapid_type, "components", None)
    if isinstance(rapid_type, RapidType) and rapid_type.key not in VALUE_KEYS and components:
        for component, item in zip(components, _items(other, len(components))):
            _spread(found, slot, path + (component.key,), component.type, item, scope,
                    ordered)
        return
    entry = found.setdefault((slot, path), [set(), False, False])
    entry[1] = entry[1] or ordered
    value = other if isinstance(other, (bool, str, float)) else \
        _constant(other, scope) if other is not None else None
    if value is None or isinstance(value, (tuple, list)):
        entry[2] = True
    else:
        entry[0].add(value)


def _items(other, count: Optional[int]) -> list:
    """The parts of an aggregate or of a constant's aggregate value; else unknown parts."""
    if isinstance(other, ast.Aggregate):
        return list(other.items)
    if isinstance(other, (tuple, list)):
        return list(other)
    return [None] * (count or 1)


def _constant(expr, scope):
    if isinstance(expr, ast.NameRef):
        symbol = scope.lookup(expr.name.key)
        if symbol is not None and symbol.kind == CONSTANT and \
                isinstance(symbol.value, (tuple, list, str, bool)):
            return symbol.value        # (an aggregate's value is spread by _spread)
    if isinstance(expr, ast.StringLiteral):
        return expr.value
    if isinstance(expr, ast.BoolLiteral):
        return expr.value
    return number_value(expr, scope)


def _domain(leaf_type: RapidType, initial: set, compared) -> Optional[tuple]:
    """The values a read of a component may take.  A number or string no code compares
    keeps its initial value: where an array's elements hold different ones, None (each
    read takes its element's stored value; choosing among all the elements' values would
    read combinations no element holds, a zero rotation of two valid ones)."""
    if leaf_type.key == "BOOL":
        return (False, True)
    if compared is None and len(initial) > 1:
        return None
    constants, ordered, open_ended = compared if compared is not None else (set(), False, False)
    if leaf_type.key == "STRING":
        values = set(initial) | {c for c in constants if isinstance(c, str)}
        if constants or open_ended:
            values.add(_other_string(values))
        return tuple(sorted(values))
    convert = to_dnum if leaf_type.key == "DNUM" else float
    numbers = {convert(c) for c in constants if isinstance(c, float)}
    values = {convert(v) for v in initial if isinstance(v, (int, float))}
    if ordered and numbers:
        return tuple(convert(v) for v in analog_points(sorted(numbers | values)))
    values |= numbers
    if numbers or open_ended:
        values.add(convert(max(values, default=0.0) + 1))
    return tuple(sorted(values)) or (convert(0),)


def _written_leaves(rapid_type, pairs: tuple) -> dict:
    """Component path -> (constants, ``Counting``s, unknown?) that the writes ``pairs``
    (``other_writers.TaskWrites``) give each value component of data of ``rapid_type``."""
    found: dict = {}
    for path, value in pairs:
        part_type = _part_type(rapid_type, path)
        if isinstance(value, Counting):
            while isinstance(part_type, ArrayType):      # (an element assigned the count)
                part_type = part_type.element
            key = getattr(part_type, "key", None)
            entry = found.setdefault((0, path), [set(), False, False])
            if key in ("NUM", "DNUM"):
                entry[0].add(value)
            else:
                entry[2] = True
        elif part_type is not None:
            _spread(found, 0, path, part_type, value, None, False)
    leaves = {}
    for (_, path), (values, _, unknown) in found.items():
        counted = tuple(v for v in values if isinstance(v, Counting))
        leaves[path] = (tuple(v for v in values if not isinstance(v, Counting)), counted,
                        unknown)
    return leaves


ALL_WRITTEN = 16              # written constants a read may all take (more: one per class)


def _written_domain(leaf_type: RapidType, initial: set, compared, writes: tuple,
                    whole: bool = False) -> tuple:
    """The values a read of a component may take when the tasks left out write it only
    with ``writes`` (constants, ``Counting``s): its initial values and, for a num or
    string datum (``whole``: not a record's component, whose values chosen apart would
    mix records no task writes), every constant written when they are at most
    ``ALL_WRITTEN`` (each may be read, and arithmetic tells apart what no comparison
    does: a divisor ``n + 1`` where a task writes -1); else one written value for each
    set of values the code's comparisons cannot tell apart (each value a constant
    compared with; the rest, split by the ordering comparisons), so no read takes a
    value no task writes."""
    constants, counted = writes[0], writes[1]
    if leaf_type.key == "BOOL":
        return tuple(sorted(set(initial) | set(constants)))
    every = whole and len(constants) <= ALL_WRITTEN and leaf_type.key != "DNUM"
    if compared is None and every and not counted and len(initial) <= 1:
        return tuple(sorted(set(initial) | set(constants)))
    if compared is None or leaf_type.key == "DNUM":
        return _domain(leaf_type, initial, compared)     # (as when the writes are unknown)
    points, ordered, open_ended = compared
    if open_ended and not counted:
        return tuple(sorted(set(initial) | set(constants)))
    if open_ended:
        return _domain(leaf_type, initial, compared)     # (a count compared with data)
    candidates = sorted(constants)
    if counted:
        near = sorted({p for p in points if isinstance(p, float)} |
                      {c.start for c in counted})
        candidates += [v for point in analog_points(near)
                       for v in (point, math.floor(point) + 0.0, math.ceil(point) + 0.0)
                       if any(c.holds(v) for c in counted)]
    chosen = {_region(v, points, ordered): v for v in reversed(candidates)}
    for value in initial:
        chosen[_region(value, points, ordered)] = value
    kept = set(constants) if every else set()
    return tuple(sorted(set(chosen.values()) | set(initial) | kept))


def _region(value, points: set, ordered: bool) -> tuple:
    """Which values the comparisons with ``points`` cannot tell apart from ``value``:
    equal to one of them, else (ordered) between the same two."""
    if value in points:
        return ("equal", value)
    if not ordered or not isinstance(value, float):
        return ("other",)
    return ("between", sum(1 for p in points if isinstance(p, float) and p < value))


def _other_string(values: set) -> str:
    other, count = "", 0
    while other in values:
        count += 1
        other = f"other{count}"
    return other


def observed_names(properties) -> frozenset:
    """Upper-case identifiers in the properties' formulas: the data their atoms may read."""
    import re
    return frozenset(word.upper() for prop in properties
                     for word in re.findall(r"[A-Za-z][A-Za-z0-9_]*", prop.text))
