"""Controller routines real programs call around their I/O: system information,
test-and-set locks, trigger moves, EGM sessions and other motion settings.

Motion is modelled as a jump to the target (see special_routines), so the
routines that only tune motion (MotionSup, ClearPath, EGM sensor guidance)
change nothing rapidmc observes: they are checked against their signatures
and do nothing.  docs/semantics.md, "Sockets and files", lists them.

The safety controller answers fixed checksums and version; a cyclic bool (re-evaluated by
the controller all the time) and load identification (which moves the robot) are not
modelled: setting one up stops the run, and until then none exists.
"""
from __future__ import annotations

from .. import values
from ..errors import ERROR_NUMBERS, RapidError
from ..machine import ABSENT
from ..expressions import Compiled, constant
from ..instructions import Action, ControlAction
from ..types import BOOL, DNUM, NUM, STRING
from .arguments import (NAME_ONLY, ROBOT_JOINTS, ROBOT_TCP, Arguments, argument_expression,
                        fixed, no_effect, not_modelled)
from .configuration import FOUND, NOT_KNOWN, UNKNOWN_VALUE, Lookup, look_up
from .configuration_outcomes import memory_slot, read_key, remember, remembered
from .data import PREDEFINED_DATA
from .environment_model import where
from .motion import move_robot
from .probed_readings import FAILING, probed_reading, readings_free
from .registry import CHOICE, FIXED, NO_EFFECT, NOT_MODELLED, ROBOT_STATE, compiled
from .signals import signal_reader
from .tasks import task_number
from .signature_parts import ACT_TAIL, AXES, JOINTS, RUN_TAIL, TRIGG_TAIL

KINEMATICS = "needs the robot's kinematic model, which rapidmc does not have"

# \SWVersionName (the RobotWare name, e.g. "RobotWare 6.08"): GetSysInfo of RobotWare 6.
SYSTEM_INFO = (("SerialNo", "rapidmc-0001"), ("SWVersion", "6.0.0"), ("RobotType", "IRB 120"),
               ("CtrlId", "rapidmc"), ("LanIp", "127.0.0.1"), ("CtrlLang", "en"),
               ("SystemName", "rapidmc"), ("SWVersionName", "RobotWare 6.0.0"))


# EGM session states (egmstate); programs compare them with <=, so they are ordered.
EGM_STATE_DISCONNECTED, EGM_STATE_CONNECTED, EGM_STATE_RUNNING = 1.0, 2.0, 3.0


# ===========================================================================
# System information
# ===========================================================================

@compiled("string GetSysInfo(" + " | ".join(f"\\switch {key}" if i == 0 else f"switch {key}"
              for i, (key, _) in enumerate(SYSTEM_INFO)) + ")",
          modelled=FIXED)
def _get_sys_info(calls, compiler, call, entry) -> Compiled:
    arguments = Arguments(calls, compiler, call, entry)
    switches = [(arguments.value(key), text) for key, text in SYSTEM_INFO]

    def info(m):
        return next((text for flag, text in switches if flag(m) is True), SYSTEM_INFO[0][1])
    return Compiled(info, STRING)


# GetServiceInfo (RobotWare 6): service information of a mechanical unit as a string, here the
# duty-time counter (\\DutyTimeCnt). The switches beyond that one are not known to rapidmc.
compiled("string GetServiceInfo(mecunit MechUnit \\switch DutyTimeCnt)",
         modelled=FIXED)(fixed("0"))


@compiled("bool IsSysId(string SystemId)", modelled=FIXED)
def _is_sys_id(calls, compiler, call, entry) -> Compiled:
    """Whether SystemId is this controller's serial number (GetSysInfo \\SerialNo)."""
    system_id = Arguments(calls, compiler, call, entry).value("SystemId")
    serial = dict(SYSTEM_INFO)["SerialNo"]
    return probed_reading(compiler, call, lambda m: system_id(m) == serial, BOOL)


compiled("WarmStart()", modelled=NOT_MODELLED)(
    not_modelled("restarts the controller, which rapidmc does not model"))


@compiled("bool RobOS()",
          modelled=FIXED)
def _rob_os(calls, compiler, call, entry) -> Compiled:
    """FALSE: rapidmc is a virtual controller, not the robot's operating system (either
    in the readings probe: probed_readings)."""
    Arguments(calls, compiler, call, entry)
    return probed_reading(compiler, call, lambda m: False, BOOL)


@compiled("bool IsStopMoveAct(\\switch FromMoveTask | switch FromNonMoveTask)",
          modelled=FIXED)
