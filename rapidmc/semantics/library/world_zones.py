"""World Zones: zone shapes and the supervision set up on them.

A world zone supervises where the TCP or the axes are during motion, which
rapidmc does not follow between targets; defining, enabling and freeing zones
is checked against the signatures and changes nothing it observes (in
particular WZDOSet sets its signal only when the robot is in the zone, which
is not modelled).
"""
from __future__ import annotations

from .arguments import no_effect
from .registry import NO_EFFECT, compiled

_SIDE = "\\switch Inside | switch Outside, VAR shapedata Shape"
_KIND = "\\switch Temp | switch Stat, INOUT anytype WorldZone"

compiled(f"WZBoxDef({_SIDE}, pos LowPoint, pos HighPoint)",
         f"WZCylDef({_SIDE}, pos CentrePoint, num Radius, num Height)",
         f"WZSphDef({_SIDE}, pos CentrePoint, num Radius)",
         f"WZHomeJointDef({_SIDE}, jointtarget MiddleJointVal, jointtarget DeltaJointVal)",
         f"WZLimJointDef({_SIDE}, jointtarget LowJointVal, jointtarget HighJointVal)",
         f"WZDOSet({_KIND} \\switch Inside | switch Before, shapedata Shape, "
             "VAR signaldo Signal, dionum SetValue)",
         f"WZLimSup({_KIND}, shapedata Shape)",
         "WZDisable(INOUT wztemporary WorldZone)",
         "WZEnable(INOUT wztemporary WorldZone)",
         "WZFree(INOUT wztemporary WorldZone)",
         modelled=NO_EFFECT)(no_effect)
