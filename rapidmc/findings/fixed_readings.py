"""Controller readings a check takes as fixed: say so beside the verdicts (RMC702).

Some predefined functions read what only the controller knows: the
operating mode (``OpMode``), the time (``CDate``, ``GetTime``), a file's
size, a task's state, the configuration (``ReadCfgData``).  When checking, the library gives each a fixed value
(docs/predefined.md, "fixed value"), and ``ClkRead`` a few sampled
readings.  A program that branches on such a reading is checked for that
value only: its other branches look unreachable, and a verdict says
nothing about a controller that reads otherwise.  ``fixed_readings`` lists
each such routine the program calls once, at its first call, with the
number of calls, so that the user knows what the verdicts assume.

Calls only inside the text of FlexPendant or log output (``TPWrite``,
``ErrWrite``, ...) or the end point of a socket (``SocketBind``, ``SocketConnect``)
decide nothing and are left out.
"""
from __future__ import annotations

from typing import Iterator

from .. import ast
from ..diagnostics import FIXED_READING, Diagnostic
from ..semantics.library import registry
from ..semantics.library.clocks import SAMPLED_READINGS_TEXT
from ..semantics.library.configuration import STANDARD_TEXT
from ..semantics.program import PROGRAM_NAMESPACE, Program
from ..semantics.robots import (RUN_TIME_TASK, argument_task, controller_task_names,
                                named_robot_readings)

# Output instructions: a reading in their arguments only ends up as text.  Socket setup: a
# reading in the address or port of SocketBind or SocketConnect (``GetSysInfo(\LanIp)``
# in the ROS drivers) names an end point, which the model's sockets never look at.
OUTPUT_ONLY = frozenset({"TPWRITE", "ERRWRITE", "ERRLOG", "WRITE", "TPPRINT", "WRITESTRBIN",
                         "SOCKETBIND", "SOCKETCONNECT"})
# Readings that are not one fixed value but a few sampled ones.
SAMPLED = {"CLKREAD": (SAMPLED_READINGS_TEXT, "those readings"),
           "READCFGDATA": (STANDARD_TEXT, "that configuration")}
FIXED = ("a fixed value", "that value")


def fixed_readings(program: Program) -> list[Diagnostic]:
    """One warning per predefined routine read as a fixed or sampled value, in source order."""
    first: dict[str, ast.Name] = {}
    calls: dict[str, int] = {}
    for name in reading_calls(program):
        key = name.key
        first.setdefault(key, name)
        calls[key] = calls.get(key, 0) + 1
    warnings = [_warning(first[key], calls[key]) for key in first] + \
        _unknown_task_robots(program)
    return sorted(warnings, key=lambda d: (d.span.file, d.span.line, d.span.column))


def _unknown_task_robots(program: Program) -> list[Diagnostic]:
    """One warning per robot reader and task argument whose task's robot the model does not
    keep (``CRobT(\\TaskName:="T_ROB9")`` of a task that is not loaded, or a name known only
    when the program runs): such a call reads the calling task's robot (``library.position``)."""
    names = controller_task_names(program)
    first: dict[tuple, ast.FunctionCall] = {}
    calls: dict[tuple, int] = {}
    for _, call, argument in named_robot_readings(program.routines):
        number = argument_task(names, argument)
        if number is not None and number != RUN_TIME_TASK:
            continue
        value = argument.value
        if number == RUN_TIME_TASK:
            what = f"the task \\{argument.name.text} names, if no loaded task has that name"
        elif isinstance(value, ast.StringLiteral):
            what = f'\\TaskName:="{value.value}", which names no loaded task'
        else:
            what = f"\\TaskRef:={value.name.text}, which names no loaded task"
        key = (call.name.key, what)
        first.setdefault(key, call)
        calls[key] = calls.get(key, 0) + 1
    warnings = []
    for key, call in first.items():
        times = "1 call" if calls[key] == 1 else f"{calls[key]} calls"
        message = (f"{call.name.text} reads the calling task's robot for {key[1]} "
                   f"when checking ({times})")
        note = "verdicts and unreached lines hold for that robot only (docs/predefined.md)"
        warnings.append(Diagnostic(FIXED_READING, message, call.name.span, severity="warning",
                                   notes=(note,)))
    return warnings


def reading_calls(program: Program) -> Iterator[ast.Name]:
    """The name of each call of the program's code to a predefined routine read as a fixed
    or sampled value, outside output instructions."""
    user_routines = {routine.key for routine in program.routines}
    for routine in program.routines:
        if routine.namespace != PROGRAM_NAMESPACE or routine.ast is None:
            continue
        for name in _readings(routine.ast):
            if name.key not in user_routines and _is_reading(name.key):
                yield name


def _is_reading(key: str) -> bool:
    if key in SAMPLED:
        return True
    entry = registry.lookup_function(key) or registry.lookup_procedure(key)
    return entry is not None and entry.modelled == registry.FIXED


def _warning(name: ast.Name, count: int) -> Diagnostic:
    how, which = SAMPLED.get(name.key, FIXED)
    times = "1 call" if count == 1 else f"{count} calls"
    # the consequence goes in a note: with the configuration's long description the
    # message alone would make a line of over 300 characters
    message = f"{name.text} reads {how} when checking ({times})"
    note = f"verdicts and unreached lines hold for {which} only (docs/predefined.md)"
    return Diagnostic(FIXED_READING, message, name.span, severity="warning", notes=(note,))


def _readings(routine_ast) -> Iterator[ast.Name]:
    """The names of routines called in a routine, outside the arguments of output and
    socket setup instructions (``OUTPUT_ONLY``)."""
    for node, parents in ast.walk(routine_ast):
        if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                not any(isinstance(p, ast.ProcedureCall) and p.name.key in OUTPUT_ONLY
                        for p in (node, *parents)):
            yield node.name
