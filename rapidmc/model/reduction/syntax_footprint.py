"""What an instruction touches, read from its syntax where its compiled form does not say.

The partial-order reduction (``partial_order``) decides per instruction whether
it is independent of every other task.  Assignments of plain data and
conditions carry their compiled form (``fusion``), whose reads are plain; the
rest is judged here from the statement the instruction was compiled from,
found by its span:

* an assignment to an element or a component (``buf{i} := x``, ``p.x := 0``),
  and ``Incr``, ``Decr``, ``Clear`` and ``Add`` read as their assignments
  (``numeric_updates``), writes the data under the target: independent when
  that is the task's own (global data no other task's code names, routine data
  not passed by reference) and every expression it evaluates reads only data
  no other task writes;
* a call of a user procedure or function with arguments evaluates them: the
  call is independent when they read only such data (an argument passed by
  reference binds a reference and reads the data of its indices; the callee's
  writes through it are judged where they are written).  A function a wait's
  condition calls is not (it reads what others write, ``Call.for_wait``);
* RETURN with a value writes the caller's temporary: independent when the
  value reads only such data;
* ``TPWrite`` writes a line to the transition's output, which no other task
  reads and no atom names, and ``WaitTime`` is one step when checking
  (``library.waits``): independent when their arguments read only such data;
* a predefined procedure that changes nothing rapidmc observes (``NO_EFFECT`` in the
  registry: ``AccSet``, ``ErrWrite``, ``ClearPath`` ...), the socket instructions
  (``library.sockets``: each reads and writes only the data passed to it, chooses
  among outcomes the check's options fix, and writes the transition's output), the
  rawbytes instructions (``library.raw_data``, the data passed to them only) and the file
  instructions (``library.files``: Open, Close, Write ... read and write only the
  ``iodev`` passed and write the transition's output; files are the environment, and no
  step of another task reads what they write) are
  independent when every argument passed by reference is the task's own (as an
  assignment's target) and every other reads only such data;
  ``SocketGetStatus`` reads only the socket passed to it.  The clock instructions
  (``library.clocks``: ClkReset, ClkStart, ClkStop) write only the clock passed, and
  ``ClkRead`` reads only that clock (and the state's clock, 0 when checking) and
  chooses among readings the check fixes;
* a move (``MoveJ``, ``MoveL``, ``MoveC``, ``MoveAbsJ``, ``MoveExtJ``, no ``\\Corr``) writes
  only its task's robot: independent where each motion task has its own robot and no
  other task's code reads this one (``cell_uses``: ``CRobT(\\TaskName:=...)``), when its
  arguments read only such data.

"Reads only data no other task writes" (``SyntaxReads.allowed``): constants,
routine data and parameters passed by value, FOR variables, global data no
other task writes (data only the outside writes, when a read chooses a value and
stores none: ``outside_free``), signals no other task may write and robots no other
task moves (``cell_uses``: ``DInput``, ``CRobT(\\TaskName:=...)`` ...), through
operators, indices, components, aggregates and predefined functions that are not
"special" (those compute from their arguments alone: Abs, NumToStr, StrPart,
Offs ...) or are controller readings the check fixes (GetMotorTorque, MaxRobSpeed:
``arguments.fixed``, the call compiled to its value; the fixed date and time: CDate, CTime,
GetTime), and user functions, which run
before the instruction (hoisted: it reads their result from its frame, and the call
is judged as above).  Signal data bound at run time reads any signal.  Anything else
is not.  ``Set``, ``Reset``, ``SetDO`` ... (no ``\\SDelay``) of a configured signal
no other task's code names write only that signal.  Whether the
instruction raises an error is not decided here: the reduction checks each
step it leaves alone (``PartialOrder._invisible_step``).
"""
from __future__ import annotations

from typing import Callable, NamedTuple, Optional

