"""Interrupt orders on signal data that AliasIO binds, for the edge inputs (issue 28).

PickMaster's supervision task binds its signal data at start and orders interrupts on it::

    signalName := "pmFlow_diStart";
    AliasIO signalName, alias_diStartFlow;
    ...
    ISignalDI alias_diStartFlow, 1, pmIntStartFlow;

The input ``pmFlow_diStart`` is then watched by that order and read nowhere: an edge input
(``edge_inputs``), once this module tells what the names mean:

* ``watched``: the one signal an order on signal data watches, when the program's
  bindings (``alias_bindings``) give that data a single known signal;
* ``reads``: a use of such data other than an order or the AliasIO that binds it
  (``DInput(alias_x)``, ``WaitDI alias_x``, an argument) reads every signal it may be
  bound to;
* ``binding_only``: a string literal naming a signal is no read when it only binds:
  the first argument of an AliasIO, or assigned to a routine's own string data that is
  used only so, whose target is signal data with known bindings (so each use of that data
  is seen). Any other string naming a signal still counts as a read.
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.configured_signals import walk_routine
from ..semantics.library.arguments import argument_expression
from ..semantics.scope import GLOBAL_DATA
from .alias_bindings import alias_bindings

_ORDERS = {"ISIGNALDI", "ISIGNALDO"}


class AliasedOrders:
    """What the program's AliasIO bindings say about its interrupt orders' signals."""

    def __init__(self, program):
        self.bindings = alias_bindings(program) or {}
        self.exempt: set = set()        # ids of the string literals that only bind
        self.targets: set = set()       # ids of the NameRefs an AliasIO binds
        if self.bindings:
            for routine in program.routines:
                if routine.ast is not None and getattr(routine, "scope", None) is not None:
                    self._binding_literals(routine)

    def bound(self, routine, expr) -> Optional[frozenset]:
        """The signals global signal data ``expr`` (a NameRef) may be bound to, or None when
        it is no such data or its bindings are not known."""
        if not isinstance(expr, ast.NameRef) or getattr(routine, "scope", None) is None:
            return None
        symbol = routine.scope.lookup(expr.name.key)
        if symbol is None or symbol.kind != GLOBAL_DATA:
            return None
        return self.bindings.get(symbol.slot)

    def watched(self, routine, order: ast.ProcedureCall) -> Optional[int]:
        """The one signal an order on bound signal data watches, else None."""
        bound = self.bound(routine, argument_expression(order, "Signal", 0))
        return next(iter(bound)) if bound is not None and len(bound) == 1 else None

    def reads(self, routine, node, watched: set) -> frozenset:
        """The signals a use of bound signal data reads (none for an order's or a binding's)."""
        if id(node) in watched or id(node) in self.targets:
            return frozenset()
        return self.bound(routine, node) or frozenset()

    def binding_only(self, literal: ast.StringLiteral) -> bool:
        return id(literal) in self.exempt

    def _binding_literals(self, routine) -> None:
        calls = [node for node in walk_routine(routine.ast)
                 if isinstance(node, ast.ProcedureCall) and node.name.key == "ALIASIO"]
        sources = {}                   # id of a FromSignal NameRef -> whether its target is known
        for call in calls:
            target = argument_expression(call, "ToSignal", 1)
            known = self.bound(routine, target) is not None
            if known:
                self.targets.add(id(target))
            source = argument_expression(call, "FromSignal", 0)
            if isinstance(source, ast.StringLiteral) and known:
                self.exempt.add(id(source))
            elif isinstance(source, ast.NameRef):
                sources[id(source)] = known
        own = {decl.name.key for decl in routine.ast.data}
        uses: dict = {}                # own data key -> [(NameRef, literal assigned or None)]
        assigned = set()
        for node in walk_routine(routine.ast):
            if isinstance(node, ast.Assignment) and isinstance(node.target, ast.NameRef) \
                    and isinstance(node.value, ast.StringLiteral):
                uses.setdefault(node.target.name.key, []).append((node.target, node.value))
                assigned.add(id(node.target))
            elif isinstance(node, ast.NameRef) and node.name.key in own and \
                    id(node) not in assigned:
                uses.setdefault(node.name.key, []).append((node, None))
        for key, found in uses.items():
            if key in own and all(literal is not None or sources.get(id(name), False)
                                  for name, literal in found):
                self.exempt.update(id(literal) for _, literal in found if literal is not None)
