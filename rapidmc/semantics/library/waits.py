"""Waiting: for a time, a signal or a condition."""
from __future__ import annotations

from ... import ast
from ..errors import RapidError
from ..instructions import ControlAction, Instruction, Wait, WaitRerun
from ..machine import ABSENT
from ..wait_outcomes import settle
from ..timing import advance_to, next_event
from ..wait_reads import global_reads
from .arguments import Arguments, argument_expression, no_effect
from ..scope import SIGNAL
from .registry import NO_EFFECT, compiled
from .signals import write_signal


@compiled("WaitTime(\\switch InPos, num Time)")
def _wait_time(calls, compiler, call, entry):
    """One step when model checking; in run mode interrupts are served during the wait."""
    seconds = Arguments(calls, compiler, call, entry).value("Time")
    deadline_slot = compiler.routine.new_temporary(1, "<WaitTime deadline>", -1.0)

    def wait(m, instruction):
        if m.chooser.check_mode:
            if seconds(m) < 0:
                raise RapidError("ERR_ARGVALERR", "WaitTime needs a time >= 0")
            m.goto(instruction.next)
            return
        deadline = m.frames[-1].locals[deadline_slot]
        if deadline < 0:
            t = seconds(m)
            if t < 0:
                raise RapidError("ERR_ARGVALERR", "WaitTime needs a time >= 0")
            deadline = m.clock + t
        due = next_event(m.interrupts)
        if due is not None and due < deadline - 1e-9:
            advance_to(m, due)
            m.set_local(deadline_slot, deadline)
            return                      # still waiting: a trap may run first
        advance_to(m, deadline)
        m.set_local(deadline_slot, -1.0)
        m.goto(instruction.next)
    return ControlAction(call.span, wait)


def _wait(calls, compiler, call, entry, condition_factory, what: str,
          condition_source=None) -> Instruction:
    """The wait; ``condition_source(arguments)``: the condition's ``Compiled`` with a
    source when the step machine may run the wait (``Wait.machine``), else None."""
    arguments = Arguments(calls, compiler, call, entry)
    condition = condition_factory(arguments)
    max_time = arguments.value("MaxTime")
    timeout = None
    timed = argument_expression(call, "MaxTime", -1) is not None
    if timed:
        timeout = max_time
    flag_ref = None
    flagged = "TIMEFLAG" in arguments.by_key and \
        argument_expression(call, "TimeFlag", -1) is not None
    if flagged:
        flag_ref = arguments.fn("TimeFlag")
    wait = Wait(call.span, condition, timeout, flag_ref, what)
    source = condition_source(arguments) if condition_source is not None else None
    limit = arguments.compiled("MaxTime") if timed else None
    flag = arguments.global_reference("TimeFlag") if flagged else None
    if source is not None and (limit is not None or not timed) and (flag or not flagged):
        wait.machine = (source, limit, flag[1] if flag else None)
    return wait


# RobotWare 6's \Visualize shows a FlexPendant message while the instruction waits
# (`WaitDI diReady,1\Visualize\Header:="..."\Message:="..."\Icon:=iconInfo;`); it
# changes nothing rapidmc observes, so the wait is the same with or without it.
_VISUALIZE = ("\\switch Visualize \\string Header \\string Message | string MsgArray{*} "
              "\\switch Wrap \\icondata Icon \\string Image \\num VisualizeTime "
              "\\VAR signaldo UIActiveSignal")


@compiled("WaitDI(VAR signaldi Signal, dionum Value \\num MaxTime \\VAR bool TimeFlag "
          f"{_VISUALIZE})",
          "WaitDO(VAR signaldo Signal, dionum Value \\num MaxTime \\VAR bool TimeFlag "
          f"{_VISUALIZE})")
def _wait_signal(calls, compiler, call, entry):
    also = _set_by_both(compiler, call) if call.name.key == "WAITDO" else None

    def factory(arguments):
        signal = arguments.fn("Signal")
        value = arguments.value("Value")
        if also is None:
            return lambda m: m.io[signal(m)] == value(m)
        label = f"{also.name} (set by {also.also_set_by})"

        def met(m):
            # an output a party left out sets too: it may have set the awaited value just
            # before; the wait then keeps it, so the code after reads what the wait saw
            index, wanted = signal(m), value(m)
            current = m.io[index]
            if current == wanted:
                return True
            if m.choose(label, (current, wanted)) != wanted:
                return False
            write_signal(m, index, wanted)
            return True
        return met
    return _wait(calls, compiler, call, entry, factory, f"{call.name.text} condition")


def _set_by_both(compiler, call):
    """The output a WaitDO waits on when the loaded code and a party left out both set it
    (``Signal.also_set_by``), else None."""
    target = argument_expression(call, "Signal", 0)
    if not isinstance(target, ast.NameRef):
        return None
    symbol = compiler.scope.lookup(target.name.key) or \
        compiler.linker.system_symbol(target.name)
    if symbol is None or symbol.kind != SIGNAL:
        return None
    signal = compiler.linker.signals[symbol.slot]
    return signal if signal.also_set_by else None


