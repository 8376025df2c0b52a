"""Conveyor tracking: connecting to an object on the conveyor and dropping it, the sensor
interface and Prox profile recording.

The conveyor is not modelled: WaitWObj connects at once (the object is
taken to be there) and DropWObj releases it; both change nothing rapidmc
observes, nor do connecting to a sensor device and recording a Prox profile.
Names known from ABB's reference only stop the run where they are reached.
"""
from __future__ import annotations

from .arguments import NAME_ONLY, no_effect, not_modelled
from .registry import NO_EFFECT, NOT_MODELLED, compiled

compiled("WaitWObj(PERS wobjdata WObj \\num RelDist \\num MaxTime)",
         "DropWObj(PERS wobjdata WObj)",
         modelled=NO_EFFECT)(no_effect)


# --- reference coverage (issue 8, item 1): the sensor interface, Prox and conveyor tracking --
# Evidence: SenDevice(string device), DropSensor(mecunit) and the Prx* parameter lists are
# those of the RAPID base module of the public re-implementation jasky1640/Tenon-IDE
# (tenon/module/base.t); its PrxSetSyncalarm takes a bool NoPulse, a switch in RAPID's
# notation. Connecting to a sensor, dropping its object and recording or using a Prox
# profile change nothing rapidmc observes (it models no conveyor and no sensor). That file
# declares PrxGetMaxRecordpos with the mechanical unit only; the reference lists it among
# the functions and it reads a sensor position, so it returns a num (the type is our
# reading of its name) and stops the run.
_PRX_UNIT = "mecunit MechUnit"
compiled("SenDevice(string device)",
         f"DropSensor({_PRX_UNIT})",
         f"PrxActivAndStoreRecord({_PRX_UNIT}, num Delay, string FileName)",
         f"PrxActivRecord({_PRX_UNIT}, num Delay)",
         f"PrxDeactRecord({_PRX_UNIT})",
         f"PrxResetPos({_PRX_UNIT})",
         f"PrxResetRecords({_PRX_UNIT})",
         f"PrxSetPosOffset({_PRX_UNIT}, num Reference)",
         f"PrxSetRecordSampleTime({_PRX_UNIT}, num SampleTime)",
         f"PrxSetSyncalarm({_PRX_UNIT}, num Time \\switch NoPulse)",
         f"PrxStopRecord({_PRX_UNIT})",
         f"PrxStoreRecord({_PRX_UNIT}, num Delay, string FileName)",
         f"PrxUseFileRecord({_PRX_UNIT}, num Delay, string FileName)",
         modelled=NO_EFFECT)(no_effect)
compiled(f"num PrxGetMaxRecordpos({_PRX_UNIT})",
         modelled=NOT_MODELLED)(not_modelled("reads a position recorded by a sensor, which "
                                             "rapidmc does not model"))
# From the name list only (no manual text or public call found): indexing conveyors,
# conveyor profiles and predictions, the rest of the sensor synchronisation, and Prox's
# PrxStartRecord and PrxDbgStoreRecord (not in that base module).
compiled("IndCnvInit(...)", "IndCnvEnable(...)", "IndCnvDisable(...)", "IndCnvReset(...)",
         "IndCnvAddObject(...)", "CnvGenInstr(...)", "CnvSync(...)", "CnvPredictReach(...)",
         "UseACCProfile(...)", "RecordProfile(...)", "WaitAndRecProf(...)", "StoreProfile(...)",
         "LoadProfile(...)", "ActivateProfile(...)", "DeactProfile(...)",
         "UseReachableTargets(...)", "GetMaxUsageTime(...)", "ResetMaxUsageTime(...)",
         "WaitSensor(...)", "SyncToSensor(...)", "SupSyncSensorOn(...)", "SupSyncSensorOff(...)",
         "PrxStartRecord(...)", "PrxDbgStoreRecord(...)",
         modelled=NOT_MODELLED)(NAME_ONLY)
