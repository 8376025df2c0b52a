"""The YuMi SmartGripper (Hand_*): servo fingers, vacuum and blow-off.

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