from ... import ast
from ...semantics.instructions import Call, LateCall
from ...semantics.library import registry
from ...semantics.library.arguments import argument_expression
from ...semantics.library.motion import PLAIN_MOVES
from ...semantics.library.program_control import RESTARTS_CYCLE
from ...semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE
from ...semantics.types import SEMI_VALUE
from .cell_uses import physical_signal, signal_data
from .merging import _walk
from .numeric_updates import as_assignment, target_root


class Footprint(NamedTuple):
    """What one instruction of a task touches, decided from its code alone.

    ``independent``: it reads only data no other task writes and writes only data
    no other task's code names (its own VAR data, TASK PERS, routine data, its own
    frames), reads no signal and waits for nothing: every step of another task
    commutes with it and neither enables nor disables it, as SPIN treats a
    statement on local variables.  ``visible``: it may change the value of an atom
    of the check (it writes data an atom names).
    """

    independent: bool
    visible: bool


LOCAL = Footprint(True, False)
VISIBLE = Footprint(True, True)
SHARED = Footprint(False, True)

# syntax that reads nothing but the data it names
_PLAIN_EXPRESSIONS = frozenset({ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral,
                                ast.Index, ast.Component, ast.Unary, ast.Binary,
                                ast.Aggregate})
# predefined procedures whose only effect is on the transition's output, or none
# when checking, besides reading their arguments
_QUIET_PROCEDURES = frozenset({"TPWRITE", "WAITTIME"})
# predefined procedures that read and write only their arguments (the data under those
# passed by reference), choose among outcomes fixed by the check's options and write the
# transition's output (``library.sockets``, ``library.raw_data``)
_ARGUMENTS_ONLY = frozenset({"SOCKETCREATE", "SOCKETBIND", "SOCKETLISTEN", "SOCKETCLOSE",
                             "SOCKETACCEPT", "SOCKETCONNECT", "SOCKETSEND", "SOCKETRECEIVE",
                             "CLEARRAWBYTES", "COPYRAWBYTES", "PACKRAWBYTES",
                             "UNPACKRAWBYTES", "CLKRESET", "CLKSTART", "CLKSTOP",
                             "OPEN", "CLOSE", "WRITE", "WRITEBIN", "WRITESTRBIN",
                             "WRITERAWBYTES", "CLEARIOBUFF", "REWIND"})
# predefined functions giving the controller's one fixed date and time (``library.system``)
_FIXED_CLOCK = frozenset({"CDATE", "CTIME", "GETTIME"})
# predefined functions that read only the data passed to them, by reference too
# (``Present`` reads whether an optional parameter of the task's own frame is given)
# (the signal readers read the signal passed: ``SyntaxReads.allowed`` judges it)
_READS_ITS_ARGUMENTS = frozenset({"SOCKETGETSTATUS", "PRESENT", "CLKREAD", "DINPUT",
                                  "DOUTPUT", "AINPUT", "AOUTPUT", "GINPUT", "GOUTPUT",
                                  "GINPUTDNUM", "GOUTPUTDNUM", "TESTDI"})
# predefined procedures that set the signal passed (at once: no \SDelay) to a value
# computed from their other arguments and, for InvertDO, its own value
_SIGNAL_WRITERS = frozenset({"SET", "RESET", "SETDO", "SETGO", "SETAO", "INVERTDO",
                             "SETDI", "SETAI", "SETGI"})
# statements and calls an instruction may be compiled from, found by span
_STATEMENTS = (ast.Assignment, ast.ProcedureCall, ast.FunctionCall, ast.Return)


