"""The YuMi SmartGripper (Hand_*, and the g_* names of RobotWare 6): servo fingers, vacuum
and blow-off.

The gripper is outside the modelled robot: moving and gripping change nothing
rapidmc observes, the position reads 0 and the gripper counts as calibrated.
"""
from __future__ import annotations

from .arguments import fixed, no_effect
from .registry import FIXED, NO_EFFECT, compiled

_GRIP = "\\num holdForce \\num targetPos \\num posAllowance \\switch NoWait"

compiled("Hand_Initialize(\\num maxSpd \\num holdForce \\num phyLimit \\switch Calibrate)",
         "Hand_DoCalibrate(\\switch Jog)",
         f"Hand_GripInward({_GRIP})",
         f"Hand_GripOutward({_GRIP})",
         "Hand_MoveTo(num targetPos \\switch NoWait)",
         "Hand_JogInward()",
         "Hand_JogOutward()",
         "Hand_Stop()",
         "Hand_SetMaxSpeed(num maxSpd)",
         "Hand_SetHoldForce(num holdForce)",
         "Hand_TurnOnVacuum1()", "Hand_TurnOffVacuum1()",
         "Hand_TurnOnVacuum2()", "Hand_TurnOffVacuum2()",
         "Hand_TurnOnBlow1()", "Hand_TurnOffBlow1()",
         "Hand_TurnOnBlow2()", "Hand_TurnOffBlow2()",
         modelled=NO_EFFECT)(no_effect)
compiled("num Hand_GetActualPos()", modelled=FIXED)(fixed(0.0))
compiled("bool Hand_IsCalibrated()", modelled=FIXED)(fixed(True))

# survey round 5 (docs/realworld-survey.md): the wait for a finished finger move, called
# after Hand_MoveTo ... \NoWait in YuMi ROS drivers; the move itself is not modelled, so
# the wait ends at once.
compiled("Hand_WaitMovingCompleted()", modelled=NO_EFFECT)(no_effect)

# The RobotWare 6 SmartGripper names, as public YuMi backups call them (survey of issue 28:
# `g_Init \maxSpd:=20, \holdForce:=20;`, `g_Calibrate \Grip;`, `g_GripIn \holdForce:=f
# \targetPos:=p \NoWait;`, `g_MoveTo 15;`, `g_SetForce f;`, `NumToStr(g_GetPos(), 2)`). Only
# the names and arguments that code shows; the model is that of their Hand_* successors.
compiled("g_Init(\\num maxSpd \\num holdForce \\switch Calibrate)",
         "g_Calibrate(\\switch Grip)",
         f"g_GripIn({_GRIP})",
         f"g_GripOut({_GRIP})",
         "g_MoveTo(num targetPos \\switch NoWait)",
         "g_JogIn()",
         "g_JogOut()",
         "g_SetForce(num holdForce)",
         modelled=NO_EFFECT)(no_effect)
compiled("num g_GetPos()", modelled=FIXED)(fixed(0.0))
