"""Dropping sliced data from states: every sliced value is reset to its initial value.

Two states that differ only in sliced data become one stored state.  The
program still computes sliced values while a step runs (from the reset
values); ``find_slicing`` guarantees that nothing observable depends on
them, so the next stored state is the same whatever they were.
"""
from __future__ import annotations

from ..semantics.program import Program
from ..semantics.state import Frame, State
from .relevance import Slicing

_new_tuple = tuple.__new__


class Projection:
    """``project(state)``: the state with the sliced data at their initial values."""

    def __init__(self, program: Program, slicing: Slicing):
        self.global_resets = tuple((slot, program.globals[slot].initial)
                                   for slot in slicing.globals)
        self.local_resets = {
            index: tuple((slot, program.routines[index].initial_locals[slot]) for slot in slots)
            for index, slots in slicing.locals.items()}

    def __call__(self, state: State) -> State:
        store = self._store(state.store)
        frames = self._stack(state.frames)
        tasks = tuple(self._stack(stack) for stack in state.tasks) if state.tasks else state.tasks
        if store is state.store and frames is state.frames and \
                all(a is b for a, b in zip(tasks, state.tasks)):
            return state
        return state._replace(store=store, frames=frames, tasks=tasks)

    def _store(self, store):
        changes = [x for slot, initial in self.global_resets if store[slot] != initial
                   for x in (slot, initial)]
        return store.mset(*changes) if changes else store

    def _stack(self, frames: tuple) -> tuple:
        if not self.local_resets:
            return frames
        changed = False
        result = []
        for frame in frames:
            resets = self.local_resets.get(frame[0])
            if resets:
                values = frame[2]
                if any(values[slot] != initial for slot, initial in resets):
                    values = list(values)
                    for slot, initial in resets:
                        values[slot] = initial
                    frame = _new_tuple(Frame, (frame[0], frame[1], tuple(values), *frame[3:]))
                    changed = True
            result.append(frame)
        return tuple(result) if changed else frames
