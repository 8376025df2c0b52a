"""The current robot position, tool and work object."""
from __future__ import annotations

from typing import Callable, Optional

from ... import ast
from ..expressions import Compiled
from ..robots import named_task
from ..values import UNCONNECTED_AXIS
from .arguments import (ROBOT_JOINTS, ROBOT_TCP, ROBOT_TOOL, ROBOT_WOBJ, Arguments,
                        argument_expression)
from .environment_model import where
from .probed_readings import readings_free
from .registry import compiled
from .signature_parts import TASK
from .tasks import task_number

# readings whose external axes the readings probe may connect (``_axes_probed``)
AXES_PROBED = ("CROBT", "CJOINTT")
# name -> (part of the robot state, component of it or None for the whole part)
ROBOT_PARTS = {"CPOS": (ROBOT_TCP, 0), "CROBT": (ROBOT_TCP, None), "CJOINTT": (ROBOT_JOINTS, None),
          "CTOOL": (ROBOT_TOOL, None), "CWOBJ": (ROBOT_WOBJ, None)}


@compiled("pos CPos(\\PERS tooldata Tool \\PERS wobjdata WObj)",
          f"robtarget CRobT({TASK} \\PERS tooldata Tool \\PERS wobjdata WObj)",
          f"jointtarget CJointT({TASK})",
          f"tooldata CTool({TASK})",
          f"wobjdata CWObj({TASK})")
def _robot_part(calls, compiler, call, entry) -> Compiled:
    """The modelled robot's position, joints, tool or work object (as last programmed):
    the calling task's robot, or with ``\\TaskName``/``\\TaskRef`` the named task's.

    Where each motion task keeps its own robot (``semantics.robots``) another task's is
    read from the robots of the state the step started from (``Machine.robots``: only the
    stepping task moves in a step).  Otherwise the state's one robot is the robot of every
    task that is loaded.  A task the check does not load, or a name only known when the
    program runs, reads the calling task's robot, and ``findings.fixed_readings`` says so.
    """
    arguments = Arguments(calls, compiler, call, entry)
    part, component = ROBOT_PARTS[entry.key]
    result_type = calls.return_type(entry)
    if component is None:
        def read(robot, m=None):
            return robot[part]
    else:
        def read(robot, m=None):
            return robot[part][component]
    named = _named_task(compiler, call, arguments) if entry.key != "CPOS" else None
    if entry.key in AXES_PROBED:
        read = _axes_probed(read, f"{call.name.text} at {where(call.span)}")
    if named is None:
        return Compiled(lambda m: read(m.robot, m), result_type)
    caller = task_number(compiler)

    def read_named(m):
        number = named(m)
        robots = m.robots
        if number is None or number == caller or robots is None:
            return read(m.robot, m)
        return read(robots[number], m)
    return Compiled(read_named, result_type)


def _axes_probed(read: Callable, label: str) -> Callable:
    """``read``, but in the readings probe (``probed_readings.readings_free``) a target
    whose external axes the modelled robot lacks (9E9: not connected) may also read them
    connected, at 0: a driver written for any robot (``IF eax <> 9E9`` in the ROS
    modules) runs its code for external axes on a cell that has them.  Only in a program
    that compares a value with 9E9 (``CheckConfig.axes_probed``).  The verdicts keep
    the modelled robot, which has none."""
    def probed(robot, m=None):
        value = read(robot)
        if m is None or not readings_free(m) or UNCONNECTED_AXIS not in value[-1] \
                or not m.chooser.config.axes_probed:
            return value
        connected = tuple(0.0 if axis == UNCONNECTED_AXIS else axis for axis in value[-1])
        return m.choose(label, (value, (*value[:-1], connected)))
    return probed


def _named_task(compiler, call, arguments: Arguments) -> Optional[Callable]:
    """fn(m) -> the number of the task a call's ``\\TaskName`` or ``\\TaskRef`` names
    (None: not a loaded task); None when the call names no task."""
    names = compiler.linker.task_names          # as GetTaskName spells them
    reference = argument_expression(call, "TaskRef", -1)
    if reference is not None:
        # taskid data have no value in the model: the name <task>Id says which task
        text = reference.name.text if isinstance(reference, ast.NameRef) else ""
        number = named_task(names, text[:-2]) if text.upper().endswith("ID") else None
        return lambda m: number
    if argument_expression(call, "TaskName", -1) is None:
        return None
    name = arguments.value("TaskName")
    return lambda m: named_task(names, name(m))


def set_robot(m, part: int, value) -> None:
    robot = list(m.robot)
    robot[part] = value
    m.robot = tuple(robot)

