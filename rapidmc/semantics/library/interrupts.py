"""Interrupts: CONNECT, ordering (ISignalDI, ISignalAI, ITimer ...), enabling."""
from __future__ import annotations

from ... import ast
from ...diagnostics import TYPE_MISMATCH, error
from .. import values
from ..errors import RapidError
from ..instructions import Action, Instruction
from ..state import Interrupt
from .arguments import Arguments, argument_expression
from .registry import compiled


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


def _single(arguments: Arguments):
    """Whether an order is for one interrupt only (\\Single or \\SingleSafe), from the machine."""
    single = arguments.value("Single")
    single_safe = arguments.value("SingleSafe")
    return lambda m: single(m) is True or single_safe(m) is True


@compiled("ISignalDI(\\switch Single | switch SingleSafe, VAR signaldi Signal, dionum TriggValue, "
              "VAR intnum Interrupt)",
          "ISignalDO(\\switch Single | switch SingleSafe, VAR signaldo Signal, dionum TriggValue, "
              "VAR intnum Interrupt)")
def _isignal(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")
    trigger = arguments.value("TriggValue")
    once = _single(arguments)
    interrupt = arguments.value("Interrupt")

    def order(m):
        source = ("signal", signal(m), trigger(m), once(m))
        _update_interrupt(m, interrupt(m), lambda e: e._replace(source=source, active=True))
    return Action(call.span, order)


# ISignalAI/AO (ABB's rule): ordering stores the signal's value as the reference; at each
# value where the condition (aiotrigg: 1 above HighValue, 2 below HighValue, 3 above LowValue,
# 4 below LowValue, 5 between the limits, 6 outside them, 7 always) holds and the value
# differs from the reference by more than DeltaValue, the reference becomes that value and,
# unless \DPos or \DNeg excludes the direction, the interrupt is ordered
# (staged_step.signal_edges_pending).  So a DeltaValue of 0 means any change.
@compiled("ISignalAI(\\switch Single | switch SingleSafe, VAR signalai Signal, aiotrigg Condition, "
              "num HighValue, num LowValue, num DeltaValue \\switch DPos | switch DNeg, "
              "VAR intnum Interrupt)",
          "ISignalAO(\\switch Single | switch SingleSafe, VAR signalao Signal, aiotrigg Condition, "
              "num HighValue, num LowValue, num DeltaValue \\switch DPos | switch DNeg, "
              "VAR intnum Interrupt)")
def _isignal_analog(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    signal = arguments.fn("Signal")
    condition = arguments.value("Condition")
    high = arguments.value("HighValue")
    low = arguments.value("LowValue")
    delta = arguments.value("DeltaValue")
    positive = arguments.value("DPos")
    negative = arguments.value("DNeg")
    once = _single(arguments)
    interrupt = arguments.value("Interrupt")

    def order(m):
        index = signal(m)
        direction = 1 if positive(m) is True else -1 if negative(m) is True else 0
        source = ("analog", index, int(condition(m)), high(m), low(m), delta(m), direction,
                  m.io[index], once(m))
        _update_interrupt(m, interrupt(m), lambda e: e._replace(source=source, active=True))
    return Action(call.span, order)


@compiled("ITimer(\\switch Single | switch SingleSafe, num Time, VAR intnum Interrupt)")
def _itimer(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    seconds = arguments.value("Time")
    once = _single(arguments)
    interrupt = arguments.value("Interrupt")

    def order(m):
        period = seconds(m)
        source = ("timer", period, once(m))
        _update_interrupt(m, interrupt(m), lambda e: e._replace(
            source=source, active=True, due=m.clock + period))
    return Action(call.span, order)


@compiled("IPers(PERS anytype Name, VAR intnum Interrupt)")
def _ipers(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    ref = arguments.fn("Name")
    interrupt = arguments.value("Interrupt")

    def order(m):
        source = ("pers", ref(m))
        _update_interrupt(m, interrupt(m), lambda e: e._replace(source=source, active=True))
    return Action(call.span, order)


@compiled("IDelete(intnum Interrupt)")
def _idelete(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    interrupt = arguments.value("Interrupt")
    target = argument_expression(call, "Interrupt", 0)
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


@compiled("ISleep(intnum Interrupt)",
          "IWatch(intnum Interrupt)")
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


@compiled("IEnable()",
          "IDisable()")
def _ienable(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)
    enabled = call.name.key == "IENABLE"
    return Action(call.span, lambda m: setattr(m, "interrupts",
                                               m.interrupts._replace(enabled=enabled)))

