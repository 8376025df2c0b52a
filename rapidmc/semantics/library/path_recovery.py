"""Path Recovery and stored paths: StorePath, RestoPath, the PathRec* routines.

rapidmc records no path (motion is a jump to each target), so storing and
restoring a path, moving back or forth along a recorded one, and stepping
back along the path (StepBwdPath), change
nothing it observes; PathRecValidBwd/Fwd answer FALSE: there is no recorded
path to move along.
"""
from __future__ import annotations

from .arguments import fixed, no_effect
from .registry import FIXED, NO_EFFECT, compiled

compiled("StorePath(\\switch KeepSync)",
         "RestoPath()",
         "PathRecStart(pathrecid ID)",
         "PathRecStop(\\switch Clear)",
         "PathRecMoveBwd(\\pathrecid ID \\switch ToolOffs \\speeddata Speed)",
         "PathRecMoveFwd(\\pathrecid ID \\switch ToolOffs \\speeddata Speed)",
         "StopMoveReset(\\switch AllMotionTasks)",
         "StartMoveRetry()",
         "StepBwdPath(num StepLength, num StepTime)",
         modelled=NO_EFFECT)(no_effect)

compiled("bool PathRecValidBwd(\\pathrecid ID)", "bool PathRecValidFwd(\\pathrecid ID)",
         modelled=FIXED)(fixed(False))
