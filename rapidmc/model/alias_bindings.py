"""Which signals signal data may be bound to by AliasIO or GetDataVal, read from the code.

An interrupt ordered on signal data (``ISignalDI alias_diStart, 1, intStart``) watches
the signal an ``AliasIO`` bound to it.  Not knowing which, the check keeps every free
input in the states (``inputs.observed_inputs``): with a controller's hundreds of
configured inputs, or a driver's 37 stand-in signals (``AliasIO`` names computed at run
time, checked with no I/O configuration), the combinations offered at each step are too
many to list (survey of issue 28).  The bindings are mostly plain to read::

    signalName := "pmFlow_diStart";
    AliasIO signalName, alias_diStartFlow;

``alias_bindings`` reads, for each global signal data object, the signals every binding
of the program may give it:

* an ``AliasIO`` whose first argument is a configured signal named directly, a string
  literal, or a routine's or module's string data whose last assignment before the call,
  in the same statement list, is a literal: that signal (with no configuration loaded, a
  name no known signal has gives the call's stand-in, ``library.signals``);
* an ``AliasIO`` given any other string: every signal of the target's kind the program
  knows, and the call's stand-in (a stand-in is found by no name, and a signal of another
  kind raises ERR_ALIASIO_TYPE);
* anything else (``GetDataVal`` into signal data, an ``AliasIO`` from signal data): not
  known, so the data object has no entry.

The data bound is followed to the global data it stands for: named directly; a routine's
own data binds no global data; a parameter stands for the argument each call of its
routine passes, and on through the callers' parameters (more than rapidmc's calls bind: a
signal parameter holds the signal bound at the call); an element of a global array counts
for the array.  When a target cannot be followed (a late-bound call may pass the
argument, an expression other than these), nothing is known (None).
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.configured_signals import walk_routine
from ..semantics.library.arguments import argument_expression
from ..semantics.library.signals import span_key
from ..semantics.scope import GLOBAL_DATA, LOCAL_DATA, SIGNAL
from ..semantics.types import SEMI_VALUE
from .reduction.numeric_updates import target_root

UNKNOWN = -1                # a binding whose signal this cannot read


def alias_bindings(program) -> Optional[dict]:
    """Global slot of signal data -> frozenset of the indices of the signals the program's
    bindings may give it (no entry: one of them is not known); None when a binding's target
    cannot be followed to the global data it stands for."""
    found: dict = {}
    targets = _Targets(program)
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            continue
        literals = _literal_names(routine)
        for node in walk_routine(routine.ast):
            if not isinstance(node, ast.ProcedureCall):
                continue
            if node.name.key == "ALIASIO":
                target = argument_expression(node, "ToSignal", 1)
                signals = _aliased(program, routine, node, literals)
            elif node.name.key == "GETDATAVAL":
                target = argument_expression(node, "Value", 1)
                if not _is_signal_data(routine, target):
                    continue
                signals = {UNKNOWN}
            else:
                continue
            slots = targets.slots(routine, target)
            if slots is None:
                return None
            for slot in slots:
                found.setdefault(slot, set()).update(signals)
    return {slot: frozenset(indices) for slot, indices in found.items()
            if UNKNOWN not in indices}


def _is_signal_data(routine, target) -> bool:
    root = target_root(target)
    if not isinstance(root, ast.NameRef):
        return True                 # (not followed: taken as a binding, unknown)
    rapid_type = getattr(routine.scope.lookup(root.name.key), "type", None)
    rapid_type = getattr(rapid_type, "element", rapid_type)
    return getattr(rapid_type, "kind", None) == SEMI_VALUE


def _aliased(program, routine, call: ast.ProcedureCall, literals: dict) -> set:
    """The signals one AliasIO call may bind (``UNKNOWN`` among them when not known)."""
    source = argument_expression(call, "FromSignal", 0)
    described = getattr(program, "alias_sources", {}).get(span_key(call.span))
    if described is None:
        return {UNKNOWN}
    kind, stand_in, by_name = described
    name = None
    if isinstance(source, ast.StringLiteral):
        name = source.value
    elif isinstance(source, ast.NameRef):
        symbol = routine.scope.lookup(source.name.key)
        if symbol is not None and symbol.kind == SIGNAL:
            return {symbol.slot}
        name = literals.get(id(call))
    if not by_name:
        return {UNKNOWN}
    if name is not None:
        signal = program.signal(name.upper())
        if signal is not None and not signal.named_at_run_time:
            return {signal.index}
        return set() if stand_in is None else {stand_in}     # (else ERR_ALIASIO_DEF)
    known = {signal.index for signal in program.signals
             if signal.kind == kind and not signal.named_at_run_time}
    return known if stand_in is None else known | {stand_in}


class _Targets:
    """The global data slots a bound expression stands for, through parameters."""

    def __init__(self, program):
        self.program = program
        self.calls: Optional[dict] = None        # routine name key -> [(caller, call)]
        self.late_bound = False

    def slots(self, routine, target, visited: Optional[set] = None) -> Optional[set]:
        root = target_root(target)
        symbol = routine.scope.lookup(root.name.key) if isinstance(root, ast.NameRef) else None
        if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA):
            return None
        if symbol.kind == GLOBAL_DATA:
            return {symbol.slot}                 # (an element counts for its array)
        parameter = self._parameter(routine, root.name.key)
        if parameter is None:
            return set()                         # the routine's own data: no global data
        if root is not target:
            return None                          # (an element of a parameter: not followed)
        return self._passed(routine, parameter, set() if visited is None else visited)

    @staticmethod
    def _parameter(routine, key: str):
        for position, parameter in enumerate(p for p in routine.ast.parameters
                                             if not p.optional):
            if parameter.name.key == key:
                return parameter, position
        for parameter in routine.ast.parameters:
            if parameter.name.key == key:
                return parameter, -1
        return None

    def _passed(self, routine, parameter, visited: set) -> Optional[set]:
        """The global slots the calls of ``routine`` pass for ``parameter``, and on through
        the callers' parameters (``visited``: the parameters already on the way)."""
        key = (id(routine), parameter[0].name.key)
        if key in visited:
            return set()                         # (a recursion adds nothing new)
        visited.add(key)
        self._index_calls()
        if self.late_bound:
            return None
        slots: set = set()
        for caller, call in self.calls.get(routine.ast.name.key, ()):
            argument = argument_expression(call, parameter[0].name.key, parameter[1])
            if argument is None:
                continue
            more = self.slots(caller, argument, visited)
            if more is None:
                return None
            slots |= more
        return slots

    def _index_calls(self) -> None:
        if self.calls is not None:
            return
        self.calls = {}
        for caller in self.program.routines:
            if caller.ast is None or getattr(caller, "scope", None) is None:
                continue
            for node in walk_routine(caller.ast):
                if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                    self.calls.setdefault(node.name.key, []).append((caller, node))
                elif isinstance(node, ast.LateBindingCall) and node.args:
                    self.late_bound = True


