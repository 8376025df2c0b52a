"""``rapidmc run``: drive the step function with a deterministic console.

The FlexPendant is the console: TPWrite goes to stdout, TPReadNum/TPReadFK
read one answer per line from stdin.  Inputs keep the values given with
``--io``.  Time is virtual: WaitTime advances a clock that drives ITimer
interrupts and \\MaxTime limits; a wait that nothing can end is reported
as a deadlock instead of hanging.
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from typing import Optional, TextIO

from ..diagnostics import (BAD_INPUT_VALUE, INPUT_EXHAUSTED, RUNTIME_ERROR, STEP_LIMIT,
                          Diagnostic, error, render)
from ..diagnostics.quoting import one_line
from ..semantics.errors import errno_name, error_detail
from ..semantics.machine import Machine
from ..semantics.program import Program
from ..semantics.state import ENDED, FAILED, RUNNING, STOPPED, State
from ..semantics.task_registers import pending_served
from ..semantics.step import (Chooser, EnvironmentFault, execute_step, run_instruction,
                             signal_edges, start_state)
from ..semantics.timing import advance_to, next_event, schedule
from ..semantics.values import format_num


class ConsoleChooser(Chooser):
    """Run mode: answers come from stdin, time is a virtual clock."""

    def __init__(self, stdin: TextIO):
        self.stdin = stdin

    def tp_answers(self, kind: str) -> tuple:
        line = self.stdin.readline()
        if not line:
            raise error(INPUT_EXHAUSTED, f"{kind} waits for an answer but standard input has "
                        "no more lines", exit_code=1)
        text = line.strip()
        try:
            value = float(text)
        except ValueError:
            raise error(BAD_INPUT_VALUE, f"{kind} needs a number, got {text!r} on standard "
                        "input") from None
        if not math.isfinite(value):
            raise error(BAD_INPUT_VALUE, f"{kind} needs a finite number, got {text!r} on "
                        "standard input")
        if kind == "TPReadFK" and value not in (1, 2, 3, 4, 5):
            raise error(BAD_INPUT_VALUE, f"TPReadFK answers are function keys 1-5, got {text!r}")
        return (value,)

    def wait_times_out(self, m: Machine, max_time: float) -> bool:
        # Inputs do not change in run mode, so a wait that is not met now is
        # only ended by its time limit.
        self.advance_time(m, max_time)
        return True

    def advance_time(self, m: Machine, seconds: float) -> None:
        advance_to(m, m.clock + seconds)

    def choose(self, name: str, domain: tuple, position: int):
        if name == "task":               # tasks take turns
            self.turn = getattr(self, "turn", -1) + 1
            return domain[self.turn % len(domain)]
        return domain[0]


@dataclass
class RunResult:
    state: State
    steps: int


def run_program(program: Program, io_values: dict, stdin: TextIO, stdout: TextIO,
                max_steps: Optional[int] = None, trace: Optional[TextIO] = None,
                input_changes: tuple = (), operator: Optional[TextIO] = None) -> RunResult:
    """Execute ``program`` to its end; FlexPendant output goes to ``stdout``.

    The run keeps one machine and applies the step function's transitions to
    it one after another (``execute_step``), so no state is packed between
    steps.  At a Stop or Break the program pauses: with an ``operator`` stream (stderr)
    the run asks there and reads one line of ``stdin`` — a line restarts the program at
    the next instruction, the end of input leaves it stopped and ends the run; without
    an ``operator`` the run ends at the first Stop.
    """
    m = Machine(program, start_state(program, io_values), ConsoleChooser(stdin))
    for seconds, index, value in input_changes:
        schedule(m, seconds, index, value)      # an input script: changes at virtual times
    output = m.output
    steps = 0
    idle = 0                             # steps in a row that changed nothing
    plain = program.environment_react is None and not program.task_entries
    while m.status == RUNNING or (m.status == STOPPED and operator is not None and
                                  operator_restarts(m, stdin, operator)):
        frames = m.frames
        depth, store, io, tasks = len(frames), m.store, m.io, m.tasks
        top = frames[-1] if frames else None
        m.waiting = False
        interrupts = m.interrupts
        if plain and not (interrupts.table or interrupts.scheduled or interrupts.pending):
            span = run_instruction(m)    # all that execute_step would do here
        else:
            span = execute_step(m)
        if output:
            stdout.write("".join(line + "\n" for line in output))
            stdout.flush()
            output.clear()
        if m.choices:
            m.choices.clear()
        if trace is not None and span is not None:
            trace.write(f"{span}\n")
        if m.status == RUNNING and m.store is store and m.io is io and \
                len(m.frames) == depth and (not depth or m.frames[-1] == top) and \
                m.tasks == tasks:
            idle += 1                    # nothing changed: a wait or a busy loop
            if idle > len(m.tasks):      # ... in every task, one after the other
                _wake(m)
                idle = 0
        else:
            idle = 0
        steps += 1
        if max_steps is not None and steps >= max_steps and m.status == RUNNING:
            raise error(STEP_LIMIT, f"the program was stopped after {max_steps} steps "
                        "(--max-steps)", exit_code=1)
    return RunResult(m.to_state(), steps)


def operator_restarts(m: Machine, stdin: TextIO, operator: TextIO) -> bool:
    """The program stopped at a Stop or Break: ask on ``operator`` and read one line of
    ``stdin`` (the operator presses Start); the end of input leaves it stopped."""
    frame = (m.frames or [stack[-1] for stack in m.tasks if stack] or [None])[-1]
    where = ""
    if frame is not None:
        span = m.program.routines[frame.routine].code[frame.pc].span
        where = f" before {span.file}:{span.line}" if span is not None else ""
    operator.write(f"rapidmc: the program is stopped (Stop/Break){where}; press Enter to "
                   "restart it (end of input: it stays stopped)\n")
    operator.flush()
    if not stdin.readline():
        return False
    m.status = RUNNING
    return True


def _wake(m: Machine) -> None:
    """The program makes no progress: let virtual time pass, or report a deadlock."""
    due = next_event(m.interrupts)
    if due is None or m.interrupts.pending:
        if pending_served(m.program, m.interrupts):
            return                       # a trap is about to run
        frame = (m.frames or [stack[-1] for stack in m.tasks if stack])[-1]
        span = m.program.routines[frame.routine].code[frame.pc].span
        raise error(RUNTIME_ERROR, "deadlock: the program waits for a condition that can never "
                    "become true (inputs keep their --io values in run mode)", span, exit_code=1)
    before = m.io
    advance_to(m, due)
    if m.interrupts.table and m.io != before:
        signal_edges(m, before)          # scripted input changes may order traps


def fault_diagnostic(program: Program, state: State) -> Diagnostic:
    fault = state.fault
    routine_index, pc = fault.instruction
    span = None
    if routine_index >= 0:
        span = program.routines[routine_index].code[pc].span
    name = errno_name(fault.errno)
    detail = error_detail(fault.errno, fault.message or "")
    message = f"uncaught RAPID error {name} (ERRNO {format_num(float(fault.errno))})"
    if detail:
        message += f": {detail}"
    return Diagnostic(RUNTIME_ERROR, one_line(message), span)   # RAPID strings may hold "\0A"
