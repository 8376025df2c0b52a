"""Predefined routines that need the program state: one factory per routine.

A factory receives the call site (already checked against the signature in
the registry) and returns a compiled closure (functions) or an instruction
(procedures).  Grouped by topic: data and system, robot position, I/O,
clocks, FlexPendant, waits, motion, interrupts, program control, and the
model-only routines of environment modules.
"""
from __future__ import annotations

from typing import Callable

from .. import ast
from ..diagnostics import ARGUMENT, TYPE_MISMATCH, error
from . import values
from .builtins.registry import special
from .calls import REFERENCE, SIGNAL_ARG, expr_root_name
from .errors import ERROR_NUMBERS, RapidError
from .errors_flow import unwind_all
from .expressions import Compiled, constant, read_signal
from .instructions import Action, ControlAction, Instruction, Wait, enter_routine
from .machine import ABSENT, GLOBAL
from .scope import LOCAL_DATA
from .state import ENDED, Frame, Interrupt, Interrupts
from .timing import advance_to, next_event, schedule
from .types import (BOOL, DNUM, NON_VALUE, NUM, RECORD, SEMI_VALUE, STRING, ArrayType,
                    RapidType)

FUNCTIONS: dict[str, Callable] = {}
PROCEDURES: dict[str, Callable] = {}
ENVIRONMENT_ONLY = {"ANYBOOL", "ANYNUM", "SETDI", "SETAI", "SETGI"}

# model-only routines of environment modules (documented in docs/environment.md)
special("bool AnyBool()")
special("num AnyNum(num Low, num High)")
special("SetDI(VAR signaldi Signal, dionum Value)")
special("SetAI(VAR signalai Signal, num Value)")
special("SetGI(VAR signalgi Signal, num Value)")

ROBOT_TCP, ROBOT_TOOL, ROBOT_WOBJ, ROBOT_JOINTS = range(4)


def function(*names: str):
    def register(factory):
        for name in names:
            FUNCTIONS[name.upper()] = factory
        return factory
    return register


def procedure(*names: str):
    def register(factory):
        for name in names:
            PROCEDURES[name.upper()] = factory
        return factory
    return register


class Arguments:
    """The bound arguments of one call, by parameter name."""

    def __init__(self, calls, compiler, call, entry):
        self.binders = calls.bind(compiler, entry, call.args, call.span)
        self.specs = entry.signature.parameters
        self.by_key = {spec.key: binder for spec, binder in zip(self.specs, self.binders)}

    def fn(self, key: str) -> Callable:
        return self.by_key[key.upper()][1]

    def kind(self, key: str) -> str:
        return self.by_key[key.upper()][0]

    def value(self, key: str) -> Callable:
        """fn(m) -> value of the argument (ABSENT if not given); reads through references."""
        kind, fn = self.by_key[key.upper()]
        if kind == REFERENCE:
            def deref(m):
                ref = fn(m)
                return ABSENT if ref is ABSENT else m.read_ref(ref)
            return deref
        return fn


def _arg_expr(call, key: str, position: int):
    """The AST expression given for a parameter (by name or position), or None."""
    positional = [a for a in call.args if a.kind == ast.REQUIRED and a.name is None]
    for arg in call.args:
        if arg.name is not None and arg.name.key == key.upper():
            return arg.value
    if 0 <= position < len(positional):
        return positional[position].value
    return None


# ===========================================================================
# Data and system functions
# ===========================================================================

@function("Present")
def _present(calls, compiler, call, entry) -> Compiled:
    if len(call.args) != 1 or call.args[0].kind != ast.REQUIRED or \
            not isinstance(call.args[0].value, ast.NameRef):
        raise error(ARGUMENT, "Present takes one optional parameter name", call.span)
    name = call.args[0].value.name
    symbol = compiler.scope.lookup(name.key)
    if symbol is None or symbol.kind != LOCAL_DATA or not symbol.optional:
        raise error(ARGUMENT, f"'{name.text}' is not an optional parameter of this routine",
                    call.args[0].span)
    slot = symbol.slot
    return Compiled(lambda m: m.frames[-1].locals[slot] is not ABSENT, BOOL)