def _is_stop_move_act(calls, compiler, call, entry) -> Compiled:
    Arguments(calls, compiler, call, entry)
    return constant(False, BOOL)


@compiled("string GetTaskName(\\INOUT num TaskNo | INOUT num MecTaskNo)")
def _get_task_name(calls, compiler, call, entry) -> Compiled:
    """The name of the task whose code calls it (``\\TaskNo``: its number, from 1)."""
    arguments = Arguments(calls, compiler, call, entry)
    numbers = [arguments.fn(key) for key in ("TaskNo", "MecTaskNo")]
    number = task_number(compiler)
    name = compiler.linker.task_names[number]

    def task_name(m):
        for ref in numbers:
            target = ref(m)
            if isinstance(target, tuple):
                m.write_ref(target, float(number + 1))
        return name
    return Compiled(task_name, STRING)


compiled("num AInput(VAR signalai Signal)",
         "num GInput(VAR signalgi Signal)")(signal_reader)


@compiled("robtarget CalcRobT(jointtarget Joint_target, PERS tooldata Tool \\PERS wobjdata WObj)",
          modelled=FIXED)
def _calc_rob_t(calls, compiler, call, entry) -> Compiled:
    """The robtarget of joint angles, without the arm's kinematics (an assumption, said by
    RMC702 as for every fixed reading, as CalcJointT's): the TCP target the modelled robot
    has now (what CRobT reads) with the external axes of the joint target, which the
    manual's result carries over.  Survey of issue 28: gantry cells compute a target from
    joints they read back, and stopped at this call."""
    joints = Arguments(calls, compiler, call, entry).value("Joint_target")

    def robtarget(m):
        return m.robot[ROBOT_TCP][:3] + (joints(m)[1],)
    return Compiled(robtarget, calls.return_type(entry))


@compiled("jointtarget CalcJointT(\\switch UseCurWObjPos, robtarget Rob_target, PERS tooldata Tool "
              "\\PERS wobjdata WObj \\num ConfAngle \\INOUT errnum ErrorNumber)",
          modelled=FIXED)
def _calc_joint_t(calls, compiler, call, entry) -> Compiled:
    """The joint angles of a robtarget, without the arm's kinematics (an assumption, said by
    RMC702 as for every fixed reading): the robot axes the modelled robot has now (what CJointT
    reads) and the external axes of the target, which the manual's result carries over.

    The target is taken as reachable: without \\ErrorNumber the controller raises ERR_ROBLIMIT
    or ERR_OUTSIDE_REACH only for a target out of reach, which rapidmc cannot tell; a program
    that asks for the error number (``\\ErrorNumber:=err``, it then gets no error raised) is
    checked with both answers, 0 and ERR_ROBLIMIT, when model checking; without it, the
    readings probe (``probed_readings``) lets the call raise ERR_ROBLIMIT, for coverage."""
    arguments = Arguments(calls, compiler, call, entry)
    target, error_number = arguments.value("Rob_target"), arguments.fn("ErrorNumber")
    label = f"CalcJointT reaches the target at {where(call.span)}"
    failure = FAILING["CALCJOINTT"]
    limit = float(ERROR_NUMBERS[failure])

    def joints(m):
        robax = m.robot[ROBOT_JOINTS][0]
        ref = error_number(m)
        if ref is not ABSENT:
            reached = m.choose(label, (True, False)) if m.chooser.check_mode else True
            m.write_ref(ref, 0.0 if reached else limit)
        elif readings_free(m) and not m.choose(label, (True, False)):
            raise RapidError(failure, "CalcJointT: the target is out of reach")
        return (robax, target(m)[3])
    return Compiled(joints, calls.return_type(entry))


# ===========================================================================
# Test-and-set locks (one task: the lock is free unless the program holds it)
# ===========================================================================

@compiled("bool TestAndSet(INOUT bool Object)")
def _test_and_set(calls, compiler, call, entry) -> Compiled:
    lock = Arguments(calls, compiler, call, entry).fn("Object")

    def test_and_set(m):
        ref = lock(m)
        if m.read_ref(ref):
            return False
        m.write_ref(ref, True)
        return True
    return Compiled(test_and_set, BOOL)


@compiled("WaitTestAndSet(INOUT bool Object)")
def _wait_test_and_set(calls, compiler, call, entry):
    """Waits while the lock is TRUE (a deadlock in one task), then takes it."""
    lock = Arguments(calls, compiler, call, entry).fn("Object")

    def wait(m, instruction):
        ref = lock(m)
        if m.read_ref(ref):
            m.waiting = True
            return
        m.write_ref(ref, True)
        m.goto(instruction.next)
    return ControlAction(call.span, wait)


