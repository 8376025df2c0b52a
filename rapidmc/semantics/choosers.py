"""Choosers: how a step resolves nondeterminism, and the choices a check allows.

``Chooser`` (run mode: first value, virtual time) and ``ScriptChooser``
(check mode: follows a script of choice indices and records the domain
sizes met, so ``next_script`` can enumerate every combination) are handed
to the step function; ``CheckConfig`` holds what a check lets vary (answer
domains, free inputs stored or chosen where read, merge points).
"""
from __future__ import annotations

import copy
import itertools
from typing import Optional

from .machine import Machine
from .program import Program
from .values import signal_value


class Chooser:
    """Base chooser: how a step resolves nondeterminism and time."""

    check_mode = False

    def choose(self, name: str, domain: tuple, position: int):
        return domain[0]

    def tp_answers(self, kind: str) -> tuple:
        raise NotImplementedError

    def wait_times_out(self, m: Machine, max_time: float) -> bool:
        return False

    def advance_time(self, m: Machine, seconds: float) -> None:
        pass

    def free_inputs(self, program: Program) -> tuple:
        return ()


class ScriptChooser(Chooser):
    """Check mode: follows a script of choice indices, records the domain sizes met."""

    check_mode = True

    def __init__(self, script: list, config: "CheckConfig", inputs: bool = True):
        self.script = script
        self.sizes: list[int] = []
        self.config = config
        self.inputs = inputs

    def choose(self, name: str, domain: tuple, position: int):
        self.sizes.append(len(domain))
        if position < len(self.script):
            return domain[self.script[position]]
        return domain[0]

    def tp_answers(self, kind: str) -> tuple:
        if kind == "TPReadFK":
            return self.config.fk_answers
        return self.config.tp_answers

    def wait_times_out(self, m: Machine, max_time: float) -> bool:
        return m.choose("timeout", (False, True))

    def free_inputs(self, program: Program) -> tuple:
        return self.config.free_inputs if self.inputs else ()

    def next_script(self) -> Optional[list]:
        return next_script(self.script, self.sizes)


def next_script(script: list, sizes: list) -> Optional[list]:
    """The script after ``script``, whose run met choices of ``sizes`` values: the last
    choice that has a next value takes it, the choices before it stay, those after it
    start again (None: every combination done)."""
    known = len(script)
    for i in range(len(sizes) - 1, -1, -1):
        current = script[i] if i < known else 0
        if current + 1 < sizes[i]:
            return script[:i] + [0] * (i - known) + [current + 1]
    return None


def no_time_limit() -> None:
    """``CheckConfig.time_check`` when no search sets one."""


