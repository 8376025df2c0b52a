"""Motion and process settings: loads, acceleration and speed limits, soft servo,
program displacement, external axes offsets, path resolution.

rapidmc models motion as a jump to the programmed target, so these change
nothing it observes: each is checked against its signature and does nothing.
The few functions that read the servo, the robot's limits or the axis distance and
move time counters give one fixed, typical value (the counters read 0).
"""
from __future__ import annotations

from .arguments import fixed, no_effect
from .registry import FIXED, NO_EFFECT, compiled

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
         "SpeedRefresh(num Override)",
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
         "IndReset(mecunit MecUnit, num Axis \\switch RefPos | switch RefNum | switch Short "
             "| switch Fwd | switch Bwd | switch Old)",
         modelled=NO_EFFECT)(no_effect)

compiled("num MaxRobSpeed()", modelled=FIXED)(fixed(5000.0))
compiled("num GetMotorTorque(\\mecunit MecUnit, num AxisNo)",
         "num ReadMotor(\\mecunit MecUnit, num Axis)", modelled=FIXED)(fixed(0.0))
compiled("num GetAxisDistance(mecunit MechUnit, num AxisNo)",
         "num GetAxisMoveTime(mecunit MechUnit, num AxisNo)", modelled=FIXED)(fixed(0.0))
compiled("num CSpeedOverride(\\switch CTask)", modelled=FIXED)(fixed(100.0))
