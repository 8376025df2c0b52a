"""Each task's ERRNO, INTNO and interrupt enable flag (IEnable / IDisable).

On a controller every RAPID program task runs with its own system variables
ERRNO (the task's last error) and INTNO (the interrupt whose TRAP the task
runs), and IEnable and IDisable enable or disable the interrupts of the task
that executes them, never another task's.

A program of one task keeps them as it always did: ``State.errno`` and
``State.intno`` are numbers and ``Interrupts.enabled`` is a bool.  A program
with further tasks (``Program.registers_per_task``) keeps one of each per
task, in task order (the main task first): ``State.errno`` and ``State.intno``
are tuples of numbers and ``Interrupts.enabled`` a tuple of bools.  A step of
task T sees T's own as the plain values (``task_view``) and puts them back
(``put_back``), as each motion task's robot is kept (``semantics.robots``);
the instructions themselves never know there are several.
"""
from __future__ import annotations

from .state import Interrupts

_new_tuple = tuple.__new__

# the name under which reports show a task's ERRNO (``T_ROB2.ERRNO`` with several tasks)
ERRNO_NAME = "ERRNO"


def names_errno(name: str) -> bool:
    """Whether a report's component ``name`` is an ERRNO: ``ERRNO`` or ``<task>.ERRNO``."""
    return name == ERRNO_NAME or name.endswith("." + ERRNO_NAME)


def initial_registers(program) -> tuple:
    """(ERRNO, INTNO, enabled) of the start state."""
    if program.registers_per_task:
        count = len(program.task_entries) + 1
        return (0.0,) * count, (0.0,) * count, (True,) * count
    return 0.0, 0.0, True


def task_view(program, interrupts: Interrupts, errno, intno, task: int) -> tuple:
    """(interrupts, ERRNO, INTNO) as task ``task`` sees them: its own flag and numbers."""
    if not program.registers_per_task:
        return interrupts, errno, intno
    return (_new_tuple(Interrupts, (interrupts[0], interrupts[1], interrupts[2][task],
                                    interrupts[3])),
            errno[task], intno[task])


def put_back(program, interrupts_before: Interrupts, errno_before, intno_before, task: int,
             interrupts: Interrupts, errno, intno) -> tuple:
    """(interrupts, ERRNO, INTNO) of the state after task ``task``'s step, from the state's
    before it (``*_before``, every task's) and the values the step left in its view."""
    if not program.registers_per_task:
        return interrupts, errno, intno
    enabled = _with(interrupts_before[2], task, interrupts[2])
    if enabled is interrupts_before[2] and interrupts[0] is interrupts_before[0] and \
            interrupts[1] is interrupts_before[1] and interrupts[3] is interrupts_before[3]:
        interrupts = interrupts_before
    else:
        interrupts = _new_tuple(Interrupts, (interrupts[0], interrupts[1], enabled,
                                             interrupts[3]))
    return interrupts, _with(errno_before, task, errno), _with(intno_before, task, intno)


def _with(values: tuple, task: int, value) -> tuple:
    if values[task] == value:
        return values
    return values[:task] + (value,) + values[task + 1:]


def others_unchanged(program, before, after, task: int) -> bool:
    """Whether a register (ERRNO, INTNO) is the same before and after a step of ``task``
    for every other task: with one register for all (a program of one task), whether it
    is the same."""
    if not program.registers_per_task:
        return before == after
    return before[:task] == after[:task] and before[task + 1:] == after[task + 1:]


def take_task_view(m, task: int) -> tuple:
    """Give the machine ``m`` task ``task``'s view; returns what ``give_back`` needs."""
    before = (m.interrupts, m.errno, m.intno)
    m.interrupts, m.errno, m.intno = task_view(m.program, m.interrupts, m.errno, m.intno, task)
    return before


def give_back(m, task: int, before: tuple) -> None:
    """Put the machine's view of task ``task`` back among every task's (``take_task_view``)."""
    m.interrupts, m.errno, m.intno = put_back(m.program, *before, task, m.interrupts, m.errno,
                                              m.intno)


def pending_served(program, interrupts: Interrupts) -> bool:
    """Whether a pending interrupt may start its TRAP: the task that serves it (or, for
    one whose task is unknown here, any task) has interrupts enabled."""
    enabled = interrupts[2]
    if not program.registers_per_task:
        return bool(interrupts[1]) and enabled
    from .staged_step import interrupt_task
    table = {entry[0]: entry for entry in interrupts[0]}
    for number in interrupts[1]:
        entry = table.get(number)
        if entry is None or enabled[interrupt_task(program, entry)]:
            return True
    return False
