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

A model whose successors depend on what the search did before (ample sets
whose proviso asks which states were expanded already) offers
``path_system()``: the same model with every transition, whose successors
are a function of the state alone.  Paths through stored states (a
counterexample's steps and labels) are rebuilt on it, since asking the
model again after the search may give another ample set than the search
took (``path_transitions``).
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


def path_system(system: TransitionSystem) -> TransitionSystem:
    """The model on which paths through stored states are rebuilt (see the module
    docstring): ``system.path_system()`` when it offers one, else ``system``."""
    offer = getattr(system, "path_system", None)
    return system if offer is None else offer()


def path_transitions(system: TransitionSystem, state: Hashable,
                     stored_id: Callable[[Hashable], int]) -> list[tuple[Label, int]]:
    """(label, id) of every transition of ``state`` into a stored state (``stored_id``:
    the id of a state, -1 when it is not stored), on ``path_system(system)`` (a
    superset of the transitions the search took: those it did not store lie on no path
    of its graph)."""
    transitions = labelled_successors(path_system(system), state)
    found = []
    for label, target in transitions:
        target_id = stored_id(target)
        if target_id >= 0:
            found.append((label, target_id))
    return found


def transition_label(system: TransitionSystem, before: Hashable, after: Hashable) -> Label:
    """The first label of a transition from ``before`` to ``after`` (a step of a path the
    search stored), on ``path_system(system)``."""
    return next(label for label, state in path_system(system).successors(before)
                if state == after)
