"""RAPID run-time error numbers (errnum constants) and the exception that carries them.

The controller's numeric values of the ERR_* constants are not documented in
any source we could check, so each gets a unique internal number from 1001
upwards (in the order below).  Programs compare ERRNO with the constants,
never with literals, so the choice is invisible to correct programs.  User
error numbers (RAISE n, BookErrNo) are 1..90.
"""
from __future__ import annotations

from typing import Optional

ERROR_NAMES: tuple[str, ...] = (
    "ERR_DIVZERO", "ERR_OUTOFBND", "ERR_NOTINTVAL", "ERR_NOTPRES", "ERR_NOTEQDIM",
    "ERR_NOTARR", "ERR_INVDIM", "ERR_ILLDIM", "ERR_STRTOOLNG", "ERR_ILLRAISE",
    "ERR_EXCRTYMAX", "ERR_FNCNORET", "ERR_ARGVALERR", "ERR_ARGNOTVAR", "ERR_ARGNOTPER",
    "ERR_ARGDUPCND", "ERR_ARGNAME", "ERR_NEGARG", "ERR_NUM_LIMIT", "ERR_INT_NOTVAL",
    "ERR_INT_MAXVAL", "ERR_CALC_OVERFLOW", "ERR_CALC_NEG", "ERR_CALC_DIVZERO",
    "ERR_MAXINTVAL", "ERR_OVERFLOW", "ERR_ALRDYCNT", "ERR_CNTNOTVAR", "ERR_INOMAX",
    "ERR_UNKINO", "ERR_WAIT_MAXTIME", "ERR_TP_MAXTIME", "ERR_TP_DIBREAK",
    "ERR_TP_DOBREAK", "ERR_TP_PERSBOOLBREAK", "ERR_TP_NO_CLIENT", "ERR_REFUNKPRC",
    "ERR_REFUNKFUN", "ERR_REFUNKDAT", "ERR_REFUNKTRP", "ERR_CALLPROC", "ERR_EXECPHR",
    "ERR_ALIASIO_DEF", "ERR_ALIASIO_TYPE", "ERR_NO_ALIASIO_DEF", "ERR_SIG_NOT_VALID",
    "ERR_NORUNUNIT", "ERR_AO_LIM", "ERR_GO_LIM", "ERR_FILEOPEN", "ERR_FILNOTFND",
    "ERR_FILEACC", "ERR_FILEEXIST", "ERR_RCVDATA", "ERR_SOCK_CLOSED", "ERR_SOCK_TIMEOUT",
    "ERR_COLL_STOP", "ERR_ROBLIMIT", "ERR_OUTSIDE_REACH", "ERR_CONC_MAX", "ERR_PATHDIST",
    "ERR_STARTMOVE", "ERR_UNLOAD", "ERR_STRTONUM", "ERR_NOTSTRING", "ERR_SYM_ACCESS",
    "ERR_USE_PROF", "ERR_TASKNAME", "ERR_NO_SGUN", "ERR_INVALID_TYPE", "ERR_ILLQUAT",
    "ERR_STACK_OVERFLOW",
    # More predefined errnum names met in real programs (round-2 survey, docs/realworld-survey.md);
    # appended so that the numbers above stay as they were.
    "ERR_UDPUC_COMM", "ERR_ACC_TOO_LOW", "ERR_ALRDY_MOVING", "ERR_AXIS_ACT", "ERR_AXIS_IND",
    "ERR_AXIS_MOVING", "ERR_AXIS_PAR", "ERR_BUSSTATE", "ERR_BWDLIMIT", "ERR_CFG_ILLTYPE",
    "ERR_CFG_INTERNAL", "ERR_CFG_LIMIT", "ERR_CFG_NOTFND", "ERR_CFG_OUTOFBOUNDS",
    "ERR_CNV_NOT_ACT", "ERR_CNV_CONNECT", "ERR_CNV_DROPPED", "ERR_COMM_EXT", "ERR_COMM_INIT",
    "ERR_DATA_RECV", "ERR_DEV_MAXTIME", "ERR_DIPLAG_LIM", "ERR_FRAME", "ERR_HAND_FAILEDGRIPPOS",
    "ERR_HAND_FAILEDMOVEPOS", "ERR_HAND_FAILEDVACUUM", "ERR_HAND_NOTCALIBRATED",
    "ERR_HAND_WRONGSTATE", "ERR_INOISSAFE", "ERR_INPAR_RDONLY", "ERR_IODISABLE", "ERR_IOENABLE",
    "ERR_IOERROR", "ERR_LINKREF", "ERR_LOADED", "ERR_LOADID_FATAL", "ERR_LOADID_RETRY",
    "ERR_MODULE", "ERR_MSG_PENDING", "ERR_NAME_INVALID", "ERR_NOT_MOVETASK", "ERR_PATH_STOP",
    "ERR_PID_MOVESTOP", "ERR_PID_RAISE_PP", "ERR_PRGMEMFULL", "ERR_PROCSIGNAL_OFF",
    "ERR_PROGSTOP", "ERR_RANYBIN_CHK", "ERR_RANYBIN_EOF", "ERR_RMQ_DIM", "ERR_RMQ_FULL",
    "ERR_RMQ_INVALID", "ERR_RMQ_INVMSG", "ERR_RMQ_MSGSIZE", "ERR_RMQ_NAME", "ERR_RMQ_NOMSG",
    "ERR_RMQ_TIMEOUT", "ERR_RMQ_VALUE", "ERR_SC_WRITE", "ERR_SIGSUPSEARCH", "ERR_SIG_NAME",
    "ERR_SOCK_ADDR_INUSE", "ERR_SOCK_NET_UNREACH", "ERR_SPEED_REFRESH_LIM", "ERR_STORE_PROF",
    "ERR_SYNCMOVEOFF", "ERR_SYNCMOVEON", "ERR_TRUSTLEVEL", "ERR_TXTNOEXIST", "ERR_UISHOW_FATAL",
    "ERR_UISHOW_FULL", "ERR_UNIT_PAR", "ERR_UNKPROC", "ERR_WAITSYNCTASK", "ERR_WHLSEARCH",
    "ERR_WOBJ_MOVING", "ERR_SYMBOL_TYPE", "ERR_CAM_NO_MORE_DATA",
    # The rest of the reference's errnum names (docs/reference-names.txt; issue 8, item 1).
    "ERR_ACTIV_PROF", "ERR_ADDR_INUSE", "ERR_ARRAY_SIZE", "ERR_CALLIO_INTER", "ERR_CAM_BUSY",
    "ERR_CAM_COM_TIMEOUT", "ERR_CAM_GET_MISMATCH", "ERR_CAM_MAXTIME", "ERR_CAM_NO_PROGMODE",
    "ERR_CAM_NO_RUNMODE", "ERR_CAM_SET_MISMATCH", "ERR_CFG_ILL_DOMAIN", "ERR_CFG_WRITEFILE",
    "ERR_COMM_INIT_FAILED", "ERR_CONTACTL", "ERR_CSV_INDEX", "ERR_DROP_LOAD", "ERR_FILESIZE",
    "ERR_FRICTUNE_FATAL", "ERR_INDCNV_ORDER", "ERR_IODN_TIMEOUT", "ERR_ITMSRC_UNDEF",
    "ERR_LOADNO_INUSE", "ERR_LOADNO_NOUSE", "ERR_MOD_NOT_LOADED", "ERR_NOTSAVED", "ERR_PATH",
    "ERR_PERSSUPSEARCH", "ERR_SGUN_ESTOP", "ERR_SGUN_MOTOFF", "ERR_SGUN_NEGVAL",
    "ERR_SGUN_NOTACT", "ERR_SGUN_NOTINIT", "ERR_SGUN_NOTOPEN", "ERR_SGUN_NOTSYNC",
    "ERR_SOCK_ADDR_INVALID", "ERR_SOCK_IS_BOUND", "ERR_SOCK_IS_CONN", "ERR_SOCK_NOT_BOUND",
    "ERR_SOCK_NOT_CONN", "ERR_SOCK_UNSPEC", "ERR_SPEEDLIM_VALUE", "ERR_SYNTAX",
    "ERR_UI_INITVALUE", "ERR_UI_MAXMIN", "ERR_UI_NOTINT",
)

