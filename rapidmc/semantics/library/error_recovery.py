"""Error reports as interrupts: IError, GetTrapData, ReadErrData.

rapidmc does not model the controller's event log, so an interrupt ordered
with IError never occurs; GetTrapData changes nothing and ReadErrData, if a
trap reaches it, reads an empty report (COMMON_ERR, 0, TYPE_ALL, empty texts).
"""
from __future__ import annotations

from ..instructions import Action
from ..machine import ABSENT
from .arguments import NAME_ONLY, Arguments, no_effect
from .data import PREDEFINED_DATA
from .registry import FIXED, NO_EFFECT, NOT_MODELLED, compiled

compiled("IError(errdomain ErrorDomain \\num ErrorId, errtype ErrorType, VAR intnum Interrupt)",
         "GetTrapData(VAR trapdata TrapEvent)",
         modelled=NO_EFFECT)(no_effect)

_TEXTS = ("Title", "Str1", "Str2", "Str3", "Str4", "Str5")


@compiled("ReadErrData(VAR trapdata TrapEvent, VAR errdomain ErrorDomain, VAR num ErrorId, "
              "VAR errtype ErrorType " + " ".join(f"\\VAR string {key}" for key in _TEXTS) + ")",
          modelled=FIXED)
def _read_err_data(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    fields = [(arguments.fn("ErrorDomain"), PREDEFINED_DATA["COMMON_ERR"].value),
              (arguments.fn("ErrorId"), 0.0),
              (arguments.fn("ErrorType"), PREDEFINED_DATA["TYPE_ALL"].value)]
    fields += [(arguments.fn(key), "") for key in _TEXTS]

    def read(m):
        for ref, value in fields:
            target = ref(m)
            if target is not ABSENT:
                m.write_ref(target, value)
    return Action(call.span, read)


# --- reference coverage (issue 8, item 1): RaiseToUser -----------------------------------------
# From the name list only: no text of its manual page and no public RAPID call of it was
# found, so neither its parameters nor how it hands an error from a NOSTEPIN routine's
# handler to the user-level routine's handler are modelled; a handler that reaches it stops
# the run (RMC305) instead of guessing where execution goes on.
compiled("RaiseToUser(...)", modelled=NOT_MODELLED)(NAME_ONLY)
