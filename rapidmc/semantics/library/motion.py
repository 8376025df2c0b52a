"""Motion: the robot state jumps to the programmed target in one step."""
from __future__ import annotations

from ..errors import RapidError
from ... import ast
from ..instructions import CheckedReads, ControlAction, Instruction, enter_routine
from ..scope import CONSTANT, GLOBAL_DATA
from ..types import NUM, SEMI_VALUE
from ..machine import ABSENT
from ..robots import move_robot_to
from .arguments import (ROBOT_JOINTS, ROBOT_TCP, ROBOT_TOOL, ROBOT_WOBJ, Arguments,
                        argument_expression, no_effect)
from .registry import EXACT, NO_EFFECT, ROBOT_STATE, compiled
from .signals import dionum, write_signal
from .signature_parts import MOVE_DO_TAIL, MOVE_TAIL


# Moves: the routines move_robot (or MoveExtJ) models, and the parameters it never evaluates,
# since the robot jumps to the target in one step: how fast, how close and how precisely it
# gets there (input_flow: a value that only reaches these tells no behaviour apart).
MOVE_ROUTINES: set = set()
UNEVALUATED_BY_MOVES = frozenset({"SPEED", "V", "T", "ZONE", "Z", "INPOS", "ID", "TLOAD"})
# Moves that change their task's robot and nothing else: no \DO, no \ProcName, no trigger
# (``move_robot``, ``_move_ext_j``); their PERS Tool, WObj and TLoad are only read.
PLAIN_MOVES = frozenset({"MOVEJ", "MOVEL", "MOVEC", "MOVEABSJ", "MOVEEXTJ"})


def _move(*texts: str, modelled: str = EXACT):
    """``compiled`` for a move, noting its name in MOVE_ROUTINES."""
    MOVE_ROUTINES.update(text.split("(", 1)[0].strip().upper() for text in texts)
    return compiled(*texts, modelled=modelled)


def arrive(m, point, tool, wobj, joint: bool = False) -> None:
    """The robot is at ``point`` (a robtarget, or a jointtarget when ``joint``) with ``tool``
    and, when given, ``wobj`` (when the check tracks it: ``robots.move_robot_to``)."""
    robot = list(m.robot)
    robot[ROBOT_JOINTS if joint else ROBOT_TCP] = point
    robot[ROBOT_TOOL] = tool
    if wobj is not ABSENT:
        robot[ROBOT_WOBJ] = wobj
    move_robot_to(m, tuple(robot))


def move_robot(calls, compiler, call, entry, target_key: str, joint: bool = False,
                signal: bool = False, sync: bool = False, checked=dionum) -> Instruction:
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
        arrive(m, target(m), tool(m), wobj(m), joint)
        if signal:
            write_signal(m, signal_fn(m), checked(signal_value(m)))
        if sync:
            name = proc_name(m)
            callee = candidates.get(name.upper())
            if callee is None:
                raise RapidError("ERR_REFUNKPRC", f"no procedure named '{name}' without parameters")
            enter_routine(m, callee, [])     # the caller goes on after the move when it returns
        else:
            m.goto(instruction.next)
    action = ControlAction(call.span, move)
    if not signal and not sync:
        action.machine = _untracked_move(arguments, compiler, call, entry,
                                         (target_key, "Tool", "WObj"))
    return action


def _untracked_move(arguments: Arguments, compiler, call, entry, keys: tuple):
    """The step machine's plan of a move where the check leaves the robot's position out
    (``CheckConfig.robot_untracked``): it evaluates the arguments ``keys`` and goes on.
    Each given argument must have a source, name global data (a PERS tool) or be an
    element of global array data with an index that has one; else None (Python steps the
    move)."""
    required = [spec.key for spec in entry.signature.parameters if not spec.optional]
    sources, elements = [], []
    for key in keys:
        position = required.index(key.upper()) if key.upper() in required else -1
        expression = argument_expression(call, key, position)
        if expression is None:
            continue                        # (an optional argument left out: ABSENT)
        compiled_ = arguments.compiled(key)
        if compiled_ is not None:
            sources.append(compiled_)
            continue
        if isinstance(expression, ast.NameRef):
            symbol = compiler.scope.lookup(expression.name.key) or \
                compiler.linker.system_symbol(expression.name)
            if symbol is not None and symbol.kind in (GLOBAL_DATA, CONSTANT) and \
                    getattr(symbol.type, "kind", None) != SEMI_VALUE:
                continue                    # (data named directly: its read never raises)
            return None
        if not (isinstance(expression, ast.Index) and len(expression.indices) == 1 and
                isinstance(expression.base, ast.NameRef)):
            return None
        symbol = compiler.scope.lookup(expression.base.name.key)
        if symbol is None or symbol.kind != GLOBAL_DATA:
            return None
        index = compiler.value(expression.indices[0], NUM)
        if index.source is None:
            return None
        elements.append((symbol.slot, index))
    return CheckedReads(tuple(sources), tuple(elements), "robot_untracked")


