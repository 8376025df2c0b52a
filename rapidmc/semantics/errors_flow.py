"""Error recovery: delivering a RAPID error to an ERROR handler, or stopping.

When an instruction raises error *n* in routine R:

1. ERRNO := n.
2. If R has an ERROR handler that catches n (no number list, or n in the
   list, or LONG_JMP_ALL_ERR) and R is not already in its handler, control
   goes to R's handler; RETRY/TRYNEXT later refer to the statement that
   raised (for a call, the call statement).
3. Otherwise the error propagates to the callers.  A routine up the chain
   whose handler lists n explicitly (an error recovery point) is preferred;
   failing that, the nearest caller with a handler that catches n takes it.
   Routines left on the way run their UNDO handlers, innermost first.
4. If no routine takes it (or it comes from a TRAP), the program stops
   with an uncaught error.
"""
from __future__ import annotations

from .errors import LONG_JMP_ALL_ERR, RapidError, errno_name
from .machine import Machine
from .state import Frame, IN_HANDLER, IN_UNDO, NORMAL

UNDO_STEP_LIMIT = 100_000


def _catches(m: Machine, routine, errno: int) -> bool:
    if routine.handler_pc < 0:
        return False
    return routine.handler_numbers is None or _lists(m, routine, errno)


def _lists(m: Machine, routine, errno: int) -> bool:
    """The handler's number list names ``errno``: a constant, LONG_JMP_ALL_ERR, or module
    data (an errnum booked with BookErrNo) holding it now."""
    numbers = routine.handler_numbers
    return routine.handler_pc >= 0 and numbers is not None and (
        errno in numbers or LONG_JMP_ALL_ERR in numbers
        or any(m.store[slot] == errno for slot in routine.handler_slots))


def deliver_error(m: Machine, errno: int, message: str, from_handler: bool = False) -> None:
    """Move control to the handler that takes ``errno``, or stop the program.

    ``from_handler``: the error was raised (RAISE) in the current routine's
    ERROR handler, so that handler cannot take it; it goes to the callers.
    """
    m.errno = float(errno)
    routines = m.program.routines
    frames = m.frames
    origin = (frames[-1].routine, frames[-1].pc)
    depth = len(frames) - 1
    frame = frames[depth]
    if not from_handler and frame.mode == NORMAL and _catches(m, routines[frame.routine], errno):
        _enter_handler(m, depth)
        return
    callers = []
    d = depth
    while d > 0 and routines[frames[d].routine].kind != "TRAP":
        d -= 1
        callers.append(d)
    open_callers = [d for d in callers if frames[d].mode == NORMAL]
    target = next((d for d in open_callers if _lists(m, routines[frames[d].routine], errno)), None)
    if target is None:
        target = next((d for d in open_callers if _catches(m, routines[frames[d].routine], errno)),
                      None)
    if target is None:
        unwind_to(m, 0)
        m.fail(errno, origin, message or errno_name(errno))
        return
    unwind_to(m, target + 1)
    _enter_handler(m, target)


def _enter_handler(m: Machine, depth: int) -> None:
    frame = m.frames[depth]
    routine = m.program.routines[frame.routine]
    start = routine.code[frame.pc].start
    retries = frame.retries if frame.error_pc == start else 0
    m.frames[depth] = Frame(frame.routine, routine.handler_pc, frame.locals, IN_HANDLER,
                            start, retries, frame.result)


def unwind_to(m: Machine, depth: int) -> None:
    """Pop frames above ``depth``, running their UNDO handlers innermost first.

    An UNDO handler runs once: when an EXIT inside it unwinds the stack again, the frame
    beneath its IN_UNDO frame (the routine being undone) is popped without running it anew
    (before, UNDO -> EXIT -> UNDO ... recursed without end).  Such an EXIT may leave fewer
    frames than the unwinding that ran the handler expected."""
    undoing = False
    while len(m.frames) > depth:
        frame = m.frames[-1]
        routine = m.program.routines[frame.routine]
        if routine.undo_pc >= 0 and frame.mode != IN_UNDO and not undoing:
            run_undo(m, frame)
        undoing = frame.mode == IN_UNDO
        if len(m.frames) > depth:
            m.frames.pop()


def unwind_all(m: Machine) -> None:
    unwind_to(m, 0)


def run_undo(m: Machine, frame: Frame) -> None:
    """Execute a routine's UNDO handler to completion inside the current step."""
    routine = m.program.routines[frame.routine]
    base = len(m.frames)
    m.frames.append(Frame(frame.routine, routine.undo_pc, frame.locals, IN_UNDO, -1, 0, -1))
    steps = 0
    try:
        while len(m.frames) > base and m.status == 0:
            top = m.frames[-1]
            m.program.routines[top.routine].code[top.pc].run(m)
            steps += 1
            if steps > UNDO_STEP_LIMIT:
                break
    except RapidError:
        pass                      # an error inside UNDO ends the UNDO handler
    del m.frames[base:]