# ===========================================================================
# Moves with triggers, and motion settings
# ===========================================================================

@compiled(f"TriggL(\\switch Conc, robtarget ToPoint \\identno ID, {TRIGG_TAIL})",
          f"TriggJ(\\switch Conc, robtarget ToPoint \\identno ID, {TRIGG_TAIL})",
          f"TriggC(\\switch Conc, robtarget CirPoint, robtarget ToPoint \\identno ID, {TRIGG_TAIL})",
          modelled=ROBOT_STATE)
def _trigg_move(calls, compiler, call, entry):
    return move_robot(calls, compiler, call, entry, "ToPoint")


compiled("SkipWarn()",
         "ClearPath()",
         "MotionSup(\\switch On | switch Off \\num TuneValue)",
         "ErrLog(num ErrorId \\switch W | switch I, anytype Argument1, anytype Argument2, "
             "anytype Argument3, anytype Argument4, anytype Argument5)",
         f"EGMActJoint(VAR egmident EGMid \\switch StreamStart \\PERS tooldata Tool \\PERS wobjdata WObj "
             f"\\PERS loaddata TLoad {JOINTS} {ACT_TAIL})",
         "EGMActPose(VAR egmident EGMid \\switch StreamStart \\PERS tooldata Tool \\PERS wobjdata WObj "
             "\\PERS loaddata TLoad, pose CorrFrame, egmframetype CorrFrType, pose SensorFrame, "
             f"egmframetype SensFrType {AXES} {ACT_TAIL})",
         "EGMRunJoint(VAR egmident EGMid, egmstopmode Mode \\switch NoWaitCond "
             + " ".join(f"\\switch J{i}" for i in range(1, 8)) + f" {RUN_TAIL})",
         # EGMRunPose's \Offset is a pose (the EGM manual: an offset frame added to the
         # corrections; EGMRunJoint's is kept as num, no evidence of its type was found)
         "EGMRunPose(VAR egmident EGMid, egmstopmode Mode \\switch NoWaitCond "
             + " ".join(f"\\switch {a}" for a in ("x", "y", "z", "rx", "ry", "rz"))
             + f" {RUN_TAIL.replace('num Offset', 'pose Offset')})",
         "EGMStop(VAR egmident EGMid, egmstopmode Mode \\num RampOutTime)",
         "EGMStreamStart(VAR egmident EGMid \\num SampleRate)",
         "EGMStreamStop(VAR egmident EGMid)",
         modelled=NO_EFFECT)(no_effect)


# ===========================================================================
# EGM sessions: the identity's state follows GetId / SetupUC / Reset
# ===========================================================================

def _egm_state(calls, compiler, call, entry, new):
    ident = Arguments(calls, compiler, call, entry).fn("EGMid")
    return Action(call.span, lambda m: m.write_ref(ident(m), new))


@compiled("EGMGetId(VAR egmident EGMid)",
          "EGMReset(VAR egmident EGMid)")
def _egm_get_id(calls, compiler, call, entry):
    return _egm_state(calls, compiler, call, entry, None)


# \APTR | \LATR go with \PathCorr: path correction from an Arc (or Laser) Path Tracking
# sensor (`EGMSetupUC ROB_1, id, "path_corr", "UCdevice" \PathCorr \APTR;`, a motion-program
# driver that runs on controllers).
@compiled("EGMSetupUC(mecunit MecUnit, VAR egmident EGMid, string ExtConfigName, string UCDevice "
              "\\switch Pose | switch Joint | switch PathCorr \\switch APTR | switch LATR "
              "\\num CommTimeout)")
def _egm_setup(calls, compiler, call, entry):
    return _egm_state(calls, compiler, call, entry, EGM_STATE_CONNECTED)


@compiled("egmstate EGMGetState(VAR egmident EGMid)")
def _egm_get_state(calls, compiler, call, entry) -> Compiled:
    ident = Arguments(calls, compiler, call, entry).fn("EGMid")

    def state(m):
        value = m.read_ref(ident(m))
        return EGM_STATE_DISCONNECTED if value is None else value
    return Compiled(state, NUM)


# ===========================================================================
# Reference coverage (issue 8, item 1)
# ===========================================================================

# Moves whose triggers come as tables (triggios, triggstrgo, triggiosdnum): a move.
_IOS = ("speeddata Speed \\num T \\triggios TriggData1{*} \\triggstrgo TriggData2{*} "
        "\\triggiosdnum TriggData3{*}, zonedata Zone \\stoppointdata Inpos, PERS tooldata Tool "
        "\\PERS wobjdata WObj")
