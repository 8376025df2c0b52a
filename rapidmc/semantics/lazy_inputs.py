"""Free inputs chosen when they are read, instead of stored in every state.

A free digital input may change between any two steps, so two reads in
different steps are independent choices; only reads within one step must
agree.  When no property observes an input (no atom names it, no interrupt
watches it), its value need not be part of the state at all: the step that
reads it chooses the value (0 or 1, once per step) and the choice appears in
the transition's label.  This removes the factor 2^N of N free inputs from
the state space and branches only where the program actually reads one.

``InputView`` stands in for the machine's ``io`` vector during a check-mode
step: reading a lazy input makes the choice; everything else is passed to
the underlying pyrsistent vector.  Lazy inputs stay 0 in stored states.
"""
from __future__ import annotations


class InputView:
    __slots__ = ("vector", "lazy", "machine")

    def __init__(self, vector, lazy: dict, machine):
        self.vector = vector          # the pvector of signal values
        self.lazy = lazy              # signal index -> (name, domain)
        self.machine = machine

    def __getitem__(self, index: int):
        entry = self.lazy.get(index)
        if entry is None:
            return self.vector[index]
        chosen = self.machine.lazy_values
        value = chosen.get(index)
        if value is None:
            name, domain = entry
            value = self.machine.choose(name, domain)
            chosen[index] = value
        return value

    def set(self, index: int, value) -> "InputView":
        return InputView(self.vector.set(index, value), self.lazy, self.machine)

    def mset(self, *pairs) -> "InputView":
        return InputView(self.vector.mset(*pairs), self.lazy, self.machine)

    def __eq__(self, other) -> bool:
        other_vector = other.vector if isinstance(other, InputView) else other
        return self.vector == other_vector

    def __ne__(self, other) -> bool:
        return not self == other

    def __len__(self) -> int:
        return len(self.vector)

    __hash__ = None


def stored(io):
    """The vector to keep in a state (lazy inputs at their resting value 0)."""
    return io.vector if isinstance(io, InputView) else io
