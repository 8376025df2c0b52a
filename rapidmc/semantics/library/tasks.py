"""The controller, its tasks and mechanical units, as a program sees them: fixed answers
for one robot task (T_ROB1, ROB_1) running in automatic mode, module loading, text
tables, test signals.

Loading and saving modules change the program on a controller; rapidmc checks
the modules it is given (give the loaded modules as files), so Load, UnLoad,
StartLoad, WaitLoad, Save and EraseModule change nothing it observes.
"""
from __future__ import annotations

from typing import Callable, NamedTuple, Optional

from ... import ast
from ..errors import RapidError
from ..expressions import Compiled
from ..instructions import Action, ControlAction
from ..machine import ABSENT
from ..program import FIRST_TASK_NAMESPACE, PROGRAM_NAMESPACE
from ..scope import GLOBAL_DATA
from .arguments import (
    ROBOT_TOOL,
    ROBOT_WOBJ,
    Arguments,
    argument_expression,
    fixed,
    no_effect,
)
from .data import PREDEFINED_DATA
from .registry import FIXED, NO_EFFECT, ROBOT_STATE, compiled

compiled("bool TaskRunMec()", "bool TaskRunRob()", "bool IsMechUnitActive(mecunit MechUnit)",
         "bool TextTabFreeToUse(string TableName)",
         modelled=FIXED)(fixed(True))
compiled("bool IsSyncMoveOn()", "bool IsStopStateEvent(\\switch PPMoved | switch PPToMain)",
         "bool PPMovedInManMode()",
         modelled=FIXED)(fixed(False))
compiled("string GetMecUnitName(mecunit MechUnit)", modelled=FIXED)(fixed("ROB_1"))
compiled("string NonMotionMode(\\switch Main)", modelled=FIXED)(fixed("OFF"))
compiled("string TextGet(num Table, num Index)", "string RobName()",
         modelled=FIXED)(fixed(""))
compiled("num TextTabGet(string TableName)", "num PathLevel()", "num MotionPlannerNo()",
         "num GetModalPayLoadMode()",
         modelled=FIXED)(fixed(1.0))
compiled("num MaxRobReorientSpeed()", modelled=FIXED)(fixed(500.0))
compiled("num MaxExtLinearSpeed()", modelled=FIXED)(fixed(5000.0))
compiled("num MaxExtReorientSpeed()", modelled=FIXED)(fixed(1000.0))
compiled("bool TaskIsActive(string TaskName)", "bool TaskIsExecuting(string TaskName)",
         modelled=FIXED)(fixed(True))
compiled("bool IsLeadThrough(\\mecunit MechUnit)", "bool IsBrakeCheckActive()",
         "bool PFRestart(\\switch Base | switch Irpt)", modelled=FIXED)(fixed(False))
compiled("iounit_state IOUnitState(string UnitName \\switch Phys | switch Logic)",
         modelled=FIXED)(fixed(PREDEFINED_DATA["IOUNIT_RUNNING"].value))
# GetNextMechUnit walks the list of mechanical units; rapidmc's controller has one, ROB_1:
# (optional parameter, value) for list entry 0.
_ROB_1 = (("MecRef", PREDEFINED_DATA["ROB_1"].value), ("TCPRob", True), ("NoOfAxes", 6.0),
          ("MecTaskNo", 1.0), ("MotPlanNo", 1.0), ("Active", True), ("DriveModule", 1.0),
          ("OKToDeact", False))


@compiled("bool GetNextMechUnit(INOUT num ListNumber, INOUT string UnitName "
              "\\VAR mecunit MecRef \\VAR bool TCPRob \\VAR num NoOfAxes \\VAR num MecTaskNo "
              "\\VAR num MotPlanNo \\VAR bool Active \\VAR num DriveModule \\VAR bool OKToDeact)",
          modelled=FIXED)
def _get_next_mech_unit(calls, compiler, call, entry) -> Compiled:
    """Entry 0 is ROB_1 (TRUE, its name and properties); there is no other entry (FALSE).
    ListNumber is incremented on every call, as on the controller."""
    arguments = Arguments(calls, compiler, call, entry)
    number, name = arguments.fn("ListNumber"), arguments.fn("UnitName")
    details = [(arguments.fn(key), value) for key, value in _ROB_1]

    def next_unit(m):
        ref = number(m)
        index = m.read_ref(ref)
        m.write_ref(ref, index + 1.0)
        if index != 0.0:
            return False
        m.write_ref(name(m), "ROB_1")
        for detail, value in details:
            target = detail(m)
            if target is not ABSENT:
                m.write_ref(target, value)
        return True
    return Compiled(next_unit, calls.return_type(entry))


