"""Search instructions: a move that watches a signal (SearchL, SearchJ, SearchC).

Whether the signal changes during the move is the world's decision: when
model checking, hit and miss are both possible; in ``run`` (inputs fixed) it
is a hit when the signal is 1.  A hit stores the search point; the point is
somewhere on the path and rapidmc, which does not follow the path, stores
the target (where it places the robot).  A miss moves the robot to the
target and raises ERR_WHLSEARCH (manual: "no search hit"), which an ERROR
handler can take.
"""
from __future__ import annotations

from ..errors import RapidError
from ..instructions import ControlAction
from ..machine import ABSENT
from ..robots import move_robot_to
from .arguments import ROBOT_JOINTS, Arguments
from .environment_model import where
from .motion import arrive
from .registry import CHOICE, compiled

# Signal | PersFlag: the manual's syntax supervises a digital input or, instead, a persistent
# bool ("PersFlag, Data type: bool, the persistent variable flag to supervise"; the search
# instructions of RobotWare 6 and 7). Real backups pass a PERS bool positionally.
_MODE = "\\switch Stop | switch PStop | switch SStop | switch Sup, " \
        "VAR signaldi Signal | PERS bool PersFlag " \
        "\\switch Flanks | switch PosFlank | switch NegFlank | switch HighLevel | switch LowLevel"
_TAIL = "\\identno ID, speeddata Speed \\num V | num T, PERS tooldata Tool \\PERS wobjdata WObj"


@compiled(f"SearchL({_MODE}, INOUT robtarget SearchPoint, robtarget ToPoint {_TAIL} "
              "\\switch Corr \\PERS loaddata TLoad)",
          f"SearchJ({_MODE}, INOUT robtarget SearchPoint, robtarget ToPoint {_TAIL} "
              "\\PERS loaddata TLoad)",
          f"SearchC({_MODE}, INOUT robtarget SearchPoint, robtarget CirPoint, robtarget ToPoint "
              f"{_TAIL} \\switch Corr \\PERS loaddata TLoad)",
          modelled=CHOICE)
def _search(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    signal, search_point = _supervised(arguments), arguments.fn("SearchPoint")
    target, tool, wobj = (arguments.value(key) for key in ("ToPoint", "Tool", "WObj"))
    label = f"{call.name.text} hit at {where(call.span)}"

    def search(m, instruction):
        point = target(m)
        hit = _hit(m, label, signal)
        arrive(m, point, tool(m), wobj(m))
        _miss_or_store(m, call, hit, search_point, point)
        m.goto(instruction.next)
    return ControlAction(call.span, search)


def _supervised(arguments):
    """fn(m) -> whether the supervised signal (or PERS bool flag) is set now."""
    signal, flag = arguments.fn("Signal"), arguments.value("PersFlag")

    def is_set(m) -> bool:
        value = flag(m)
        if value is not ABSENT:
            return bool(value)
        return m.io[signal(m)] == 1
    return is_set


def _hit(m, label: str, supervised) -> bool:
    """Check mode: hit and miss are both possible; run: a hit when the signal (or the
    PERS bool) is set."""
    if m.chooser.check_mode:
        return m.choose(label, (True, False))
    return supervised(m)


def _miss_or_store(m, call, hit: bool, search_point, point) -> None:
    if not hit:
        raise RapidError("ERR_WHLSEARCH", f"{call.name.text}: the signal did not change "
                         "during the search")
    m.write_ref(search_point(m), point)


# --- reference coverage (issue 8, item 1) -------------------------------------------------

@compiled(f"SearchExtJ({_MODE}, INOUT jointtarget SearchJointPos, jointtarget ToJointPos "
              "\\identno ID \\switch UseEOffs, speeddata Speed \\num T)",
          modelled=CHOICE)
def _search_ext_j(calls, compiler, call, entry):
    """A search with the external axes only: as MoveExtJ, the robot's joints keep their
    values; a hit stores the target, a miss raises ERR_WHLSEARCH."""
    arguments = Arguments(calls, compiler, call, entry)
    signal, search_point = _supervised(arguments), arguments.fn("SearchJointPos")
    target = arguments.value("ToJointPos")
    label = f"{call.name.text} hit at {where(call.span)}"

    def search(m, instruction):
        point = target(m)
        hit = _hit(m, label, signal)
        robot = list(m.robot)
        robot[ROBOT_JOINTS] = (robot[ROBOT_JOINTS][0], point[1])
        move_robot_to(m, tuple(robot))
        _miss_or_store(m, call, hit, search_point, point)
        m.goto(instruction.next)
    return ControlAction(call.span, search)