compiled(f"TriggLIOs(robtarget ToPoint \\identno ID, {_IOS} \\switch Corr \\PERS loaddata TLoad)",
         f"TriggJIOs(robtarget ToPoint \\identno ID, {_IOS} \\PERS loaddata TLoad)",
         modelled=ROBOT_STATE)(_trigg_move)

# The safety controller (SafeMove): its checksums and version are fixed texts.
compiled("string SafetyControllerGetChecksum()", "string SafetyControllerGetUserChecksum()",
         modelled=FIXED)(fixed("00000000"))
compiled("string SafetyControllerGetSWVersion()", modelled=FIXED)(fixed("1.0.0"))
compiled("num SafetyControllerGetOpModePinCode()", modelled=FIXED)(fixed(0.0))
compiled("SafetyControllerSyncRequest()",
         "MotionProcessModeSet(motionprocessmode Mode)",
         "RemoveCyclicBool(PERS bool Flag)",
         "RemoveAllCyclicBool()",
         modelled=NO_EFFECT)(no_effect)

# Cyclic bools: the controller re-evaluates a condition into a flag all the time, which
# rapidmc does not model; so setting one up stops the run, and until then none exists.
compiled("SetupCyclicBool(PERS bool Flag, bool Cond \\switch Permanent)",
         modelled=NOT_MODELLED)(not_modelled("evaluates a condition cyclically, which rapidmc "
                                             "does not model"))
compiled("bool IsCyclicBool(PERS bool Flag)", modelled=FIXED)(fixed(False))
compiled("num GetNumberOfCyclicBool()", modelled=FIXED)(fixed(0.0))

# Load identification moves the robot to measure the load: not modelled; the robot is
# always valid for it.
compiled("paridvalidnum ParIdRobValid(paridnum ParIdType \\mecunit MechUnit \\num AxisNo)",
         modelled=FIXED)(fixed(PREDEFINED_DATA["ROB_LOAD_VAL"].value))
compiled("bool ParIdPosValid(paridnum ParIdType, robtarget Pos, INOUT num AxValid{*} "
             "\\num ConfAngle)",
         modelled=FIXED)(fixed(True))
compiled("LoadId(paridnum ParIdType, loadidnum LoadIdType, PERS tooldata Tool "
             "\\PERS loaddata PayLoad \\PERS wobjdata WObj \\num ConfAngle \\switch SlowTest "
             "\\VAR num Accuracy)",
         modelled=NOT_MODELLED)(not_modelled("identifies a load by moving the robot, which "
                                             "rapidmc does not model"))
# The service routine an operator starts from the FlexPendant (Debug > Call routine) to
# identify a tool's or payload's load; RobotWare installs it in every motion task. Evidence:
# a public controller backup (RobotWare 6.13) calls `LoadIdentify;` without arguments from a
# procedure of its own. It asks the operator which data to identify and calls LoadId.
compiled("LoadIdentify()",
         modelled=NOT_MODELLED)(not_modelled("asks the operator which load to identify and "
                                             "moves the robot, which rapidmc does not model"))
compiled("ProcerrRecovery(\\switch SyncOrgMoveInst | switch SyncLastMoveInst "
             "\\VAR signaldo ProcSignal)",
         modelled=NOT_MODELLED)(not_modelled("raises a process error in the running move, which "
                                             "rapidmc does not model"))

# EGM path correction: the moves go to their targets; the correction changes nothing.
compiled("EGMMoveL(VAR egmident EGMid, robtarget ToPoint, speeddata Speed \\num T, zonedata Zone, "
             "PERS tooldata Tool \\PERS wobjdata WObj \\PERS loaddata TLoad)",
         "EGMMoveC(VAR egmident EGMid, robtarget CirPoint, robtarget ToPoint, speeddata Speed "
             "\\num T, zonedata Zone, PERS tooldata Tool \\PERS wobjdata WObj \\PERS loaddata TLoad)",
         modelled=ROBOT_STATE)(_trigg_move)
compiled("EGMActMove(VAR egmident EGMid, pose SensorFrame \\num SampleRate)",
         modelled=NO_EFFECT)(no_effect)
compiled("PackDNHeader(string Service, string Path, VAR rawbytes RawData)",
         modelled=NOT_MODELLED)(not_modelled("writes a DeviceNet message header, whose layout "
                                             "rapidmc does not model"))


