"""Program control: Stop, ExitCycle, error numbers, late binding."""
from __future__ import annotations

from .. import values
from ...diagnostics import UNSUPPORTED, error
from ..errors import USER_ERROR_RANGE, RapidError
from ..errors_flow import unwind_all
from ..instructions import Action, ControlAction, enter_routine
from ..state import ENDED, STOPPED, Frame
from .arguments import Arguments
from .registry import compiled


# The choice a Stop makes in a program of several tasks (check mode).
STOP_CHOICE = "Stop"
STOPS_PROGRAM = "the program stops"
TASK_STOPS_FOR_GOOD = "this task stops for good, the others go on"
# predefined procedures that call a procedure of the program named by a string at run time
# (CallByVar; MoveJSync, MoveLSync and MoveCSync at the target), and ExitCycle, which goes
# on at the start of the task's entry routine: after a call of a routine that reaches one,
# any routine or any statement of the entry routine may run next
CALLS_BY_NAME = frozenset({"CALLBYVAR", "MOVEJSYNC", "MOVELSYNC", "MOVECSYNC"})
RESTARTS_CYCLE = frozenset({"EXITCYCLE"})


@compiled("Stop(\\switch NoRegain | switch AllMoveTasks)", "Break()")
def _stop(calls, compiler, call, entry):
    """Stop and Break pause the program; the operator may restart it at the next
    instruction (docs/semantics.md, "Stop and Break").  With several tasks a check also
    lets the stopping task stay stopped while the others go on (an over-approximation:
    which tasks a Stop halts is not modelled)."""
    Arguments(calls, compiler, call, entry)

    def stop(m, instruction):
        m.goto(instruction.next)
        if m.chooser.check_mode and len(m.program.task_names) > 1 and \
                m.choose(STOP_CHOICE, (STOPS_PROGRAM, TASK_STOPS_FOR_GOOD)) \
                == TASK_STOPS_FOR_GOOD:
            m.frames = []
            m.status = ENDED
            return
        m.status = STOPPED
    return ControlAction(call.span, stop)


@compiled("SystemStopAction(\\switch Stop | switch StopBlock | switch Halt)")
def _system_stop_action(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)

    def stop(m, instruction):
        m.frames = []
        m.status = ENDED
    return ControlAction(call.span, stop)


@compiled("ExitCycle()")
def _exit_cycle(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)

    def restart(m, instruction):
        # the task's own entry routine: the bottom of the stack the step runs on (a
        # further task's step runs on that task's frames)
        entry = m.frames[0].routine if m.frames else m.program.entry
        unwind_all(m)
        if not m.chooser.check_mode:
            m.status = ENDED           # a run is one cycle
            return
        main = m.program.routines[entry]
        m.frames = [Frame(main.index, 0, main.initial_locals)]
    return ControlAction(call.span, restart)


@compiled("BookErrNo(VAR errnum ErrorName)")
def _book_err_no(calls, compiler, call, entry):
    """Each BookErrNo of the program books its own number from the top of the user range
    (90, 89, ...), which RAISE accepts; the controller's choice is not documented, and
    programs only compare ERRNO with the booked data."""
    ref = Arguments(calls, compiler, call, entry).fn("ErrorName")
    linker = compiler.linker
    number = float(USER_ERROR_RANGE[-1] - linker.booked_errors)
    if number < USER_ERROR_RANGE[0]:
        raise error(UNSUPPORTED, "more BookErrNo calls than user error numbers (1..90)",
                    call.span)
    linker.booked_errors += 1
    return Action(call.span, lambda m: m.write_ref(ref(m), number))


@compiled("CallByVar(string Name, num Number)")
def _call_by_var(calls, compiler, call, entry):
    arguments = Arguments(calls, compiler, call, entry)
    name = arguments.value("Name")
    number = arguments.value("Number")
    candidates = {c.key: c for c in compiler.linker.procedures_visible(compiler.routine)
                  if not c.parameters}

    def call_by_var(m, instruction):
        full = name(m) + values.num_to_str(number(m), 0)
        callee = candidates.get(full.upper())
        if callee is None:
            raise RapidError("ERR_REFUNKPRC", f"no procedure named '{full}'")
        enter_routine(m, callee, [])
    return ControlAction(call.span, call_by_var)


@compiled("ResetRetryCount()")
def _reset_retry_count(calls, compiler, call, entry):
    Arguments(calls, compiler, call, entry)

    def reset(m):
        frame = m.frames[-1]
        m.frames[-1] = frame._replace(retries=0)
    return Action(call.span, reset)
