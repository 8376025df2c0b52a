"""Merged steps: which instructions may run in the same transition as the one before.

SPIN merges a process's statements that touch only its own data into one
transition.  Here an instruction is a *merge point* when executing it
changes nothing a property can observe and gives nobody else a turn:

* it is a condition (IF, WHILE, compact IF, TEST, FOR entry or step), a
  GOTO or an assignment (``Incr x``, ``Decr``, ``Clear``, ``Add`` count as
  theirs, ``numeric_updates``);
* the expressions it evaluates call no predefined function that acts on
  the controller (I/O, files, clocks: the "special" routines);
* it is no loop head (so a step never runs around a loop).

An assignment to data an atom names is *visible*, and so is a read of data only the
outside writes that an atom names (the read stores the value it took:
``load.outside_data``).  A step that reaches a
merge point goes on executing (``semantics.step``) as long as at most one
instruction of the step is visible (the step's first instruction counts
as visible unless it is an invisible merge point).  Every state dropped
then has the atom values of the state before or after it, and no other
process runs in between, so runs of the merged model and of the plain one
agree up to stuttering: the verdict of every property without the
next-time operator X is kept (Peled's stutter argument, as in SPIN's
statement merging).  Deadlock detection still looks at single steps
(``RapidSystem.stuck``).  Merging is off when
it could be seen: properties with X, location or status atoms
(InRoutine, AtLine, AtLabel, AtTarget, Ended, Failed, ERRNO), environment
models, further tasks, interrupts (checked at each step), and free inputs
stored in states (their values are chosen once per transition).
Reading a free input that is chosen where read stays a choice inside the
merged transition, made afresh by each instruction; so does a read of PERS
data written from outside the loaded code (``load.outside_data``).  Each
combination of choices is a transition of its own, so a merged step stops
before an instruction that may read a signal or choose such data once a
choice was made (``CheckConfig.merge_table``): the choices of a chain of
IFs add up instead of multiplying (a gantry's monitoring loop made 152,404
transitions between 5 states from one state).
"""
from __future__ import annotations

from typing import Iterable, Iterator

from ... import ast
from ...ltl import syntax
from ...semantics.library import registry
from ...semantics.instructions import Action, Branch, ForInit, ForNext, Jump, TestDispatch
from ...semantics.program import Program
from .numeric_updates import as_assignment, target_root

# where an instruction may continue (``start`` and ``after`` serve RETRY and TRYNEXT,
# which are never merged)
JUMP_FIELDS = ("next", "target_true", "target_false", "target", "exit", "body", "default")
LOCATION_ATOMS = frozenset({"INROUTINE", "ATLINE", "ATLABEL", "ATTARGET", "ENDED", "FAILED",
                            "STOPPED", "WAITING", "ERRNO", "INTNO"})


def merging_allowed(program: Program, formulas: Iterable, atom_keys: set[str],
                    stores_inputs: bool) -> bool:
    """Whether merged steps keep every verdict of these properties on this program."""
    if program.environment_react is not None or program.environment_init is not None or \
            program.task_entries or stores_inputs:
        return False
    if atom_keys & LOCATION_ATOMS:
        return False
    return not any(_has_next(formula) for formula in formulas)


INVISIBLE, VISIBLE, LOOP_HEAD, NEVER = 0, 1, 2, 3