@compiled("WaitUntil(\\switch InPos, bool Cond \\num PollRate \\num MaxTime \\VAR bool TimeFlag "
          f"{_VISUALIZE})")
def _wait_until(calls, compiler, call, entry):
    pending = []                     # what its reads by outcome chose (wait_outcomes)

    def factory(arguments):
        condition = arguments.value("Cond")
        return _kept_where_it_ends(condition, pending) if compiler.wait_choices else condition
    def source(arguments):
        # (a condition that keeps what it read where it ends is Python's alone)
        return None if compiler.wait_choices else arguments.compiled("Cond")
    compiler.in_wait = True          # PERS another party writes too: the wait may end (issue 28)
    compiler.wait_choices = False
    compiler.wait_outcomes = pending
    hoist, callees, results = compiler.hoist, [], {}
    if hoist is not None:
        def noted(function_call, callee):
            callees.append(callee)
            slot = hoist(function_call, callee, for_wait=True)
            results[slot] = compiler.routine.initial[slot]
            return slot
        compiler.hoist = noted
    try:
        wait = _wait(calls, compiler, call, entry, factory, "WaitUntil condition", source)
    finally:
        compiler.in_wait = False
        compiler.wait_outcomes = None
        compiler.hoist = hoist
    if callees:                      # called anew when what they read changes
        condition = argument_expression(call, "Cond", 0)
        reads = None if condition is None else \
            global_reads(compiler.linker, condition, compiler.scope, callees)
        wait.rerun = WaitRerun(compiler.routine.new_temporary(1, "<WaitUntil reads>", None),
                               reads, results)
        wait.machine = None          # the step machine does not call the functions again
    return wait


def _kept_where_it_ends(condition, pending: list):
    """``condition``, whose reads of PERS another party writes too store the value they
    take (``ExpressionCompiler._outside_read``), keeping those values only where it holds:
    the code after the wait reads what the wait saw, while a try that keeps the task
    waiting leaves the data as it was.  Else a wait that no value ends would change the
    state at every try and never be seen to wait forever.  Reads that took one value per
    outcome of a comparison (``wait_outcomes``, noted in ``pending``) choose among their
    class's values only where it holds."""
    def seen(m):
        store = m.store
        pending.clear()
        if condition(m):
            settle(m, pending)
            pending.clear()
            return True
        pending.clear()
        m.store = store
        return False
    return seen


compiled("WaitRob(\\switch InPos | switch ZeroSpeed)",
          "StopMove(\\switch Quick \\switch AllMotionTasks)",
          "StartMove(\\switch AllMotionTasks)",
          "ConfJ(\\switch On | switch Off)",
          "ConfL(\\switch On | switch Off)",
          "AccSet(num Acc, num Ramp \\num FinePointRamp)",
          "VelSet(num Override, num Max)",
          "SingArea(\\switch Wrist | switch LockAxis4 | switch Off)",
          "TriggIO(VAR triggdata TriggData, num Distance \\switch Start | switch Time "
              "\\VAR signaldo DOp | VAR signalgo GOp | VAR signalao AOp | num ProcID, "
              "num SetValue | dnum SetDvalue \\num DODelay)",
          modelled=NO_EFFECT)(no_effect)


_COMPARISONS = (("LT", lambda a, b: a < b), ("GT", lambda a, b: a > b),
                ("NOTEQ", lambda a, b: a != b))


@compiled("WaitAI(VAR signalai Signal \\switch LT | switch GT, num Value \\num MaxTime "
              "\\VAR num ValueAtTimeout)",
          "WaitAO(VAR signalao Signal \\switch LT | switch GT, num Value \\num MaxTime "
              "\\VAR num ValueAtTimeout)",
          "WaitGI(VAR signalgi Signal \\switch NOTEQ | switch LT | switch GT, "
              "num Value | dnum Dvalue \\num MaxTime \\VAR num ValueAtTimeout)",
          "WaitGO(VAR signalgo Signal \\switch NOTEQ | switch LT | switch GT, "
              "num Value | dnum Dvalue \\num MaxTime \\VAR num ValueAtTimeout)")
def _wait_compare(calls, compiler, call, entry):
    """Waits until the signal equals the value, or is less, greater, different with the
    switch; at \\MaxTime ERR_WAIT_MAXTIME (\\ValueAtTimeout is not written)."""
    def factory(arguments):
        signal = arguments.fn("Signal")
        value = arguments.value("Value")
        dvalue = arguments.value("Dvalue") if "DVALUE" in arguments.by_key else None
        switches = [(arguments.value(key), test) for key, test in _COMPARISONS
                    if key in arguments.by_key]

        def condition(m):
            wanted = value(m)
            if wanted is ABSENT and dvalue is not None:
                wanted = dvalue(m)
            actual = m.io[signal(m)]
            for present, test in switches:
                if present(m) is True:
                    return test(actual, wanted)
            return actual == wanted
        return condition
    return _wait(calls, compiler, call, entry, factory, f"{call.name.text} condition")
