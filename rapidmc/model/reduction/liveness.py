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
(``Totality``) never raise.  Where the raising statement's error numbers are
known (``raised_errors``), the handler's tests of ERRNO take only the branches
those numbers take.  Inside a handler the raising statement is not
known: RETRY and TRYNEXT may continue anywhere, as may instructions the
analysis does not recognise, which also use everything.

* Routine data (VAR data declared in the routine) not live at a frame's
  program counter is reset in the stored state: only that routine's
  frames can reach it (a reference passed to a call is a use).
* Global data is analysed only where no one else can read it: no
  environment model, no further tasks, and only globals no TRAP routine
  (nor a routine it calls) names: a trap runs between any two instructions,
  and an error it raises stops the program.  A user routine call, a user
  function's call inside an expression included, uses every global that
  routine, or one it calls, names anywhere (every global when one of them
  calls by a computed name or reaches data by name; any instruction that
  may call a routine itself, CallByVar or MoveLSync's procedure, uses every
  global).  When a routine (a TRAP's included) may end the cycle, main
  starts again at any step (ExitCycle keeps every value): what is live at
  main's start is then live at each of its pcs.  A move, WaitTime and a barrier
  (``GOES_ON``) read data only through their arguments and go on to the
  next instruction, as a predefined procedure does.  Globals are reset by the program
  counter of main's frame, the bottom of the stack: while a routine main
  called runs, main stands at the call, where everything that routine and
  the rest of main may read is live.  In a final state (ended or failed)
  every global no atom names is dead.

Values an atom names are always live.  When in doubt, data is live.
"""
from __future__ import annotations

from typing import Iterable, Iterator, Optional

from ... import ast
from ...semantics.instructions import (Action, Branch, Call, ControlAction, EndRoutine, EndUndo,
                                      ExitProgram, ForInit, ForNext, Jump, Retry, Return,
                                      TestDispatch, TryNext, Wait)
from ...semantics.program import PROGRAM_NAMESPACE, Program
from ...semantics.library.motion import MOVE_ROUTINES
from ...semantics.library.program_control import CALLS_BY_NAME, RESTARTS_CYCLE
from ...semantics.scope import ROUTINE
from .merging import JUMP_FIELDS, nodes_by_span
from .raised_errors import BookedErrnums, ErrnoTests, StatementErrors
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
        # the same in ERROR handlers, per (pc, start of the statement that raised): a
        # frame in its handler keeps that start (``Frame.error_pc``)
        self.handler_locals: dict[int, dict[tuple, tuple]] = {}
        self.handler_globals: dict[tuple, tuple] = {}
        self.final_globals: tuple = ()
        self._analyse(atom_keys, set(skip))

    @property
    def empty(self) -> bool:
        return not any(any(per_pc) for per_pc in self.locals.values()) and \
            not any(any(per_node.values()) for per_node in self.handler_locals.values()) and \
            not any(self.globals) and not any(self.handler_globals.values()) and \
            not self.final_globals

    def _analyse(self, atom_keys: set[str], skip: set) -> None:
        program = self.program
        global_candidates = _global_candidates(program, atom_keys, skip)
        reads = _global_reads(program) if global_candidates else {}
        global_candidates = _untrapped(program, global_candidates, reads)
        booked = BookedErrnums(program)
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
            live, in_handler = _live_in(routine, tracked, reads,
                                        routine.index == program.entry, program, booked)

            def dead(candidates: list, kind: tuple, live_here: set) -> tuple:
                return tuple(slot for slot in candidates if (*kind, slot) not in live_here)
            local_kind = ("L", routine.index)
            self.locals[routine.index] = [dead(local_candidates, local_kind, live_pc)
                                          for live_pc in live]
            self.handler_locals[routine.index] = {
                node: dead(local_candidates, local_kind, live_node)
                for node, live_node in in_handler.items()}
            if routine.index == program.entry and global_candidates:
                if _restarts(reads):
                    # the cycle may start again at any step: what main's start reads is
                    # live everywhere
                    restart = {key for key in live[0] if key[0] == "G"}
                    live = [live_pc | restart for live_pc in live]
                    in_handler = {node: live_node | restart
                                  for node, live_node in in_handler.items()}
                self.globals = [dead(global_candidates, ("G",), live_pc) for live_pc in live]
                self.handler_globals = {node: dead(global_candidates, ("G",), live_node)
                                        for node, live_node in in_handler.items()}
        self.final_globals = tuple(global_candidates)


def _global_candidates(program: Program, atom_keys: set[str], skip: set) -> list[int]:
    if program.environment_react is not None or program.environment_init is not None or \
            program.task_entries:
        return []
    return [data.slot for data in program.globals
            if data.namespace == PROGRAM_NAMESPACE and is_value(data.type)
            and data.key not in atom_keys and ("G", data.slot) not in skip]


def _untrapped(program: Program, candidates: list[int], reads: dict) -> list[int]:
    """The ``candidates`` no TRAP routine, nor a routine it calls, names: a trap runs
    between any two instructions of main (or of a routine main called), and an error it
    raises stops the program (``errors_flow``), so the rest of main's flow is the same
    with traps.  None when a trap may read any global (``_global_reads``)."""
    named: set = set()
    for routine in program.routines:
        if routine.kind != "TRAP":
            continue
        read = reads.get(routine.index)
        if read is None:
            return []
        named |= read
    return [slot for slot in candidates if ("G", slot) not in named]


def _restarts(reads: dict) -> bool:
    """Whether some routine may end the cycle (``RESTARTS``)."""
    return any(read is not None and RESTARTS in read for read in reads.values())


def _global_reads(program: Program) -> dict[int, Optional[frozenset]]:
    """routine index -> the global keys it or a routine it calls names anywhere (None: any
    global, as when it calls a routine by a computed name (``%name%``, CallByVar,
    MoveLSync) or reaches data by name).  A routine that may end the cycle (ExitCycle:
    the entry routine starts again, reading what is live at its start) holds the key
    ``RESTARTS``: the analysis then keeps what main's start reads live everywhere."""
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
            if call.name.key in RESTARTS_CYCLE:
                names[routine.index].add(RESTARTS)
                continue
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
_UNKNOWN_READS = DATA_BY_NAME | CALLS_BY_NAME
# the key in a routine's reads that says it may end the cycle (``_global_reads``)
RESTARTS = ("RESTARTS",)


def _connects(node) -> Iterator:
    """Every CONNECT statement inside ``node``."""
    if isinstance(node, ast.Connect):
        yield node
    elif isinstance(node, (tuple, list)):
        for item in node:
            yield from _connects(item)
    else:
        for field in getattr(node, "__dataclass_fields__", ()):
            if field != "span":
                yield from _connects(getattr(node, field))


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


def _live_in(routine, tracked: set, reads: dict, entry: bool = False,
             program: Optional[Program] = None,
             booked: Optional[BookedErrnums] = None) -> tuple[list[set], dict]:
    """(live(pc) ∩ tracked for every pc, live((pc, e)) for every pc of the ERROR handler
    and every statement start ``e`` an error may come from), by backward iteration to a
    fixed point.

    An error in the body enters the ERROR handler, whose RETRY goes back to the start of
    the statement that raised and whose TRYNEXT goes on after it; the frame keeps that
    start (``Frame.error_pc``).  So the handler is analysed once per statement an error
    may come from: at ``(pc, e)`` RETRY goes to ``e`` and TRYNEXT to the statement after
    it, and before a body instruction that may raise, what is live at ``(handler, its
    statement's start)`` is live (it writes nothing when it raises).  The projection reads
    the handler's dead data by ``(pc, error_pc)``: data dead where an error is raised stays
    dead in the handler until it is written, as it does in the body.  The handler's pcs
    alone (``live(pc)``) take RETRY and TRYNEXT as going anywhere, for an error whose
    statement is not known."""
    code = routine.code
    resolve = Resolver(routine)
    nodes = nodes_by_span(routine.ast)
    for call in _calls(routine.ast):          # a user function's Call: its call expression
        if isinstance(call, ast.FunctionCall):
            nodes.setdefault(call.span, call)
    for connect in _connects(routine.ast):
        nodes.setdefault(connect.span, connect)
    uses, defines, successors = [], [], []
    for pc, instruction in enumerate(code):
        used, defined = _effects(instruction, nodes.get(instruction.span), resolve, tracked,
                                 reads)
        uses.append(used)
        defines.append(defined)
        successors.append(_successors(routine, pc, instruction, nodes.get(instruction.span),
                                      entry))
    totality = Totality(resolve.symbol)
    handler, undo = routine.handler_pc, routine.undo_pc
    body_end = min(pc for pc in (handler, undo, len(code)) if pc >= 0)
    in_handler = range(handler, undo if undo > handler else len(code)) if handler >= 0 \
        else range(0)
    graph = _Graph(uses, defines, successors)
    leaving = [undo] if undo >= 0 else []          # an error that leaves runs UNDO
    for pc in range(len(code)):
        if pc >= body_end:                          # handlers: errors leave the routine
            graph.raises.append(leaving + ([handler] if handler >= 0 else []))
        elif handler < 0 or _cannot_raise(code[pc], nodes.get(code[pc].span), totality):
            graph.raises.append(list(leaving))
        else:
            start = getattr(code[pc], "start", None)
            known = isinstance(start, int) and 0 <= start < body_end
            graph.raises.append(leaving + [(handler, start) if known else handler])
    errors = _errors_by_start(code, nodes, body_end, StatementErrors(totality))
    tests = ErrnoTests(program, routine, nodes, booked) if handler >= 0 and program is not None \
        else None
    for start in sorted({target[1] for raised in graph.raises for target in raised
                         if isinstance(target, tuple)}):
        _add_handler_copy(graph, code, in_handler, start, leaving, tests, errors.get(start))
    live = graph.fixed_point()
    return live[:len(code)], {node: live[index] for node, index in graph.copies.items()}


def _errors_by_start(code, nodes: dict, body_end: int, known: StatementErrors) -> dict:
    """Statement start -> the errors its instructions may raise (``raised_errors``; None:
    any)."""
    errors: dict = {}
    for pc in range(body_end):
        start = getattr(code[pc], "start", None)
        if not isinstance(start, int):
            continue
        raised = known.errors(nodes.get(code[pc].span)) if type(code[pc]) is Action else None
        before = errors.get(start, frozenset())
        errors[start] = None if raised is None or before is None else before | raised
    return errors


def _add_handler_copy(graph: "_Graph", code, in_handler: range, start: int,
                      leaving: list, tests: Optional[ErrnoTests] = None,
                      errors: Optional[frozenset] = None) -> None:
    """The ERROR handler's instructions once more, for errors raised by the statement that
    starts at ``start``: RETRY goes back to it, TRYNEXT to the statement after it.  A test
    of ERRNO the statement's ``errors`` decide takes only the branches they may take
    (``raised_errors.ErrnoTests``)."""
    after = getattr(code[start], "after", None)
    after = after if isinstance(after, int) and 0 <= after < len(code) else None
    for pc in in_handler:
        graph.copies[(pc, start)] = len(graph.uses) + pc - in_handler.start
    for pc in in_handler:
        instruction = code[pc]
        if isinstance(instruction, Retry):
            targets = [start]
        elif isinstance(instruction, TryNext):
            targets = [after] if after is not None else list(range(len(code)))
        else:
            taken = tests.targets(pc, errors) if tests is not None else None
            targets = [graph.copies.get((target, start), target)
                       for target in (graph.successors[pc] if taken is None else taken)]
        graph.uses.append(graph.uses[pc])
        graph.defines.append(graph.defines[pc])
        graph.successors.append(targets)
        graph.raises.append(list(leaving))


class _Graph:
    """Nodes with their uses, definitions, successors and the nodes an error they raise
    goes to (with nothing written): a routine's pcs, then copies of its handler
    (``copies``: (pc, statement start) -> node)."""

    def __init__(self, uses: list, defines: list, successors: list):
        self.uses, self.defines, self.successors = list(uses), list(defines), list(successors)
        self.raises: list[list] = []
        self.copies: dict[tuple, int] = {}

    def fixed_point(self) -> list[set]:
        raises = [[self.copies.get(target, target) if isinstance(target, tuple) else target
                   for target in targets] for targets in self.raises]
        live = [set() for _ in self.uses]
        changed = True
        while changed:
            changed = False
            for node in range(len(live) - 1, -1, -1):
                out = set()
                for target in self.successors[node]:
                    out |= live[target]
                new = (out - self.defines[node]) | self.uses[node]
                # an instruction that raises writes nothing: what is live on the error's
                # path is live before it, whatever it would have written
                for target in raises[node]:
                    new |= live[target]
                if new != live[node]:
                    live[node] = new
                    changed = True
        return live


def _cannot_raise(instruction, node, totality: Totality) -> bool:
    """Instructions that never enter the ERROR handler: a jump, the end of a procedure, an
    assignment ``x := e`` to data named directly (not through a reference, which may be
    an absent optional argument) and a test of a condition, ``e`` and the condition total
    and ``e`` stored without a conversion that may fail (``Totality``: no division,
    index, call or conversion that may fail)."""
    kind = type(instruction)
    if kind is Jump or kind is EndRoutine and not instruction.is_function:
        return True
    if kind is Action and isinstance(node, ast.Assignment):
        target = node.target
        symbol = totality.lookup(target.name) if isinstance(target, ast.NameRef) else None
        return symbol is not None and not symbol.by_reference and not symbol.optional and \
            totality.assignable(node.value, symbol.type)
    if kind is Branch and isinstance(node, (ast.IfBranch, ast.While, ast.CompactIf)):
        return totality.total(node.condition)
    return False


def _successors(routine, pc: int, instruction, node=None, entry: bool = False) -> list[int]:
    """The pcs that may run after ``pc`` in the same frame (an ExitCycle: the UNDO handler
    it runs, then main's start when ``routine`` is the entry routine; only main's globals
    live on past it, and main is the only routine whose globals are analysed)."""
    size = len(routine.code)
    if _ends_cycle(instruction, node):
        return [target for target in ((0 if entry else -1), routine.undo_pc) if target >= 0]
    if isinstance(instruction, ANYWHERE) and not _goes_on(instruction, node):
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


# predefined instructions the step machine runs as a ControlAction that still only go on
# to the next instruction or wait where they are: every move but MoveJSync, MoveLSync
# and MoveCSync (they call a procedure named at run time), WaitTime, and the barriers
GOES_ON = frozenset(MOVE_ROUTINES - CALLS_BY_NAME) | \
    frozenset({"WAITTIME", "WAITSYNCTASK", "SYNCMOVEON", "SYNCMOVEOFF"})


def _plain_wait(instruction) -> bool:
    """A WaitUntil, WaitDI or WaitDO whose condition calls no user function: it reads data
    only through its arguments and waits where it is or goes on (one that calls user
    functions goes back to their calls, ``WaitRerun``)."""
    return type(instruction) is Wait and instruction.rerun is None


def _ends_cycle(instruction, node) -> bool:
    """An ExitCycle: it reads nothing and goes on at the start of the entry routine."""
    return isinstance(instruction, ControlAction) and isinstance(node, ast.ProcedureCall) \
        and isinstance(node.name, ast.Name) and node.name.key in RESTARTS_CYCLE


def _goes_on(instruction, node) -> bool:
    """A ControlAction of ``GOES_ON``: it reads data only through its arguments and goes
    on, as a predefined Action does."""
    return isinstance(instruction, ControlAction) and isinstance(node, ast.ProcedureCall) \
        and isinstance(node.name, ast.Name) and node.name.key in GOES_ON


# predefined procedures whose named argument receives a whole new value whenever the
# instruction goes on (each error it raises comes before that write): the request string
# of a socket server is written anew by each SocketReceive
WHOLE_WRITES = {"SOCKETRECEIVE": "STR"}


def _whole_write(node: ast.ProcedureCall, resolve: "Resolver") -> Optional[tuple]:
    """(argument, data key) of the data ``node`` writes whole (``WHOLE_WRITES``), when it
    is data named directly (not through a reference), or None."""
    parameter = WHOLE_WRITES.get(node.name.key)
    if parameter is None:
        return None
    for argument in node.args:
        if argument.name is not None and argument.name.key == parameter and \
                isinstance(argument.value, ast.NameRef):
            key = resolve.key(argument.value.name)
            if key is not None and not resolve.by_reference(argument.value.name):
                return argument, key
    return None


def _effects(instruction, node, resolve: "Resolver", tracked: set,
             reads: dict) -> tuple[set, set]:
    """(data used, data defined) among ``tracked``; unknown instructions use everything."""
    kind = type(instruction)
    if kind in (Jump, ForNext, EndRoutine, EndUndo, ExitProgram, Retry, TryNext) or \
            _ends_cycle(instruction, node):
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
    elif (kind is Action or _goes_on(instruction, node) or _plain_wait(instruction)) and \
            isinstance(node, ast.ProcedureCall) and node.name.key not in DATA_BY_NAME:
        used = resolve.keys(node.args)            # predefined: data only through arguments
        written = _whole_write(node, resolve)
        if written is not None:
            argument, key = written
            used = resolve.keys([arg for arg in node.args if arg is not argument])
            defined = {key}
    elif kind is Branch and isinstance(node, (ast.IfBranch, ast.While, ast.CompactIf)):
        used = resolve.keys(node.condition)
    elif kind is Action and isinstance(node, ast.Connect):
        used = resolve.keys(node.target)          # the interrupt number it binds
    elif kind is TestDispatch and isinstance(node, ast.Test):
        used = resolve.keys((node.subject, [case.values for case in node.cases]))
    elif kind is ForInit and isinstance(node, ast.For):
        used = resolve.keys((node.start, node.stop, node.step))
    elif kind is Return and isinstance(node, ast.Return):
        used = resolve.keys(node.value)
    elif kind is Call and isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
        callee = resolve.symbol(node.name)
        read = reads.get(callee.slot) if callee is not None and callee.kind == ROUTINE else None
        used = resolve.keys(node.args) | \
            ({key for key in tracked if key[0] == "G"} if read is None else set(read))
    if used is EVERYTHING:
        return set(tracked), set()
    return used & tracked, defined & tracked
