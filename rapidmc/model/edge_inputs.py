"""Free digital inputs that only interrupts watch: their edges, not their values.

An input watched by ``ISignalDI diReset, 1, intReset`` is stored in every state
(``inputs.observed_inputs``), since a rising edge between two states raises the
interrupt: with four such inputs every state has 16 copies.  When nothing but
interrupt orders names the input (no ``DInput``, ``WaitDI``, ``TestDI``, no
condition, no atom, no AliasIO, no string that could name it) its value can be seen
only through the interrupts it raises.  An order may name signal data that AliasIO binds
to the input, and a string may name the input only to bind such data, as long as the
bindings are known and nothing else uses that data (``aliased_orders``).  Such an input is an *edge input* (its orders
all watch the rising edge, ``1``, or all both edges, ``2``): each step still chooses
its value, so an edge may come at any step, but the state after the step keeps the
input at 0, ready for the next edge.  (Falling edges, ``0``, keep the value stored.)

What this adds to the controller's runs: a rising edge in the step right after the one
before (a real input must fall in between, one step at least).  Such an edge only
matters when the step between removed the interrupt from the queue: it started its TRAP
(the task, in that TRAP, takes no new one next step), or ISleep or IDelete dropped it
(then no edge queues it).  Its only effect is the interrupt pending one step early, so
every line, error and atom value of such a run is reached by a run of the controller one
step later, and every run of the exact model is kept (a value 1 without an edge leads to
the state 0 gives too).  The verdicts rest on no assumption; still, a VIOLATED verdict is
printed only when its counterexample has no such input at 1 in two steps in a row
(``realizable``), else the check runs again with the values stored (``api``, RMC733).
"""
from __future__ import annotations

from typing import Optional

from .. import ast
from ..semantics.configured_signals import walk_routine
from ..semantics.edge_traps import routine_task
from ..semantics.staged_step import in_trap
from ..semantics.library.arguments import argument_expression
from .aliased_orders import AliasedOrders
from .idle_arguments import idle_literals
from .inputs import ordered_signal

_ORDERS = {"ISIGNALDI", "ISIGNALDO"}
_BY_NAME = {"ALIASIO", "GETDATAVAL", "SETDATAVAL", "GETNEXTSYM", "SETALLDATAVAL"}
_TRIGGER_NAMES = {"LOW": 0, "HIGH": 1, "EDGE": 2}


def edge_inputs(program, atoms, observed: Optional[set]) -> dict:
    """Signal index -> whether its orders watch both edges (else the rising one), for
    each stored digital input that only interrupt orders name, all with the same literal
    trigger, 1 or 2 (``{}``: none, or the program reaches signals in ways this cannot
    bound: an environment model reading signals, a name built at run time).  A late-bound
    call binds only loaded procedures (``statements._LateBindingCall``), walked here like
    the rest; a string given to a parameter its routine never names is no read
    (``idle_arguments``)."""
    if observed is None or program.environment_reads_io or atoms.observes_signal_data:
        return {}
    triggers: dict = {}             # signal index -> set of literal trigger values
    read = set(atoms.observed)
    names = {signal.key: signal.index for signal in program.signals}
    aliased = AliasedOrders(program)
    idle = idle_literals(program)
    for routine in program.routines:
        if routine.ast is None:
            continue
        watched = set()             # ids of the NameRef nodes that are an order's signal
        for node in walk_routine(routine.ast):
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                    node.name.key in _BY_NAME and not _literal_names(node):
                return {}
            if isinstance(node, ast.ProcedureCall) and node.name.key in _ORDERS:
                signal = argument_expression(node, "Signal", 0)
                index = _watched(program, routine, node, names, aliased)
                if index is not None:
                    watched.add(id(signal))
                    trigger = _trigger(argument_expression(node, "TriggValue", 1))
                    triggers.setdefault(index, set()).add(trigger)
            elif isinstance(node, ast.NameRef) and node.name.key in names and \
                    id(node) not in watched:
                read.add(names[node.name.key])
            elif isinstance(node, ast.NameRef):
                read |= aliased.reads(routine, node, watched)
            elif isinstance(node, ast.StringLiteral) and node.value.upper() in names and \
                    not aliased.binding_only(node) and id(node) not in idle:
                read.add(names[node.value.upper()])
    edges = {}
    for index, found in triggers.items():
        signal = program.signals[index]
        if index not in read and index in observed and signal.kind in ("DI", "DO") and \
                found in ({1}, {2}):
            edges[index] = found == {2}
    return edges


def _watched(program, routine, order: ast.ProcedureCall, names: dict,
             aliased: AliasedOrders) -> Optional[int]:
    """The signal an interrupt order watches: a configured one it names, or the one its
    signal data is bound to (``aliased_orders``); None when not known."""
    signal = argument_expression(order, "Signal", 0)
    if isinstance(signal, ast.NameRef) and signal.name.key in names and \
            ordered_signal(program, routine, order) is not None:
        return names[signal.name.key]
    return aliased.watched(routine, order)


