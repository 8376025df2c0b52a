"""The immutable, hashable state of a running RAPID program.

A ``State`` is a named tuple of immutable parts, so two states that mean the
same are equal and hash alike (the model checker stores them in a set):

* ``frames``: the call stack (``Frame`` per active routine, innermost last),
  each with its program counter, local data and error-handler bookkeeping;
* ``store``: global data by slot (a pyrsistent ``pvector``: module VAR and PERS
  data of the program and of environment modules; CONSTs live in the program);
* ``io``: physical I/O signal values by signal index (``pvector``);
* ``robot``: TCP target, active tool, work object and joint position;
* ``interrupts``: connected interrupts, pending queue, IEnable/IDisable flag;
* ``errno`` / ``intno``: the ERRNO and INTNO system variables;
* ``status``: RUNNING, ENDED (end of main, EXIT), STOPPED (Stop or Break: the
  program waits for the operator, who may restart it at the next instruction;
  the stacks are kept) or FAILED (uncaught error; ``fault`` says which and where);
* ``clock``: virtual time in seconds (advanced by waits in ``run`` mode only;
  always 0 when model checking, where time is abstracted away);
* ``tasks``: the call stacks of further RAPID tasks running beside the main
  task (whose stack is ``frames``); one task steps at a time.

FlexPendant output is not part of the state: it is an effect of a
transition, so printing does not make states distinct.
"""
from __future__ import annotations

from typing import NamedTuple, Optional

RUNNING = 0
ENDED = 1
FAILED = 2
STOPPED = 3         # Stop/Break: paused, the operator may restart it

NORMAL = 0          # frame executes its body
IN_HANDLER = 1      # frame executes its ERROR handler
IN_UNDO = 2         # frame executes its UNDO handler while unwinding


class Frame(NamedTuple):
    routine: int            # index into Program.routines
    pc: int                 # index of the next instruction in the routine's code
    locals: tuple           # parameters, routine data, FOR variables, temporaries
    mode: int = NORMAL      # NORMAL, IN_HANDLER, IN_UNDO
    error_pc: int = -1      # first instruction of the statement that raised (RETRY/TRYNEXT)
    retries: int = 0        # RETRYs since the handler was entered
    result: int = -1        # caller's local slot that receives a FUNC result


class Interrupt(NamedTuple):
    number: int             # the intnum value handed out by CONNECT
    trap: int               # routine index of the TRAP
    source: tuple = ()      # () not ordered; ("timer", period, single); ("signal", index, trigger, single);
    # ("analog", index, condition, high, low, delta, direction, reference, single): ISignalAI/AO
    active: bool = True     # False after ISleep
    due: float = 0.0        # next firing time of a timer in run mode


class Interrupts(NamedTuple):
    table: tuple = ()       # Interrupt entries ordered by number
    pending: tuple = ()     # interrupt numbers waiting for their trap
    enabled: bool = True    # IDisable queues, IEnable delivers
    scheduled: tuple = ()   # delayed signal changes (due time, signal index, value), in order


class Fault(NamedTuple):
    errno: int
    instruction: tuple      # (routine index, pc) where the error was raised
    message: str


class State(NamedTuple):
    frames: tuple
    store: object           # pvector
    io: object              # pvector
    robot: tuple            # (tcp robtarget, tool tooldata, wobj wobjdata, joints jointtarget)
    interrupts: Interrupts
    errno: float = 0.0
    intno: float = 0.0
    status: int = RUNNING
    fault: Optional[Fault] = None
    clock: float = 0.0
    tasks: tuple = ()       # call stacks of further tasks (empty: that task has ended)


class Transition(NamedTuple):
    """One step: the choices made, the source executed, the new state, the text printed."""

    label: tuple            # ((choice name, value), ...) in the order the choices were made
    span: object            # rapidmc.ast.Span of the executed statement (None at the end)
    state: State
    output: str = ""
    waiting: bool = False   # the program is blocked in a wait (nothing else happened)