ERROR_NUMBERS: dict[str, int] = {name: 1001 + i for i, name in enumerate(ERROR_NAMES)}
ERROR_BY_NUMBER: dict[int, str] = {n: name for name, n in ERROR_NUMBERS.items()}

LONG_JMP_ALL_ERR = -1          # wildcard in ERROR (...) recovery-point lists
USER_ERROR_RANGE = range(1, 91)


def errno_name(number: int) -> str:
    """The ERR_* name of an error number, or 'user error n'."""
    name = ERROR_BY_NUMBER.get(number)
    return name if name else f"user error {number}"


def error_detail(errno: int, message: str) -> str:
    """A fault's message without the error's name in front (``RapidError`` texts begin
    ``ERR_DIVZERO: ...``): what follows ``ERR_DIVZERO:`` where a text names it once."""
    name = errno_name(errno)
    if message == name or message.startswith(name + ":"):
        return message[len(name) + 1:].strip()
    return message


class RapidError(Exception):
    """A recoverable RAPID run-time error, e.g. ``RapidError("ERR_DIVZERO")``.

    Raised by evaluation and by predefined routines; the interpreter turns it
    into ERRNO and a jump to the routine's ERROR handler.
    """

    def __init__(self, name_or_number: str | int, detail: str = ""):
        if isinstance(name_or_number, str):
            self.errno = ERROR_NUMBERS[name_or_number]
        else:
            self.errno = int(name_or_number)
        self.detail = detail
        super().__init__(f"{errno_name(self.errno)}: {detail}" if detail else errno_name(self.errno))

    @property
    def name(self) -> str:
        return errno_name(self.errno)


def placeholder_reached(kind: str) -> None:
    """Execution reached an editor placeholder (``<SMT>``, ``<EXP>`` ...): ERR_EXECPHR.

    The RAPID kernel reference: a program with placeholders is syntactically correct and can be
    loaded; if they cause no semantic error it can even be executed, but any placeholder
    encountered causes an execution error (errnum ERR_EXECPHR, "executed a placeholder").
    """
    raise RapidError("ERR_EXECPHR", f"the editor placeholder <{kind}> was executed (that "
                     "part of the program was never completed)")


class FatalRapidError(Exception):
    """A non-recoverable run-time error (no ERROR handler may catch it)."""

    def __init__(self, message: str, errno: Optional[int] = None):
        self.errno = errno
        super().__init__(message)
