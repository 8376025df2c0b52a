"""Pieces shared by the signatures of several predefined routines."""

TP_BREAKS = ("\\num MaxTime \\VAR signaldi DIBreak \\VAR signaldo DOBreak "
             "\\PERS bool PersBoolBreak \\VAR errnum BreakFlag")
TASK = "\\REF taskid TaskRef | string TaskName"
MOVE_TAIL = ("speeddata Speed \\num V | num T, zonedata Zone \\num Z \\stoppointdata Inpos, "
             "PERS tooldata Tool \\PERS wobjdata WObj")
MOVE_DO_TAIL = "speeddata Speed \\num T, zonedata Zone, PERS tooldata Tool \\PERS wobjdata WObj"
TRIGGERS = ("VAR triggdata Trigg_1 \\VAR triggdata T2 \\VAR triggdata T3 \\VAR triggdata T4 "
             "\\VAR triggdata T5 \\VAR triggdata T6 \\VAR triggdata T7 \\VAR triggdata T8")
TRIGG_TAIL = (f"speeddata Speed \\num T, {TRIGGERS}, zonedata Zone \\stoppointdata Inpos, "
               "PERS tooldata Tool \\PERS wobjdata WObj \\PERS loaddata TLoad")
JOINTS = " ".join(f"\\egm_minmax J{i}" for i in range(1, 8))
AXES = " ".join(f"\\egm_minmax {a}" for a in ("x", "y", "z", "rx", "ry", "rz"))
ACT_TAIL = "\\num LpFilter \\num SampleRate \\num MaxPosDeviation \\num MaxSpeedDeviation"
RUN_TAIL = "\\num CondTime \\num RampInTime \\num RampOutTime \\num Offset \\num PosCorrGain"
TIME = "\\num Time"
DEVICE = "VAR iodev IODevice"
FORMATS = "\\switch Hex1 | num IntX | switch Float4"