def _literal_names(routine) -> dict:
    """id of an AliasIO call -> the string literal its first argument, a data name, was
    last assigned, on every path to the call."""
    names: dict = {}
    handlers = (routine.ast.backward, routine.ast.undo,
                routine.ast.error.body if routine.ast.error else None)
    # (a handler may write the data and RETRY a statement of the body)
    volatile = {node.name.key for handler in handlers for statement in handler or ()
                for node, _ in ast.walk(statement) if isinstance(node, ast.NameRef)}
    reader = _Literals(routine.scope.lookup, volatile, names)
    for body in (routine.ast.body,) + handlers:
        reader.statements(body or (), {})
    return names


class _Literals:
    """The string literals a routine's data holds where its AliasIO calls are."""

    def __init__(self, lookup, volatile: set, names: dict):
        self.lookup = lookup
        self.volatile = volatile        # names never taken as known
        self.names = names

    def statements(self, statements, known: dict) -> None:
        """``known``: data name (upper case) -> the literal it was last assigned, on every
        path to the statement at hand (a label, which a GOTO may reach, knows nothing; a
        loop's body starts without the names it mentions)."""
        for statement in statements:
            if isinstance(statement, ast.Label):
                known.clear()
                continue
            if isinstance(statement, ast.Assignment) and isinstance(statement.target,
                                                                     ast.NameRef):
                key = statement.target.name.key
                if isinstance(statement.value, ast.StringLiteral) and self._data(key) \
                        and key not in self.volatile:
                    known[key] = statement.value.value
                else:
                    known.pop(key, None)
                continue
            if isinstance(statement, ast.ProcedureCall) and statement.name.key == "ALIASIO":
                source = argument_expression(statement, "FromSignal", 0)
                if isinstance(source, ast.NameRef) and source.name.key in known:
                    self.names[id(statement)] = known[source.name.key]
            # anything else may write the data it names: forget them, and read the blocks
            # inside with what is known here (what they write is forgotten after)
            for node, _ in ast.walk(statement):
                if isinstance(node, ast.NameRef):
                    known.pop(node.name.key, None)
            for block in _blocks(statement):
                self.statements(block, dict(known))

    def _data(self, key: str) -> bool:
        symbol = self.lookup(key)
        return symbol is not None and symbol.kind in (GLOBAL_DATA, LOCAL_DATA)


def _blocks(statement) -> list:
    """The statement lists inside a compound statement."""
    if isinstance(statement, ast.If):
        return [branch.body for branch in statement.branches] + [statement.else_body or ()]
    if isinstance(statement, ast.CompactIf):
        return [(statement.statement,)]
    if isinstance(statement, (ast.While, ast.For)):
        return [statement.body]
    if isinstance(statement, ast.Test):
        return [case.body for case in statement.cases] + [statement.default or ()]
    return []
