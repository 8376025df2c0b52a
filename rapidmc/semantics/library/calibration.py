"""Tool and frame calibration from taught robot positions.

Computing a TCP or a frame from joint positions needs the robot's kinematic
model, which rapidmc does not have: programs with these calls load, and
reaching one stops the run with RMC305.  (DefFrame, a frame from three
Cartesian positions, is plain geometry: library/geometry.py.)
"""
from __future__ import annotations

from .arguments import not_modelled
from .controller import KINEMATICS
from .registry import NOT_MODELLED, compiled

_FOUR = "jointtarget Pos1, jointtarget Pos2, jointtarget Pos3, jointtarget Pos4"

compiled(f"MToolTCPCalib({_FOUR}, INOUT tooldata Tool, VAR num MaxErr, VAR num MeanErr)",
         "MToolRotCalib(jointtarget RefTip, jointtarget ZPos \\jointtarget XPos, "
             "INOUT tooldata Tool)",
         "SToolRotCalib(jointtarget RefTip, jointtarget ZPos, jointtarget XPos, "
             "INOUT tooldata Tool)",
         f"SToolTCPCalib({_FOUR}, INOUT tooldata Tool, VAR num MaxErr, VAR num MeanErr)",
         "pose DefDFrame(robtarget OldP1, robtarget OldP2, robtarget OldP3, robtarget NewP1, "
             "robtarget NewP2, robtarget NewP3)",
         modelled=NOT_MODELLED)(not_modelled(KINEMATICS))


# --- reference coverage (issue 8, item 1): frames fitted to measured targets -------------
compiled("pose CalcRotAxisFrame(mecunit MechUnit, robtarget TargetList{*}, num TargetsInList, "
             "VAR num MaxErr, VAR num MeanErr)",
         "pose CalcRotAxFrameZ(robtarget TargetList{*}, num TargetsInList, "
             "robtarget PositiveZPoint, VAR num MaxErr, VAR num MeanErr)",
         "pose DefAccFrame(robtarget TargetListOne{*}, robtarget TargetListTwo{*}, "
             "num TargetsInList, VAR num MaxErr, VAR num MeanErr)",
         modelled=NOT_MODELLED)(not_modelled("fits a frame to measured robot positions, which "
                                             "rapidmc does not model"))