class CheckConfig:
    """Model-checking choices: answer domains and which inputs are free."""

    def __init__(self, program: Program, tp_answers=(1.0, 2.0, 3.0),
                 fk_answers=(1.0, 2.0, 3.0, 4.0, 5.0), input_domains: Optional[dict] = None,
                 observed: Optional[set] = None):
        """``observed``: indices of the free inputs properties look at; the others are
        chosen when read (see lazy_inputs).  None: every free input is stored."""
        self.tp_answers = tuple(float(a) for a in tp_answers)
        self.fk_answers = tuple(float(a) for a in fk_answers)
        domains = input_domains or {}
        free = []
        lazy = {}
        for signal in program.signals:
            # an input, or an output no loaded code sets (load.outside_outputs)
            if signal.driven or not (signal.kind.endswith("I") or signal.outside):
                continue
            if signal.kind in ("DI", "DO"):
                domain = (0.0, 1.0)
            elif signal.key in domains:
                domain = tuple(dict.fromkeys(signal_value(signal.kind, value)
                                             for value in domains[signal.key]))
            else:
                continue
            if observed is None or signal.index in observed:
                free.append((signal.index, signal.name, domain))
            else:
                lazy[signal.index] = (signal.name, domain)
        self.free_inputs = tuple(free)
        self.lazy_inputs = lazy
        # stored inputs that only interrupts watch: index -> whether both edges are
        # watched; every state after a step keeps them at 0 (``model.edge_inputs``);
        # empty: the exact model
        self.edge_inputs: dict = {}
        # those of them some task's interrupts watch: an edge starts a TRAP of the task
        # whose step brings it or is dropped (``edge_traps``)
        self.served_edges: tuple = ()
        # those of them several tasks' interrupts watch: each task's step chooses its own
        # edge (``edge_inputs.shared_edges``)
        self.shared_edges: tuple = ()
        # stored digital inputs put at rest where no active interrupt watches them: index ->
        # name (``resting_inputs``); empty: every value stored, exact
        self.resting_inputs: dict = {}
        # a step leaves those and the edge inputs unchosen where it reads no signal and no
        # active interrupt watches them (``unread_inputs``); False: every step chooses every
        # value
        self.inputs_where_read = False
        self.input_choices = None        # (program, unread_inputs.InputChoices)
        # the fair search's: a task's steps that change nothing stay even where another
        # task can go on (``staged_step.idle_steps_dropped`` keeps them; ``with_idle_steps``)
        self.idle_steps_kept = False
        self._with_idle = None           # the copy ``with_idle_steps`` made
        # called between two runs of one step with different choices: the search engine's
        # ``check.budget.time_check`` raises there once the running search's time is up,
        # so a step with thousands of successors cannot run far past the time limit
        self.time_check = no_time_limit
        # the coverage probe's: controller readings read any value of their domain
        # (library.probed_readings); never for verdicts
        self.free_readings = False
        # ... and, in a program that tells them apart, CRobT and CJointT read the external
        # axes connected too (library.position)
        self.axes_probed = False
        # the readings probes': the robot may start at these robtargets besides home
        # (findings.start_positions; model.rapid_system.RapidSystem.initial_states)
        self.start_targets: tuple = ()
        # the closure probe's: SocketBind may find its port taken (library.sockets)
        self.socket_setup_failures = False
        # moves leave the robot where it is: nothing but moves reads its position
        # (model.robot_tracking decides; semantics.robots.robot_tracked)
        self.robot_untracked = False
        # (routine, pc) -> visible, for instructions that join the step before them
        # (reduction.merging); empty: one instruction per step
        self.merge_points: dict = {}
        self._merge_table = None         # (merge_points, program, table): see merge_table
        self.fused = None                # (merge_points, program, skipped_writes,
                                         # routines): fused_step's
        # spans of assignments to sliced data the fused step may skip when only the
        # projected target states are wanted (``reduction.relevance``, total_writes)
        self.skipped_writes: frozenset = frozenset()
        self._unmerged = None            # (merge_points, copy without them): see unmerged
        self.view_steps = None           # staged_step's remembered steps (ViewSteps)
        # every combination of free input values, in the order the chooser enumerates them
        self.input_valuations = tuple(itertools.product(*(d for _, _, d in free)))
        # per valuation: pvector.mset arguments and the label part naming the values
        self.input_assignments = tuple(
            tuple(x for (index, _, _), value in zip(free, valuation) for x in (index, value))
            for valuation in self.input_valuations)
        self.input_labels = tuple(
            tuple((name, value) for (_, name, _), value in zip(free, valuation))
            for valuation in self.input_valuations)

    def with_inputs_held(self) -> "CheckConfig":
        """A copy in which the inputs stored at every step (those an interrupt or a
        property watches: ``free_inputs``) keep their present value, so no interrupt on a
        signal fires; inputs read when read stay free.  An environment whose signals stay
        put is one a cell allows, so every state this copy reaches is reachable: a coverage
        probe uses it when the inputs' changes at every step make its search too broad."""
        held = copy.copy(self)
        held.free_inputs = ()
        held.resting_inputs = {}
        held.input_choices = None
        held.input_valuations = ((),)
        held.input_assignments = ((),)
        held.input_labels = ((),)
        held._merge_table = held.fused = held._unmerged = held.view_steps = None
        held._with_idle = None
        return held

    def with_idle_steps(self) -> "CheckConfig":
        """A copy whose successors keep every task's steps that change nothing (a task
        waiting for an input value it may never get), made once: which tasks could take
        such a step, for the fair search (``fairness.TaskFairness.excused``)."""
        if self.idle_steps_kept:
            return self
        if self._with_idle is None:
            kept = copy.copy(self)
            kept.idle_steps_kept = True
            kept._with_idle = None
            self._with_idle = kept
        return self._with_idle

    def unmerged(self) -> "CheckConfig":
        """This configuration without merge points (one instruction per step), made once
        per merge points."""
        if not self.merge_points:
            return self
        cached = self._unmerged
        if cached is None or cached[0] is not self.merge_points:
            plain = copy.copy(self)
            plain.merge_points = {}
            plain._merge_table = plain.fused = plain._unmerged = plain.view_steps = None
            plain._with_idle = None
            cached = self._unmerged = (self.merge_points, plain)
        return cached[1]

    def merge_table(self, program: Program) -> dict:
        """``merge_points`` with what a merged run looks up per pc: routine index ->
        (kinds, code), where a kind gains 4 when its instruction may read a signal or
        choose a value of data written from outside (``Instruction.chooses``).
        Derived once per merge points and program (copies of the config that change
        ``merge_points`` derive their own)."""
        cached = self._merge_table
        if cached is not None and cached[0] is self.merge_points and cached[1] is program:
            return cached[2]
        table = {}
        for index, kinds in self.merge_points.items():
            code = program.routines[index].code
            table[index] = (bytes(kind | (4 if instruction.reads_io or instruction.chooses
                                          else 0)
                                  for kind, instruction in zip(kinds, code)), code)
        self._merge_table = (self.merge_points, program, table)
        return table