# --- survey round 4 ---------------------------------------------------------------------------

@compiled("ReadCfgData(string InstancePath, string Attribute, VAR anytype CfgData \\num ListNo)",
          modelled=CHOICE)
def _read_cfg_data(calls, compiler, call, entry):
    """The instance and attribute as far as rapidmc knows them (``configuration``): found
    with a known value (written to CfgData), found with a value rapidmc does not know
    (CfgData keeps its value), not found (ERR_CFG_NOTFND), or not known either way: then,
    when checking, a choice between found and ERR_CFG_NOTFND made at the run's first read
    of that instance and attribute and kept for the later ones (``configuration_outcomes``;
    ``run``: found)."""
    arguments = Arguments(calls, compiler, call, entry)
    path, attribute, target = (arguments.value("InstancePath"), arguments.value("Attribute"),
                               arguments.fn("CfgData"))
    _, target_type, _ = compiler.reference(argument_expression(call, "CfgData", 2),
                                           "written by ReadCfgData")
    label = f"ReadCfgData outcome at {where(call.span)}"
    memory = memory_slot(compiler.linker, call.span)

    def read(m):
        path_text, attribute_text = path(m), attribute(m)
        found = look_up(m.program.options.get("configuration"), path_text, attribute_text)
        if found.outcome == NOT_KNOWN and m.chooser.check_mode:
            found = Lookup(_chosen_once(m, memory, read_key(path_text, attribute_text), label))
        if found.outcome not in (FOUND, NOT_KNOWN):
            raise RapidError("ERR_CFG_NOTFND", "ReadCfgData: no such instance or attribute in "
                             "the configuration")
        value = configured_value(found.value, target_type)
        if value is not None:
            m.write_ref(target(m), value)
    return Action(call.span, read)


def _chosen_once(m, memory: int, key: tuple, label: str) -> str:
    """FOUND or ERR_CFG_NOTFND for a read rapidmc cannot look up: chosen at the run's
    first read of ``key``, the same at every later one (``configuration_outcomes``)."""
    outcomes = m.store[memory]
    found = remembered(outcomes, key)
    if found is None:
        outcome = m.choose(label, (FOUND, "ERR_CFG_NOTFND"))
        m.store = m.store.set(memory, remember(outcomes, key, outcome == FOUND))
        return outcome
    return FOUND if found else "ERR_CFG_NOTFND"


def configured_value(text, rapid_type):
    """A configuration attribute's text as a value of the data's type (None: not known, or
    not of that type)."""
    if text is UNKNOWN_VALUE:
        return None
    if rapid_type is BOOL:
        return True if text is True else {"TRUE": True, "FALSE": False}.get(str(text).upper())
    if text is True:
        return None
    if rapid_type is STRING:
        return values.checked_string(text)
    if rapid_type in (NUM, DNUM):
        try:
            number = float(text)
        except ValueError:
            return None
        return values.to_dnum(number) if rapid_type is DNUM else values.to_num(number)
    return None


# --- reference coverage (issue 8, item 1): brake check, friction identification ------------
# Evidence: a public production program calls `CyclicBrakeCheck;` without arguments; the
# public re-implementation jasky1640/Tenon-IDE declares `fricidinit()` without parameters
# (tenon/module/base.t). A brake check tests the brakes with the robot standing still, and
# starting a friction identification records nothing the program reads: no effect.
compiled("CyclicBrakeCheck()", "FricIdInit()", modelled=NO_EFFECT)(no_effect)
# From the name list only: the rest of friction identification, joint data and torque
# margins, hollow wrist and I/O-controlled axes, manual load identification, EGM's analog,
# group and lead-through setups, group signal information, SCWrite, least-squares tools
# (FitCircle, Matrix*).
compiled("FricIdEvaluate(...)", "FricIdSetFricLevels(...)", "GetJointData(...)",
         "GetTorqueMargin(...)", "ResetTorqueMargin(...)", "HollowWristReset(...)",
         "IoCtrlAxis_RefSync(...)", "IoCtrlAxis_RefSyncOn(...)", "IoCtrlAxis_RefSyncOff(...)",
         "ManLoadIdProc(...)", "EGMSetupAI(...)", "EGMSetupAO(...)", "EGMSetupGI(...)",
         "EGMSetupLTAPP(...)", "GetGroupSignalInfo(...)", "SCWrite(...)", "FitCircle(...)",
         "MatrixSolve(...)", "MatrixSolveQR(...)", "MatrixSVD(...)",
         modelled=NOT_MODELLED)(NAME_ONLY)
