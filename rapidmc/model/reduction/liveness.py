"""Dead data: values that will be written before they are read again.

A backward live-data analysis over each routine's compiled instructions:
``live(pc)`` is the data some path from ``pc`` may read before writing it.
An instruction *uses* the data its expressions read (found through the
statement its span names) and *defines* the target of a plain assignment
``x := e``.  An instruction that raises writes nothing and enters the
routine's ERROR handler (or its UNDO handler, as the error leaves): before a
body instruction that may raise, what the handler reads is live, and so is
what is live where its RETRY (the start of the raising statement) and
TRYNEXT (the statement after it) go back to.  Jumps, a procedure's end,
assignments ``x := e`` to a name and conditions that are total
(``Totality``) never raise.  Inside a handler the raising statement is not
known: RETRY and TRYNEXT may continue anywhere, as may instructions the
analysis does not recognise, which also use everything.

* Routine data (VAR data declared in the routine) not live at a frame's
  program counter is reset in the stored state: only that routine's
  frames can reach it (a reference passed to a call is a use).
* Global data is analysed only where no one else can read it: no
  environment model, no further tasks, no TRAP routines.  A user routine
  call uses every global that routine, or one it calls, names anywhere
  (every global when one of them calls by a computed name or reaches data
  by name), so globals are reset only while main runs without callers, and
  in a final state (ended or failed) every global no atom names is dead.

Values an atom names are always live.  When in doubt, data is live.
"""
from __future__ import annotations

from typing import Iterable, Iterator, Optional

from ... import ast
from ...semantics.instructions import (Action, Branch, Call, ControlAction, EndRoutine, EndUndo,
                                      ExitProgram, ForInit, ForNext, Jump, Retry, Return,
                                      TestDispatch, TryNext)
from ...semantics.program import PROGRAM_NAMESPACE, Program
from ...semantics.library.program_control import CALLS_BY_NAME, RESTARTS_CYCLE
from ...semantics.scope import ROUTINE
from .merging import JUMP_FIELDS, nodes_by_span
from .relevance import DATA_BY_NAME, Resolver, is_value, routine_data
from .totality import Totality

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
        reads = _global_reads(program) if global_candidates else {}
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
            live = _live_in(routine, tracked, reads)
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


def _global_reads(program: Program) -> dict[int, Optional[frozenset]]:
    """routine index -> the global keys it or a routine it calls names anywhere (None: any
    global, as when it calls a routine by a computed name (``%name%``, CallByVar,
    MoveLSync), reaches data by name, or ends the cycle (ExitCycle: the entry routine
    starts again, reading what is live at its start))."""
    names: dict[int, set] = {}
    callees: dict[int, Optional[set]] = {}
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            continue
        resolve = Resolver(routine)
        names[routine.index] = {key for key in resolve.keys(routine.ast) if key[0] == "G"}
        called: Optional[set] = set()
        for call in _calls(routine.ast):
            if isinstance(call, ast.LateBindingCall) or call.name.key in _UNKNOWN_READS:
                called = None
                break
            symbol = resolve.symbol(call.name)
            if symbol is not None and symbol.kind == ROUTINE:
                called.add(symbol.slot)
        callees[routine.index] = called
    reads: dict[int, Optional[frozenset]] = {}
    for index in names:
        seen, todo, keys = {index}, [index], set()
        while todo:
            current = todo.pop()
            if current not in names or callees[current] is None:
                keys = None
                break
            keys |= names[current]
            for callee in callees[current] - seen:
                seen.add(callee)
                todo.append(callee)
        reads[index] = None if keys is None else frozenset(keys)
    return reads


# calls after which a routine's call may read any global
_UNKNOWN_READS = DATA_BY_NAME | CALLS_BY_NAME | RESTARTS_CYCLE


def _calls(node) -> Iterator:
    """Every procedure, function and late-bound call inside ``node``."""
    if isinstance(node, (ast.ProcedureCall, ast.FunctionCall, ast.LateBindingCall)):
        yield node
    if isinstance(node, (tuple, list)):
        for item in node:
            yield from _calls(item)
        return
    for field in getattr(node, "__dataclass_fields__", ()):
        if field != "span":
            yield from _calls(getattr(node, field))


