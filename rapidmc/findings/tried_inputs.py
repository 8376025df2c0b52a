"""The inputs a check tried only some values of: what "never reached" and vacuity rest on.

A complete search shows what happens for the values each input was offered.
For most inputs those are all the values the program can tell apart (digital
inputs, TPReadFK buttons, derived analog and group domains, socket messages
that are only compared with strings).  Others were given a sample: socket
messages the program parses or searches, lines of files, numbers typed on the
FlexPendant.  Code that is never reached in such a check may still be reached
by another message, line or answer, so its warning says "with the ... tried"
and names the reading instruction instead of "under any input".

The controller's readings a check takes as fixed (OpMode, GetSysInfo, ...: RMC702,
``fixed_readings``) are inputs of the same kind: each call is named ("and the
controller's readings fixed (OpMode at line 107)").  So is an output signal that no
loaded code sets, read back with DOutput (a system output the controller sets, or one
another task sets): "the outputs no loaded code sets at their first value (DOutput at
line 118)"; and, in a program of one task, shared PERS data a condition reads (another
task or a PC may write it): "no other task writing the persistent data (SocketStr at line
38)".
A complete readings probe (``api``) read OpMode, RunMode, RobOS, IsSysId
and those DOutput reads at every value (``probed``): then they no longer explain anything.

A peer that closes its connection is an input too: in reality SocketSend and
SocketReceive then raise ERR_SOCK_CLOSED, which an ERROR handler may catch; a
check models that only with ``--socket-closures``.  So is a server's port that the
previous run still holds (SocketBind raises ERR_SOCK_ADDR_INUSE): "with the server's
port free (SocketBind at line 32)"; the closure probe tries both.  Likewise an EGM session may fail
(ERR_UDPUC_COMM when the sensor stops answering), which the check never makes happen:
in a program with an ERROR handler each EGM instruction that ran is named ("with no EGM
session failing (EGMRunJoint at line 29)").  Without it, when the program
has an ERROR handler, each such instruction that ran is named as well ("with no
peer closing its socket (SocketSend at line 97)"): the handler's code may be
reached by a closure the check did not try.  An interrupt the check does not model
(ISignalGI, IError, TriggInt ... have no effect in it) never comes, so a TRAP only it runs
is "never reached with no interrupt coming that the check does not model (IError at
line 12)".  The check's robot starts at its home position (every coordinate 0), a real one
wherever it was left: code that branches on a position read back (``IF CRobT().trans.z
< 500``, not a move relative to it) is "never reached with the robot starting at the
check's home position (CRobT at line 5)".

An input counts when its reading instruction ran in the search (an input the
program never reads cannot explain anything), and only for code some call could
reach: a routine that no entry, TRAP or late-bound call leads to is never
reached under any input (``called_routines``).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable, Sequence

from .. import ast
from ..semantics.program import ENVIRONMENT_NAMESPACE, PROGRAM_NAMESPACE, Program
from ..load.call_graph import called_routines  # noqa: F401  (coverage asks it here)
from ..load.input_flow import InputFlow
from ..semantics.scope import GLOBAL_DATA
from ..semantics.library import lookup_procedure
from ..semantics.library.position import AXES_PROBED
from ..semantics.values import UNCONNECTED_AXIS, to_num
from ..semantics.library.probed_readings import DOMAINS as PROBED_READINGS, FAILING
from ..semantics.library.registry import NO_EFFECT
from .fixed_readings import reading_calls

# instruction or function (canonical name) -> what a check offers it only some of
SAMPLED = {
    "SOCKETRECEIVE": "socket messages", "SOCKETRECEIVEFROM": "socket messages",
    "READSTR": "file lines", "READNUM": "file lines", "READBIN": "file lines",
    "READANYBIN": "file lines", "READSTRBIN": "file lines", "READRAWBYTES": "file lines",
    "TPREADNUM": "FlexPendant answers", "TPREADDNUM": "FlexPendant answers",
    "UINUMENTRY": "FlexPendant answers", "UIDNUMENTRY": "FlexPendant answers",
    "UINUMTUNE": "FlexPendant answers", "UIDNUMTUNE": "FlexPendant answers",
    "UIALPHAENTRY": "FlexPendant answers",
}


# instructions that raise ERR_SOCK_CLOSED when the peer has closed the connection
CLOSABLE = ("SOCKETSEND", "SOCKETRECEIVE", "SOCKETRECEIVEFROM")
# functions reading back an output signal's value
OUTPUT_READS = ("DOUTPUT", "GOUTPUT", "GOUTPUTDNUM", "AOUTPUT")
PEERS_OPEN = "no peer closing its socket"      # the kind of those, when closures are not tried
PLACES_SHOWN = 5     # lines named per reading instruction in a warning; the rest counted
# a server's SocketBind may find its port taken (ERR_SOCK_ADDR_INUSE), which only the closure
# probe makes happen
BINDS = ("SOCKETBIND",)
PORT_FREE = "the server's port free"            # the kind of those, in a program with a handler
FIXED = "the controller's readings fixed"      # the kind of a fixed reading (RMC702)
UNSET = "the outputs no loaded code sets at their first value"   # (system outputs, other tasks)
# EGM instructions whose session may fail on a real controller (ERR_UDPUC_COMM when the
# sensor stops answering), which the check never makes happen (they have no effect in it)
EGM_SESSIONS = ("EGMRUNJOINT", "EGMRUNPOSE", "EGMSETUPUC", "EGMACTJOINT", "EGMACTPOSE",
                "EGMSTREAMSTART")
EGM_UP = "no EGM session failing"              # the kind of those, in a program with a handler
# shared PERS data a condition reads in a task checked alone: another task or a PC may write
# it on the controller, which the check does not model
UNWRITTEN = "no other task writing the persistent data"
# instructions ordering an interrupt the check never delivers (modelled with no effect:
# ISignalGI/GO, IError, TriggInt ...): a real controller may run its TRAP
NO_INTERRUPT = "no interrupt coming that the check does not model"
# a read of the robot's position that does more than shape a move's target: the check's
# robot starts at its home position, a real one wherever the last program left it
START = "the robot starting at the check's home position"
# data written from outside (load.outside_data) that the code does more with than compare
# with constants: its domain (the constants compared, one other value, ...) is a sample
OUTSIDE_VALUES = "values written from outside"
# a free analog or group input with no exact default (load.stated_domains): the values the
# code singles out are a sample of those it may read
STATED = "assumed input values"
PHRASES = (PEERS_OPEN, PORT_FREE, FIXED, UNSET, UNWRITTEN, EGM_UP,
           NO_INTERRUPT, START)   # kinds that are phrases of their own


@dataclass(frozen=True)
class TriedInput:
    """A reading instruction whose input the check offered only a sample of values."""

    kind: str                  # "socket messages"
    instruction: str           # "SocketReceive", as written
    span: ast.Span


def sampled_inputs(program: Program, exact: Iterable[tuple] = (),
                   closures: bool = False, stated: frozenset = frozenset()) -> tuple:
    """Every reading instruction of the program's code whose input is sampled, in source
    order; ``exact``: (file, line, column) of sites whose domain covers every value;
    ``closures``: whether the check lets peers close their sockets (else the socket
    instructions that would raise ERR_SOCK_CLOSED are named, when an ERROR handler could
    catch it); ``stated``: upper-case names that read an input whose values are assumed,
    not exact (``load.stated_domains``)."""
    exact = set(exact)
    routines = [routine for routine in program.routines
                if routine.ast is not None and routine.namespace != ENVIRONMENT_NAMESPACE]
    # (every task's code: the environment model is no input)
    has_handler = any(routine.ast.error is not None for routine in routines)
    handled = not closures and has_handler
    found = []
    for routine in routines:
        for node, parents in ast.walk(routine.ast):
            if not isinstance(node, (ast.ProcedureCall, ast.FunctionCall, ast.NameRef)):
                continue
            if isinstance(node, ast.NameRef):
                if node.name.key in stated and not _binds_signal(parents):
                    found.append(TriedInput(STATED, node.name.text, node.span))
                continue
            if node.name.key in SAMPLED \
                    and (node.span.file, node.span.line, node.span.column) not in exact:
                found.append(TriedInput(SAMPLED[node.name.key], node.name.text, node.span))
            if handled and node.name.key in CLOSABLE:
                found.append(TriedInput(PEERS_OPEN, node.name.text, node.span))
            if has_handler and node.name.key in BINDS:     # (--socket-closures binds)
                found.append(TriedInput(PORT_FREE, node.name.text, node.span))
            if has_handler and node.name.key in EGM_SESSIONS:
                found.append(TriedInput(EGM_UP, node.name.text, node.span))
    found += [TriedInput(FIXED, name.text, name.span) for name in reading_calls(program)]
    found += [TriedInput(FIXED, call.name.text, call.span) for call in axis_reads(program)]
    found += [TriedInput(UNSET, read.name.text, read.span)
              for read in unset_output_reads(program)]
    found += [TriedInput(UNWRITTEN, ref.name.text, ref.span)
              for ref in unwritten_pers_reads(program)]
    found += [TriedInput(NO_INTERRUPT, call.name.text, call.span)
              for call in unmodelled_interrupt_orders(program)]
    found += [TriedInput(START, call.name.text, call.span)
              for call in start_position_reads(program)]
    found += [TriedInput(OUTSIDE_VALUES, ref.name.text, ref.span)
              for ref in sampled_outside_reads(program)]
    return tuple(sorted(set(found), key=lambda t: (t.span.file, t.span.line, t.span.column)))


def _binds_signal(parents: tuple) -> bool:
    """Whether a name is an argument of AliasIO (which binds signal data, reading nothing)."""
    return any(isinstance(p, ast.ProcedureCall) and p.name.key == "ALIASIO" for p in parents)


def start_position_reads(program: Program) -> list:
    """The calls (every task's code) of CRobT, CPos and CJointT whose value does more than
    shape moves' targets (``InputFlow.position_reads_kept``): until a move puts the
    robot somewhere, they read the check's home position, where a real robot may be
    anywhere."""
    reads = program.analyses.get("start position reads")
    if reads is None:
        routines = [routine for routine in program.routines
                    if routine.ast is not None and routine.namespace != ENVIRONMENT_NAMESPACE]
        reads = tuple(InputFlow(routines, frozenset(), False,
                                tuple(program.globals)).position_reads_kept())
        program.analyses["start position reads"] = reads
    return list(reads)


def unset_output_reads(program: Program) -> list:
    """The reads (DOutput, GOutput, AOutput calls; a digital output read by name, ``IF
    doZone = 1``: its NameRef) of an output signal that no loaded code sets.

    The controller sets such an output itself (a system output: motors on, cycle on,
    execution error) or another task does; the check reads the value it started with.  A
    signal counts as set when any call of the program (every task, the environment model)
    passes it by name as an argument, to Set, SetDO, PulseDO, a routine of the program's own
    taking a signal parameter, or anything but the reads themselves."""
    reads, passed = [], set()
    digital = {signal.key for signal in program.signals if signal.kind == "DO"}
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node, parents in ast.walk(routine.ast):
            if isinstance(node, ast.NameRef) and node.name.key in digital and \
                    routine.namespace != ENVIRONMENT_NAMESPACE and \
                    not isinstance(parents[-1] if parents else None, ast.Argument):
                reads.append((node.name.key, node))       # read by name: IF doZone = 1
            if not isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                continue
            names = [a.value.name.key for a in node.args if isinstance(a.value, ast.NameRef)]
            if node.name.key in OUTPUT_READS and isinstance(node, ast.FunctionCall):
                if names and routine.namespace != ENVIRONMENT_NAMESPACE:
                    reads.append((names[0], node))
            else:
                passed.update(names)
    # (an output read as set outside the loaded code takes both values: load.outside_outputs)
    outputs = {signal.key for signal in program.signals
               if signal.kind.endswith("O") and not signal.outside}
    return [read for name, read in reads if name in outputs and name not in passed]


def unmodelled_interrupt_orders(program: Program) -> list:
    """The calls (every task's code) of predefined instructions that order an interrupt
    (an ``intnum`` parameter) and are modelled with no effect: the check never delivers
    that interrupt, which a real controller does (a group signal changing, an error of a
    domain, a trigger point passed)."""
    calls = []
    for routine in program.routines:
        if routine.ast is None or routine.namespace == ENVIRONMENT_NAMESPACE:
            continue
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.ProcedureCall) and \
                    routine.scope.lookup(node.name.key) is None and \
                    _orders_unmodelled_interrupt(node.name.key):
                calls.append(node)
    return calls


def _orders_unmodelled_interrupt(key: str) -> bool:
    entry = lookup_procedure(key)
    return entry is not None and entry.modelled == NO_EFFECT and \
        any(parameter.type_name.upper() == "INTNUM" for parameter in entry.signature.parameters)


def unwritten_pers_reads(program: Program) -> list:
    """In a program of one task, the reads of shared PERS data (not TASK PERS) in a
    condition (IF, WHILE, TEST, WaitUntil) that the check does not already choose as data
    written from outside (``Program.outside_data``): another task or a PC may write such
    data on the controller (the Hanoi socket task waits for ``SocketStr = ""``, which the
    motion task sets), while the check sees only this task's writes."""
    if program.task_entries:
        return []                  # (the loaded tasks' writes are modelled)
    by_slot = {data.slot: data for data in program.globals}
    outside = set(getattr(program, "outside_data", None) or {})
    reads = []
    for routine in program.routines:
        if routine.ast is None or routine.namespace != PROGRAM_NAMESPACE:
            continue
        for node in _conditions(routine.ast):
            for ref, _ in ast.walk(node):
                if not isinstance(ref, ast.NameRef):
                    continue
                symbol = routine.scope.lookup(ref.name.key)
                data = by_slot.get(symbol.slot) if symbol is not None \
                    and symbol.kind == GLOBAL_DATA else None
                if data is not None and data.storage == "PERS" and not data.task_local \
                        and data.slot not in outside:
                    reads.append(ref)
    return reads


def sampled_outside_reads(program: Program) -> list:
    """The reads of PERS data the check chooses as written from outside
    (``Program.outside_data``) whose domain is a sample: data of a string or number
    component that some read does more with than compare with a constant (``=``, ``<>``,
    an ordering, TEST ... CASE): cut with StrPart, searched with StrFind, parsed, computed
    with.  Its domain holds the constants compared and a few texts built for such reads
    (``load.outside_data``); a PC may write any other, and code unreached with the values
    tried may run with one of those (``IF StrMatch(command, 1, "move") = 1``).  Every
    read of such data is named; data only compared with constants (or bool) has an exact
    domain and is not."""
    outside = getattr(program, "outside_data", None) or {}
    if not outside:
        return []
    reads: dict = {}                 # slot -> its reads
    sampled = set()
    for node, parents, symbol in named_in_code(program):
        if symbol.kind != GLOBAL_DATA or symbol.slot not in outside:
            continue
        outer, above = _whole_read(node, parents)
        if isinstance(above, ast.Assignment) and above.target is outer:
            continue                                    # (a write)
        reads.setdefault(symbol.slot, []).append(node)
        if not _compared_with_constant(outer, above) and \
                any(values and not isinstance(values[0], bool)
                    for values in outside[symbol.slot].domains.values()):
            sampled.add(symbol.slot)
    return [ref for slot in sorted(sampled) for ref in reads[slot]]


def named_in_code(program: Program):
    """(NameRef, its parents, the symbol it names) for each name of the program's code
    (every task's, not the environment model's) that its routine's scope resolves."""
    for routine in program.routines:
        if routine.ast is None or routine.namespace == ENVIRONMENT_NAMESPACE:
            continue
        for node, parents in ast.walk(routine.ast):
            if isinstance(node, ast.NameRef):
                symbol = routine.scope.lookup(node.name.key)
                if symbol is not None:
                    yield node, parents, symbol


def _whole_read(node, parents: tuple) -> tuple:
    """The data path expression a name starts (``name.c{i}``) and the node above it."""
    index = len(parents)
    outer = node
    while index and isinstance(parents[index - 1], (ast.Component, ast.Index)) and \
            parents[index - 1].base is outer:
        outer = parents[index - 1]
        index -= 1
    return outer, parents[index - 1] if index else None


def _compared_with_constant(outer, above) -> bool:
    """Whether the read ``outer`` is a side of a comparison with a literal, or what a TEST
    tells apart."""
    if isinstance(above, ast.Test):
        return above.subject is outer
    if isinstance(above, ast.Binary) and above.op in ("=", "<>", "<", "<=", ">", ">="):
        other = above.right if above.left is outer else above.left
        if isinstance(other, ast.Unary) and other.op in ("-", "+"):
            other = other.operand
        return isinstance(other, (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral))
    return False


def _conditions(routine_ast):
    """The expressions a routine's choices and waits depend on."""
    for node, _ in ast.walk(routine_ast):
        if isinstance(node, (ast.IfBranch, ast.While)) and node.condition is not None:
            yield node.condition
        elif isinstance(node, ast.Test):
            yield node.subject
        elif isinstance(node, ast.ProcedureCall) and node.name.key == "WAITUNTIL":
            yield from (argument.value for argument in node.args if argument.value is not None)


def axis_reads(program: Program) -> list:
    """The calls of the program's code that read the robot's external axes (CRobT,
    CJointT), in a program that tells connected axes apart (``tests_axes``): the modelled
    robot has none (9E9), a cell may have some, and only the readings probe connects them
    (``library.position``)."""
    if not tests_axes(program):
        return []
    own = {routine.key for routine in program.routines}       # (a routine of that name)
    return [node for routine in program.routines
            if routine.ast is not None and routine.namespace == PROGRAM_NAMESPACE
            for node, _ in ast.walk(routine.ast)
            if isinstance(node, ast.FunctionCall) and node.name.key in AXES_PROBED
            and node.name.key not in own]


def tests_axes(program: Program) -> bool:
    """Whether the program's code compares a value with 9E9 (= or <>), the value of an
    external axis a robot lacks (``IF eax <> 9E9`` in the ROS modules).  Only then does
    the readings probe connect external axes: each such choice doubles the states of a
    probe after every CRobT, and a program that never tells the axes apart gains nothing."""
    return any(isinstance(node, ast.Binary) and node.op in ("=", "<>") and any(
               isinstance(side, ast.NumLiteral) and to_num(float(side.value)) == UNCONNECTED_AXIS
               for side in (node.left, node.right))
               for routine in program.routines
               if routine.ast is not None and routine.namespace == PROGRAM_NAMESPACE
               for node, _ in ast.walk(routine.ast))


def unset_digital_outputs(program: Program) -> list:
    """The digital outputs of ``unset_output_reads``: the readings probe lets them read 0
    or 1 (a system output, another task, the FlexPendant's I/O view may set them)."""
    keys = {read.name.key if isinstance(read, ast.NameRef) else read.args[0].value.name.key
            for read in unset_output_reads(program)
            if isinstance(read, ast.NameRef) or read.name.key == "DOUTPUT"}
    return [signal for signal in program.signals if signal.key in keys]


def probed(read: TriedInput) -> bool:
    """Whether the readings probe frees ``read``: a reading of ``probed_readings.DOMAINS``
    or a DOutput of an output no loaded code sets."""
    name = read.instruction.upper()
    return (read.kind == FIXED and (name in PROBED_READINGS or name in AXES_PROBED)) or \
        (read.kind == UNSET and (name == "DOUTPUT" or name not in OUTPUT_READS))   # (a DO by name)


def varied(read: TriedInput) -> bool:
    """Whether the readings probe varies ``read``: those it frees (``probed``) and those
    it lets fail (``probed_readings.FAILING``: CalcJointT out of reach)."""
    return probed(read) or (read.kind == FIXED and read.instruction.upper() in FAILING)


def reached(inputs: Sequence[TriedInput], executed: set) -> tuple:
    """The inputs whose reading instruction ran (``executed``: (file, line) pairs)."""
    return tuple(t for t in inputs if (t.span.file, t.span.line) in executed)


def qualifier(inputs: Sequence[TriedInput]) -> str:
    """``under any input``, or ``with the socket messages tried (SocketReceive at line 191)``."""
    if not inputs:
        return "under any input"
    kinds = list(dict.fromkeys(t.kind for t in inputs if t.kind not in PHRASES))
    phrases = [f"the {kinds[0] if len(kinds) == 1 else ', '.join(kinds[:-1]) + ' and ' + kinds[-1]}"
               f" tried"] if kinds else []
    phrases += [phrase for phrase in PHRASES if any(t.kind == phrase for t in inputs)]
    places = []
    for name in dict.fromkeys(t.instruction for t in inputs):
        lines = sorted({t.span.line for t in inputs if t.instruction == name})
        shown = ", ".join(map(str, lines[:PLACES_SHOWN]))
        if len(lines) > PLACES_SHOWN:       # a reading called all over a backup: a count
            shown += f" and {len(lines) - PLACES_SHOWN} more"
        places.append(f"{name} at line{'s' if len(lines) > 1 else ''} {shown}")
    return f"with {' and '.join(phrases)} ({'; '.join(places)})"