class SyntaxReads:
    """Whether expressions of a task read only data no other task writes, from their
    syntax (see the module docstring): ``stable[task]``, the global slots no other
    task writes; ``outside``, the global slots written outside the loaded code."""

    def __init__(self, stable: list, outside, references: "ReferenceParameters", cell):
        self.stable = stable
        self.outside = outside
        self.references = references
        self.cell = cell                # CellView: the signals and robots others touch
        self._loops: dict = {}          # routine index -> names of its FOR variables

    def allowed(self, task: int, routine, expression) -> bool:
        if expression is None:
            return False
        lookup = routine.scope.lookup
        work = [expression]
        while work:
            node = work.pop()
            kind = type(node)
            if kind is ast.NameRef:
                symbol = lookup(node.name.key)
                if symbol is None and node.name.key in self.loop_variables(routine):
                    continue             # a FOR variable (its scope is the loop's)
                index = physical_signal(self.references.program, routine, node.name)
                if index is not None:
                    if not self.cell.signal_readable(task, index):
                        return False
                    continue             # a signal no other task writes
                if signal_data(symbol):
                    # bound at run time (AliasIO, a signal parameter): any signal; a
                    # global one's binding is data another task may write
                    if not self.cell.signal_readable(task, None) or \
                            symbol.kind == GLOBAL_DATA and not self.readable(task, symbol.slot):
                        return False
                    continue
                if symbol is None or not (
                        symbol.kind == CONSTANT or
                        symbol.kind == LOCAL_DATA and not symbol.by_reference or
                        symbol.kind == GLOBAL_DATA and self.readable(task, symbol.slot) or
                        symbol.kind == LOCAL_DATA and self._referents_readable(
                            task, routine, symbol)):
                    return False
                continue
            if kind is ast.FunctionCall:
                symbol = lookup(node.name.key)
                if symbol is not None and symbol.kind == ROUTINE:
                    # a user function: hoisted before the instruction, which reads the
                    # result from the frame (its arguments are the call's to judge)
                    continue
                robot = self.cell.robot_readable(task, node) if symbol is None else None
                if robot is False:
                    return False         # another task's moves change what it reads
                if not (robot or _pure_function(node, lookup) or
                        node.name.key in _READS_ITS_ARGUMENTS and symbol is None):
                    return False
                work.extend(argument for argument in node.args)
            elif kind is ast.Argument:
                if node.kind == ast.CONDITIONAL:
                    return False
            elif kind not in _PLAIN_EXPRESSIONS:
                return False
            for field in node.__dataclass_fields__:
                if field not in ("span", "name") and not (kind is ast.FunctionCall):
                    value = getattr(node, field)
                    if isinstance(value, (tuple, list)):
                        work.extend(item for item in value if item is not None)
                    elif hasattr(value, "__dataclass_fields__"):
                        work.append(value)
        return True

    def readable(self, task: int, slot: int) -> bool:
        """Whether global data ``slot`` is written by no other task and, when written
        outside the loaded code, its reads only choose (``outside_free``)."""
        return slot in self.stable[task] and (slot not in self.outside or
                                              outside_free(self.outside[slot]))

    def _referents_readable(self, task: int, routine, symbol) -> bool:
        """A parameter passed by reference: whether every datum a call passes is."""
        referents = self.references.referents(routine.index, symbol)
        return referents is not None and all(
            where is not None or self.readable(task, slot) for where, slot in referents)

    def loop_variables(self, routine) -> frozenset:
        found = self._loops.get(routine.index)
        if found is None:
            found = self._loops[routine.index] = frozenset(
                node.variable.key for node in _walk(routine.ast)
                if isinstance(node, ast.For)) if routine.ast is not None else frozenset()
        return found


