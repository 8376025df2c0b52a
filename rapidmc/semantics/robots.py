"""The robots of a controller: which tasks move one, and each task's robot in the state.

A RAPID task that moves a robot is a *motion task*: the backup's ``SYS.cfg``
marks it (``-MotionTask``), or its code calls a move instruction (``MoveL``,
``SearchL``, ``TriggL`` ... : the predefined procedures modelled on the robot
state).  A MultiMove controller has several, each with its own robot.

A program of one task, or a controller with one motion task, keeps one robot
in the state (``State.robot``: TCP target, tool, work object, joints), as it
always did.  With two or more motion tasks (``Program.robot_per_task``) the
state keeps one robot per task, in task order: ``State.robot`` is then a tuple
of robots, and a step of task T sees T's robot as its own (``task_robot``) and
puts it back (``with_task_robot``), so T's moves change T's robot only.  A task
that moves nothing keeps its robot at home.

A check may leave the robot's position out of its states (``robot_tracked``):
where the analysis of ``model.robot_tracking`` proves that nothing but moves
reads it, moves still evaluate their arguments (and raise what those raise)
but leave the robot where it was, so every position read back is the start
position and a program that moves relative to where it is
(``MoveL Offs(CRobT(), 0, 0, 10)``) no longer drifts through endless states.
"""
from __future__ import annotations

from typing import Iterable, Iterator

from .. import ast
from .configured_signals import walk_routine
from .program import FIRST_TASK_NAMESPACE, PROGRAM_NAMESPACE
from .scope import ROUTINE

# how traces name a robot's TCP (``T_ROB2.robot TCP`` for each motion task's own robot)
ROBOT_TCP = "robot TCP"


def task_namespace(number: int) -> int:
    """The namespace of task ``number`` (the main task is 0)."""
    return PROGRAM_NAMESPACE if number == 0 else FIRST_TASK_NAMESPACE + number - 1


def motion_task_numbers(linker, task_names: tuple, configured: Iterable[str]) -> tuple:
    """The numbers of the tasks that move a robot: those ``configured`` names (a backup's
    ``-MotionTask``), and those whose code calls a move instruction."""
    configured_keys = {name.upper() for name in configured}
    moving = _moving_namespaces(linker)
    return tuple(number for number, name in enumerate(task_names)
                 if name.upper() in configured_keys or task_namespace(number) in moving)


def _moving_namespaces(linker) -> set:
    """The namespaces with a call of a predefined procedure that moves the robot."""
    from .library.registry import ROBOT_STATE, lookup_procedure
    found = set()
    for routine in linker.routines:
        namespace = routine.namespace
        if namespace in found or routine.ast is None:
            continue
        scope = linker.namespaces.get(namespace)
        for node in walk_routine(routine.ast):      # (a handler's moves too)
            if not isinstance(node, ast.ProcedureCall):
                continue
            name = node.name
            own = scope.names.get(name.key) if scope is not None else None
            if own is not None and own.kind == ROUTINE:
                continue                       # the task's own routine of that name
            entry = lookup_procedure(name.key)
            if entry is not None and entry.modelled == ROBOT_STATE and \
                    entry.key not in _NOT_MOVING:
                found.add(namespace)
                break
    return found


# modelled on the robot state, but reading or setting data, not moving
_NOT_MOVING = frozenset({"GETSYSDATA", "SETSYSDATA"})

# the functions that read a robot, any task's with \TaskName or \TaskRef
TASK_ROBOT_READERS = frozenset({"CROBT", "CJOINTT", "CTOOL", "CWOBJ"})
TASK_ARGUMENTS = frozenset({"TASKNAME", "TASKREF"})


def controller_task_names(program) -> tuple:
    """The tasks' names as the controller (GetTaskName, \\TaskName) spells them: a backup's,
    else T_ROB1 for the main task."""
    return (program.options.get("main_task_name") or "T_ROB1",) + tuple(program.task_names[1:])