@_move(f"MoveJ(\\switch Conc, robtarget ToPoint \\identno ID, {MOVE_TAIL} \\PERS loaddata TLoad)",
          f"MoveL(\\switch Conc, robtarget ToPoint \\identno ID, {MOVE_TAIL} \\switch Corr "
              "\\PERS loaddata TLoad)",
          f"MoveC(\\switch Conc, robtarget CirPoint, robtarget ToPoint \\identno ID, {MOVE_TAIL} "
              "\\switch Corr \\PERS loaddata TLoad)",
          modelled=ROBOT_STATE)
def _move_to_point(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint")


@_move(f"MoveAbsJ(\\switch Conc, jointtarget ToJointPos \\identno ID \\switch NoEOffs, {MOVE_TAIL} "
              "\\PERS loaddata TLoad)",
          modelled=ROBOT_STATE)
def _move_abs_j(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToJointPos", joint=True)


@_move(f"MoveJDO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, VAR signaldo Signal, dionum Value "
              "\\PERS loaddata TLoad)",
          f"MoveLDO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, VAR signaldo Signal, dionum Value "
              "\\PERS loaddata TLoad)",
          f"MoveCDO(robtarget CirPoint, robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, "
              "VAR signaldo Signal, dionum Value \\PERS loaddata TLoad)")
def _move_do(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint", signal=True)


@_move(f"MoveJSync(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, string ProcName \\PERS loaddata TLoad)",
          f"MoveLSync(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, string ProcName \\PERS loaddata TLoad)",
          f"MoveCSync(robtarget CirPoint, robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, "
              "string ProcName \\PERS loaddata TLoad)")
def _move_sync(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint", sync=True)


@_move("MoveExtJ(\\switch Conc, jointtarget ToJointPos \\identno ID \\switch UseEOffs, "
              "speeddata Speed \\num T, zonedata Zone \\stoppointdata Inpos)",
          modelled=ROBOT_STATE)
def _move_ext_j(calls, compiler, call, entry):
    """Only the external axes move: the robot's joints keep their values."""
    target = Arguments(calls, compiler, call, entry).value("ToJointPos")

    def move(m, instruction):
        robot = list(m.robot)
        robot[ROBOT_JOINTS] = (robot[ROBOT_JOINTS][0], target(m)[1])
        move_robot_to(m, tuple(robot))
        m.goto(instruction.next)
    return ControlAction(call.span, move)


def _analog(value: float) -> float:
    return float(value)


_AO_TAIL = "VAR signalao Signal, num Value \\PERS loaddata TLoad"
_GO_TAIL = "VAR signalgo Signal, num Value \\PERS loaddata TLoad"


@_move(f"MoveJAO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_AO_TAIL})",
          f"MoveLAO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_AO_TAIL})",
          f"MoveCAO(robtarget CirPoint, robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_AO_TAIL})",
          f"MoveJGO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_GO_TAIL})",
          f"MoveLGO(robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_GO_TAIL})",
          f"MoveCGO(robtarget CirPoint, robtarget ToPoint \\identno ID, {MOVE_DO_TAIL}, {_GO_TAIL})")
def _move_analog_or_group(calls, compiler, call, entry):
    """The move, and the analog or group output set at the target (as MoveLDO does)."""
    return move_robot(calls, compiler, call, entry, "ToPoint", signal=True, checked=_analog)


# --- survey round 4: the Paint option (RobotWare Paint, IRB 5500 cells) ----------------------
# PaintL/PaintC move like MoveL/MoveC (the robot jumps to the target); the paint events
# along the path and the brush table SetBrush selects are not modelled (SetBrush: no effect).

_PAINT_TAIL = "speeddata Speed \\num T, zonedata Zone, PERS tooldata Tool \\PERS wobjdata WObj"


@_move(f"PaintL(robtarget ToPoint \\identno ID, {_PAINT_TAIL})",
          f"PaintC(robtarget CirPoint, robtarget ToPoint \\identno ID, {_PAINT_TAIL})",
          modelled=ROBOT_STATE)
def _paint_move(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint")


compiled("SetBrush(num BrushNumber \\num X | num Y | num Z)",
         modelled=NO_EFFECT)(no_effect)