def merge_points(program: Program, atom_keys: set[str]) -> dict:
    """Routine index -> bytes with one kind per pc: INVISIBLE, VISIBLE, LOOP_HEAD or NEVER.

    INVISIBLE and VISIBLE points may join the step before them; visible
    ones (assignments to data an atom names) only a step that has executed
    no visible instruction yet.  Loop heads (targets of a jump backwards)
    never join, so a merged step never runs around a loop (within a merged
    step the program counter only grows), but an invisible loop head that
    starts a step does not count as visible.  Routines without any point
    are left out.
    """
    points = {}
    # data only the outside writes that a property names: each read stores the value it
    # took (load.outside_data), a change the atoms see
    kept = frozenset(data.name.upper() for data in
                     (getattr(program, "outside_data", None) or {}).values() if data.observed)
    for routine in program.routines:
        if routine.ast is None:
            continue
        nodes = nodes_by_span(routine.ast)
        lookup = routine.scope.lookup if getattr(routine, "scope", None) is not None else None
        heads = loop_heads(routine.code)
        kinds = bytearray([NEVER]) * len(routine.code)
        for pc, instruction in enumerate(routine.code):
            node = nodes.get(instruction.span)
            if isinstance(node, ast.ProcedureCall) and lookup is not None:
                node = as_assignment(node, lookup)      # Incr x: x := x + 1
            if not _mergeable(instruction, node):
                continue
            visible = _visible(node, atom_keys, kept)
            if pc in heads:
                if not visible:
                    kinds[pc] = LOOP_HEAD
            else:
                kinds[pc] = VISIBLE if visible else INVISIBLE
        if any(kind != NEVER for kind in kinds):
            points[routine.index] = bytes(kinds)
    return points


def loop_heads(code: list) -> set[int]:
    """The pcs a jump goes back to (or stays at)."""
    heads = set()
    for pc, instruction in enumerate(code):
        for target in _targets(instruction):
            if 0 <= target <= pc:
                heads.add(target)
    return heads


def _targets(instruction) -> Iterator[int]:
    for field in JUMP_FIELDS:
        target = getattr(instruction, field, None)
        if isinstance(target, int):
            yield target
    if isinstance(instruction, TestDispatch):
        yield from (target for _, target in instruction.cases)


def _visible(node, atom_keys: set[str], kept: frozenset = frozenset()) -> bool:
    if isinstance(node, ast.Assignment) and target_root(node.target).name.key in atom_keys:
        return True
    return bool(kept) and any(isinstance(part, ast.NameRef) and part.name.key in kept
                              for part in _walk(node))


def _mergeable(instruction, node) -> bool:
    kind = type(instruction)
    if kind is Jump or kind is ForNext:
        return True
    if node is None:
        return False
    if kind is Branch and isinstance(node, (ast.IfBranch, ast.While, ast.CompactIf)):
        return _quiet(node.condition)
    if kind is TestDispatch and isinstance(node, ast.Test):
        return _quiet(node.subject) and all(_quiet(v) for case in node.cases
                                            for v in case.values)
    if kind is ForInit and isinstance(node, ast.For):
        return all(_quiet(e) for e in (node.start, node.stop, node.step))
    if kind is Action and isinstance(node, ast.Assignment):
        return isinstance(target_root(node.target), ast.NameRef) and _quiet(node.target) and \
            _quiet(node.value)
    return False


def _quiet(expr) -> bool:
    """No call of a predefined function that acts on the controller (and no user FUNC)."""
    for node in _walk(expr):
        if isinstance(node, ast.FunctionCall):
            entry = registry.lookup_function(node.name.key)
            if entry is None or entry.special:
                return False
    return True


def _walk(node) -> Iterator:
    if node is None:
        return
    if isinstance(node, (tuple, list)):
        for item in node:
            yield from _walk(item)
        return
    fields = getattr(node, "__dataclass_fields__", None)
    if fields is None:
        return
    yield node
    for field in fields:
        if field != "span":
            yield from _walk(getattr(node, field))


def nodes_by_span(decl: ast.Routine) -> dict:
    """Statement-like nodes of a routine by span: the first one wins (outermost)."""
    nodes: dict = {}
    for node in _walk((decl.body, decl.error, decl.undo, decl.backward)):
        if isinstance(node, (ast.Assignment, ast.IfBranch, ast.While, ast.CompactIf, ast.Test,
                             ast.For, ast.ProcedureCall)):
            nodes.setdefault(node.span, node)
    return nodes


def _has_next(formula) -> bool:
    return any(isinstance(node, syntax.Next) for node in _walk(formula))


def executed_spans(span) -> tuple:
    """The spans a transition's span stands for: a merged step's span is the tuple of
    every instruction it ran, in order; any other step's is one span (or None)."""
    return span if isinstance(span, tuple) else (span,)
