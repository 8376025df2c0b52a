"""Predefined data of the BASE system module: constants, speeds, zones, tool0 ...

``PREDEFINED_DATA`` maps each canonical name to a ``PredefinedData`` with
its RAPID type name, storage class and value in rapidmc's representation
(records as tuples, num values rounded to float32).  Numbers of the
symbolic constants (OP_*, RUN_*, LT...GT, OpAdd...OpMod) are not documented
by ABB as far as we found; programs compare with the names, so the values
only need to be distinct within each type.
"""
from __future__ import annotations

from dataclasses import dataclass

from ..types import STOPPED_CLOCK
from ..values import to_num

CONST, PERS, VAR = "CONST", "PERS", "VAR"


@dataclass(frozen=True)
class PredefinedData:
    name: str          # spelling as in the manual
    type_name: str     # RAPID type, lower case
    storage: str       # CONST, PERS, or VAR (a variable of the USER system module)
    value: object


PREDEFINED_DATA: dict[str, PredefinedData] = {}


def _define(name: str, type_name: str, value: object, storage: str = CONST) -> None:
    assert name.upper() not in PREDEFINED_DATA, name
    PREDEFINED_DATA[name.upper()] = PredefinedData(name, type_name, storage, value)


def _nums(*values: float) -> tuple[float, ...]:
    return tuple(to_num(v) for v in values)


# --- numbers and strings --------------------------------------------------------
_define("pi", "num", to_num(3.1415926))
_define("WAIT_MAX", "num", to_num(8388608))
_define("EOF_NUM", "num", to_num(9.998e36))
_define("stEmpty", "string", "")
_define("STR_DIGIT", "string", "0123456789")
# Latin-1 letters in case pairs: A-Z, then À..Ö and Ø..Þ (no ß, no ÿ).
_define("STR_UPPER", "string", "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
        + "".join(map(chr, range(0xC0, 0xD7))) + "".join(map(chr, range(0xD8, 0xDF))))
_define("STR_LOWER", "string", "abcdefghijklmnopqrstuvwxyz"
        + "".join(map(chr, range(0xE0, 0xF7))) + "".join(map(chr, range(0xF8, 0xFF))))
_define("STR_WHITE", "string", " ")

# --- signal values (dionum) -------------------------------------------------------
for _number, _name in enumerate(("low", "high", "edge")):
    _define(_name, "dionum", float(_number))

# --- StrDigCmp relations (opnum) and StrDigCalc operators (opcalc) ---------------
for _number, _name in enumerate(("LT", "LTEQ", "EQ", "NOTEQ", "GTEQ", "GT"), start=1):
    _define(_name, "opnum", float(_number))
for _number, _name in enumerate(("OpAdd", "OpSub", "OpMult", "OpDiv", "OpMod"), start=1):
    _define(_name, "opcalc", float(_number))

# --- OpMode / RunMode results (symnum) ---------------------------------------------
for _number, _name in enumerate(("OP_UNDEF", "OP_AUTO", "OP_MAN_PROG", "OP_MAN_TEST")):
    _define(_name, "symnum", float(_number))
for _number, _name in enumerate(("RUN_UNDEF", "RUN_CONT_CYCLE", "RUN_INSTR_FWD",
                                 "RUN_INSTR_BWD", "RUN_SIM", "RUN_STEP_MOVE")):
    _define(_name, "symnum", float(_number))

# --- speeddata [v_tcp, v_ori, v_leax, v_reax] --------------------------------------
SPEEDS = (5, 10, 20, 30, 40, 50, 60, 80, 100, 150, 200, 300, 400, 500, 600, 800, 1000,
          1500, 2000, 2500, 3000, 4000, 5000, 6000, 7000)
for _speed in SPEEDS:
    _define(f"v{_speed}", "speeddata", _nums(_speed, 500, 5000, 1000))
_define("vmax", "speeddata", _nums(5000, 500, 5000, 1000))  # robot dependent; a typical value

# --- zonedata [finep, pzone_tcp, pzone_ori, pzone_eax, zone_ori, zone_leax, zone_reax]
ZONES = (1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200)
_define("fine", "zonedata", (True,) + _nums(0, 0, 0, 0, 0, 0))
_define("z0", "zonedata", (False,) + _nums(0.3, 0.3, 0.3, 0.03, 0.3, 0.03))
_define("z1", "zonedata", (False,) + _nums(1, 1, 1, 0.1, 1, 0.1))
for _zone in ZONES[1:]:
    _define(f"z{_zone}", "zonedata",
            (False,) + _nums(_zone, 1.5 * _zone, 1.5 * _zone, 0.15 * _zone, 1.5 * _zone, 0.15 * _zone))

