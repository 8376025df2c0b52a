"""Compiled instructions: what one step of a routine does.

A routine's statements compile to a flat list of instructions with
statically known successors (structured statements become branches).
Executing one instruction is one step of the small-step semantics: a
simple statement, one condition evaluation, or a routine entry or exit.

Every instruction knows
* ``span``   – the source of the statement it belongs to (for traces);
* ``next``   – where execution continues normally;
* ``start``  – the first instruction of its statement (RETRY goes there);
* ``after``  – the instruction after its whole statement (TRYNEXT goes there).
"""
from __future__ import annotations

from typing import Any, Callable, NamedTuple, Optional

from .errors import ERROR_NUMBERS, RapidError, USER_ERROR_RANGE
from .machine import ABSENT, Machine
from .state import ENDED, Frame, IN_HANDLER, IN_UNDO, NORMAL
from . import values


class Instruction:
    __slots__ = ("span", "next", "start", "after", "text", "reads_io", "signals_read",
                 "chooses", "fusion", "machine")

    def __init__(self, span):
        self.span = span
        self.next = -1
        self.start = -1
        self.after = -1
        self.reads_io = False       # may read a signal value (inputs matter to this step)
        # the signals it may read where ``reads_io``, by their names (None: any signal)
        self.signals_read: Optional[frozenset] = frozenset()
        # may choose a value of data written from outside the loaded code
        # (``load.outside_data``): a merged step stops before it once a choice was made
        self.chooses = False
        # what ``fused_step`` needs to run this instruction as Python source, or None:
        # a Branch's condition (a ``Compiled`` with a source), an Action's assignment
        # ("store" or "local", slot, the value's ``Compiled``), a ForInit's FROM, TO
        # (and STEP), a TestDispatch's subject and CASE values per case
        self.fusion = None
        # what the compiled core's step machine needs to run this instruction as one
        # task's step among several (``model.packed.bytecode``), or None: a Wait's
        # (the condition's and the \MaxTime's ``Compiled`` with sources, the \MaxTime's
        # None when not given; the \TimeFlag's store slot or None), a barrier's
        # ``SyncPlan`` (``library.tasks``), a ``ConstantWrite``
        self.machine = None

    def run(self, m: Machine) -> None:
        raise NotImplementedError

    def describe(self) -> str:
        return type(self).__name__


class ConstantWrite(NamedTuple):
    """An instruction's whole effect on the state for the step machine: global data
    ``slot`` becomes ``value`` (unless not ``writes``) and the task goes on, where the
    slot holds one of ``required`` (empty: any value; another value: the Python step,
    which raises or decides).  ``choice_option``: the ``CheckConfig`` flag that, when
    on, lets the instruction fail by a choice (then Python steps it)."""

    slot: int
    required: tuple
    value: Any
    choice_option: str = ""
    writes: bool = True


class ChosenWrite(NamedTuple):
    """An instruction's whole effect on the state for the step machine: global data
    ``slot`` becomes one of the values ``domain(config)`` gives, chosen in their order
    (one transition each, as ``Machine.choose`` gives them), and the task goes on, where
    global data ``guard`` holds ``required`` (another value: the Python step).
    ``domain`` gives None where the check's configuration lets the instruction fail by a
    choice (then Python steps it)."""

    slot: int
    guard: int
    required: Any
    domain: Callable


class CheckedReads(NamedTuple):
    """An instruction's whole effect on the state for the step machine, where the check
    configuration's flag ``option`` is on: it reads data and goes on.  ``sources``: the
    ``Compiled`` values (with sources) it evaluates; ``elements``: (global data slot of an
    array, the index's ``Compiled`` with a source) of the elements it reads.  A read that
    raises (an index not an integer in 1..the array's length) is the Python step's."""

    sources: tuple
    elements: tuple
    option: str


class ElementWrite(NamedTuple):
    """An assignment's whole effect on the state for the step machine: element ``index``
    (a ``Compiled`` with a source) of the array in global data ``slot`` becomes ``value``
    (a ``Compiled`` with a source), or, with a ``path`` of record component offsets, that
    component of the element (``targets{i}.trans.x``: the path (0, 0)).  An index not an
    integer in 1..the array's length is the Python step's (it raises ERR_OUTOFBND)."""

    slot: int
    index: Any
    value: Any
    path: tuple = ()