compiled("num ProgMemFree()", modelled=FIXED)(fixed(1_000_000.0))
compiled("num TestSignRead(num Channel)", modelled=FIXED)(fixed(0.0))
compiled("event_type EventType(\\switch Cont)", modelled=FIXED)(
    fixed(PREDEFINED_DATA["EVENT_NONE"].value))
compiled("exec_level ExecLevel()", modelled=FIXED)(fixed(PREDEFINED_DATA["LEVEL_NORMAL"].value))
compiled("handler_type ExecHandler()", modelled=FIXED)(
    fixed(PREDEFINED_DATA["HANDLER_NONE"].value))

compiled("Load(\\switch Dynamic, string FilePath \\string File \\switch CheckRef)",
         "UnLoad(\\switch ErrIfChanged | switch Save, string FilePath \\string File)",
         "StartLoad(\\switch Dynamic, string FilePath \\string File, VAR loadsession LoadNo)",
         "WaitLoad(\\string UnloadPath \\string UnloadFile, VAR loadsession LoadNo "
             "\\switch CheckRef)",
         "Save(\\string TaskRef | string TaskName, string ModuleName \\string FilePath "
             "\\string File)",
         "EraseModule(string ModuleName)",
         "TextTabInstall(string File)",
         "TestSignDefine(num Channel, testsignal SignalId, mecunit MechUnit, num Axis, "
             "num SampleTime)",
         "TestSignReset()",
         "WriteCfgData(string InstancePath, string Attribute, anytype CfgData \\num ListNo)",
         "SaveCfgData(string FilePath, string Domain)",
         "SetLeadThrough(\\switch On | switch Off)",
         "TPShow(tpnum Window)",
         "SpyStart(string File)",
         "SpyStop()",
         "SyncMoveSuspend()",
         "SyncMoveResume()",
         "SyncMoveUndo()",
         "ResetPPMoved()",
         "ActEventBuffer()",
         "DeactEventBuffer()",
         "BrakeCheck()",
         "CheckProgRef()",
         "CancelLoad(VAR loadsession LoadNo)",
         modelled=NO_EFFECT)(no_effect)


@compiled("bool ModExist(string ModuleName)")
def _mod_exist(calls, compiler, call, entry) -> Compiled:
    """Whether a module of that name is loaded: one of the modules rapidmc was given."""
    name = Arguments(calls, compiler, call, entry).value("ModuleName")
    loaded = {module for _, module in compiler.linker.module_scopes}
    return Compiled(lambda m: name(m).upper() in loaded, calls.return_type(entry))


_SYSTEM_DATA = {"TOOLDATA": ROBOT_TOOL, "WOBJDATA": ROBOT_WOBJ}


def _system_part(compiler, call, key: str, position: int):
    """The robot state part a tool or work object argument stands for (None: not modelled)."""
    expr = argument_expression(call, key, position)
    found = compiler.value(expr).type if expr is not None else None
    return _SYSTEM_DATA.get(getattr(found, "key", ""))


@compiled("GetSysData(PERS anytype DestObject \\string ObjectName)", modelled=ROBOT_STATE)
def _get_sys_data(calls, compiler, call, entry):
    """The current tool or work object (as last programmed) copied to the argument."""
    Arguments(calls, compiler, call, entry)
    part = _system_part(compiler, call, "DestObject", 0)
    if part is None:
        return Action(call.span, lambda m: None)
    target, _, _ = compiler.reference(argument_expression(call, "DestObject", 0),
                                      "written by GetSysData")
    return Action(call.span, lambda m: m.write_ref(target(m), m.robot[part]))


@compiled("SetSysData(anytype SourceObject \\string ObjectName)", modelled=ROBOT_STATE)
def _set_sys_data(calls, compiler, call, entry):
    """The argument becomes the current tool or work object."""
    source = Arguments(calls, compiler, call, entry).value("SourceObject")
    part = _system_part(compiler, call, "SourceObject", 0)

    def set_data(m):
        robot = list(m.robot)
        robot[part] = source(m)
        m.robot = tuple(robot)
    return Action(call.span, (lambda m: None) if part is None else set_data)


