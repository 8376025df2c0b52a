"""The linked, checked and compiled form of a RAPID program.

``link.build`` turns an ``ast.Program`` into a ``Program``: global data get
slots in the state's store, routines get instruction lists (``code``), and
physical I/O signals get indices in the state's ``io`` vector.  A
``Program`` never changes while the program runs; everything that changes
is in ``State``.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Optional

from ..ast import Span
from .types import AnyType
from .values import to_num

PROGRAM_NAMESPACE = 0
ENVIRONMENT_NAMESPACE = 1
FIRST_TASK_NAMESPACE = 2       # further RAPID tasks running beside the main task


@dataclass
class GlobalData:
    """A module-level VAR or PERS data object (a slot of ``State.store``)."""

    slot: int
    name: str
    key: str
    type: AnyType
    storage: str                  # VAR or PERS
    module: str
    namespace: int
    local: bool
    span: Span
    initial: Any = None           # initial value (computed at link time)
    declared_without_value: bool = False
    task_local: bool = False      # TASK PERS: not shared with other tasks
    # where its value comes from when another task's declaration gives it (``task T
    # (file:line)``: a task not loaded, ``Linker._values_declared_elsewhere``), else None
    initial_from: Optional[str] = None

    @property
    def is_task_list(self) -> bool:
        """A list of tasks (``tasks``): it names the controller's tasks for a barrier, and
        no PC or task rewrites it in a running cell."""
        return getattr(self.type, "element", self.type).key == "TASKS"


@dataclass
class Parameter:
    name: str
    key: str
    type: AnyType
    mode: str                     # IN, VAR, INOUT, PERS
    optional: bool
    group: Optional[int]
    rank: int                     # {*} array rank, 0 for scalars
    slot: int
    span: Span

    @property
    def by_reference(self) -> bool:
        return self.mode != "IN"

    def convert(self, value: Any) -> Any:
        """An IN argument as the parameter holds it (num arguments rounded to num)."""
        if getattr(self.type, "key", "") == "NUM" and type(value) is float:
            return to_num(value)
        return value

    @property
    def is_switch(self) -> bool:
        return getattr(self.type, "key", "") == "SWITCH"


@dataclass
class Routine:
    index: int
    name: str
    key: str
    kind: str                     # PROC, FUNC, TRAP
    module: str
    namespace: int
    local: bool
    span: Span
    end_span: Span
    return_type: Optional[AnyType] = None
    parameters: tuple = ()
    local_names: list = field(default_factory=list)   # display names of local slots
    local_count: int = 0
    data_init: list = field(default_factory=list)     # (slot, fn(machine) -> value) for routine data
    code: list = field(default_factory=list)          # instructions
    handler_pc: int = -1                              # first instruction of the ERROR handler
    handler_numbers: Optional[frozenset] = None       # ERROR (n1, ...) list; None = catch all
    handler_slots: tuple = ()                         # global slots of errnum data in the list
    undo_pc: int = -1
    ast: Any = None
    initial: list = field(default_factory=list)       # initial value of each local slot
    initial_locals: tuple = ()                        # frozen copy of ``initial`` used by calls
    loop_counters: list = field(default_factory=list)  # (slot, first pc, last pc) of each FOR

    def hidden_slots(self, pc: int) -> frozenset:
        """Local slots whose names other slots of this routine share, hidden at ``pc``.

        A FOR counter is a slot of its own and may share its name with routine data or with
        the counters of the routine's other FOR loops (``FOR i`` in three CASEs).  At ``pc``
        the name means the innermost FOR whose code holds ``pc``, else the routine data of
        that name, else the first FOR counter; the other slots of the name are hidden.
        """
        names: dict[str, list[int]] = {}
        for slot, name in enumerate(self.local_names):
            if not name.startswith("<"):
                names.setdefault(name.upper(), []).append(slot)
        counters = {slot: (first, last) for slot, first, last in self.loop_counters}
        hidden = set()
        for slots in names.values():
            if len(slots) < 2:
                continue
            holding = [slot for slot in slots if slot in counters
                       and counters[slot][0] <= pc <= counters[slot][1]]
            declared = [slot for slot in slots if slot not in counters]
            if holding:
                shown = max(holding, key=lambda slot: counters[slot][0])
            else:
                shown = (declared or slots)[0]
            hidden.update(slot for slot in slots if slot != shown)
        return frozenset(hidden)

    def add_local(self, name: str, initial: Any) -> int:
        """A new frame slot (parameter, routine data, FOR variable or temporary)."""
        self.local_names.append(name)
        self.initial.append(initial)
        self.local_count = len(self.initial)
        self.initial_locals = tuple(self.initial)
        return self.local_count - 1

    def new_temporary(self, count: int = 1, name: str = "", initial: Any = 0.0) -> int:
        first = self.add_local(name or f"<tmp{self.local_count}>", initial)
        for _ in range(count - 1):
            self.add_local(f"<{name}:hidden>", 0.0)
        return first

    def convert_result(self, value: Any) -> Any:
        if self.return_type is not None and getattr(self.return_type, "key", "") == "NUM":
            return to_num(value)
        return value


@dataclass
class Signal:
    """A physical I/O signal (configured in the controller, named by AliasIO)."""

    index: int
    name: str
    key: str
    kind: str                     # DI, DO, AI, AO, GI, GO
    driven: bool = False          # an environment module drives it (inputs only)
    span: Optional[Span] = None
    # an output no loaded code sets, read like a free input: who sets it (load.outside_outputs)
    outside: Optional[str] = None
    # an output the loaded code sets and a party left out sets too: who (a WaitDO on it may
    # end at any try: load.outside_outputs.outputs_set_by_both), else None
    also_set_by: Optional[str] = None
    # with no I/O configuration loaded, the signal an AliasIO names only at run time
    # (``AliasIO prefix + side, alias``) when the name is no signal the program names:
    # the name expression's place, ``file:line`` (``library.signals``), else None
    named_at_run_time: Optional[str] = None


@dataclass
class Program:
    routines: list[Routine]
    globals: list[GlobalData]
    signals: list[Signal]
    entry: int
    environment_init: Optional[int] = None
    environment_react: Optional[int] = None
    files: tuple = ()
    options: dict = field(default_factory=dict)
    signal_index: dict = field(default_factory=dict)       # key -> Signal
    alias_sources: dict = field(default_factory=dict)      # AliasIO calls (link.Linker)
    routine_index: dict = field(default_factory=dict)      # (namespace, key) -> routine index (global)
    scopes: Any = None                                     # name resolution for atoms
    environment_reads_io: bool = False                     # some environment code reads signals
    task_entries: tuple = ()                               # entry routines of further tasks
    task_names: tuple = ("main task",)                     # one name per task, main task first
    motion_tasks: tuple = ()                               # numbers of the tasks that move a robot
    # the state keeps one robot per task (two or more motion tasks: semantics.robots)
    robot_per_task: bool = False
    # each task keeps its own ERRNO, INTNO and IEnable flag (further tasks: task_registers)
    registers_per_task: bool = False
    # some code reads another task's robot (CRobT(\\TaskName:=...)) while each motion task
    # keeps its own: its steps need every task's robot (general driver, Machine.robots)
    reads_task_robots: bool = False
    load_notes: tuple = ()                                 # Diagnostics about what was loaded
    # indices of the signals the code names; None: unknown (AliasIO of a computed name)
    named_signals: Optional[frozenset] = None
    # PERS written from outside the loaded code, read as choices: slot -> OutsideData
    outside_data: dict = field(default_factory=dict)
    # slots of that data a wait reads whole at its stored value (too many combinations)
    whole_reads_fixed: frozenset = frozenset()
    # slots of that data -> the spans of its reads that take only an array's indexes
    # (``ExpressionCompiler._outside_index``)
    outside_indexes: dict = field(default_factory=dict)
    # results of analyses of the whole linked program that several findings ask for
    # (name -> result): a big backup's walks are seconds each, and the code does not
    # change once linked
    analyses: dict = field(default_factory=dict, repr=False, compare=False)

    def signal(self, key: str) -> Optional[Signal]:
        return self.signal_index.get(key)