@function("Dim")
def _dim(calls, compiler, call, entry) -> Compiled:
    args = [a for a in call.args if a.kind == ast.REQUIRED]
    if len(args) != 2:
        raise error(ARGUMENT, "Dim takes an array and a dimension number", call.span)
    array = compiler.value(args[0].value)
    if array.type is not None and not isinstance(array.type, ArrayType):
        raise error(TYPE_MISMATCH, "the first argument of Dim must be an array", args[0].span)
    number = compiler.value(args[1].value, NUM)
    array_fn, number_fn = array.fn, number.fn

    def dim(m):
        value = array_fn(m)
        n = number_fn(m)
        if n != int(n) or n < 1:
            raise RapidError("ERR_ILLDIM", f"dimension {values.format_num(n)} does not exist")
        for _ in range(int(n) - 1):
            if not value or not isinstance(value[0], tuple):
                raise RapidError("ERR_ILLDIM", f"the array has fewer than {int(n)} dimensions")
            value = value[0]
        return float(len(value))
    return Compiled(dim, NUM)


def value_kind(rapid_type):
    """The ``kind`` argument of ``values.format_value`` for a static type."""
    if isinstance(rapid_type, ArrayType):
        inner = ArrayType(rapid_type.element, rapid_type.dims[1:]) if rapid_type.rank > 1 \
            else rapid_type.element
        return ("array", value_kind(inner))
    if rapid_type is None:
        return "num"
    if rapid_type.kind == RECORD:
        return tuple(value_kind(c.type) for c in rapid_type.components)
    return "dnum" if rapid_type is DNUM else "num"


def format_typed(value, kind) -> str:
    if isinstance(kind, tuple) and kind and kind[0] == "array":
        return "[" + ",".join(format_typed(v, kind[1]) for v in value) + "]"
    return values.format_value(value, kind)


@function("ValToStr")
def _val_to_str(calls, compiler, call, entry) -> Compiled:
    args = [a for a in call.args if a.kind == ast.REQUIRED]
    if len(args) != 1:
        raise error(ARGUMENT, "ValToStr takes one value", call.span)
    value = compiler.value(args[0].value)
    kind = value_kind(value.type)
    fn = value.fn
    return Compiled(lambda m: values.checked_string(format_typed(fn(m), kind)), STRING)


@function("StrToVal")
def _str_to_val(calls, compiler, call, entry) -> Compiled:
    from .literals import parse_literal
    arguments = Arguments(calls, compiler, call, entry)
    text_fn = arguments.fn("Str")
    ref_fn = arguments.fn("Val")
    target = _arg_expr(call, "Val", 1)
    _, target_type, _ = compiler.reference(target, "written by StrToVal")
    element = target_type.element if isinstance(target_type, ArrayType) else target_type
    if isinstance(element, RapidType) and element.kind in (SEMI_VALUE, NON_VALUE):
        raise error(TYPE_MISMATCH, f"StrToVal writes value data, not {element.name}",
                    target.span)

    def str_to_val(m):
        parsed = parse_literal(text_fn(m), target_type)
        if parsed is None:
            return False
        m.write_ref(ref_fn(m), parsed)
        return True
    return Compiled(str_to_val, BOOL)


@function("IsPers", "IsVar")
def _is_pers(calls, compiler, call, entry) -> Compiled:
    target = _arg_expr(call, "DatObj", 0)
    _, _, symbol = compiler.reference(target, "inspected")
    storage = symbol.storage
    wanted = "PERS" if call.name.key == "ISPERS" else "VAR"
    return constant(storage == wanted, BOOL)


@function("OpMode")
def _op_mode(calls, compiler, call, entry) -> Compiled:
    return constant(compiler.linker.system_symbol(ast.Name.of("OP_AUTO")).value, NUM)


@function("RunMode")
def _run_mode(calls, compiler, call, entry) -> Compiled:
    return constant(compiler.linker.system_symbol(ast.Name.of("RUN_CONT_CYCLE")).value, NUM)


@function("RemainingRetries")
def _remaining_retries(calls, compiler, call, entry) -> Compiled:
    return Compiled(lambda m: float(max(0, m.program.options.get("max_retries", 4)
                                        - m.frames[-1].retries)), NUM)


@function("CDate", "CTime")
def _date(calls, compiler, call, entry) -> Compiled:
    text = "2026-01-01" if call.name.key == "CDATE" else "00:00:00"
    return constant(text, STRING)


@function("GetTime")
def _get_time(calls, compiler, call, entry) -> Compiled:
    return constant(0.0, NUM)


# ===========================================================================
# Robot position
# ===========================================================================