def served_edges(program, edges: dict) -> tuple:
    """The edge inputs of ``edges`` whose interrupt orders are in the routines of a task:
    their edges start a TRAP in a step of that task or are dropped
    (``semantics.edge_traps``).  An input several tasks watch is served by each of them
    apart (``shared_edges``)."""
    return tuple(sorted(_edge_owners(program, edges)))


def shared_edges(program, edges: dict) -> tuple:
    """The served edge inputs that the interrupts of several tasks watch: each task's TRAP
    start chooses its own edge, so a run may have one task see an edge the other never
    does, which no real input gives (``realizable`` sends such a counterexample to the
    exact model)."""
    return tuple(sorted(index for index, owners in _edge_owners(program, edges).items()
                        if len(owners) > 1))


def _edge_owners(program, edges: dict) -> dict:
    """Signal index -> the tasks whose routines order an interrupt on it, per edge input
    of ``edges`` some order names."""
    tasks: dict = {}
    names = {signal.key: signal.index for signal in program.signals}
    aliased = AliasedOrders(program)
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node in walk_routine(routine.ast):
            if isinstance(node, ast.ProcedureCall) and node.name.key in _ORDERS:
                signal = argument_expression(node, "Signal", 0)
                named = names.get(signal.name.key) if isinstance(signal, ast.NameRef) \
                    else None
                for index in (named, aliased.watched(routine, node)):
                    if index in edges:
                        tasks.setdefault(index, set()).add(routine_task(routine.namespace))
    return tasks


def _trigger(expression) -> Optional[int]:
    """A literal trigger value (0, 1, 2, or low, high, edge), else None."""
    if isinstance(expression, ast.NumLiteral) and expression.value in (0, 1, 2):
        return int(expression.value)
    if isinstance(expression, ast.NameRef):
        return _TRIGGER_NAMES.get(expression.name.key)
    return None


def _literal_names(call) -> bool:
    """Whether a call that reaches data or signals by name names them by literals only."""
    for argument in call.args:
        value = argument.value
        if value is not None and not isinstance(
                value, (ast.StringLiteral, ast.NameRef, ast.NumLiteral, ast.BoolLiteral)):
            return False
    return True


def realizable(result, edges: dict, names: dict, program=None, served: tuple = (),
               shared: tuple = ()) -> bool:
    """Whether the counterexample ``result`` (a ``SearchResult``, replayed on the unreduced
    system: one instruction per step) of a model with these edge inputs is a run of the
    exact model: no input watched for its rising edge is 1 in two steps in a row (round
    the loop too).  Then the exact model runs it with the same values (a value 1 comes
    after a 0, so each edge is one there too; nothing else reads the input).  An input
    watched for both edges always is: its value flips at each edge.  ``names``: signal
    name -> index.

    An input of ``served`` (``served_edges``, with ``program``) counts only in the steps
    where its edge started a TRAP (elsewhere it was dropped: ``semantics.edge_traps``), and
    such a step must start from a state with no interrupt pending: the exact model's edge
    one step earlier is then the first in its queue.  An input of ``shared``
    (``shared_edges``: several tasks' interrupts watch it) must start no TRAP at all: each
    task chose its own edge, and the run may need one edge that one task saw and another,
    watching it too, did not.

    Conservative: False sends the check to the exact model (RMC733), which decides."""
    served_names = {name for name, index in names.items() if index in served}
    shared_names = {name for name, index in names.items() if index in shared}
    rising = {name for name, index in names.items() if index in edges and not edges[index]}
    if not rising and not served_names:
        return True
    steps = result.prefix + result.cycle
    states = [step.state for step in steps]
    labels = [step.label for step in steps[1:]]
    if result.cycle:
        labels.append(result.closing_label)
        states.append(steps[len(result.prefix)].state)
    marks = []
    for position, label in enumerate(labels):
        ones = _ones(label, rising | served_names)
        if ones & served_names:
            source, target = states[position], states[position + 1]
            if not _trap_started(program, source, target):
                ones -= served_names
            elif source.interrupts.pending or ones & shared_names:
                return False
        marks.append(ones & rising)
    if result.cycle:
        loop = len(marks) - len(result.cycle)
        marks.append(marks[loop])
    return not any(a & b for a, b in zip(marks, marks[1:]))


def _trap_started(program, source, target) -> bool:
    """Whether a task is in a TRAP in ``target`` that was in none in ``source``."""
    before = (source.frames,) + tuple(source.tasks)
    after = (target.frames,) + tuple(target.tasks)
    return any(in_trap(program, new) and not in_trap(program, old)
               for old, new in zip(before, after))


def _ones(label, rising: set) -> set:
    """The inputs of ``rising`` a transition's label sets to 1."""
    if not label:
        return set()
    return {name for name, value in label[0] if name in rising and value == 1}
