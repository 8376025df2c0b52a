"""Plain steps: the successors of a state where only the program's own instruction runs.

Most states a check meets are *plain*: one task, no interrupt connected,
pending or scheduled, no environment reaction, and no free input stored
in states (inputs are chosen where they are read).  A transition from such
a state is the instruction at the program counter, then the merge points
after it (``reduction.merging``).  ``plain_successors`` gives exactly the
transitions of the general driver (``step.successors``: ``enumerate_choices``
over ``step``), in the same order, with less machinery: one loop over the
choice scripts, the instruction looked up once, and merged runs steered by
one table per routine (``CheckConfig.merge_table``).
tests/test_plain_step.py compares both drivers on whole state graphs.
"""
from __future__ import annotations

from .choosers import CheckConfig, ScriptChooser
from .errors import RapidError, errno_name
from .errors_flow import deliver_error
from .instructions import ReRaise
from .lazy_inputs import InputView
from .machine import Machine
from .state import RUNNING, State, Transition

_new_tuple = tuple.__new__
MERGED_STEP_LIMIT = 10_000


def is_plain(program, state: State, config: CheckConfig) -> bool:
    """Whether ``plain_successors`` may stand in for the general driver at ``state``."""
    if state[10] or config.free_inputs or program.environment_react is not None:
        return False                     # tasks, stored inputs, an environment reaction
    interrupts = state[4]                # (table, pending, enabled, scheduled)
    return not (interrupts[0] or interrupts[1] or interrupts[3])


def plain_successors(program, state: State, config: CheckConfig) -> list[Transition]:
    """Every transition from a running plain state (``is_plain``), in the general order."""
    frames = state.frames
    frame = frames[-1]
    instruction = program.routines[frame[0]].code[frame[1]]
    lazy = config.lazy_inputs
    table = config.merge_table(program) if config.merge_points else None
    result = []
    script = []
    while script is not None:
        chooser = ScriptChooser(script, config)
        m = Machine(program, state, chooser)
        if lazy:
            m.io = InputView(m.io, lazy, m)
            m.lazy_values = {}
        execute(m, instruction)
        span = instruction.span
        if table is not None and m.status == RUNNING:
            span = run_merged(m, table, frames, span)
        output = "".join(line + "\n" for line in m.output) if m.output else ""
        result.append(_new_tuple(Transition, (tuple(m.choices), span, m.to_state(), output,
                                              m.waiting)))
        script = chooser.next_script()
        if script is not None:
            config.time_check()
    return result


def run_instruction(m: Machine):
    """Execute the instruction at the program counter; errors go to their handler."""
    frame = m.frames[-1]
    instruction = m.program.routines[frame.routine].code[frame.pc]
    execute(m, instruction)
    return instruction.span


def execute(m: Machine, instruction) -> None:
    """Execute ``instruction`` on ``m``; a RAPID error goes to its handler."""
    try:
        instruction.run(m)
    except RapidError as exc:
        deliver_error(m, exc.errno, str(exc))
    except ReRaise as exc:
        deliver_error(m, exc.errno, errno_name(exc.errno), from_handler=True)


def run_merged(m: Machine, table: dict, frames_before: tuple, span):
    """Go on executing merge points (see ``reduction.merging``) within this transition.

    ``table`` (``CheckConfig.merge_table``) gives per routine the merge
    points' kind per pc (plus 4 where a signal may be read): 0
    invisible, 1 visible, 2 invisible loop head (never joins), 3 never
    joins.  At most one visible instruction runs per transition (the first
    one counts as visible unless it is of kind 0 or 2), and no instruction
    that may read a signal joins once a choice was made (each combination
    of choices re-runs the whole transition).  Loop heads never join, so
    the program counter only grows while merging.  Returns the span of the
    step, or the tuple of every span executed when more than one
    instruction ran.  Stops as soon as the program waits, stops, raises,
    calls or returns, or has interrupts or tasks.
    """
    if not frames_before:
        return span
    frame = frames_before[-1]
    entry = table.get(frame[0])
    seen_visible = entry is None or entry[0][frame[1]] & 3 in (1, 3)
    spans = None
    errno = m.errno
    depth = len(m.frames)                # calls and returns never join: it stays
    for _ in range(MERGED_STEP_LIMIT):
        frames = m.frames
        if m.status != RUNNING or m.waiting or m.tasks or m.errno != errno or \
                len(frames) != depth:
            break
        interrupts = m.interrupts
        if interrupts.table or interrupts.pending or interrupts.scheduled:
            break
        frame = frames[-1]
        entry = table.get(frame[0])
        if entry is None:
            break
        kinds, code = entry
        pc = frame[1]
        kind = kinds[pc]
        if kind & 2 or frame[3] != 0:
            break                            # a loop head, never joins, or in a handler
        if kind & 1:
            if seen_visible:
                break
            seen_visible = True
        if kind & 4 and m.choices:
            break                            # one choice point per transition (as in SPIN)
        if m.lazy_values is not None:
            m.lazy_values = {}               # each instruction reads inputs afresh
        instruction = code[pc]
        execute(m, instruction)
        if spans is None:
            spans = [span]
        spans.append(instruction.span)
    return span if spans is None else tuple(spans)
