"""Outputs no loaded code reads back: their values are reset in stored states (issue 28).

A monitoring task sets and resets outputs every round for other tasks or a PLC to
watch (``Set intMoveHome_Gantry`` when a partner reports an error, ``Reset`` else).
Checked alone, nothing it runs reads them again, yet each state keeps the value of the
last round: a public backup's monitoring task had 35,972 states, 621 of them distinct
once seven such outputs are left out.

An output is *unread* when

* it is a configured digital, group or analog output that no party left out sets too
  and no cross-connection drives (``Signal.outside``, ``Signal.also_set_by``);
* its name occurs in the program only as the signal of ``Set``, ``Reset``, ``SetDO``,
  ``SetGO`` or ``SetAO`` without optional arguments (no ``\\SDelay`` that schedules a
  change, no read by ``DOutput``, a wait, ``PulseDO``/``InvertDO``, an interrupt order,
  a routine's signal parameter) and no routine or data of that name hides it;
* no property's atom names it (signal data an atom may read is bound only by
  ``AliasIO`` or by name, which turn this off);
* the program is one task, has no environment model, binds no signal data at run
  time (``AliasIO``) and reaches no data by name (``GetDataVal`` and the others).

Nothing the program computes then depends on such an output's value: a write sets it
whatever it was, and nothing else touches it.  Two states that differ only in these
values have the same successors up to these values, so resetting them to 0 (their
value at the start) in stored states (``OutputResets``, after the other resets of
``projection``) keeps every verdict (the argument of dead data, for a value that is never read).  A
counterexample is re-executed on the plain program (``expansion``), so its steps still
show each output set.
"""
from __future__ import annotations

from typing import Iterable, Iterator, Optional

from ... import ast
from ...semantics.program import Program
from .merging import _walk
from .partial_order import reaches_data_by_name
from .relevance import DATA_BY_NAME

OUTPUT_KINDS = frozenset({"DO", "GO", "AO"})
# writes of one output: the routine's key and the number of arguments it then has
WRITES = {"SET": 1, "RESET": 1, "SETDO": 2, "SETGO": 2, "SETAO": 2}
BINDS_SIGNALS = frozenset({"ALIASIO", "ALIASIORESET"}) | DATA_BY_NAME
RESET_VALUE = 0.0                    # every signal's value in the start state (step.start_state)


def unread_outputs(program: Program, atom_keys: set[str]) -> tuple[int, ...]:
    """The indices (in the state's ``io``) of the outputs no loaded code reads back."""
    if program.task_entries or program.environment_react is not None or \
            program.environment_init is not None or reaches_data_by_name(program):
        return ()
    candidates = {signal.key: signal.index for signal in program.signals
                  if signal.kind in OUTPUT_KINDS and signal.outside is None
                  and signal.also_set_by is None and signal.named_at_run_time is None
                  and signal.key not in atom_keys}
    if not candidates:
        return ()
    hidden = {routine.name.upper() for routine in program.routines}
    hidden |= {getattr(data, "key", "") for data in program.globals}
    for key in hidden & set(candidates):
        del candidates[key]
    for routine in program.routines:
        if routine.ast is None:
            continue
        for key in _names_read(routine):
            if key is None:
                return ()                        # binds signals at run time
            candidates.pop(key, None)
        if not candidates:
            return ()
    return tuple(sorted(candidates.values()))


def _names_read(routine) -> Iterator[Optional[str]]:
    """The keys of the names a routine uses other than as the output a plain write sets,
    and of the names it declares; None for a call that binds signals or data by name."""
    decl = routine.ast
    yield from (declared.name.key for declared in (*decl.parameters, *decl.data))
    code = (decl.data, decl.body, decl.error, decl.undo, decl.backward)
    written: set[int] = set()                    # id() of the NameRefs a plain write sets
    for node in _walk(code):
        if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
            if node.name.key in BINDS_SIGNALS:
                yield None
            if isinstance(node, ast.ProcedureCall) and _plain_write(node):
                written.add(id(node.args[0].value))
    for node in _walk(code):
        if isinstance(node, ast.NameRef) and id(node) not in written:
            yield node.name.key


def _plain_write(call: ast.ProcedureCall) -> bool:
    count = WRITES.get(call.name.key)
    return count is not None and len(call.args) == count and \
        all(arg.kind == ast.REQUIRED and arg.name is None for arg in call.args) and \
        isinstance(call.args[0].value, ast.NameRef)


class OutputResets:
    """``project(state)``: ``inner``'s projection (or the state), with the unread outputs
    at their initial values.  Not a ``Projection``: the packed step machine, which takes
    only those, leaves such a check to the Python steps."""

    def __init__(self, outputs: Iterable[int], inner=None):
        self.inner = inner
        self.resets = tuple((index, RESET_VALUE) for index in outputs)

    def keeps_fused_targets(self, sliced: set, written: set, main_stops: set) -> bool:
        return False                             # a fused step's targets are projected

    def __call__(self, state):
        if self.inner is not None:
            state = self.inner(state)
        io = state[2]
        changes = []
        for index, initial in self.resets:
            if io[index] != initial:
                changes += (index, initial)
        if not changes:
            return state
        return state._replace(io=io.mset(*changes))