class CallPlan(NamedTuple):
    """A procedure call's whole effect for the step machine (``enter_routine``): a frame
    of ``routine`` pushed on the task's stack, its locals the routine's initial ones with
    each parameter's the value of its argument (``arguments``: per parameter, in order,
    an IN argument's ``Compiled`` with a source; a num parameter rounds a num to single
    precision, as ``Parameter.convert`` does)."""

    routine: int
    arguments: tuple


class LeavePlan(NamedTuple):
    """The end of a procedure (ENDPROC, RETURN without a value) for the step machine
    (``leave_routine``): the task's frame of ``routine`` popped, its caller going on after
    the call.  The last frame of a task, a trap's or a function's are Python's."""

    routine: int


class Action(Instruction):
    """A simple statement: ``fn(machine)``, then continue with ``next``."""

    __slots__ = ("fn",)

    def __init__(self, span, fn: Callable[[Machine], None]):
        super().__init__(span)
        self.fn = fn

    def run(self, m: Machine) -> None:
        self.fn(m)
        m.goto(self.next)


class ControlAction(Instruction):
    """A predefined instruction that decides itself where execution goes.

    ``fn(machine, instruction)`` must move the program counter (or end the
    program); ``m.goto(instruction.next)`` is the normal way.
    """

    __slots__ = ("fn",)

    def __init__(self, span, fn):
        super().__init__(span)
        self.fn = fn

    def run(self, m: Machine) -> None:
        self.fn(m, self)


class Branch(Instruction):
    """Evaluate a condition; continue at ``target_true`` or ``target_false``."""

    __slots__ = ("condition", "target_true", "target_false", "expression")

    def __init__(self, span, condition, expression=None):
        super().__init__(span)
        self.condition = condition
        self.target_true = -1
        self.target_false = -1
        self.expression = expression    # the condition's syntax (what it reads, for analyses)

    def run(self, m: Machine) -> None:
        m.goto(self.target_true if self.condition(m) else self.target_false)


class Jump(Instruction):
    """GOTO label."""

    __slots__ = ("target",)

    def __init__(self, span, target: int = -1):
        super().__init__(span)
        self.target = target

    def run(self, m: Machine) -> None:
        m.goto(self.target)


class ForInit(Instruction):
    """FOR entry: evaluate FROM, TO, STEP once, set the loop variable, test."""

    __slots__ = ("slot", "start_fn", "stop_fn", "step_fn", "exit")

    def __init__(self, span, slot, start_fn, stop_fn, step_fn):
        super().__init__(span)
        self.slot = slot
        self.start_fn = start_fn
        self.stop_fn = stop_fn
        self.step_fn = step_fn
        self.exit = -1

    def run(self, m: Machine) -> None:
        first = self.start_fn(m)
        last = self.stop_fn(m)
        if self.step_fn is None:
            step = -1.0 if first > last else 1.0
        else:
            step = self.step_fn(m)
        frame = m.frames[-1]
        locals_ = list(frame.locals)
        slot = self.slot
        locals_[slot] = first
        locals_[slot + 1] = last
        locals_[slot + 2] = step
        low, high = (first, last) if first <= last else (last, first)
        pc = self.next if low <= first <= high else self.exit
        m.frames[-1] = Frame(frame.routine, pc, tuple(locals_), frame.mode, frame.error_pc,
                             frame.retries, frame.result)


class ForNext(Instruction):
    """End of a FOR body: add STEP, test against the FROM..TO interval."""

    __slots__ = ("slot", "body", "exit", "first_slot")

    def __init__(self, span, slot):
        super().__init__(span)
        self.slot = slot
        self.body = -1
        self.exit = -1

    def run(self, m: Machine) -> None:
        frame = m.frames[-1]
        locals_ = list(frame.locals)
        slot = self.slot
        value = values.to_num(locals_[slot] + locals_[slot + 2])
        last = locals_[slot + 1]
        step = locals_[slot + 2]
        locals_[slot] = value
        inside = value <= last if step >= 0 else value >= last
        m.frames[-1] = Frame(frame.routine, self.body if inside else self.exit, tuple(locals_),
                             frame.mode, frame.error_pc, frame.retries, frame.result)


class TestDispatch(Instruction):
    """TEST: compare the subject with each CASE value in order; no match goes to DEFAULT."""

    __slots__ = ("subject", "cases", "default")

    def __init__(self, span, subject):
        super().__init__(span)
        self.subject = subject
        self.cases: list[tuple[list, int]] = []
        self.default = -1

    def run(self, m: Machine) -> None:
        value = self.subject(m)
        for value_fns, target in self.cases:
            for fn in value_fns:
                if fn(m) == value:
                    m.goto(target)
                    return
        m.goto(self.default)


