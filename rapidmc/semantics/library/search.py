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
from .arguments import Arguments
from .environment_model import where
from .motion import arrive
from .registry import CHOICE, compiled

_MODE = "\\switch Stop | switch PStop | switch SStop | switch Sup, VAR signaldi Signal " \
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
    signal, search_point = arguments.fn("Signal"), arguments.fn("SearchPoint")
    target, tool, wobj = (arguments.value(key) for key in ("ToPoint", "Tool", "WObj"))
    label = f"{call.name.text} hit at {where(call.span)}"

    def search(m, instruction):
        point = target(m)
        if m.chooser.check_mode:
            hit = m.choose(label, (True, False))
        else:
            hit = m.io[signal(m)] == 1
        arrive(m, point, tool(m), wobj(m))
        if not hit:
            raise RapidError("ERR_WHLSEARCH", f"{call.name.text}: the signal did not change "
                             "during the search")
        m.write_ref(search_point(m), point)
        m.goto(instruction.next)
    return ControlAction(call.span, search)
