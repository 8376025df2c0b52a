"""The current robot position, tool and work object."""
from __future__ import annotations

from ..expressions import Compiled
from .arguments import ROBOT_JOINTS, ROBOT_TCP, ROBOT_TOOL, ROBOT_WOBJ, Arguments
from .registry import compiled
from .signature_parts import TASK

# name -> (part of the robot state, component of it or None for the whole part)
ROBOT_PARTS = {"CPOS": (ROBOT_TCP, 0), "CROBT": (ROBOT_TCP, None), "CJOINTT": (ROBOT_JOINTS, None),
          "CTOOL": (ROBOT_TOOL, None), "CWOBJ": (ROBOT_WOBJ, None)}


@compiled("pos CPos(\\PERS tooldata Tool \\PERS wobjdata WObj)",
          f"robtarget CRobT({TASK} \\PERS tooldata Tool \\PERS wobjdata WObj)",
          f"jointtarget CJointT({TASK})",
          f"tooldata CTool({TASK})",
          f"wobjdata CWObj({TASK})")
def _robot_part(calls, compiler, call, entry) -> Compiled:
    """The modelled robot's position, joints, tool or work object (as last programmed)."""
    Arguments(calls, compiler, call, entry)
    part, component = ROBOT_PARTS[entry.key]
    if component is None:
        return Compiled(lambda m: m.robot[part], calls.return_type(entry))
    return Compiled(lambda m: m.robot[part][component], calls.return_type(entry))


def set_robot(m, part: int, value) -> None:
    robot = list(m.robot)
    robot[part] = value
    m.robot = tuple(robot)