class Call(Instruction):
    """Enter a user routine: bind the arguments, push a frame (one step)."""

    __slots__ = ("routine", "binders", "result_slot", "program_routines", "for_wait")

    def __init__(self, span, routine, binders, result_slot: int = -1):
        super().__init__(span)
        self.routine = routine
        self.binders = binders
        self.result_slot = result_slot
        # a function a WaitUntil or polling condition calls (``called_from_wait``)
        self.for_wait = False

    def run(self, m: Machine) -> None:
        enter_routine(m, self.routine, [b(m) for _, b in self.binders], self.result_slot)


def called_from_wait(m: Machine) -> bool:
    """Whether the running function evaluates, directly or through other routines, part of
    a WaitUntil or polling condition: a caller's frame stands at a call so marked."""
    routines = m.program.routines
    for frame in reversed(m.frames[:-1]):
        code = routines[frame.routine].code
        if 0 <= frame.pc < len(code) and getattr(code[frame.pc], "for_wait", False):
            return True
    return False


def enter_routine(m: Machine, routine, arguments: list, result_slot: int = -1) -> None:
    if len(m.frames) >= 512:
        raise RapidError("ERR_STACK_OVERFLOW", f"call depth exceeds 512 in {routine.name}")
    locals_ = list(routine.initial_locals)
    for param, value in zip(routine.parameters, arguments):
        if value is not ABSENT and not param.by_reference and param.type is not None:
            value = param.convert(value)
        locals_[param.slot] = value
    m.frames.append(Frame(routine.index, 0, tuple(locals_), NORMAL, -1, 0, result_slot))


class LateCall(Instruction):
    """``%name% args;``: find the procedure by name at run time."""

    __slots__ = ("name_fn", "candidates")

    def __init__(self, span, name_fn, candidates: dict):
        super().__init__(span)
        self.name_fn = name_fn
        self.candidates = candidates        # key -> (routine, binders) or (routine, None)

    def run(self, m: Machine) -> None:
        name = self.name_fn(m)
        candidate = self.candidates.get(name.upper())
        if candidate is None:
            raise RapidError("ERR_REFUNKPRC", f"no procedure named '{name}'")
        routine, binders = candidate
        if binders is None:
            raise RapidError("ERR_CALLPROC", f"the arguments do not fit procedure '{name}'")
        enter_routine(m, routine, [b(m) for _, b in binders])


class Return(Instruction):
    """RETURN [value]: leave the routine (one step)."""

    __slots__ = ("value_fn",)

    def __init__(self, span, value_fn=None):
        super().__init__(span)
        self.value_fn = value_fn

    def run(self, m: Machine) -> None:
        value = self.value_fn(m) if self.value_fn is not None else None
        leave_routine(m, value)


class EndRoutine(Instruction):
    """ENDPROC / ENDTRAP / end of an ERROR handler: return; ENDFUNC without RETURN fails."""

    __slots__ = ("is_function", "name")

    def __init__(self, span, is_function: bool, name: str):
        super().__init__(span)
        self.is_function = is_function
        self.name = name

    def run(self, m: Machine) -> None:
        if self.is_function:
            raise RapidError("ERR_FNCNORET", f"function {self.name} ended without RETURN")
        leave_routine(m, None)


def leave_routine(m: Machine, value: Any) -> None:
    frame = m.frames.pop()
    if not m.frames:
        m.status = ENDED
        return
    routine = m.program.routines[frame.routine]
    if routine.kind == "TRAP":
        return                           # the interrupted routine resumes where it was
    caller = m.frames[-1]
    if frame.result >= 0:
        values_ = list(caller.locals)
        values_[frame.result] = routine.convert_result(value)
        caller = caller._replace(locals=tuple(values_))
    call = m.program.routines[caller.routine].code[caller.pc]
    m.frames[-1] = caller
    m.goto(call.next)


class EndUndo(Instruction):
    """End of an UNDO handler: the frame is discarded (unwinding continues)."""

    def run(self, m: Machine) -> None:
        m.frames.pop()


