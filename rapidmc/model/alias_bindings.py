"""Which configured signals signal data may be bound to by AliasIO, read from the code.

An interrupt ordered on signal data (``ISignalDI alias_diStart, 1, intStart``) watches
the signal an ``AliasIO`` bound to it.  Not knowing which, the check keeps every free
input in the states (``inputs.observed_inputs``): with a controller's hundreds of
configured inputs, the combinations offered at each step are too many to list (a
palletizing cell's PickMaster server task, survey of issue 28).  The bindings are
mostly plain to read::

    signalName := "pmFlow_diStart";
    AliasIO signalName, alias_diStartFlow;

``alias_bindings`` reads, for each global signal data object, the configured signals
every ``AliasIO`` of the program may bind to it: its first argument a configured signal
named directly, a string literal, or a routine's or module's string data whose last
assignment before the call, in the same statement list, is a literal.  A data object
with one binding this cannot read has no entry; when an ``AliasIO`` binds something
other than global signal data named directly (a parameter, an element), nothing is
known (None).
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.library.arguments import argument_expression
from ..semantics.scope import GLOBAL_DATA, LOCAL_DATA, SIGNAL

UNKNOWN = object()          # a binding whose signal this cannot read


def alias_bindings(program) -> Optional[dict]:
    """Global slot of signal data -> frozenset of the indices of the configured signals
    the program's AliasIO calls may bind to it (no entry: one of them is not known);
    None when an AliasIO binds data this does not follow."""
    found: dict = {}
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            continue
        handlers = (routine.ast.backward, routine.ast.undo,
                    routine.ast.error.body if routine.ast.error else None)
        # (a handler may write the data and RETRY a statement of the body)
        written_in_handlers = {node.name.key for handler in handlers
                               for statement in handler or ()
                               for node, _ in ast.walk(statement)
                               if isinstance(node, ast.NameRef)}
        reader = _Reader(program, routine.scope.lookup, found, written_in_handlers)
        for body in (routine.ast.body,) + handlers:
            reader.statements(body or (), {})
        if reader.unfollowed:
            return None
    return {slot: frozenset(indices) for slot, indices in found.items()
            if UNKNOWN not in indices}


class _Reader:
    """The AliasIO calls of one routine, with the string literals its data holds."""

    def __init__(self, program, lookup, found: dict, volatile: set):
        self.program = program
        self.lookup = lookup
        self.found = found
        self.volatile = volatile        # names never taken as known
        self.unfollowed = False

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
                self._alias(statement, known)
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

    def _alias(self, call: ast.ProcedureCall, known: dict) -> None:
        source = argument_expression(call, "FromSignal", 0)
        target = argument_expression(call, "ToSignal", 1)
        symbol = self.lookup(target.name.key) if isinstance(target, ast.NameRef) else None
        if symbol is None or symbol.kind != GLOBAL_DATA:
            self.unfollowed = True
            return
        self.found.setdefault(symbol.slot, set()).add(self._signal(source, known))

    def _signal(self, source, known: dict):
        name = None
        if isinstance(source, ast.StringLiteral):
            name = source.value
        elif isinstance(source, ast.NameRef):
            symbol = self.lookup(source.name.key)
            if symbol is not None and symbol.kind == SIGNAL:
                name = source.name.text
            else:
                name = known.get(source.name.key)
        signal = self.program.signal(name.upper()) if name is not None else None
        return signal.index if signal is not None else UNKNOWN


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
