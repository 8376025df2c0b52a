"""The working copy of a state while one step executes.

``step`` never mutates a ``State``: it unpacks it into a ``Machine``, lets one
instruction update the machine's fields (each update builds new immutable
values), and packs the result into a new ``State``.  The machine also
carries the step's effects that are not state: FlexPendant output and the
choices made (input values, FlexPendant answers).

References (VAR/INOUT/PERS arguments, assignment targets) are triples
``(space, index, path)``: ``space`` is ``GLOBAL`` for global data or the
frame depth for routine data, ``index`` the slot, ``path`` the 0-based
component and element offsets inside the slot's value.
"""
from __future__ import annotations

from typing import Any

from .errors import RapidError
from .lazy_inputs import stored
from .state import Fault, Frame, State, RUNNING, FAILED

GLOBAL = -1


class Absent:
    """The value of an optional parameter that was not passed."""

    _instance = None

    def __new__(cls):
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "ABSENT"

    def __hash__(self) -> int:
        return 0x5EED

    def __reduce__(self):
        return (Absent, ())


ABSENT = Absent()


def replace_at(value: Any, path: tuple, new: Any) -> Any:
    """``value`` with the part at ``path`` replaced by ``new`` (tuples rebuilt along the path)."""
    if not path:
        return new
    head = path[0]
    items = list(value)
    items[head] = replace_at(items[head], path[1:], new)
    return tuple(items)


def read_at(value: Any, path: tuple) -> Any:
    for offset in path:
        value = value[offset]
    return value


_new_tuple = tuple.__new__


def with_locals(frame: Frame, slot: int, value: Any) -> Frame:
    """``frame`` with local ``slot`` set to ``value`` (a new frame)."""
    values = list(frame[2])
    values[slot] = value
    return _new_tuple(Frame, (frame[0], frame[1], tuple(values), frame[3], frame[4], frame[5],
                              frame[6]))


def statement_completed(program, frame: Frame, pc: int) -> bool:
    """Whether going to ``pc`` completes the statement that was retried (RETRY counting)."""
    return frame.mode == 0 and frame.error_pc >= 0 and \
        pc == program.routines[frame.routine].code[frame.error_pc].after


class ChoiceNeeded(Exception):
    """Internal: the step reached a choice that the current script does not cover."""


class Machine:
    """Mutable working copy of a ``State`` for the duration of one step."""

    __slots__ = ("program", "frames", "store", "io", "robot", "interrupts", "errno",
                 "intno", "status", "fault", "clock", "output", "chooser", "choices",
                 "span", "waiting", "lazy_values", "tasks", "robots")

    def __init__(self, program, state: State, chooser):
        self.program = program
        (frames, self.store, self.io, self.robot, self.interrupts, self.errno, self.intno,
         self.status, self.fault, self.clock, self.tasks) = state
        self.frames = list(frames)
        self.output: list[str] = []
        self.chooser = chooser
        self.choices: list[tuple] = []
        self.span = None
        self.waiting = False
        self.lazy_values = None          # lazily chosen free inputs of this step (check mode)
        # every task's robot when the step started, where each motion task has its own and
        # the step is one task's (semantics.robots; None: only the machine's own robot)
        self.robots = None

    def to_state(self) -> State:
        """The state the step leaves (the step is over: no input is chosen any more)."""
        io = self.io
        if self.lazy_values is not None:
            # The input view refers back to this machine: without that cycle the
            # machine, its chooser and lists are freed now, not by the cycle collector.
            io = self.io = stored(io)
        return _new_tuple(State, (tuple(self.frames), self.store, io, self.robot,
                                  self.interrupts, self.errno, self.intno, self.status,
                                  self.fault, self.clock, self.tasks))

    # --- choices -------------------------------------------------------------
    def choose(self, name: str, domain: tuple) -> Any:
        """Pick a value from ``domain`` (nondeterministic choice, recorded in the label)."""
        value = self.chooser.choose(name, domain, len(self.choices))
        self.choices.append((name, value))
        return value

    # --- frames --------------------------------------------------------------
    @property
    def top(self) -> Frame:
        return self.frames[-1]

    def goto(self, pc: int) -> None:
        frame = self.frames[-1]
        retries = frame[5]
        if retries and statement_completed(self.program, frame, pc):
            retries = 0
        self.frames[-1] = _new_tuple(Frame, (frame[0], pc, frame[2], frame[3], frame[4],
                                             retries, frame[6]))

    def local(self, slot: int) -> Any:
        return self.frames[-1].locals[slot]

    def set_local(self, slot: int, value: Any, depth: int = -1) -> None:
        self.frames[depth] = with_locals(self.frames[depth], slot, value)

    # --- references ----------------------------------------------------------
    def read_ref(self, ref: tuple) -> Any:
        space, index, path = ref
        if space == GLOBAL:
            value = self.store[index]
        else:
            value = self.frames[space].locals[index]
        for offset in path:
            value = value[offset]
        return value

    def write_ref(self, ref: tuple, new: Any) -> None:
        space, index, path = ref
        if space == GLOBAL:
            self.store = self.store.set(index, replace_at(self.store[index], path, new) if path else new)
        else:
            frame = self.frames[space]
            self.frames[space] = with_locals(frame, index, replace_at(frame[2][index], path, new)
                                             if path else new)

    # --- ending ---------------------------------------------------------------
    def fail(self, errno: int, where: tuple, message: str) -> None:
        self.status = FAILED
        self.fault = Fault(errno, where, message)
        self.frames = []
        self.tasks = ()                  # an uncaught error stops every task

    def check_running(self) -> bool:
        return self.status == RUNNING


def raise_rapid(name: str, detail: str = "") -> None:
    raise RapidError(name, detail)
