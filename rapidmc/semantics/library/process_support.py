"""Process support that acts while the robot moves: triggers, path correction, the sensor
interface, independent axes, interrupts on group signals, I/O units.

rapidmc follows no path between targets and no external sensor, so these are
checked against their signatures and change nothing it observes: trigger
events and correction offsets never happen, an independent axis is always in
position, an interrupt on a group signal never occurs (ISignalDI/DO and ISignalAI/AO
interrupts are modelled: interrupts.py), I/O units are always running.
"""
from __future__ import annotations

from .arguments import NAME_ONLY, fixed, no_effect, not_modelled
from .registry import FIXED, NO_EFFECT, NOT_MODELLED, compiled

_SIGNAL_OUT = "\\VAR signaldo DOp | VAR signalgo GOp | VAR signalao AOp | num ProcID"
_INDEPENDENT = "mecunit MecUnit, num Axis"

compiled("TriggInt(VAR triggdata TriggData, num Distance \\switch Start | switch Time, "
             "VAR intnum Interrupt)",
         f"TriggEquip(VAR triggdata TriggData, num Distance \\switch Start, num EquipLag "
             f"{_SIGNAL_OUT}, num SetValue | dnum SetDvalue \\switch Inhib \\num InhibSetValue)",
         "TriggSpeed(VAR triggdata TriggData, num Distance \\switch Start, num ScaleLag, "
             "VAR signalao AOp, num ScaleValue \\num DipLag \\VAR errnum ErrDO \\switch Inhib)",
         "TriggDataReset(VAR triggdata TriggData)",
         "TriggStopProc(VAR restartdata RestartRef \\VAR signaldo DO1 \\VAR signaldo DO2 "
             "\\VAR signaldo DO3 \\VAR signaldo DO4, VAR signaldo ShadowDO)",
         "CorrCon(VAR corrdescr Descr)",
         "CorrWrite(VAR corrdescr Descr, pos Data)",
         "CorrDiscon(VAR corrdescr Descr)",
         "CorrClear()",
         "SiConnect(PERS sensor Sensor \\switch NoStop)",
         "SiClose(PERS sensor Sensor)",
         "SiGetCyclic(PERS sensor Sensor, PERS anytype Data, num Rate)",
         "SiSetCyclic(PERS sensor Sensor, PERS anytype Data, num Rate)",
         f"IndAMove({_INDEPENDENT} \\num ToAbsPos | jointtarget ToAbsNum, num Speed \\switch Ramp)",
         f"IndCMove({_INDEPENDENT}, num Speed \\switch Ramp)",
         f"IndDMove({_INDEPENDENT}, num Delta, num Speed \\switch Ramp)",
         f"IndRMove({_INDEPENDENT} \\num ToRelPos | jointtarget ToAbsNum \\switch Short "
             "| switch Fwd | switch Bwd, num Speed \\switch Ramp)",
         "ISignalGI(\\switch Single | switch SingleSafe, VAR signalgi Signal, VAR intnum Interrupt)",
         "ISignalGO(\\switch Single | switch SingleSafe, VAR signalgo Signal, VAR intnum Interrupt)",
         "IOEnable(string UnitName, num MaxTime)",
         "IODisable(string UnitName, num MaxTime)",
         "IOBusStart(string BusName)",
         "SocketSendTo(VAR socketdev Socket, string RemoteAddress, num RemotePort "
             "\\string Str | VAR rawbytes RawData | VAR anytype Data \\num NoOfBytes)",
         modelled=NO_EFFECT)(no_effect)
compiled(f"bool IndInpos({_INDEPENDENT})",
         f"bool IndSpeed({_INDEPENDENT} \\switch InSpeed | switch ZeroSpeed)",
         modelled=FIXED)(fixed(True))
compiled("pos CorrRead()", modelled=FIXED)(fixed((0.0, 0.0, 0.0)))


# --- reference coverage (issue 8, item 1): the rest of the trigger instructions ----------
# TriggCheckIO's check and TriggRampAO's ramp act during the move; TriggDataCopy copies a
# trigger definition, which rapidmc does not keep; so a trigger is always valid.
compiled("TriggCheckIO(VAR triggdata TriggData, num Distance \\switch Start | switch Time, "
             "VAR anytype Signal, opnum Relation, num CheckValue | dnum CheckDvalue "
             "\\switch StopMove, VAR intnum Interrupt)",
         "TriggRampAO(VAR triggdata TriggData, num Distance \\switch Start, num EquipLag, "
             "VAR signalao AOutput, num SetValue, num RampLength \\switch Time)",
         "TriggDataCopy(VAR triggdata Source, VAR triggdata Destination)",
         modelled=NO_EFFECT)(no_effect)
compiled("bool TriggDataValid(VAR triggdata TriggData)", modelled=FIXED)(fixed(True))

# --- reference coverage (issue 8, item 1): servo tools and the serial sensor interface ------
_GUN = "string ToolName"
_SENSOR = "string device"
compiled(f"STOpen({_GUN} \\switch WaitZeroSpeed \\switch Conc)",
         f"STClose({_GUN}, num TipForce, num Thickness \\VAR num RetThickness \\switch Conc)",
         f"STCalib({_GUN} \\switch ToolChg | switch TipChg | switch TipWear \\VAR num RetTipWear "
             "\\VAR num RetPosAdj \\num PrePos \\switch Conc)",
         f"STIndGun({_GUN}, num GunPos)",
         f"STIndGunReset({_GUN})",
         "STTune(mecunit MecUnit, num TuneValue, tunegtype Type)",
         "STTuneReset(mecunit MecUnit)",
         f"WriteVar({_SENSOR}, num VarNo, num VarData \\string TaskName)",
         f"WriteBlock({_SENSOR}, num BlockNo, string FileName \\string TaskName)",
         f"ReadBlock({_SENSOR}, num BlockNo, string FileName \\string TaskName)",
         modelled=NO_EFFECT)(no_effect)
compiled(f"bool STIsOpen({_GUN})",
         f"bool STIsClosed({_GUN} \\VAR num RetThickness)",
         f"bool STIsCalib({_GUN} \\switch sguninit | switch sgunsynch)",
         f"bool STIsIndGun({_GUN})",
         f"num STCalcForce({_GUN}, num MotorTorque)",
         f"num STCalcTorque({_GUN}, num TipForce)",
         modelled=NOT_MODELLED)(not_modelled("reads the state of a servo tool, which rapidmc "
                                             "does not model"))
compiled(f"num ReadVar({_SENSOR}, num VarNo \\string TaskName)",
         modelled=NOT_MODELLED)(not_modelled("reads a value from a serial sensor, which rapidmc "
                                             "does not model"))

# --- reference coverage (issue 8, item 1): arrays of sensor variables -------------------------
# From the name list only (no manual text or public call found): ReadVarArr, WriteVarArr and
# IVarValue, interrupts on a sensor variable.
compiled("ReadVarArr(...)", "WriteVarArr(...)", "IVarValue(...)",
         modelled=NOT_MODELLED)(NAME_ONLY)