def named_task(names: tuple, text: str):
    """The number of the task called ``text`` (case-insensitive) among ``names``, or None."""
    key = text.upper()
    return next((number for number, name in enumerate(names) if name.upper() == key), None)


def named_robot_readings(routines) -> Iterator[tuple]:
    """(routine, call, task argument) for each call of a robot reader that names a task
    (``CRobT(\\TaskName:="T_ROB2")``), a user routine of that name left out."""
    own = {(routine.namespace, routine.key) for routine in routines}
    for routine in routines:
        if routine.ast is None:
            continue
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.FunctionCall) and node.name.key in TASK_ROBOT_READERS \
                    and (routine.namespace, node.name.key) not in own:
                for argument in node.args:
                    if argument.name is not None and argument.name.key in TASK_ARGUMENTS:
                        yield routine, node, argument


RUN_TIME_TASK = -1      # a task argument whose name only the running program knows


def argument_task(names: tuple, argument: ast.Argument) -> "int | None":
    """The number of the task among ``names`` (as GetTaskName spells them) that a robot
    reader's ``\\TaskName:="T_ROB2"`` or ``\\TaskRef:=T_ROB2Id`` names, None when it names
    no loaded task, ``RUN_TIME_TASK`` for a name computed when the program runs (taskid
    data have no value in the model: the name <task>Id says which task)."""
    value = argument.value
    if argument.name.key == "TASKREF" and isinstance(value, ast.NameRef):
        text = value.name.text
        return named_task(names, text[:-2]) if text.upper().endswith("ID") else None
    if argument.name.key == "TASKNAME" and isinstance(value, ast.StringLiteral):
        return named_task(names, value.value)
    return RUN_TIME_TASK


def reads_other_task_robot(routines, names: tuple) -> bool:
    """Whether a robot reader may read another loaded task's robot (``argument_task``): a
    name of the calling task, or of no loaded task, reads the calling task's robot
    (``library.position``), which that task's own step sees."""
    for routine, _, argument in named_robot_readings(routines):
        namespace = routine.namespace
        caller = namespace - FIRST_TASK_NAMESPACE + 1 if namespace >= FIRST_TASK_NAMESPACE \
            else 0
        number = argument_task(names, argument)
        if number is not None and number != caller:
            return True
    return False


def robot_tracked(m) -> bool:
    """Whether a step's moves put the robot where they take it: always when running; when
    checking, unless the check proved the robot's position unobserved
    (``CheckConfig.robot_untracked``)."""
    chooser = m.chooser
    return not (chooser.check_mode and chooser.config.robot_untracked)


def move_robot_to(m, robot: tuple) -> None:
    """The machine's robot becomes ``robot`` (the moved TCP, tool, work object, joints),
    unless the check does not track the robot's position (``robot_tracked``)."""
    if robot_tracked(m):
        m.robot = robot


class NoTaskRobot:
    """The robot environment code sees on a controller where each motion task has its own:
    no task is stepping, so reading (or moving) "the" robot is a modelling error
    (ERR_NOT_MOVETASK), never a silent choice of one task's robot."""

    def __init__(self, program):
        motion = ", ".join(program.task_names[number] for number in program.motion_tasks)
        self.message = (f"environment code reads or moves the robot, and each of the motion "
                        f"tasks {motion} moves its own (not modelled)")

    def __getitem__(self, part):
        from .errors import RapidError
        raise RapidError("ERR_NOT_MOVETASK", self.message)

    def __iter__(self):
        return self[0]


def initial_robots(program, home: tuple):
    """The robot part of the start state: ``home``, once per task when each has its own."""
    if program.robot_per_task:
        return (home,) * len(program.task_names)
    return home


def task_robot(program, robot, task: int) -> tuple:
    """Task ``task``'s robot in a state's robot part ``robot``."""
    return robot[task] if program.robot_per_task else robot


def with_task_robot(program, robot, task: int, moved: tuple):
    """The robot part ``robot`` with task ``task``'s robot ``moved``."""
    if not program.robot_per_task:
        return moved
    if robot[task] is moved:
        return robot
    return robot[:task] + (moved,) + robot[task + 1:]