# --- tool, work object, load ----------------------------------------------------------
_IDENTITY_POSE = (_nums(0, 0, 0), _nums(1, 0, 0, 0))
LOAD0 = (to_num(0.001), _nums(0, 0, 0.001), _nums(1, 0, 0, 0)) + _nums(0, 0, 0)
_define("load0", "loaddata", LOAD0, PERS)
_define("tool0", "tooldata", (True, _IDENTITY_POSE, LOAD0), PERS)
_define("wobj0", "wobjdata", (False, True, "", _IDENTITY_POSE, _IDENTITY_POSE), PERS)


# --- motion settings -------------------------------------------------------------------
# C_MOTSET: the current motion settings (motsetdata), read-only system data that VelSet,
# AccSet, SingArea, ConfL/ConfJ, PathResol ... change. rapidmc models those instructions as
# no effect (semantics/library/motion_settings.py), so a read gives the settings a program
# starts with: override 100 %, max TCP speed 5000 mm/s, full acceleration, no singularity
# area interpolation, configuration supervision on (axis limits 30/45/90 degrees), path
# resolution 100 %, motion supervision on, tuning 100 %, no path or world acceleration
# limits (-1), circle reorientation standard, event buffer on, prefetch time 0.
_define("C_MOTSET", "motsetdata",
        (_nums(100, 5000), _nums(100, 100, 100), (False, False, False),
         (True, True) + _nums(30, 45, 90), to_num(100), True, to_num(100), False, to_num(-1),
         False, to_num(-1), to_num(0), False, to_num(-1), True, to_num(0)), VAR)

# --- stop points (stoppoint, the type component of stoppointdata) -------------------
for _number, _name in enumerate(("inpos", "stoptime", "fllwtime"), start=1):
    _define(_name, "stoppoint", float(_number))

# --- the USER system module every task loads: reg1..reg5 and clock1 ------------------
# They are variables: the linker gives one a slot the first time the program uses
# it without declaring it (so programs that never use them keep their state shape).
for _number in range(1, 6):
    _define(f"reg{_number}", "num", 0.0, VAR)
_define("clock1", "clock", STOPPED_CLOCK, VAR)


# --- sockets, rawbytes, files and EGM (rapidmc.semantics.special_io and friends) -------------
# socketstatus and egmstate numbers are our choice (programs compare with the names).
for _number, _name in enumerate(("SOCKET_CREATED", "SOCKET_CONNECTED", "SOCKET_BOUND",
                                 "SOCKET_LISTENING", "SOCKET_CLOSED"), start=1):
    _define(_name, "socketstatus", float(_number))
for _name, _size in (("USINT", 1), ("UINT", 2), ("UDINT", 4), ("ULINT", 8),
                     ("SINT", -1), ("INT", -2), ("DINT", -4), ("LINT", -8)):
    _define(_name, "inttypes", float(_size))
_define("EOF_BIN", "num", -1.0)
# What ReadStr and ReadStrBin return at the end of a file (`IF text = EOF THEN`).
_define("EOF", "string", "EOF")
for _name in ("diskhome", "diskram", "disktemp"):
    _define(_name, "string", {"diskhome": "HOME:", "diskram": "RAMDISK:", "disktemp": "TEMP:"}[_name])
for _number, _name in enumerate(("EGM_STATE_DISCONNECTED", "EGM_STATE_CONNECTED",
                                 "EGM_STATE_RUNNING"), start=1):
    _define(_name, "egmstate", float(_number))
for _number, _name in enumerate(("EGM_STOP_HOLD", "EGM_STOP_RAMP_DOWN"), start=1):
    _define(_name, "egmstopmode", float(_number))
for _number, _name in enumerate(("EGM_FRAME_BASE", "EGM_FRAME_TOOL", "EGM_FRAME_WOBJ",
                                 "EGM_FRAME_WORLD", "EGM_FRAME_JOINT"), start=1):
    _define(_name, "egmframetype", float(_number))
for _number in range(1, 7):
    _define(f"ROB_{_number}", "mecunit", None)


# --- FlexPendant dialogs, error reports, events (numbers: our choice, distinct per type) --
for _number, _name in enumerate(("resUnkwn", "resOK", "resAbort", "resRetry", "resIgnore",
                                 "resCancel", "resYes", "resNo")):
    _define(_name, "btnres", float(_number))
for _number, _name in enumerate(("btnNone", "btnOK", "btnAbrtRtryIgn", "btnOKCancel",
                                 "btnRetryCancel", "btnYesNo", "btnYesNoCancel"), start=-1):
    _define(_name, "buttondata", float(_number))
for _number, _name in enumerate(("iconNone", "iconInfo", "iconWarning", "iconError")):
    _define(_name, "icondata", float(_number))