class StatementFootprints:
    """Footprints of the instructions ``fusion`` does not describe, from the statements
    they were compiled from (see the module docstring).  ``own[task]``: the global slots
    only that task's code names; ``visible_local(routine, slot)``: whether an atom names
    that routine datum; ``visible``: the global data keys atoms name."""

    def __init__(self, reads: SyntaxReads, own: list, visible: set,
                 visible_local: Callable, global_keys: list):
        self.reads = reads
        self.global_keys = global_keys  # global slot -> its data's key (upper case)
        self.own = own
        self.visible = visible
        self.visible_local = visible_local
        self._nodes: dict = {}          # routine index -> span -> statement or call
        # an atom naming signal data (bound at run time) may read any signal
        program = reads.references.program
        self.signal_data_visible = any(
            getattr(data.type, "kind", None) == SEMI_VALUE and data.key in visible
            for data in program.globals) or any(
            signal_data(routine.scope.lookup(key)) for routine in program.routines
            if routine.scope is not None for key in visible)

    def statement(self, task: int, routine, instruction) -> Footprint:
        """An Action or ControlAction: an assignment, a numeric update, TPWrite, WaitTime."""
        node = self._node(routine, instruction.span)
        lookup = routine.scope.lookup
        if isinstance(node, ast.ProcedureCall):
            update = as_assignment(node, lookup)
            if update is None:
                return self._predefined(task, routine, node) \
                    if lookup(node.name.key) is None else SHARED
            node = update
        if not isinstance(node, ast.Assignment):
            return SHARED
        if not self.reads.allowed(task, routine, node.value):
            return SHARED
        return self._written(task, routine, node.target)

    def _predefined(self, task: int, routine, call) -> Footprint:
        """A call of a predefined procedure: TPWrite and WaitTime, a procedure with no
        effect, a socket instruction (module docstring); any other is shared."""
        key = call.name.key
        if key in _SIGNAL_WRITERS:
            return self._signal_written(task, routine, call)
        if key in _QUIET_PROCEDURES:
            return LOCAL if self._arguments_allowed(task, routine, call) else SHARED
        if key in PLAIN_MOVES:
            # the task's own robot (``cell_uses``), its arguments read (the PERS tool and
            # work object too: ``data_uses(moves_read=True)``); \ID is never evaluated and
            # the barriers are SyncMoveOn/Off; path corrections (\Corr) left shared
            return LOCAL if self.reads.cell.robot_own(task) and not any(
                argument.name is not None and argument.name.key == "CORR"
                for argument in call.args) and self._arguments_allowed(task, routine, call) \
                else SHARED
        entry = registry.lookup_procedure(key)
        if entry is None or key not in _ARGUMENTS_ONLY and entry.modelled != registry.NO_EFFECT:
            return SHARED
        parameters = entry.signature.parameters
        required = [parameter for parameter in parameters if not parameter.optional]
        found, position = LOCAL, 0
        for argument in call.args:
            if argument.kind == ast.CONDITIONAL:
                return SHARED
            if argument.name is not None:
                spec = next((p for p in parameters if p.key == argument.name.key), None)
            else:
                spec = required[position] if position < len(required) else None
                position += 1
            if argument.value is None and spec is not None and argument.name is not None:
                continue                         # a switch
            if spec is None:
                return SHARED
            if spec.by_reference:
                footprint = self._written(task, routine, argument.value)
            else:
                footprint = LOCAL if self.reads.allowed(task, routine, argument.value) \
                    else SHARED
            if not footprint.independent:
                return SHARED
            found = VISIBLE if footprint.visible else found
        return found

    def _signal_written(self, task: int, routine, call) -> Footprint:
        """Set, Reset, SetDO ... of a configured signal no other task names (``cell_uses``),
        its value read from data no other task writes; visible when an atom names it."""
        signal = argument_expression(call, "Signal", 0)
        if not isinstance(signal, ast.NameRef) or any(
                argument.kind == ast.CONDITIONAL or argument.name is not None and
                argument.name.key == "SDELAY" for argument in call.args):
            return SHARED
        index = physical_signal(self.reads.references.program, routine, signal.name)
        if index is None or not self.reads.cell.signal_own(task, index) or \
                not all(argument.value is signal or argument.value is None or
                        self.reads.allowed(task, routine, argument.value)
                        for argument in call.args):
            return SHARED
        key = self.reads.references.program.signals[index].key
        return VISIBLE if key in self.visible or self.signal_data_visible else LOCAL

    def _written(self, task: int, routine, target) -> Footprint:
        """A write of the data under ``target`` (its indices read): independent when that
        is the task's own (module docstring)."""
        lookup = routine.scope.lookup
        if not self.reads.allowed(task, routine, target):
            return SHARED
        root = target_root(target)
        symbol = lookup(root.name.key) if isinstance(root, ast.NameRef) else None
        if symbol is None:
            return SHARED
        if symbol.kind == GLOBAL_DATA:
            if symbol.slot not in self.own[task] or symbol.slot in self.reads.outside:
                return SHARED
            return VISIBLE if self.global_keys[symbol.slot] in self.visible else LOCAL
        if symbol.kind == LOCAL_DATA and not symbol.by_reference and not symbol.optional:
            return VISIBLE if self.visible_local(routine, symbol.slot) else LOCAL
        if symbol.kind == LOCAL_DATA:
            return self._through_reference(task, routine, symbol)
        return SHARED

    def _through_reference(self, task: int, routine, symbol) -> Footprint:
        """A write through a parameter passed by reference: to whatever its calls pass,
        each of which must be the task's own."""
        referents = self.reads.references.referents(routine.index, symbol)
        if referents is None:
            return SHARED
        visible = self.visible_local(routine, symbol.slot)
        for where, slot in referents:
            if where is None:
                if slot not in self.own[task] or slot in self.reads.outside:
                    return SHARED
                visible = visible or self.global_keys[slot] in self.visible
            else:
                visible = visible or self.visible_local(
                    self.reads.references.program.routines[where], slot)
        return VISIBLE if visible else LOCAL

    def call(self, task: int, routine, instruction) -> Footprint:
        """A Call with arguments (of a procedure, or a function hoisted before its
        statement): it binds them and pushes a frame of the task's own."""
        callee = instruction.routine
        if instruction.for_wait or callee.kind not in ("PROC", "FUNC"):
            return SHARED
        node = self._node(routine, instruction.span)
        if not isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) or \
                node.name.key != callee.name.upper():
            return SHARED
        return LOCAL if self._arguments_allowed(task, routine, node) else SHARED

    def returned(self, task: int, routine, instruction) -> Footprint:
        """RETURN with a value: it writes the caller's temporary and pops the frame."""
        node = self._node(routine, instruction.span)
        if routine.kind != "FUNC" or not isinstance(node, ast.Return) or node.value is None:
            return SHARED
        return LOCAL if self.reads.allowed(task, routine, node.value) else SHARED

    def wait(self, task: int, routine, instruction) -> Footprint:
        """A WaitUntil without a time limit: it reads its condition and moves on or stays
        (a task there may wait; ``task_groups`` tells the two apart in each state)."""
        node = self._node(routine, instruction.span)
        if instruction.timeout is not None or instruction.flag_ref is not None or \
                instruction.rerun is not None or not isinstance(node, ast.ProcedureCall) or \
                node.name.key != "WAITUNTIL":
            return SHARED
        return LOCAL if self._arguments_allowed(task, routine, node) else SHARED

    def restarts_cycle(self, routine, instruction) -> bool:
        """Whether the instruction is ExitCycle: its task starts its entry routine again
        (its frames only, and the UNDO handlers of the routines it leaves)."""
        node = self._node(routine, instruction.span)
        return isinstance(node, ast.ProcedureCall) and node.name.key in RESTARTS_CYCLE and \
            routine.scope.lookup(node.name.key) is None

    def _arguments_allowed(self, task: int, routine, call) -> bool:
        return all(argument.kind != ast.CONDITIONAL and
                   (argument.value is None or
                    self.reads.allowed(task, routine, argument.value))
                   for argument in call.args)

    def _node(self, routine, span):
        nodes = self._nodes.get(routine.index)
        if nodes is None:
            nodes = self._nodes[routine.index] = statement_nodes(routine)
        return nodes.get(span)


