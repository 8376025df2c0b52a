"""Dropping sliced and dead data from states: such values are reset to their initial values.

Two states that differ only in data nothing will read become one stored
state.  Sliced data (``relevance``) is reset everywhere; dead data
(``liveness``) where the program counter says it will be written before
it is read.  The program still computes those values while a step runs
(from the reset values); the analyses guarantee that nothing observable
depends on them, so the next stored state is the same whatever they were.

The resets must also agree along every step: data reset in a state and
not written by the step is reset again in the state after it, or the
stored successor of a projected state would differ from the projection of
the program's own successor, and a counterexample rebuilt on the plain
program (``expansion``) would not reach it.  Dead globals therefore go by
main's program counter whatever runs above main (main waits at its call,
where dead data stays dead until the call returns), not only while main
runs alone.
"""
from __future__ import annotations

from typing import Optional

from ...semantics.program import Program
from ...semantics.state import IN_HANDLER, Frame, State
from .liveness import DeadData
from .relevance import Slicing

_new_tuple = tuple.__new__


class Projection:
    """``project(state)``: the state with sliced and dead data at their initial values."""

    def __init__(self, program: Program, slicing: Slicing, dead: Optional[DeadData] = None):
        initial_global = [data.initial for data in program.globals]
        sliced = set(slicing.globals)
        self.global_resets = _resets(sliced, initial_global)
        # slot -> the object last found equal to its initial value (a state rebuilt from
        # the checker's table holds its own equal object; comparing 512 records is not free)
        self._equal_initial: dict[int, object] = {}
        self.main = program.entry
        self.main_resets: list[tuple] = []
        # main in its ERROR handler: per (pc, start of the statement that raised)
        self.main_handler_resets: dict[tuple, tuple] = {}
        self.final_resets: tuple = self.global_resets
        if dead is not None and dead.globals:
            self.main_resets = [_resets(sliced | set(slots), initial_global)
                                for slots in dead.globals]
            self.main_handler_resets = {node: _resets(sliced | set(slots), initial_global)
                                        for node, slots in dead.handler_globals.items()}
        if dead is not None and dead.final_globals:
            self.final_resets = _resets(sliced | set(dead.final_globals), initial_global)
        self.frame_resets: dict[int, list[tuple]] = {}
        self.handler_frame_resets: dict[int, dict[tuple, tuple]] = {}
        for routine in program.routines:
            always = set(slicing.locals.get(routine.index, ()))
            per_pc = dead.locals.get(routine.index) if dead is not None else None
            per_node = dead.handler_locals.get(routine.index, {}) if dead is not None else {}
            if not always and not per_pc and not per_node:
                continue
            initial = routine.initial_locals
            per_pc_resets = [_resets(always | set(per_pc[pc] if per_pc else ()), initial)
                             for pc in range(max(len(routine.code), 1))]
            handler_resets = {node: _resets(always | set(slots), initial)
                              for node, slots in per_node.items()}
            if any(per_pc_resets) or any(handler_resets.values()):
                self.frame_resets[routine.index] = per_pc_resets
                self.handler_frame_resets[routine.index] = handler_resets
        # rawbytes data only sent that a sliced counter is packed into (``sent_counters``):
        # their contents are reset to zeros, their length kept
        self.blank_globals = tuple(sorted(key[1] for key in slicing.sent_bytes
                                          if key[0] == "G"))
        self.blank_locals: dict[int, tuple] = {}
        for key in sorted(slicing.sent_bytes):
            if key[0] == "L":
                self.blank_locals[key[1]] = self.blank_locals.get(key[1], ()) + (key[2],)
        self.blanks = bool(self.blank_globals or self.blank_locals)

    def keeps_fused_targets(self, sliced: set, written: set, main_stops: set) -> bool:
        """Whether the fused step's targets from projected states are projected already:
        no routine data is ever reset, and every global value reset at a target is sliced
        data (at its initial value in every projected state) that no step writes
        (``written``: the global slots the step may write; ``main_stops``: the pcs of main
        where it may stop).  (A fused step never ends the program: the final resets do
        not apply.)"""
        if self.frame_resets or self.blanks:
            return False
        at_stops = [resets for pc, resets in enumerate(self.main_resets) if pc in main_stops]
        reset = {slot for resets in (self.global_resets, *at_stops) for slot, _ in resets}
        return reset <= sliced and not reset & written

    def __call__(self, state: State) -> State:
        # (the hot path: once per successor; a state that needs no reset is returned as
        # it is after a comparison per reset value, without building anything)
        frames, store, tasks = state[0], state[1], state[10]
        if not frames:
            resets = self.final_resets
        elif self.main_resets and not tasks and frames[0][0] == self.main:
            bottom = frames[0]
            resets = self.main_resets[bottom[1]]
            if bottom[3] == IN_HANDLER:
                resets = self.main_handler_resets.get((bottom[1], bottom[4]), resets)
        else:
            resets = self.global_resets
        equal = self._equal_initial
        for slot, initial in resets:
            value = store[slot]
            if value is initial or value is equal.get(slot):
                continue
            if value != initial:
                store = self._reset_store(store, resets)
                break
            equal[slot] = value
        new_frames, new_tasks = frames, tasks
        if self.frame_resets:
            new_frames, new_tasks = _stacks(self._stack, frames, tasks)
        if self.blanks:
            store, new_frames, new_tasks = self._blank(store, new_frames, new_tasks)
        if store is state[1] and new_frames is frames and new_tasks is tasks:
            return state
        return state._replace(store=store, frames=new_frames, tasks=new_tasks)

    def _blank(self, store, frames: tuple, tasks: tuple) -> tuple:
        """(store, frames, tasks) with the contents of the bytes only sent reset."""
        changes = []
        for slot in self.blank_globals:
            blank = _blank_bytes(store[slot])
            if blank is not None:
                changes += (slot, blank)
        if changes:
            store = store.mset(*changes)
        if self.blank_locals:
            frames, tasks = _stacks(self._blank_stack, frames, tasks)
        return store, frames, tasks

    def _blank_stack(self, frames: tuple) -> tuple:
        result, changed = [], False
        for frame in frames:
            slots = self.blank_locals.get(frame[0])
            if slots:
                values = frame[2]
                blanks = [(slot, _blank_bytes(values[slot])) for slot in slots]
                if any(blank is not None for _, blank in blanks):
                    values = list(values)
                    for slot, blank in blanks:
                        if blank is not None:
                            values[slot] = blank
                    frame = _new_tuple(Frame, (frame[0], frame[1], tuple(values), *frame[3:]))
                    changed = True
            result.append(frame)
        return tuple(result) if changed else frames

    def _reset_store(self, store, resets: tuple):
        """``store`` with each slot of ``resets`` at its initial value (the initial object
        itself: an equal one may differ in the type of a number inside)."""
        equal = self._equal_initial
        changes = []
        for slot, initial in resets:
            value = store[slot]
            if value is initial or value is equal.get(slot):
                continue
            if value == initial:
                equal[slot] = value
            else:
                changes += (slot, initial)
        return store.mset(*changes) if changes else store

    def _stack(self, frames: tuple) -> tuple:
        changed = False
        result = []
        for frame in frames:
            per_pc = self.frame_resets.get(frame[0])
            if per_pc:
                resets = per_pc[frame[1]] if 0 <= frame[1] < len(per_pc) else ()
                if frame[3] == IN_HANDLER:
                    resets = self.handler_frame_resets[frame[0]].get((frame[1], frame[4]),
                                                                     resets)
                values = frame[2]
                if any(values[slot] != initial for slot, initial in resets):
                    values = list(values)
                    for slot, initial in resets:
                        values[slot] = initial
                    frame = _new_tuple(Frame, (frame[0], frame[1], tuple(values), *frame[3:]))
                    changed = True
            result.append(frame)
        return tuple(result) if changed else frames


def _stacks(change, frames: tuple, tasks: tuple) -> tuple:
    """(frames, tasks) with ``change`` applied to the main stack and each task's (the same
    objects where nothing changed)."""
    frames = change(frames)
    if tasks:
        stacks = tuple(change(stack) for stack in tasks)
        if any(a is not b for a, b in zip(stacks, tasks)):
            tasks = stacks
    return frames, tasks


def _blank_bytes(value) -> Optional[bytes]:
    """Zeros as many as the bytes ``value`` holds, or None when it holds no other byte."""
    if isinstance(value, bytes) and value.strip(b"\0"):
        return bytes(len(value))
    return None


def _resets(slots: set, initial) -> tuple:
    return tuple((slot, initial[slot]) for slot in sorted(slots))