# errdomain numbers as public programs compute with them (ErrID := domain * 10000 + number)
for _number, _name in enumerate(("COMMON_ERR", "OP_STATE", "SYSTEM_ERR", "HARDWARE_ERR",
                                 "PROGRAM_ERR", "MOTION_ERR", "OPERATOR_ERR", "IO_COM_ERR",
                                 "USER_DEF_ERR", "SAFETY_ERR", "OPTION_PROD_ERR", "PROCESS_ERR",
                                 "CFG_ERR")):
    _define(_name, "errdomain", float(_number))
for _number, _name in enumerate(("TYPE_ALL", "TYPE_STATE", "TYPE_WARN", "TYPE_ERR")):
    _define(_name, "errtype", float(_number))
for _number, _name in enumerate(("EVENT_NONE", "EVENT_POWERON", "EVENT_START", "EVENT_STOP",
                                 "EVENT_QSTOP", "EVENT_RESTART", "EVENT_RESET", "EVENT_STEP")):
    _define(_name, "event_type", float(_number))
for _number, _name in enumerate(("HANDLER_NONE", "HANDLER_BWD", "HANDLER_ERR", "HANDLER_UNDO")):
    _define(_name, "handler_type", float(_number))
for _number, _name in enumerate(("LEVEL_NORMAL", "LEVEL_TRAP", "LEVEL_SERVICE")):
    _define(_name, "exec_level", float(_number))
for _number, _name in enumerate(("TUNE_DF", "TUNE_KP", "TUNE_KV", "TUNE_TI", "TUNE_FRIC_LEV",
                                 "TUNE_FRIC_RAMP", "TUNE_DG", "TUNE_DH", "TUNE_DI", "TUNE_DK",
                                 "TUNE_DL")):
    _define(_name, "tunetype", float(_number))


# --- speeds of external axes only: vrot (rotational, deg/s) and vlin (linear, mm/s) ------
for _speed in (1, 2, 5, 10, 20, 50, 100):
    _define(f"vrot{_speed}", "speeddata", _nums(0, 0, 0, _speed))
for _speed in (10, 20, 50, 100, 200, 500, 1000):
    _define(f"vlin{_speed}", "speeddata", _nums(0, 0, _speed, 0))

# --- stop point data [type, progsynch, [position, speed, mintime, maxtime], stoptime,
#     followtime, signal, relation, checkvalue] --------------------------------------------
_INPOS, _STOPTIME, _FLLWTIME = 1.0, 2.0, 3.0
for _size in (20, 50, 100):
    _define(f"inpos{_size}", "stoppointdata",
            (_INPOS, False, _nums(_size, _size, 0, 2), 0.0, 0.0, "", 0.0, 0.0))
for _text, _seconds in (("0_5", 0.5), ("1_0", 1.0), ("1_5", 1.5)):
    _define(f"stoptime{_text}", "stoppointdata",
            (_STOPTIME, False, _nums(0, 0, 0, 0), _seconds, 0.0, "", 0.0, 0.0))
    _define(f"fllwtime{_text}", "stoppointdata",
            (_FLLWTIME, True, _nums(0, 0, 0, 0), 0.0, _seconds, "", 0.0, 0.0))

# --- texts for ErrRaise and ErrLog arguments (errstr) -------------------------------------
for _name in ("ERRSTR_EMPTY", "ERRSTR_UNUSED", "ERRSTR_TASK", "ERRSTR_CONTEXT"):
    _define(_name, "errstr", "")


# --- FlexPendant windows (tpnum) and I/O unit states (iounit_state) -----------------------
for _number, _name in enumerate(("TP_LATEST", "TP_PROGRAM", "TP_SCREENVIEWER"), start=1):
    _define(_name, "tpnum", float(_number))
for _number, _name in enumerate(("IOUNIT_RUNNING", "IOUNIT_RUNERROR", "IOUNIT_DISABLE",
                                 "IOUNIT_OTHERERR"), start=1):
    _define(_name, "iounit_state", float(_number))

# --- conditions of ISignalAI/AO (aiotrigg) ------------------------------------------------
for _number, _name in enumerate(("AIO_ABOVE_HIGH", "AIO_BELOW_HIGH", "AIO_ABOVE_LOW",
                                 "AIO_BELOW_LOW", "AIO_BETWEEN", "AIO_OUTSIDE", "AIO_ALWAYS"),
                                start=1):
    _define(_name, "aiotrigg", float(_number))


# --- reference coverage (issue 8, item 1; docs/reference-names.txt) ------------------------
# USB memories: the file-system prefixes of the manual's usbdisk1 .. usbdisk10.
for _number in range(1, 11):
    _define(f"usbdisk{_number}", "string", f"/bd{_number - 1}:")
