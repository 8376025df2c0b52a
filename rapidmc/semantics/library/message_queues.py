"""RAPID Message Queues (RMQ): messages between tasks and to external clients.

Other tasks and clients are not modelled: finding a slot, sending and
emptying the queue change nothing rapidmc observes; no message ever arrives,
so RMQReadWait waits until its \\TimeOut and raises ERR_RMQ_TIMEOUT (without
\\TimeOut it would wait for ever: rapidmc raises ERR_RMQ_TIMEOUT as well,
documented here), and IRMQMessage's interrupt never occurs.
"""
from __future__ import annotations

from ..errors import RapidError
from ..instructions import Action
from .arguments import Arguments, fixed, no_effect
from .registry import EXACT, FIXED, NO_EFFECT, compiled

compiled("RMQFindSlot(VAR rmqslot Slot, string Name)",
         "RMQSendMessage(VAR rmqslot Slot, anytype SendData \\num UserDef)",
         "RMQEmptyQueue()",
         "RMQGetMessage(VAR rmqmessage Message)",
         "RMQGetMsgHeader(rmqmessage Message \\VAR rmqheader Header \\VAR rmqslot SenderId "
             "\\VAR num UserDef)",
         "RMQGetMsgData(rmqmessage Message, VAR anytype Data)",
         "IRMQMessage(anytype InterruptDataType, VAR intnum Interrupt)",
         modelled=NO_EFFECT)(no_effect)
compiled("string RMQGetSlotName(rmqslot Slot)", modelled=FIXED)(fixed(""))


@compiled("RMQReadWait(VAR rmqmessage Message \\num TimeOut)",
          "RMQSendWait(VAR rmqslot Slot, anytype SendData, VAR rmqmessage Message, "
              "anytype ReceiveDataType \\num UserDef \\num TimeOut)",
          modelled=EXACT)
def _rmq_wait(calls, compiler, call, entry):
    """No answer arrives: the wait ends with ERR_RMQ_TIMEOUT."""
    Arguments(calls, compiler, call, entry)

    def wait(m):
        raise RapidError("ERR_RMQ_TIMEOUT", f"{call.name.text}: no message arrives (other tasks "
                         "and clients are not modelled)")
    return Action(call.span, wait)
