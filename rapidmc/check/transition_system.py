"""What the engine needs to know about a model: states, successors, valuations.

The engine never sees RAPID.  A model is any object with two methods; the
caller also supplies ``valuation(state) -> int`` for the automaton's atoms
(bit ``1 << i`` set exactly when atom ``i`` holds in the state).

Example (a counter modulo 3 that may also stay put)::

    class Counter:
        def initial_states(self):
            return (0,)
        def successors(self, state):
            return (("inc", (state + 1) % 3), ("stay", state))

A state with no successors is a *deadlock*.  Models should avoid them
(finished programs loop on themselves), but the engine copes: it extends
the run by repeating the stuck state (the stutter extension SPIN uses),
labels that step ``STUTTER`` and counts deadlocks in the statistics.
"""
from __future__ import annotations

from typing import Callable, Hashable, Protocol, Sequence, TypeVar

State = TypeVar("State", bound=Hashable)
Label = Hashable
Valuation = Callable[[Hashable], int]


class TransitionSystem(Protocol):
    """A model: initial states and labelled successors, both in deterministic order."""

    def initial_states(self) -> Sequence[Hashable]: ...

    def successors(self, state: Hashable) -> Sequence[tuple[Label, Hashable]]: ...


class _Stutter:
    """The label of the step that repeats a state without successors."""

    _instance = None

    def __new__(cls) -> "_Stutter":
        if cls._instance is None:
            cls._instance = super().__new__(cls)
        return cls._instance

    def __repr__(self) -> str:
        return "STUTTER"

    def __reduce__(self):
        return (_Stutter, ())


STUTTER = _Stutter()


def labelled_successors(system: TransitionSystem, state: Hashable) -> Sequence[tuple[Label, Hashable]]:
    """The successors of ``state``; a deadlocked state repeats itself via ``STUTTER``."""
    successors = as_sequence(system.successors(state))
    if not successors:
        return ((STUTTER, state),)
    return successors


def as_sequence(successors) -> Sequence:
    """``successors`` as a list or tuple (a model may hand back any iterable)."""
    return successors if isinstance(successors, (list, tuple)) else tuple(successors)
