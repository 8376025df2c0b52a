"""Dead data: values that will be written before they are read again.

A backward live-data analysis over each routine's compiled instructions:
``live(pc)`` is the data some path from ``pc`` may read before writing it.
An instruction *uses* the data its expressions read (found through the
statement its span names) and *defines* the target of a plain assignment
``x := e``.  Every instruction of a body may also continue in the
routine's ERROR and UNDO handlers, having written nothing when it raised
(what a handler reads is live before ``x := e`` too); RETRY, TRYNEXT and
instructions the analysis does not recognise may continue anywhere and use
everything.

* Routine data (VAR data declared in the routine) not live at a frame's
  program counter is reset in the stored state: only that routine's
  frames can reach it (a reference passed to a call is a use).
* Global data is analysed only where no one else can read it: no
  environment model, no further tasks, no TRAP routines.  A user routine
  call uses every global, so globals are reset only while main runs
  without callers, and in a final state (ended or failed) every global no
  atom names is dead.

Values an atom names are always live.  When in doubt, data is live.
"""
from __future__ import annotations

from typing import Iterable, Optional

from ... import ast
from ...semantics.instructions import (Action, Branch, Call, ControlAction, EndRoutine, EndUndo,
                                      ExitProgram, ForInit, ForNext, Jump, Retry, Return,
                                      TestDispatch, TryNext)
from ...semantics.program import PROGRAM_NAMESPACE, Program
from .merging import JUMP_FIELDS, nodes_by_span
from .relevance import Resolver, is_value, routine_data

EVERYTHING = None          # the use set of an instruction that may read anything
NO_SUCCESSORS = (EndRoutine, EndUndo, ExitProgram, Return)
ANYWHERE = (Retry, TryNext, ControlAction)


class DeadData:
    """Per (routine, pc): local slots to reset; per main pc: global slots to reset."""

    def __init__(self, program: Program, atom_keys: set[str], skip: Iterable = ()):
        self.program = program
        self.locals: dict[int, list[tuple]] = {}       # routine -> per pc: dead local slots
        self.globals: list[tuple] = []                 # per pc of main: dead global slots
        self.final_globals: tuple = ()
        self._analyse(atom_keys, set(skip))

    @property
    def empty(self) -> bool:
        return not any(any(per_pc) for per_pc in self.locals.values()) and \
            not any(self.globals) and not self.final_globals

    def _analyse(self, atom_keys: set[str], skip: set) -> None:
        program = self.program
        global_candidates = _global_candidates(program, atom_keys, skip)
        for routine in program.routines:
            if routine.ast is None or getattr(routine, "scope", None) is None:
                continue
            local_candidates = [slot for slot in routine_data(routine)
                                if routine.local_names[slot].upper() not in atom_keys
                                and ("L", routine.index, slot) not in skip]
            tracked = {("L", routine.index, slot) for slot in local_candidates}
            if routine.index == program.entry:
                tracked |= {("G", slot) for slot in global_candidates}
            if not tracked:
                continue
            live = _live_in(routine, tracked)
            self.locals[routine.index] = [
                tuple(slot for slot in local_candidates
                      if ("L", routine.index, slot) not in live[pc])
                for pc in range(len(routine.code))]
            if routine.index == program.entry and global_candidates:
                self.globals = [tuple(slot for slot in global_candidates
                                      if ("G", slot) not in live[pc])
                                for pc in range(len(routine.code))]
        self.final_globals = tuple(global_candidates)


def _global_candidates(program: Program, atom_keys: set[str], skip: set) -> list[int]:
    if program.environment_react is not None or program.environment_init is not None or \
            program.task_entries or any(r.kind == "TRAP" for r in program.routines):
        return []
    return [data.slot for data in program.globals
            if data.namespace == PROGRAM_NAMESPACE and is_value(data.type)
            and data.key not in atom_keys and ("G", data.slot) not in skip]


def _live_in(routine, tracked: set) -> list[set]:
    """live(pc) ∩ tracked for every pc, by backward iteration to a fixed point."""
    code = routine.code
    resolve = Resolver(routine)
    nodes = nodes_by_span(routine.ast)
    uses, defines, successors = [], [], []
    handlers = [target for target in (routine.handler_pc, routine.undo_pc) if target >= 0]
    for pc, instruction in enumerate(code):
        used, defined = _effects(instruction, nodes.get(instruction.span), resolve, tracked)
        uses.append(used)
        defines.append(defined)
        successors.append(_successors(routine, pc, instruction))
    live = [set() for _ in code]
    changed = True
    while changed:
        changed = False
        for pc in range(len(code) - 1, -1, -1):
            out = set()
            for target in successors[pc]:
                out |= live[target]
            # an instruction that raises writes nothing: what its handlers read is live
            # before it, whatever it would have written
            raised = set()
            for target in handlers:
                raised |= live[target]
            new = (out - defines[pc]) | uses[pc] | raised
            if new != live[pc]:
                live[pc] = new
                changed = True
    return live


def _successors(routine, pc: int, instruction) -> list[int]:
    size = len(routine.code)
    if isinstance(instruction, ANYWHERE):
        return list(range(size))
    targets = set()
    if not isinstance(instruction, NO_SUCCESSORS):
        for field in JUMP_FIELDS:
            target = getattr(instruction, field, None)
            if isinstance(target, int) and 0 <= target < size:
                targets.add(target)
        if isinstance(instruction, TestDispatch):
            targets.update(t for _, t in instruction.cases if 0 <= t < size)
    return sorted(targets)


def _effects(instruction, node, resolve: "Resolver", tracked: set) -> tuple[set, set]:
    """(data used, data defined) among ``tracked``; unknown instructions use everything."""
    kind = type(instruction)
    if kind in (Jump, ForNext, EndRoutine, EndUndo, ExitProgram, Retry, TryNext):
        return set(), set()
    used: Optional[set] = EVERYTHING
    defined: set = set()
    if kind is Action and isinstance(node, ast.Assignment):
        target = node.target
        used = resolve.keys(node.value)
        if isinstance(target, ast.NameRef):
            key = resolve.key(target.name)
            if key is not None and not resolve.by_reference(target.name):
                defined = {key}
        else:
            used |= resolve.keys(target)          # a partial write keeps the rest
    elif kind is Action and isinstance(node, ast.ProcedureCall):
        used = resolve.keys(node.args)            # predefined: data only through arguments
    elif kind is Branch and isinstance(node, (ast.IfBranch, ast.While, ast.CompactIf)):
        used = resolve.keys(node.condition)
    elif kind is TestDispatch and isinstance(node, ast.Test):
        used = resolve.keys((node.subject, [case.values for case in node.cases]))
    elif kind is ForInit and isinstance(node, ast.For):
        used = resolve.keys((node.start, node.stop, node.step))
    elif kind is Return and isinstance(node, ast.Return):
        used = resolve.keys(node.value)
    elif kind is Call and isinstance(node, ast.ProcedureCall):
        used = resolve.keys(node.args) | {key for key in tracked if key[0] == "G"}
    if used is EVERYTHING:
        return set(tracked), set()
    return used & tracked, defined & tracked
