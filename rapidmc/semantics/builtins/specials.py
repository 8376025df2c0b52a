"""Signatures of the predefined routines the interpreter implements itself.

These need the program state (I/O, motion, FlexPendant, clocks, interrupts,
parameter presence, ValToStr/StrToVal of any type).  Registering them here
lets the static checker treat every call alike.  Modes follow the manuals'
syntax sections: signals are passed as VAR, tools and work objects as PERS,
``REF`` marks a reference to any data object (constants included).
"""
from __future__ import annotations

from .registry import special

# Optional arguments shared by the TPRead* instructions.
_TP_BREAKS = ("\\num MaxTime \\VAR signaldi DIBreak \\VAR signaldo DOBreak "
              "\\PERS bool PersBoolBreak \\VAR errnum BreakFlag")
_TASK = "\\REF taskid TaskRef | string TaskName"
# Speed, zone and tool part of the Move instructions.
_MOVE_TAIL = ("speeddata Speed \\num V | num T, zonedata Zone \\num Z \\stoppointdata Inpos, "
              "PERS tooldata Tool \\PERS wobjdata WObj")
_MOVE_DO_TAIL = "speeddata Speed \\num T, zonedata Zone, PERS tooldata Tool \\PERS wobjdata WObj"

SPECIAL_SIGNATURES = (
    # --- data and system functions -----------------------------------------------
    "bool Present(REF anytype OptPar)",
    "num Dim(REF anytype ArrPar, num DimNo)",
    "string ValToStr(anytype Val)",
    "bool StrToVal(string Str, INOUT anytype Val)",
    "bool IsPers(INOUT anytype DatObj)",
    "bool IsVar(INOUT anytype DatObj)",
    "symnum OpMode()",
    "symnum RunMode(\\switch Main)",
    "num RemainingRetries()",
    "string CDate()",
    "string CTime()",
    "num GetTime(\\switch WDay | switch Hour | switch Min | switch Sec)",
    # --- current robot position ----------------------------------------------------
    "pos CPos(\\PERS tooldata Tool \\PERS wobjdata WObj)",
    f"robtarget CRobT({_TASK} \\PERS tooldata Tool \\PERS wobjdata WObj)",
    f"jointtarget CJointT({_TASK})",
    f"tooldata CTool({_TASK})",
    f"wobjdata CWObj({_TASK})",
    # --- I/O -------------------------------------------------------------------------
    "dionum DInput(VAR signaldi Signal)",
    "dionum DOutput(VAR signaldo Signal)",
    "bool TestDI(VAR signaldi Signal)",
    "bool ValidIO(VAR anytype Signal)",
    "num AOutput(VAR signalao Signal)",
    "num GOutput(VAR signalgo Signal)",
    "dnum GInputDnum(VAR signalgi Signal)",
    "dnum GOutputDnum(VAR signalgo Signal)",
    "Set(VAR signaldo Signal)",
    "Reset(VAR signaldo Signal)",
    "SetDO(\\num SDelay | switch Sync, VAR signaldo Signal, dionum Value)",
    "SetAO(VAR signalao Signal, num Value)",
    "SetGO(\\num SDelay, VAR signalgo Signal, num Value | dnum Dvalue)",
    "PulseDO(\\switch High \\num PLength, VAR signaldo Signal)",
    "InvertDO(VAR signaldo Signal)",
    "AliasIO(anytype FromSignal, VAR anytype ToSignal)",
    "AliasIOReset(VAR anytype Signal)",
    # --- clocks ------------------------------------------------------------------------
    "num ClkRead(VAR clock Clock \\switch HighRes)",
    "ClkReset(VAR clock Clock)",
    "ClkStart(VAR clock Clock)",
    "ClkStop(VAR clock Clock)",
    # --- FlexPendant --------------------------------------------------------------------
    "TPWrite(string String \\num Num | bool Bool | pos Pos | orient Orient | dnum Dnum)",
    f"TPReadNum(INOUT num TPAnswer, string TPText {_TP_BREAKS})",
    f"TPReadDnum(INOUT dnum TPAnswer, string TPText {_TP_BREAKS})",
    "TPReadFK(INOUT num TPAnswer, string TPText, string TPFK1, string TPFK2, string TPFK3, "
    f"string TPFK4, string TPFK5 {_TP_BREAKS})",
    "TPErase()",
    "ErrWrite(\\switch W | switch I, string Header, string Reason "
    "\\string RL2 \\string RL3 \\string RL4)",
    # --- waiting ---------------------------------------------------------------------------
    "WaitTime(\\switch InPos, num Time)",
    "WaitDI(VAR signaldi Signal, dionum Value \\num MaxTime \\VAR bool TimeFlag)",
    "WaitDO(VAR signaldo Signal, dionum Value \\num MaxTime \\VAR bool TimeFlag)",
    "WaitUntil(\\switch InPos, bool Cond \\num PollRate \\num MaxTime \\VAR bool TimeFlag)",
    "WaitRob(\\switch InPos | switch ZeroSpeed)",
    # --- motion ------------------------------------------------------------------------------
    f"MoveJ(\\switch Conc, robtarget ToPoint \\identno ID, {_MOVE_TAIL} \\PERS loaddata TLoad)",
    f"MoveL(\\switch Conc, robtarget ToPoint \\identno ID, {_MOVE_TAIL} \\switch Corr "
    "\\PERS loaddata TLoad)",
    f"MoveC(\\switch Conc, robtarget CirPoint, robtarget ToPoint \\identno ID, {_MOVE_TAIL} "
    "\\switch Corr \\PERS loaddata TLoad)",
    f"MoveAbsJ(\\switch Conc, jointtarget ToJointPos \\identno ID \\switch NoEOffs, {_MOVE_TAIL} "
    "\\PERS loaddata TLoad)",
    f"MoveJDO(robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, VAR signaldo Signal, dionum Value "
    "\\PERS loaddata TLoad)",
    f"MoveLDO(robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, VAR signaldo Signal, dionum Value "
    "\\PERS loaddata TLoad)",
    f"MoveCDO(robtarget CirPoint, robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, "
    "VAR signaldo Signal, dionum Value \\PERS loaddata TLoad)",
    f"MoveJSync(robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, string ProcName \\PERS loaddata TLoad)",
    f"MoveLSync(robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, string ProcName \\PERS loaddata TLoad)",
    f"MoveCSync(robtarget CirPoint, robtarget ToPoint \\identno ID, {_MOVE_DO_TAIL}, "
    "string ProcName \\PERS loaddata TLoad)",
    "StopMove(\\switch Quick \\switch AllMotionTasks)",
    "StartMove(\\switch AllMotionTasks)",
    "ConfJ(\\switch On | switch Off)",
    "ConfL(\\switch On | switch Off)",
    "AccSet(num Acc, num Ramp \\num FinePointRamp)",
    "VelSet(num Override, num Max)",
    "SingArea(\\switch Wrist | switch LockAxis4 | switch Off)",
    "TriggIO(VAR triggdata TriggData, num Distance \\switch Start | switch Time "
    "\\VAR signaldo DOp | VAR signalgo GOp | VAR signalao AOp | num ProcID, "
    "num SetValue | dnum SetDvalue \\num DODelay)",
    # --- interrupts -----------------------------------------------------------------------------
    "ISignalDI(\\switch Single | switch SingleSafe, VAR signaldi Signal, dionum TriggValue, "
    "VAR intnum Interrupt)",
    "ISignalDO(\\switch Single | switch SingleSafe, VAR signaldo Signal, dionum TriggValue, "
    "VAR intnum Interrupt)",
    "ITimer(\\switch Single | switch SingleSafe, num Time, VAR intnum Interrupt)",
    "IPers(PERS anytype Name, VAR intnum Interrupt)",
    "IDelete(intnum Interrupt)",
    "ISleep(intnum Interrupt)",
    "IWatch(intnum Interrupt)",
    "IEnable()",
    "IDisable()",
    # --- program control and errors ----------------------------------------------------------------
    "Stop(\\switch NoRegain | switch AllMoveTasks)",
    "Break()",
    "ExitCycle()",
    "BookErrNo(VAR errnum ErrorName)",
    "CallByVar(string Name, num Number)",
    "ResetRetryCount()",
)

for _text in SPECIAL_SIGNATURES:
    special(_text)
