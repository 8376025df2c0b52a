"""Arc welding (RobotWare Arc): the weld moves ArcL, ArcC and their Start/End forms.

A weld move is a move: the robot state jumps to the target as with MoveL and
MoveC.  The welding process (arc, wire feed, weaving, seam tracking) is not
modelled.
"""
from __future__ import annotations

from .arguments import NAME_ONLY, no_effect
from .motion import _move, _move_ext_j, move_robot
from .registry import NO_EFFECT, NOT_MODELLED, ROBOT_STATE, compiled

_WELD = "seamdata Seam, welddata Weld \\weavedata Weave"
_TAIL = ("PERS tooldata Tool \\PERS wobjdata WObj \\switch Corr \\PERS anytype Track "
         "\\switch PreProcessTracking \\string SeamName \\PERS loaddata TLoad")
_ON_OFF = "\\switch On \\switch Off"
_FULL = (f"\\identno ID, speeddata Speed \\num T, {_WELD}, zonedata Zone \\num Z "
         f"\\stoppointdata Inpos, {_TAIL}")
_ENDS = f"\\identno ID, speeddata Speed, {_WELD}, zonedata Zone, {_TAIL}"


@compiled(f"ArcL({_ON_OFF}, robtarget ToPoint {_FULL})",
          f"ArcC({_ON_OFF}, robtarget CirPoint, robtarget ToPoint {_FULL})",
          f"ArcLStart(robtarget ToPoint {_ENDS})",
          f"ArcLEnd(robtarget ToPoint {_ENDS})",
          f"ArcCStart(robtarget CirPoint, robtarget ToPoint {_ENDS})",
          f"ArcCEnd(robtarget CirPoint, robtarget ToPoint {_ENDS})",
          modelled=ROBOT_STATE)
def _weld_move(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint")


# ArcRefresh applies changed weld data at once; the optional tuning arguments are those an
# add-in's welding code (a public RobotWare add-in, survey of issue 28) passes
compiled("ArcRefresh(\\num WeldSpeed \\num WeaveWidth)", modelled=NO_EFFECT)(no_effect)


# --- reference coverage (issue 8, item 1): the weld moves of robots 1 and 2 (MultiMove) ------
# ArcL1/ArcL2 ... take the arguments of ArcL ... and move the same way.
compiled(*(f"{name}{robot}({_ON_OFF}, robtarget ToPoint {_FULL})"
           for name in ("ArcL",) for robot in (1, 2)),
         *(f"ArcC{robot}({_ON_OFF}, robtarget CirPoint, robtarget ToPoint {_FULL})"
           for robot in (1, 2)),
         *(f"ArcL{robot}{end}(robtarget ToPoint {_ENDS})"
           for robot in (1, 2) for end in ("Start", "End")),
         *(f"ArcC{robot}{end}(robtarget CirPoint, robtarget ToPoint {_ENDS})"
           for robot in (1, 2) for end in ("Start", "End")),
         modelled=ROBOT_STATE)(_weld_move)


# --- reference coverage (issue 8, item 1): weld error recovery --------------------------------
# Evidence: a public cladding program calls `RecoveryPosSet;` before its weld and
# `RecoveryPosReset;` after it, without arguments; ABB's station templates (PartR2S2 ...)
# name the pair for error handling. They switch the path recorder used by the weld error
# recovery, which rapidmc does not model: no effect. The recovery menus and the process name
# are known from the name list only.
compiled("RecoveryPosSet()", "RecoveryPosReset()", modelled=NO_EFFECT)(no_effect)
compiled("RecoveryMenu(...)", "RecoveryMenuWR(...)", "SetWRProcName(...)",
         modelled=NOT_MODELLED)(NAME_ONLY)


# ArcMoveExtJ moves only the external axes within a weld, as MoveExtJ does outside one.
# Evidence: a public gantry welding backup (taeyangshim, issue 28) calls it between
# SyncMoveOn and SyncMoveOff as `ArcMoveExtJ jTempGantry{1}\ID:=10,vWeld{1},fine;`; a check
# that reached the call stopped with RMC305 (the gantry task HOLDS at 191,371 states now).
# A public RobotWare add-in's welding task (Ebara, survey of issue 28) ends the first move
# of a weld with the switch Start, `ArcMoveExtJ jointNext\ID:=index,speedWeld,fine\Start;`;
# the switch (where the weld starts) does not change where the axes go.
_move("ArcMoveExtJ(jointtarget ToJointPos \\identno ID, speeddata Speed \\num T, "
         "zonedata Zone \\stoppointdata Inpos \\switch Start)",
      modelled=ROBOT_STATE)(_move_ext_j)