def _live_in(routine, tracked: set, reads: dict) -> list[set]:
    """live(pc) ∩ tracked for every pc, by backward iteration to a fixed point.

    An error in the body enters the ERROR handler, whose RETRY goes back to the start of
    the statement that raised and whose TRYNEXT goes on after it: before a body
    instruction, the handler adds what it reads itself (its RETRY and TRYNEXT taken as
    ends) and what is live where those two go back to from this very instruction.  Inside
    the handler the statement that raised is not known: RETRY and TRYNEXT may continue
    anywhere."""
    code = routine.code
    resolve = Resolver(routine)
    nodes = nodes_by_span(routine.ast)
    uses, defines, successors = [], [], []
    for pc, instruction in enumerate(code):
        used, defined = _effects(instruction, nodes.get(instruction.span), resolve, tracked,
                                 reads)
        uses.append(used)
        defines.append(defined)
        successors.append(_successors(routine, pc, instruction))
    totality = Totality(resolve.symbol)
    quiet = [_cannot_raise(instruction, nodes.get(instruction.span), totality)
             for instruction in code]
    handler, undo = routine.handler_pc, routine.undo_pc
    body_end = min(pc for pc in (handler, undo, len(code)) if pc >= 0)
    in_handler = range(handler, undo if undo > handler else len(code)) if handler >= 0 \
        else range(0)
    goes_back = {type(code[pc]) for pc in in_handler} & {Retry, TryNext}
    if handler >= 0:
        # the handler alone: RETRY and TRYNEXT end it
        closed = [[] if isinstance(code[pc], (Retry, TryNext)) else successors[pc]
                  for pc in range(len(code))]
        handler_reads = _fixed_point(code, uses, defines, closed, lambda pc, live: (
            live[undo] if undo >= 0 else set()))[handler]
    else:
        handler_reads = set()

    def raised(pc: int, live: list) -> set:
        """What is live before ``pc`` on the path of an error it raises (writing nothing)."""
        extra = set(live[undo]) if undo >= 0 else set()
        if pc >= body_end:                   # handlers: errors leave the routine
            return extra | (live[handler] if handler >= 0 else set())
        if quiet[pc]:
            return extra
        extra |= handler_reads
        start = getattr(code[pc], "start", -1)
        if Retry in goes_back:
            extra |= live[start] if 0 <= start < len(code) else set(tracked)
        if TryNext in goes_back:
            after = getattr(code[start], "after", None) if 0 <= start < len(code) else None
            extra |= live[after] if isinstance(after, int) and 0 <= after < len(code) \
                else set(tracked)
        return extra

    return _fixed_point(code, uses, defines, successors, raised)


def _cannot_raise(instruction, node, totality: Totality) -> bool:
    """Instructions that never enter the ERROR handler: a jump, the end of a procedure, an
    assignment ``x := e`` to a name and a test of a condition, ``e`` and the condition
    total (``Totality``: no division, index, call or conversion that may fail)."""
    kind = type(instruction)
    if kind is Jump or kind is EndRoutine and not instruction.is_function:
        return True
    if kind is Action and isinstance(node, ast.Assignment):
        return isinstance(node.target, ast.NameRef) and totality.total(node.value)
    if kind is Branch and isinstance(node, (ast.IfBranch, ast.While, ast.CompactIf)):
        return totality.total(node.condition)
    return False


def _fixed_point(code, uses: list, defines: list, successors: list, raised) -> list[set]:
    live = [set() for _ in code]
    changed = True
    while changed:
        changed = False
        for pc in range(len(code) - 1, -1, -1):
            out = set()
            for target in successors[pc]:
                out |= live[target]
            # an instruction that raises writes nothing: what is live on the error's path
            # is live before it, whatever it would have written
            new = (out - defines[pc]) | uses[pc] | raised(pc, live)
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


def _effects(instruction, node, resolve: "Resolver", tracked: set,
             reads: dict) -> tuple[set, set]:
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
        callee = resolve.symbol(node.name)
        read = reads.get(callee.slot) if callee is not None and callee.kind == ROUTINE else None
        used = resolve.keys(node.args) | \
            ({key for key in tracked if key[0] == "G"} if read is None else set(read))
    if used is EVERYTHING:
        return set(tracked), set()
    return used & tracked, defined & tracked