def statement_nodes(routine) -> dict:
    """The assignments, calls and RETURNs of a routine by span (the outermost first)."""
    nodes: dict = {}
    decl = routine.ast
    if decl is not None:
        for node in _walk((decl.body, decl.error, decl.undo, decl.backward)):
            if isinstance(node, _STATEMENTS):
                nodes.setdefault(node.span, node)
    return nodes


class ReferenceParameters:
    """What the parameters passed by reference (VAR, INOUT, PERS) of each routine stand
    for: the roots of the arguments every call of the routine passes, each (None, global
    slot) or (calling routine's index, its own datum's slot); unknown (None) when some call
    passes anything else (a parameter passed on by reference, an optional one), names
    its arguments or gives an optional one, or a late-bound call (``%name%``) may reach
    the routine.  Optional parameters a call leaves out are absent.  Calls pass arguments only so (``Call``, ``LateCall``): an entry, a trap
    and a routine a move runs take none."""

    def __init__(self, program):
        self.program = program
        self._passed: Optional[dict] = None   # (routine, slot) -> set of roots, or None

    def referents(self, routine_index: int, symbol) -> Optional[frozenset]:
        """The roots ``symbol`` (a by-reference parameter of the routine) stands for."""
        if self._passed is None:
            self._passed = self._find()
        found = self._passed.get((routine_index, symbol.slot))
        return None if not found or symbol.optional else frozenset(found)

    def _find(self) -> dict:
        passed: dict = {}
        for caller in self.program.routines:
            nodes = None
            for instruction in caller.code:
                if isinstance(instruction, LateCall):
                    for callee, _ in instruction.candidates.values():
                        for parameter in callee.parameters:
                            passed[(callee.index, parameter.slot)] = None
                    continue
                if not isinstance(instruction, Call):
                    continue
                callee = instruction.routine
                if nodes is None:
                    nodes = statement_nodes(caller)
                node = nodes.get(instruction.span)
                args = getattr(node, "args", None)
                # positional arguments bind the required parameters in order (optional
                # ones left out are absent: ``referents`` gives nothing for them)
                required = [parameter for parameter in callee.parameters
                            if not parameter.optional]
                plain = args is not None and len(args) == len(required) and all(
                    argument.kind == ast.REQUIRED and argument.name is None
                    for argument in args)
                for parameter in callee.parameters:
                    if not parameter.by_reference:
                        continue
                    key = (callee.index, parameter.slot)
                    root = _root(caller, args[required.index(parameter)].value) \
                        if plain and not parameter.optional else None
                    if root is None or passed.get(key, set()) is None:
                        passed[key] = None
                    else:
                        passed.setdefault(key, set()).add(root)
        return passed


