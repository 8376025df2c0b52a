"""Controller readings a check takes as fixed, and the coverage probe that frees them.

``OpMode``, ``RunMode``, ``RobOS`` and ``IsSysId`` read what only the controller
knows; the check compiles each in as one value (``registry.FIXED``: automatic
mode, continuous run, a virtual controller, another system id) and its verdicts
rest on that value (RMC702 says so).  Code guarded by another reading is still
reachable: on a controller in manual mode, on the robot's own operating system.
The readings probe (``api``'s coverage probe, ``CheckConfig.free_readings``) lets
each call read any value of the reading's real domain, chosen at each call (the
operator may turn the key between two calls), so that coverage can tell such code
from dead code.  Verdicts never run with it.
"""
from __future__ import annotations

from typing import Callable

from ... import ast
from ..expressions import Compiled
from .environment_model import where

# reading (canonical name) -> the symbolic constants or truth values a controller returns
# (the check's fixed value first)
DOMAINS = {
    "OPMODE": ("OP_AUTO", "OP_MAN_PROG", "OP_MAN_TEST", "OP_UNDEF"),
    "RUNMODE": ("RUN_CONT_CYCLE", "RUN_INSTR_FWD", "RUN_INSTR_BWD", "RUN_SIM",
                "RUN_STEP_MOVE", "RUN_UNDEF"),
    "ROBOS": (False, True),
    "ISSYSID": (False, True),
}


# readings the probe varies beyond DOMAINS: each call may fail with this error.  Their
# value stays fixed when they succeed (CalcJointT has no kinematics), so a complete probe
# does not free them from a warning's wording
FAILING = {"CALCJOINTT": "ERR_ROBLIMIT"}


def readings_free(m) -> bool:
    """Whether ``m`` runs in the readings probe (``CheckConfig.free_readings``).  A
    property's atom reads a state with no chooser (``CRobT()`` in an atom): never."""
    chooser = m.chooser
    return chooser is not None and chooser.check_mode and getattr(getattr(chooser, "config", None), "free_readings",
                                          False)


def probed_reading(compiler, call, fixed: Callable, rapid_type) -> Compiled:
    """The compiled call of a reading (a ``DOMAINS`` key): ``fixed(m)``, or in the
    readings probe any value of its domain, a choice named after the call."""
    domain = tuple(_value(compiler, value) for value in DOMAINS[call.name.key])
    label = f"{call.name.text} at {where(call.span)}"

    def read(m):
        if readings_free(m):
            return m.choose(label, domain)
        return fixed(m)
    return Compiled(read, rapid_type)


def _value(compiler, value):
    if isinstance(value, bool):
        return value
    return compiler.linker.system_symbol(ast.Name.of(value)).value

