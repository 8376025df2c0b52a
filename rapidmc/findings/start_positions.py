"""Where a coverage probe lets the robot start: the positions the program itself names.

The check's robot starts at its home position (every coordinate 0); a real one starts
wherever the last program, a jog or a power failure left it.  A start-up routine that
finds out where the robot is before it moves home (``IF bCurPos(pPick, ...) THEN MoveJ
Offs(pPick, 0, 0, 20) ...``: Hanoi's ``rMoveHome``) runs the branch for a taught position
only for a robot that starts there, which the check's never does: each branch was
reported "never reached with the robot starting at the check's home position".

A robot can start at any position, so a run that starts at one of the program's own
targets is a real run, and a line it runs is reachable.  A small breadth-first probe
(``api._start_probe``, with the readings free) starts the robot at the home position and
at each target the code compares a position with (robtarget data and constants, at their stored or
declared value, in a comparison or passed to a routine of the program), at most
``START_TARGETS`` of them, in the order the code first names them
(``CheckConfig.start_targets``; ``RapidSystem.initial_states`` starts there).  Only in a
program that reads the position back for more than a move's target
(``tried_inputs.start_position_reads``): elsewhere where the robot starts changes
nothing.  Only the TCP starts there: CJointT still reads the home joints (the check has
no kinematics to find a target's joints).  The verdicts keep the home start
(``assumes:`` says so), and the warnings for what no probe reached still name the start
("with the robot starting at the check's home position"): the targets are a sample of
the places a robot may be.
"""
from __future__ import annotations

from .. import ast
from ..semantics.configured_signals import COMPARISONS
from ..semantics.program import Program
from ..semantics.scope import CONSTANT, GLOBAL_DATA
from ..semantics.types import RapidType
from .tried_inputs import named_in_code

START_TARGETS = 32      # start positions a probe tries besides home (each one more start)


def named_targets(program: Program) -> tuple:
    """The distinct robtarget values the program's code compares a position with (a data
    object's stored value, a constant's), in the order first named, at most
    ``START_TARGETS``: those named in a comparison or passed to a routine of the program
    (``bCurPos(pPick, tGripper, ...)``), where a robot starting there may take another
    branch; a move's target alone (``MoveJ pPick, ...``) tells nothing of where it starts."""
    found: dict = {}
    for node, parents, symbol in named_in_code(program):
        if not _is_robtarget(symbol.type) or not _compared(parents, program):
            continue
        if symbol.kind == CONSTANT:
            value = symbol.value
        elif symbol.kind == GLOBAL_DATA:
            value = program.globals[symbol.slot].initial
        else:
            continue
        if value is not None:
            found.setdefault(value, None)
        if len(found) >= START_TARGETS:
            break
    return tuple(found)


def _compared(parents: tuple, program: Program) -> bool:
    """Whether a name sits in a comparison or in the arguments of a call of one of the
    program's own routines."""
    own = {routine.name.upper() for routine in program.routines}
    return any((isinstance(parent, ast.Binary) and parent.op in COMPARISONS) or
               (isinstance(parent, (ast.FunctionCall, ast.ProcedureCall))
                and parent.name.key in own)
               for parent in parents)


def _is_robtarget(rapid_type) -> bool:
    return isinstance(rapid_type, RapidType) and rapid_type.key == "ROBTARGET"