class Raise(Instruction):
    """RAISE [errno]."""

    __slots__ = ("value_fn",)

    def __init__(self, span, value_fn=None):
        super().__init__(span)
        self.value_fn = value_fn

    def run(self, m: Machine) -> None:
        frame = m.frames[-1]
        if self.value_fn is None:
            raise ReRaise(int(m.errno))
        number = self.value_fn(m)
        if number != int(number) or (int(number) not in USER_ERROR_RANGE and
                                     int(number) < 1001):
            raise RapidError("ERR_ILLRAISE", f"RAISE {values.format_num(number)} is outside 1..90")
        if frame.mode == IN_HANDLER:
            raise ReRaise(int(number))
        raise RapidError(int(number))


class ReRaise(Exception):
    """RAISE inside an ERROR handler: the error goes to the caller."""

    def __init__(self, errno: int):
        self.errno = errno
        super().__init__(errno)


class Retry(Instruction):
    def run(self, m: Machine) -> None:
        frame = m.frames[-1]
        retries = frame.retries + 1
        if retries > m.program.options.get("max_retries", 4):
            raise ReRaise(ERROR_NUMBERS["ERR_EXCRTYMAX"])
        m.frames[-1] = frame._replace(pc=frame.error_pc, mode=NORMAL, retries=retries)


class TryNext(Instruction):
    def run(self, m: Machine) -> None:
        frame = m.frames[-1]
        code = m.program.routines[frame.routine].code
        m.frames[-1] = frame._replace(pc=code[frame.error_pc].after, mode=NORMAL, retries=0)


class ExitProgram(Instruction):
    def run(self, m: Machine) -> None:
        from .errors_flow import unwind_all
        unwind_all(m)
        m.status = ENDED


class Wait(Instruction):
    """A blocking wait (WaitUntil, WaitDI, WaitDO): stays here until ``condition`` holds.

    ``timeout`` (the \\MaxTime value function) and ``flag_ref`` (\\TimeFlag)
    model a time limit: when model checking, the wait may time out at any
    step where it would block; in ``run`` mode, virtual time decides.
    """

    __slots__ = ("condition", "timeout", "flag_ref", "what", "rerun")

    def __init__(self, span, condition, timeout=None, flag_ref=None, what="condition"):
        super().__init__(span)
        self.condition = condition
        self.timeout = timeout
        self.flag_ref = flag_ref
        self.what = what
        self.rerun: Optional[WaitRerun] = None   # the condition calls user functions

    def run(self, m: Machine) -> None:
        if self.condition(m):
            if self.rerun is not None:
                self.rerun.forget(m)
            if self.flag_ref is not None:
                m.write_ref(self.flag_ref(m), False)
            m.goto(self.next)
            return
        if self.timeout is not None and m.chooser.wait_times_out(m, self.timeout(m)):
            if self.flag_ref is not None:
                m.write_ref(self.flag_ref(m), True)
                m.goto(self.next)
                return
            raise RapidError("ERR_WAIT_MAXTIME", f"{self.what} not met within \\MaxTime")
        if self.rerun is not None and self.rerun.again(m, self.start):
            return
        m.waiting = True


class WaitRerun:
    """A WaitUntil whose condition calls user functions (called before the wait, their
    results read by it) calls them again, as a controller evaluates the condition at each
    poll, when what they read may have changed (``semantics.wait_reads``): ``reads`` holds
    the global data slots they read, whose values at their last call ``slot`` (a frame
    temporary) keeps; None: they read what changes without a step of the program (a
    signal, data written outside), so each try calls them again.  Going back, the calls'
    result slots (``results``: slot -> initial value) are cleared, so the task is where it
    was before the first call and the states before each call are the same (as they are
    after the wait ends: ``forget``)."""

    __slots__ = ("slot", "reads", "results")

    def __init__(self, slot: int, reads: Optional[tuple], results: dict):
        self.slot = slot
        self.reads = reads
        self.results = results

    def again(self, m: Machine, start: int) -> bool:
        """Go back to the calls (True) unless nothing they read changed since the last."""
        if self.reads is not None:
            seen = tuple(m.store[slot] for slot in self.reads)
            if m.local(self.slot) == seen:
                return False             # the same calls would answer the same: it waits
            m.set_local(self.slot, seen)
        for slot, initial in self.results.items():
            m.set_local(slot, initial)
        m.goto(start)
        return True

    def forget(self, m: Machine) -> None:
        """The wait ends: clear what it kept, so the states after it do not differ by
        the values its calls last answered."""
        if m.local(self.slot) is not None:
            m.set_local(self.slot, None)
        for slot, initial in self.results.items():
            m.set_local(slot, initial)