# GetSignalOrigin results (signalorigin), motion process modes (motionprocessmode),
# trigger modes (triggmode), load identification (paridnum, paridvalidnum, loadidnum),
# sensor states (sensorstate), configuration domains (cfgdomain), bus states (busstate),
# task selection panel states (tsp_status); numbers: our choice.
for _names, _type in (
        (("SIGORIG_NONE", "SIGORIG_CFG", "SIGORIG_ALIAS"), "signalorigin"),
        (("OPTIMAL_CYCLE_TIME_MODE", "LOW_SPEED_ACCURACY_MODE", "LOW_SPEED_STIFF_MODE",
          "ACCURACY_MODE", "MPM_USER_MODE_1", "MPM_USER_MODE_2", "MPM_USER_MODE_3",
          "MPM_USER_MODE_4"), "motionprocessmode"),
        (("TRIGG_MODE1", "TRIGG_MODE2", "TRIGG_MODE3"), "triggmode"),
        (("TOOL_LOAD_ID", "PAY_LOAD_ID", "IRBP_K", "IRBP_L", "IRBP_C", "IRBP_C_INDEX", "IRBP_T",
          "IRBP_R", "IRBP_A", "IRBP_B", "IRBP_D"), "paridnum"),
        (("ROB_LOAD_VAL", "ROB_NOT_LOAD_VAL", "ROB_LM1_LOAD_VAL"), "paridvalidnum"),
        (("MASS_KNOWN", "MASS_WITH_AX3"), "loadidnum"),
        (("STATE_ERROR", "STATE_UNDEFINED", "STATE_CONNECTED", "STATE_OPERATING",
          "STATE_CLOSED"), "sensorstate"),
        (("ALL_DOMAINS", "EIO_DOMAIN", "MMC_DOMAIN", "MOC_DOMAIN", "PROC_DOMAIN", "SIO_DOMAIN",
          "SYS_DOMAIN"), "cfgdomain"),
        (("IOBUS_LOG_STATE_STARTED", "IOBUS_LOG_STATE_STOPPED", "IOBUS_PHYS_STATE_ERROR",
          "IOBUS_PHYS_STATE_HALTED", "IOBUS_PHYS_STATE_INIT", "IOBUS_PHYS_STATE_RUNNING",
          "IOBUS_PHYS_STATE_STARTUP", "BUSSTATE_ERROR", "BUSSTATE_HALTED", "BUSSTATE_INIT",
          "BUSSTATE_RUN", "BUSSTATE_STARTUP"), "busstate"),
        (("TSP_STATUS_NOT_NORMAL_TASK", "TSP_STATUS_DEACT", "TSP_STATUS_DEACT_SERV_ROUT",
          "TSP_STATUS_ACT"), "tsp_status")):
    for _number, _name in enumerate(_names, start=1):
        _define(_name, _type, float(_number))
# I/O unit states of RobotWare 6 (logical and physical), after the four of RobotWare 5 above.
for _number, _name in enumerate(("IOUNIT_LOG_STATE_DISABLED", "IOUNIT_LOG_STATE_ENABLED",
                                 "IOUNIT_PHYS_STATE_DEACTIVATED", "IOUNIT_PHYS_STATE_RUNNING",
                                 "IOUNIT_PHYS_STATE_ERROR", "IOUNIT_PHYS_STATE_UNCONNECTED",
                                 "IOUNIT_PHYS_STATE_UNCONFIGURED", "IOUNIT_PHYS_STATE_STARTUP",
                                 "IOUNIT_PHYS_STATE_INIT"), start=5):
    _define(_name, "iounit_state", float(_number))
# The application domains of the event log report process errors (domain 11, PROCESS_ERR):
# they share its number, so ErrId arithmetic gives the documented 11xxxx numbers.
for _name in ("ARCWELD_ERR", "SPOTWELD_ERR", "PAINT_ERR", "PICKWARE_ERR"):
    _define(_name, "errdomain", PREDEFINED_DATA["PROCESS_ERR"].value)


# SoftMove (issue 8, item 1): the soft directions CSS_X .. CSS_XYRZ numbered 1 .. 8 and the
# reference frames CSS_REFFRAME_TOOL 1, CSS_REFFRAME_WOBJ 2, as a public program that calls
# CSSAct lists them; the force offset directions in the order a public SoftMove note lists
# them, numbers: our choice.
for _names, _type in ((("CSS_X", "CSS_Y", "CSS_Z", "CSS_XY", "CSS_XZ", "CSS_YZ", "CSS_XYZ",
                        "CSS_XYRZ"), "css_soft_dir"),
                      (("CSS_REFFRAME_TOOL", "CSS_REFFRAME_WOBJ"), "num"),
                      (("CSS_POSX", "CSS_POSY", "CSS_POSZ", "CSS_NEGX", "CSS_NEGY", "CSS_NEGZ"),
                       "css_offset_dir")):
    for _number, _name in enumerate(_names, start=1):
        _define(_name, _type, float(_number))


def lookup_data(key: str) -> PredefinedData | None:
    """The predefined data object with canonical name ``key``, or None."""
    return PREDEFINED_DATA.get(key)