@function("CPos")
def _cpos(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return Compiled(lambda m: m.robot[ROBOT_TCP][0], calls.linker.builtin_types["POS"])


@function("CRobT")
def _crobt(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return Compiled(lambda m: m.robot[ROBOT_TCP], calls.linker.builtin_types["ROBTARGET"])


@function("CJointT")
def _cjointt(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return Compiled(lambda m: m.robot[ROBOT_JOINTS], calls.linker.builtin_types["JOINTTARGET"])


@function("CTool")
def _ctool(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return Compiled(lambda m: m.robot[ROBOT_TOOL], calls.linker.builtin_types["TOOLDATA"])


@function("CWObj")
def _cwobj(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return Compiled(lambda m: m.robot[ROBOT_WOBJ], calls.linker.builtin_types["WOBJDATA"])


def _set_robot(m, part: int, value) -> None:
    robot = list(m.robot)
    robot[part] = value
    m.robot = tuple(robot)


# ===========================================================================
# I/O
# ===========================================================================

@function("DInput", "DOutput", "AOutput", "GOutput", "GInputDnum", "GOutputDnum")
def _read_signal(calls, compiler, call, entry) -> Compiled:
    signal = Arguments(calls, compiler, call, entry).fn("Signal")
    result = DNUM if call.name.key.endswith("DNUM") else NUM
    return Compiled(lambda m: m.io[signal(m)], result)


@function("TestDI")
def _test_di(calls, compiler, call, entry) -> Compiled:
    signal = Arguments(calls, compiler, call, entry).fn("Signal")
    return Compiled(lambda m: m.io[signal(m)] == 1, BOOL)


@function("ValidIO")
def _valid_io(calls, compiler, call, entry) -> Compiled:
    target = _arg_expr(call, "Signal", 0)
    if target is None:
        raise error(ARGUMENT, "ValidIO takes one signal", call.span)
    if isinstance(target, ast.NameRef):
        symbol = compiler.scope.lookup(target.name.key) or compiler.linker.system_symbol(target.name)
        if symbol is not None and symbol.kind == "signal":
            return constant(True, BOOL)
    ref_fn, _, _ = compiler.reference(target, "checked by ValidIO")
    return Compiled(lambda m: m.read_ref(ref_fn(m)) >= 0, BOOL)


def _write_signal(m, index: int, value: float) -> None:
    m.io = m.io.set(index, float(value))


def _dionum(value: float) -> float:
    if value not in (0, 1):
        raise RapidError("ERR_ARGVALERR", f"digital signal value must be 0 or 1, not "
                         f"{values.format_num(value)}")
    return float(value)


def _signal_action(calls, compiler, call, entry, compute) -> Instruction:
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")

    def act(m):
        index = signal(m)
        _write_signal(m, index, compute(m, arguments, m.io[index]))
    return Action(call.span, act)


@procedure("Set")
def _set(calls, compiler, call, entry):
    return _signal_action(calls, compiler, call, entry, lambda m, a, old: 1.0)


@procedure("Reset")
def _reset(calls, compiler, call, entry):
    return _signal_action(calls, compiler, call, entry, lambda m, a, old: 0.0)


@procedure("InvertDO")
def _invert(calls, compiler, call, entry):
    return _signal_action(calls, compiler, call, entry, lambda m, a, old: 1.0 - old)


@procedure("PulseDO")
def _pulse(calls, compiler, call, entry):
    """A pulse of \\PLength seconds (default 0.2): inverted (or high) now, back afterwards."""
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")
    high = arguments.value("High")
    length = arguments.value("PLength")

    def pulse(m):
        index = signal(m)
        old = m.io[index]
        seconds = length(m)
        seconds = 0.2 if seconds is ABSENT else seconds
        if high(m) is True:
            _write_signal(m, index, 1.0)
            schedule(m, seconds, index, 0.0)
        else:
            _write_signal(m, index, 1.0 - old)
            schedule(m, seconds, index, old)
    return Action(call.span, pulse)


@procedure("SetDO")
def _set_do(calls, compiler, call, entry):
    """SetDO: at once, or after \\SDelay seconds."""
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")
    value = arguments.value("Value")
    delay = arguments.value("SDelay")

    def set_do(m):
        index = signal(m)
        new = _dionum(value(m))
        seconds = delay(m)
        if seconds is ABSENT or seconds <= 0:
            _write_signal(m, index, new)
        else:
            schedule(m, seconds, index, new)
    return Action(call.span, set_do)


@procedure("SetDI")
def _set_di(calls, compiler, call, entry):
    def new_value(m, arguments, old):
        return _dionum(arguments.value("Value")(m))
    return _signal_action(calls, compiler, call, entry, new_value)


@procedure("SetAO", "SetAI", "SetGI")
def _set_ao(calls, compiler, call, entry):
    return _signal_action(calls, compiler, call, entry,
                          lambda m, arguments, old: arguments.value("Value")(m))


@procedure("SetGO")
def _set_go(calls, compiler, call, entry):
    def new_value(m, arguments, old):
        value = arguments.value("Value")(m)
        if value is ABSENT:
            value = arguments.value("Dvalue")(m)
        if value < 0 or value != int(value):
            raise RapidError("ERR_GO_LIM", "group output value must be a non-negative integer")
        return value
    return _signal_action(calls, compiler, call, entry, new_value)


@procedure("AliasIO")
def _alias_io(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    source = _arg_expr(call, "FromSignal", 0)
    target = _arg_expr(call, "ToSignal", 1)
    target_ref, target_type, _ = compiler.reference(target, "bound by AliasIO")
    if not (isinstance(target_type, RapidType) and target_type.kind == SEMI_VALUE):
        raise error(TYPE_MISMATCH, "the second argument of AliasIO must be signal data",
                    target.span)
    kind = target_type.signal_kind
    linker = compiler.linker
    source_value = compiler.value(source)
    if source_value.type is STRING:
        if source_value.is_constant:
            linker.physical_signal(source_value.constant, kind, source.span)
        name_fn = source_value.fn

        def source_index(m):
            signal = m.program.signal_index.get(name_fn(m).upper())
            if signal is None:
                raise RapidError("ERR_ALIASIO_DEF", f"no I/O signal named '{name_fn(m)}'")
            if signal.kind != kind:
                raise RapidError("ERR_ALIASIO_TYPE", f"signal {signal.name} is a {signal.kind}, "
                                 f"not a {kind}")
            return signal.index
    else:
        from .calls import signal_designator
        source_index = signal_designator(compiler, source, target_type)

    def alias(m):
        m.write_ref(target_ref(m), source_index(m))
    return Action(call.span, alias)


@procedure("AliasIOReset")
def _alias_io_reset(calls, compiler, call, entry):
    target = _arg_expr(call, "Signal", 0)
    target_ref, _, _ = compiler.reference(target, "reset by AliasIOReset")
    return Action(call.span, lambda m: m.write_ref(target_ref(m), -1))


# ===========================================================================
# Clocks: (running, started at, accumulated seconds) in virtual time
# ===========================================================================

def _clock_action(calls, compiler, call, entry, update) -> Instruction:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    return Action(call.span, lambda m: m.write_ref(ref(m), update(m, m.read_ref(ref(m)))))


def _elapsed(m, clock) -> float:
    running, started, accumulated = clock
    return accumulated + (m.clock - started if running else 0.0)


@procedure("ClkReset")
def _clk_reset(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: (clock[0], m.clock, 0.0))


@procedure("ClkStart")
def _clk_start(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: clock if clock[0] else (True, m.clock, clock[2]))


@procedure("ClkStop")
def _clk_stop(calls, compiler, call, entry):
    return _clock_action(calls, compiler, call, entry,
                         lambda m, clock: (False, m.clock, _elapsed(m, clock)))


@function("ClkRead")
def _clk_read(calls, compiler, call, entry) -> Compiled:
    ref = Arguments(calls, compiler, call, entry).fn("Clock")
    return Compiled(lambda m: values.to_num(round(_elapsed(m, m.read_ref(ref(m))), 3)), NUM)


# ===========================================================================
# FlexPendant
# ===========================================================================

TP_OPTIONS = (("NUM", "num"), ("BOOL", "bool"), ("POS", "num"), ("ORIENT", "num"),
              ("DNUM", "dnum"))


@procedure("TPWrite")
def _tp_write(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    text = arguments.fn("String")
    options = [(arguments.value(key), kind) for key, kind in TP_OPTIONS]

    def write(m):
        line = text(m)
        for fn, kind in options:
            value = fn(m)
            if value is not ABSENT:
                line += values.format_value(value, kind)
        m.output.append(line)
    return Action(call.span, write)


@procedure("TPErase")
def _tp_erase(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    return Action(call.span, lambda m: None)


@procedure("ErrWrite")
def _err_write(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    return Action(call.span, lambda m: None)


def _tp_read(calls, compiler, call, entry, kind: str):
    arguments = Arguments(calls, compiler, call, entry)
    answer = arguments.fn("TPAnswer")
    text = arguments.fn("TPText")
    convert = values.to_dnum if kind == "TPReadDnum" else values.to_num

    def read(m):
        m.output.append(text(m))
        value = m.choose(kind, m.chooser.tp_answers(kind))
        m.write_ref(answer(m), convert(value))
    return Action(call.span, read)


@procedure("TPReadNum", "TPReadDnum", "TPReadFK")
def _tp_read_any(calls, compiler, call, entry):
    return _tp_read(calls, compiler, call, entry, entry.signature.name)


# ===========================================================================
# Waiting
# ===========================================================================

@procedure("WaitTime")
def _wait_time(calls, compiler, call, entry):
    """One step when model checking; in run mode interrupts are served during the wait."""
    seconds = Arguments(calls, compiler, call, entry).value("Time")
    deadline_slot = compiler.routine.new_temporary(1, "<WaitTime deadline>", -1.0)

    def wait(m, instruction):
        if m.chooser.check_mode:
            if seconds(m) < 0:
                raise RapidError("ERR_ARGVALERR", "WaitTime needs a time >= 0")
            m.goto(instruction.next)
            return
        deadline = m.frames[-1].locals[deadline_slot]
        if deadline < 0:
            t = seconds(m)
            if t < 0:
                raise RapidError("ERR_ARGVALERR", "WaitTime needs a time >= 0")
            deadline = m.clock + t
        due = next_event(m.interrupts)
        if due is not None and due < deadline - 1e-9:
            advance_to(m, due)
            m.set_local(deadline_slot, deadline)
            return                      # still waiting: a trap may run first
        advance_to(m, deadline)
        m.set_local(deadline_slot, -1.0)
        m.goto(instruction.next)
    return ControlAction(call.span, wait)


def _wait(calls, compiler, call, entry, condition_factory, what: str) -> Instruction:
    arguments = Arguments(calls, compiler, call, entry)
    condition = condition_factory(arguments)
    max_time = arguments.value("MaxTime")
    flag = arguments.fn("TimeFlag")
    timeout = None
    if _arg_expr(call, "MaxTime", -1) is not None:
        timeout = max_time
    flag_ref = flag if _arg_expr(call, "TimeFlag", -1) is not None else None
    return Wait(call.span, condition, timeout, flag_ref, what)


@procedure("WaitDI", "WaitDO")
def _wait_signal(calls, compiler, call, entry):
    def factory(arguments):
        signal = arguments.fn("Signal")
        value = arguments.value("Value")
        return lambda m: m.io[signal(m)] == value(m)
    return _wait(calls, compiler, call, entry, factory, f"{call.name.text} condition")


@procedure("WaitUntil")
def _wait_until(calls, compiler, call, entry):
    def factory(arguments):
        return arguments.value("Cond")
    return _wait(calls, compiler, call, entry, factory, "WaitUntil condition")


@procedure("WaitRob", "StopMove", "StartMove", "ConfJ", "ConfL", "AccSet", "VelSet",
           "SingArea", "TriggIO", "ResetRetryCount", "Break_noop")
def _no_op(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    if call.name.key == "RESETRETRYCOUNT":
        def reset(m):
            frame = m.frames[-1]
            m.frames[-1] = frame._replace(retries=0)
        return Action(call.span, reset)
    return Action(call.span, lambda m: None)


# ===========================================================================
# Motion: the robot state jumps to the programmed target in one step
# ===========================================================================

def _move(calls, compiler, call, entry, target_key: str, joint: bool = False,
          signal: bool = False, sync: bool = False) -> Instruction:
    arguments = Arguments(calls, compiler, call, entry)
    target = arguments.value(target_key)
    tool = arguments.value("Tool")
    wobj = arguments.value("WObj")
    signal_fn = arguments.fn("Signal") if signal else None
    signal_value = arguments.value("Value") if signal else None
    proc_name = arguments.value("ProcName") if sync else None
    candidates = {}
    if sync:
        routine = compiler.routine
        for callee in compiler.linker.procedures_visible(routine):
            if not callee.parameters:
                candidates[callee.key] = callee

    def move(m, instruction):
        robot = list(m.robot)
        point = target(m)
        if joint:
            robot[ROBOT_JOINTS] = point
        else:
            robot[ROBOT_TCP] = point
        robot[ROBOT_TOOL] = tool(m)
        w = wobj(m)
        if w is not ABSENT:
            robot[ROBOT_WOBJ] = w
        m.robot = tuple(robot)
        if signal:
            _write_signal(m, signal_fn(m), _dionum(signal_value(m)))
        if sync:
            name = proc_name(m)
            callee = candidates.get(name.upper())
            if callee is None:
                raise RapidError("ERR_REFUNKPRC", f"no procedure named '{name}' without parameters")
            enter_routine(m, callee, [])     # the caller goes on after the move when it returns
        else:
            m.goto(instruction.next)
    return ControlAction(call.span, move)


@procedure("MoveJ", "MoveL", "MoveC")
def _move_to_point(calls, compiler, call, entry):
    return _move(calls, compiler, call, entry, "ToPoint")


@procedure("MoveAbsJ")
def _move_abs_j(calls, compiler, call, entry):
    return _move(calls, compiler, call, entry, "ToJointPos", joint=True)


@procedure("MoveJDO", "MoveLDO", "MoveCDO")
def _move_do(calls, compiler, call, entry):
    return _move(calls, compiler, call, entry, "ToPoint", signal=True)


@procedure("MoveJSync", "MoveLSync", "MoveCSync")
def _move_sync(calls, compiler, call, entry):
    return _move(calls, compiler, call, entry, "ToPoint", sync=True)


# ===========================================================================
# Interrupts
# ===========================================================================

def connect(calls, compiler, statement: ast.Connect) -> Instruction:
    ref_fn, ref_type, symbol = compiler.reference(statement.target, "connected")
    if ref_type is not None and getattr(ref_type, "key", "") != "NUM":
        raise error(TYPE_MISMATCH, "CONNECT needs an intnum variable", statement.target.span)
    trap_symbol = compiler.scope.lookup(statement.trap.key)
    routine = None
    if trap_symbol is not None and trap_symbol.kind == "routine":
        routine = compiler.linker.routine_by_index(trap_symbol.slot)
    if routine is None or routine.kind != "TRAP":
        raise error(TYPE_MISMATCH, f"'{statement.trap.text}' is not a TRAP routine",
                    statement.trap.span)
    trap_index = routine.index

    def do_connect(m):
        ref = ref_fn(m)
        current = m.read_ref(ref)
        table = m.interrupts.table
        if current and any(i.number == current for i in table):
            raise RapidError("ERR_ALRDYCNT", "the interrupt variable is already connected")
        used = {i.number for i in table}
        number = next(n for n in range(1, len(used) + 2) if n not in used)
        if number > 100:
            raise RapidError("ERR_INOMAX", "no more interrupt numbers")
        entry = Interrupt(number, trap_index)
        m.interrupts = m.interrupts._replace(
            table=tuple(sorted(table + (entry,), key=lambda i: i.number)))
        m.write_ref(ref, float(number))
    return Action(statement.span, do_connect)


def _update_interrupt(m, number: float, change) -> None:
    table = list(m.interrupts.table)
    for i, entry in enumerate(table):
        if entry.number == number:
            table[i] = change(entry)
            m.interrupts = m.interrupts._replace(table=tuple(table))
            return
    raise RapidError("ERR_UNKINO", f"interrupt number {values.format_num(number)} is not "
                     "connected")


@procedure("ISignalDI", "ISignalDO")
def _isignal(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")
    trigger = arguments.value("TriggValue")
    single = arguments.value("Single")
    single_safe = arguments.value("SingleSafe")
    interrupt = arguments.value("Interrupt")

    def order(m):
        once = single(m) is True or single_safe(m) is True
        source = ("signal", signal(m), trigger(m), once)
        _update_interrupt(m, interrupt(m), lambda e: e._replace(source=source, active=True))
    return Action(call.span, order)


@procedure("ITimer")
def _itimer(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    seconds = arguments.value("Time")
    single = arguments.value("Single")
    single_safe = arguments.value("SingleSafe")
    interrupt = arguments.value("Interrupt")

    def order(m):
        period = seconds(m)
        once = single(m) is True or single_safe(m) is True
        source = ("timer", period, once)
        _update_interrupt(m, interrupt(m), lambda e: e._replace(
            source=source, active=True, due=m.clock + period))
    return Action(call.span, order)


@procedure("IPers")
def _ipers(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    ref = arguments.fn("Name")
    interrupt = arguments.value("Interrupt")

    def order(m):
        source = ("pers", ref(m))
        _update_interrupt(m, interrupt(m), lambda e: e._replace(source=source, active=True))
    return Action(call.span, order)


@procedure("IDelete")
def _idelete(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    interrupt = arguments.value("Interrupt")
    target = _arg_expr(call, "Interrupt", 0)
    try:
        ref_fn, _, _ = compiler.reference(target, "deleted")
    except Exception:
        ref_fn = None

    def delete(m):
        number = interrupt(m)
        table = tuple(e for e in m.interrupts.table if e.number != number)
        pending = tuple(n for n in m.interrupts.pending if n != number)
        m.interrupts = m.interrupts._replace(table=table, pending=pending)
        if ref_fn is not None:
            m.write_ref(ref_fn(m), 0.0)
    return Action(call.span, delete)


@procedure("ISleep", "IWatch")
def _isleep(calls, compiler, call, entry):
    interrupt = Arguments(calls, compiler, call, entry).value("Interrupt")
    active = call.name.key == "IWATCH"

    def sleep(m):
        number = interrupt(m)
        _update_interrupt(m, number, lambda e: e._replace(active=active))
        if not active:
            m.interrupts = m.interrupts._replace(
                pending=tuple(n for n in m.interrupts.pending if n != number))
    return Action(call.span, sleep)


@procedure("IEnable", "IDisable")
def _ienable(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    enabled = call.name.key == "IENABLE"
    return Action(call.span, lambda m: setattr(m, "interrupts",
                                               m.interrupts._replace(enabled=enabled)))


# ===========================================================================
# Program control
# ===========================================================================

@procedure("Stop", "Break")
def _stop(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)

    def stop(m, instruction):
        m.frames = []
        m.status = ENDED
    return ControlAction(call.span, stop)


@procedure("ExitCycle")
def _exit_cycle(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)

    def restart(m, instruction):
        unwind_all(m)
        if not m.chooser.check_mode:
            m.status = ENDED           # a run is one cycle
            return
        main = m.program.routines[m.program.entry]
        m.frames = [Frame(main.index, 0, main.initial_locals)]
    return ControlAction(call.span, restart)


_booked = [91]


@procedure("BookErrNo")
def _book_err_no(calls, compiler, call, entry):
    ref = Arguments(calls, compiler, call, entry).fn("ErrorName")
    number = float(_booked[0])
    _booked[0] += 1
    return Action(call.span, lambda m: m.write_ref(ref(m), number))


@procedure("CallByVar")
def _call_by_var(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    name = arguments.value("Name")
    number = arguments.value("Number")
    candidates = {c.key: c for c in compiler.linker.procedures_visible(compiler.routine)
                  if not c.parameters}

    def call_by_var(m, instruction):
        full = name(m) + values.num_to_str(number(m), 0)
        callee = candidates.get(full.upper())
        if callee is None:
            raise RapidError("ERR_REFUNKPRC", f"no procedure named '{full}'")
        enter_routine(m, callee, [])
    return ControlAction(call.span, call_by_var)


# ===========================================================================
# Model-only routines (environment modules)
# ===========================================================================

def _where(span) -> str:
    from pathlib import Path
    return f"{Path(span.file).name}:{span.line}:{span.column}"


@function("AnyBool")
def _any_bool(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    name = f"AnyBool at {_where(call.span)}"
    return Compiled(lambda m: m.choose(name, (False, True)), BOOL)


@function("AnyNum")
def _any_num(calls, compiler, call, entry) -> Compiled:
    arguments = Arguments(calls, compiler, call, entry)
    low = arguments.value("Low")
    high = arguments.value("High")
    name = f"AnyNum at {_where(call.span)}"

    def any_num(m):
        lo, hi = low(m), high(m)
        if lo != int(lo) or hi != int(hi) or hi < lo or hi - lo > 1000:
            raise RapidError("ERR_ARGVALERR", "AnyNum needs integer bounds Low <= High "
                             "(at most 1001 values)")
        return m.choose(name, tuple(float(v) for v in range(int(lo), int(hi) + 1)))
    return Compiled(any_num, NUM)


# Further groups of state-dependent routines register themselves through the
# decorators above when imported.
from . import special_io  # noqa: E402,F401  (sockets, files, more I/O)