def _root(caller, argument) -> Optional[tuple]:
    """(None, global slot) or (the caller's index, slot) of the datum under an argument
    passed by reference; None for anything else."""
    root = target_root(argument)
    if not isinstance(root, ast.NameRef):
        return None
    symbol = caller.scope.lookup(root.name.key)
    if symbol is None:
        return None
    if symbol.kind == GLOBAL_DATA:
        return None, symbol.slot
    if symbol.kind == LOCAL_DATA and not symbol.by_reference and not symbol.optional:
        return caller.index, symbol.slot
    return None


def outside_free(data) -> bool:
    """Whether a read of data written outside the loaded code (``load.outside_data``)
    only chooses a value and stores none: no loaded code writes it, no wait keeps what it
    read, no atom names it.  Its stored value never changes, so such a read commutes with
    every other task's step, as the read of a free input chosen where it is read does."""
    return not data.written_by_waits and not data.observed


def _pure_function(call, lookup) -> bool:
    """A predefined function that computes from its arguments alone (not "special", none
    passed by reference), a controller reading the check fixes (``arguments.fixed``:
    GetMotorTorque, MaxRobSpeed; the call compiles to its constant value), or the fixed
    date and time (CDate, CTime, GetTime: ``library.system``)."""
    if lookup(call.name.key) is not None:
        return False                     # (data of that name: not a function)
    if call.name.key in _FIXED_CLOCK:
        return True                      # (a constant: the check's fixed date and time)
    entry = registry.lookup_function(call.name.key)
    return entry is not None and \
        (not entry.special or hasattr(entry.factory, "reading")) and \
        not any(parameter.by_reference for parameter in entry.signature.parameters)