# --- reference coverage (issue 8, item 1) -------------------------------------------------
compiled("num TasksInSync(INOUT tasks TaskList{*})", modelled=FIXED)(fixed(0.0))
# The task selection panel: every task rapidmc runs is a normal task selected in it.
compiled("tsp_status GetTSPStatus(string TaskName)", modelled=FIXED)(
    fixed(PREDEFINED_DATA["TSP_STATUS_ACT"].value))


# ===========================================================================
# Synchronisation between tasks: WaitSyncTask, SyncMoveOn, SyncMoveOff
# ===========================================================================
#
# Each is a barrier: a task that reaches it waits until every task of its list
# has reached the same synchronisation point (the syncident data object of the
# same name, declared in each task), then all go on.  The state of a barrier is
# kept in the tasks' own syncident objects (no other RAPID code can read them):
# a task's object holds its *generation*, the number of times it passed the
# point, modulo 3, plus ARRIVED while it waits there.  Task P has reached
# generation g when its generation is g or g + 1 (a task that passed g may
# already wait at g + 1; no task can be further ahead or behind, since none
# passes a generation before all have reached it), so three values suffice and
# a barrier in an endless loop keeps the state space finite.
#
# A task list's empty entries ("") name no task: lists of a fixed size padded with
# them (``[["T_ROB1"],["T_ROB2"],[""]]``) are what real cells pass, to WaitSyncTask and
# SyncMoveOn alike, and the controller skips them (taken from that code: ABB's manuals
# say nothing of it).

ARRIVED = 10.0


def task_number(compiler) -> int:
    """The index of the task (0: the main task) whose code ``compiler`` compiles."""
    namespace = compiler.routine.namespace
    return 0 if namespace < FIRST_TASK_NAMESPACE else namespace - FIRST_TASK_NAMESPACE + 1


def _task_namespace(number: int) -> int:
    return PROGRAM_NAMESPACE if number == 0 else FIRST_TASK_NAMESPACE + number - 1


def _syncident_slots(compiler, key: str) -> dict:
    """Task index -> store slot of that task's global syncident named ``key``."""
    linker = compiler.linker
    slots = {}
    for number in range(len(linker.task_names)):
        namespace = _task_namespace(number)
        scopes = [linker.namespaces.get(namespace)] + [
            scope for (space, _), scope in sorted(linker.module_scopes.items())
            if space == namespace]
        for scope in scopes:
            symbol = scope.names.get(key) if scope is not None else None
            if symbol is not None and symbol.kind == GLOBAL_DATA:
                slots[number] = symbol.slot
                break
    return slots


def _generation(value) -> tuple[float, bool]:
    """(generation modulo 3, arrived) of a syncident's value (never written: 0, not arrived)."""
    if not isinstance(value, float):
        return 0.0, False
    return (value - ARRIVED, True) if value >= ARRIVED else (value, False)


class SyncWait(ControlAction):
    """A barrier instruction; ``missing(store, task)`` names the tasks it still waits for;
    ``times_out``: it has a ``\\TimeOut`` (it never waits forever); ``machine``: a
    ``SyncPlan`` when the step machine may run it (``model.packed.bytecode``), else None."""

    __slots__ = ("missing", "times_out")


class SyncPlan(NamedTuple):
    """What the step machine needs of a barrier without ``\\TimeOut``: the store slot
    of the task's own syncident, each task's syncident slot by task number, whether no
    other task declares it, the store slot of the TaskList (None: SyncMoveOff, every
    task declaring it) and ``partners(task_list_value)``: the other tasks the barrier
    waits for (may raise ``RapidError``)."""

    own: int
    slots: dict
    unshared: bool
    task_list: Optional[int]
    partners: Callable


