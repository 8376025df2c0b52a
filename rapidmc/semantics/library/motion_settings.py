"""Motion and process settings: loads, acceleration and speed limits, soft servo,
program displacement, external axes offsets, path resolution.

rapidmc models motion as a jump to the programmed target, so these change
nothing it observes: each is checked against its signature and does nothing.
The few functions that read the servo, the robot's limits or the axis distance and
move time counters give one fixed, typical value (the counters read 0).
"""
from __future__ import annotations

from ..errors import RapidError
from ..instructions import Action
from .arguments import NAME_ONLY, Arguments, fixed, no_effect, not_modelled
from .motion import move_robot
from .registry import FIXED, NO_EFFECT, NOT_MODELLED, ROBOT_STATE, compiled

compiled("GripLoad(PERS loaddata Load)",
         "WorldAccLim(\\num On | switch Off)",
         "PathAccLim(bool AccLim \\num AccMax, bool DecelLim \\num DecelMax)",
         "PathResol(num PathSampleTime)",
         "SoftAct(\\mecunit MechUnit, num Axis, num Softness \\num Ramp)",
         "SoftDeact(\\num Ramp)",
         "CirPathMode(\\switch PathFrame | switch ObjectFrame | switch CirPointOri "
             "| switch Wrist45 | switch Wrist46 | switch Wrist56)",
         "CornerPathWarning(bool Status)",
         "SpeedLimAxis(mecunit MechUnit, num AxisNo, num AxisSpeed)",
         "SpeedLimCheckPoint(num RobSpeed)",
         "TuneServo(mecunit MecUnit, num Axis, num TuneValue \\tunetype Type)",
         "TuneReset()",
         "DitherAct(\\mecunit MechUnit, num Axis \\num Level)",
         "DitherDeact()",
         "ActUnit(mecunit MechUnit)",
         "DeactUnit(mecunit MechUnit)",
         "MechUnitLoad(mecunit MechUnit, num AxisNo, PERS loaddata Load)",
         "EOffsOn(\\jointtarget ExeP, jointtarget ProgPoint)",
         "EOffsSet(extjoint EAxOffs)",
         "EOffsOff()",
         "PDispOn(\\switch Rot \\robtarget ExeP, robtarget ProgPoint, PERS tooldata Tool "
             "\\PERS wobjdata WObj)",
         "PDispSet(pose DispFrame)",
         "PDispOff()",
         "ResetAxisDistance(mecunit MechUnit, num AxisNo)",
         "ResetAxisMoveTime(mecunit MechUnit, num AxisNo)",
         # (the manual: the reference is a robtarget or a num of degrees, then how the
         # axis gets there; public code writes 'IndReset STN1, 1 \\RefNum:=0 \\Short')
         "IndReset(mecunit MecUnit, num Axis \\robtarget RefPos | num RefNum "
             "\\switch Short | switch Fwd | switch Bwd | switch Old)",
         modelled=NO_EFFECT)(no_effect)

# SpeedRefresh's override is a percentage: outside 0-100 the controller raises
# ERR_SPEED_REFRESH_LIM (the manual's example clips it in an ERROR handler and retries);
# within, it changes nothing rapidmc observes.  input_domains reads the call as a comparison
# of the value with 0 and 100 (SPEED_REFRESH_LIMITS).
SPEED_REFRESH_LIMITS = (0.0, 100.0)


@compiled("SpeedRefresh(num Override)")
def _speed_refresh(calls, compiler, call, entry):
    override = Arguments(calls, compiler, call, entry).value("Override")
    low, high = SPEED_REFRESH_LIMITS

    def refresh(m):
        value = override(m)
        if not low <= value <= high:
            raise RapidError("ERR_SPEED_REFRESH_LIM",
                             f"SpeedRefresh: the override {value:g} is outside 0-100 %")
    return Action(call.span, refresh)


# Electronically linked motors (an option): its standard system module LINKEDM.sys, which
# backups of controllers with the option hold, offers the service routine Linked_m, calling
# the option's own Linked_m_exe (a FlexPendant dialog that jogs and links the follower axis
# to its master). Motion is a jump to the target here, so the dialog changes nothing rapidmc
# observes.
compiled("Linked_m_exe()", modelled=NO_EFFECT)(no_effect)

compiled("num MaxRobSpeed()", modelled=FIXED)(fixed(5000.0))
compiled("num GetMotorTorque(\\mecunit MecUnit, num AxisNo)",
         "num ReadMotor(\\mecunit MecUnit, num Axis)", modelled=FIXED)(fixed(0.0))
compiled("num GetAxisDistance(mecunit MechUnit, num AxisNo)",
         "num GetAxisMoveTime(mecunit MechUnit, num AxisNo)", modelled=FIXED)(fixed(0.0))
compiled("num CSpeedOverride(\\switch CTask)", modelled=FIXED)(fixed(100.0))


# --- reference coverage (issue 8, item 1): SoftMove (Cartesian soft servo) ------------------
# Evidence: public RAPID programs. A ROS socket server calls
# `CSSAct \RefFrame:=.. \RefOrient:=[..], dir \StiffnessNonSoftDir:=.. \Stiffness:=.. \AllowMove
# \Ramp:=..;` (its comment gives the order [\RefFrame] [\RefOrient] SoftDir
# [\StiffnessNonSoftDir] [\Stiffness] [\AllowMove] [\Ramp]),
# `CSSOffsetTune \RefFrame:=CSS_REFFRAME_WOBJ, CSS_NEGX, ForceOffset \StiffnessNonSoftDir:=30;`
# (then prints ForceOffset: it is written), `CSSForceOffsetAct CSS_NEGX, ForceOffset;` and
# `CSSDeactMoveL target, speed, tool \WObj:=wobj;` (also in a public SoftMove note). Softness
# and force offsets act on the servo, which rapidmc does not model; CSSDeactMoveL moves like
# MoveL; CSSOffsetTune measures a force, so it stops the run. CSSDeact and
# CSSForceOffsetDeact are known from the name list only.
compiled("CSSAct(\\num RefFrame \\orient RefOrient, css_soft_dir SoftDir "
             "\\num StiffnessNonSoftDir \\num Stiffness \\switch AllowMove \\num Ramp)",
         "CSSForceOffsetAct(css_offset_dir ForceOffsetDir, num ForceOffset)",
         modelled=NO_EFFECT)(no_effect)
compiled("CSSOffsetTune(\\num RefFrame, css_offset_dir OffsetDir, VAR num ForceOffset "
             "\\num StiffnessNonSoftDir)",
         modelled=NOT_MODELLED)(not_modelled("measures a force offset on the servo, which "
                                             "rapidmc does not model"))


@compiled("CSSDeactMoveL(robtarget ToPoint, speeddata Speed, PERS tooldata Tool "
          "\\PERS wobjdata WObj)", modelled=ROBOT_STATE)
def _soft_move_end(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint")


# From the name list only: the rest of SoftMove, path length measurement, the elbow's
# softness.
compiled("CSSDeact(...)", "CSSForceOffsetDeact(...)", "PathLengthStart(...)",
         "PathLengthStop(...)", "PathLengthReset(...)", "SoftElbow(...)",
         modelled=NOT_MODELLED)(NAME_ONLY)