def _barrier(calls, compiler, call, entry, what: str, error_name: str, listed: bool):
    """The barrier of ``what`` (WaitSyncTask, SyncMoveOn: the tasks of its TaskList;
    SyncMoveOff: every task declaring the syncident).  With ``\\TimeOut`` the wait may
    end, when model checking, at any step where it would block: ``error_name``."""
    arguments = Arguments(calls, compiler, call, entry)
    sync_expression = argument_expression(call, "SyncID", 0)
    key = sync_expression.name.key if isinstance(sync_expression, ast.NameRef) else ""
    slots = _syncident_slots(compiler, key)
    me = task_number(compiler)
    own = slots.get(me)
    names = compiler.linker.task_names
    by_name = {name.upper(): number for number, name in enumerate(names)}
    complete = compiler.linker.options.get("all_tasks_loaded", False)
    task_list = arguments.value("TaskList") if listed else None
    timeout = arguments.value("TimeOut") \
        if argument_expression(call, "TimeOut", -1) is not None else None

    def partners(m) -> list:
        if task_list is None:
            return [number for number in slots if number != me]
        return partners_in(task_list(m))

    def partners_in(items) -> list:
        """The other tasks a task list names (``items``: the TaskList's value)."""
        found = []
        for item in items:
            name = (item[0] if isinstance(item, tuple) else item).strip().upper()
            if not name:
                continue                   # an empty entry names no task (above)
            number = by_name.get(name)
            if number is None:
                if complete:
                    raise RapidError("ERR_TASKNAME", f"{what}: no task named {name!r}")
                continue                   # a task not loaded: assumed to arrive
            if number != me:
                found.append(number)
        return found

    def missing_from(store, generation: float, among: list) -> list:
        ahead = (generation + 1.0) % 3.0
        return [number for number in among
                if number not in slots or _generation(store[slots[number]])[0]
                not in (generation, ahead)]

    # no other loaded task declares the syncident, so none reads its generation: a barrier
    # that waits for no loaded task passes without counting (a task checked alone, whose
    # partners are assumed to arrive, would otherwise store a count modulo 3 per syncident)
    unshared = set(slots) == {me}

    def wait(m, instruction):
        current, arrived = _generation(m.store[own])
        generation = current if arrived else (current + 1.0) % 3.0
        among = partners(m)
        if unshared and not among and not arrived:
            m.goto(instruction.next)
            return
        if not missing_from(m.store, generation, among):
            m.store = m.store.set(own, generation)
            m.goto(instruction.next)
            return
        if timeout is not None and m.chooser.wait_times_out(m, timeout(m)):
            m.store = m.store.set(own, (generation - 1.0) % 3.0)
            raise RapidError(error_name, f"{what}: not every task arrived within \\TimeOut")
        if not arrived:
            m.store = m.store.set(own, generation + ARRIVED)
        else:
            m.waiting = True

    def missing(store, _task) -> list:
        current, arrived = _generation(store[own])
        generation = current if arrived else (current + 1.0) % 3.0
        try:
            among = partners(_StoreView(store))
        except Exception:              # a task list in routine data: not readable here
            return []
        # named as the program's task_names show them (the main task: "main task", not
        # the T_ROB1 that GetTaskName and task lists use), which callers look up
        shown = compiler.linker.shown_task_names
        return [shown[number] for number in missing_from(store, generation, among)]

    if own is None:                    # (the linker reports a syncident it cannot find)
        return Action(call.span, lambda m: None)
    instruction = SyncWait(call.span, wait)
    instruction.missing = missing
    instruction.times_out = timeout is not None
    list_ref = arguments.global_reference("TaskList") if listed else None
    if timeout is None and (list_ref is not None or not listed):
        instruction.machine = SyncPlan(own, slots, unshared, list_ref and list_ref[1],
                                       partners_in if listed else
                                       (lambda _: partners(None)))
    return instruction


class _StoreView:
    """Enough of a machine to read arguments from a stored state's global data."""

    def __init__(self, store):
        self.store = store

    def read_ref(self, ref):
        index, path = ref[1], ref[2]
        value = self.store[index]
        for step in path:
            value = value[step]
        return value


@compiled("WaitSyncTask(\\switch InPos, VAR syncident SyncID, REF tasks TaskList{*} "
          "\\num TimeOut)")
def _wait_sync_task(calls, compiler, call, entry):
    return _barrier(calls, compiler, call, entry, "WaitSyncTask", "ERR_WAITSYNCTASK", True)


@compiled("SyncMoveOn(VAR syncident SyncID, REF tasks TaskList{*} \\num TimeOut)")
def _sync_move_on(calls, compiler, call, entry):
    return _barrier(calls, compiler, call, entry, "SyncMoveOn", "ERR_SYNCMOVEON", True)


@compiled("SyncMoveOff(VAR syncident SyncID \\num TimeOut)")
def _sync_move_off(calls, compiler, call, entry):
    return _barrier(calls, compiler, call, entry, "SyncMoveOff", "ERR_SYNCMOVEOFF", False)
