"""Stored inputs no active interrupt watches: both values kept as one state.

A free digital input that an interrupt order names is stored in every state
(``model.inputs.observed_inputs``): the edge test at the end of a step compares
its stored value with the one the step chose.  Nothing else reads the stored
value: every step chooses each stored input's value afresh before its
instruction runs (``step.execute_step``, ``staged_step``).  And the edge test
looks only at the interrupts active *after* the step (``signal_edges_pending``).
So where no active interrupt watches the input in the state after a step, the
two successors that differ only in the value the step chose for it (the step did
not read it, or read it and did the same) lead to states that behave alike, but
for one thing: a later step that makes an interrupt on the input active
(ISignalDI, IWatch) compares with the value stored.

Such a pair of successors becomes one state, the input holding ``AT_REST``
(``merged_pairs``).  Where the step's outcome depended on the value (it read the
input and took another branch, printed another line), the value stays stored.
A state with an input at rest stands for both states of the exact model, so its
successors are those of both (``with_priors``): the steps that make an interrupt
on it active are taken from the state with the input at 0 and from the state
with it at 1 (the latter labelled ``<input> before = 1``); every other step is the
same from both.  The graph is the exact model's with those pairs of states made
one: every verdict is the exact model's.  ``--exact-edges`` keeps every value
stored (tests/test_resting_inputs.py compares the two).

Kraker1's cell orders its interrupts on five inputs its code also reads, but
connects them only inside the routines that supervise a spindle, a gripper or
a light beam, and sleeps them outside: in its first 1,500 states no interrupt
watched four of the five, and those states were 58 states apart from the
values of the inputs (issue 27).
"""
from __future__ import annotations

import itertools

AT_REST = -1.0          # the stored value of an input at rest (no step reads it)


def watched_inputs(interrupts) -> frozenset:
    """The signals an active interrupt of ``interrupts`` is ordered on."""
    return frozenset(entry[2][1] for entry in interrupts[0]
                     if entry[3] and entry[2] and entry[2][0] in ("signal", "analog"))


def at_rest(state, transitions: list, resting: dict, successors_of) -> list:
    """``transitions`` of ``state`` with the stored inputs ``resting`` (signal index ->
    name) kept at rest where no active interrupt watches them (module docstring);
    ``successors_of(state)``: the driver's transitions of another state."""
    if not resting or not transitions:
        return transitions
    io = state[2]
    marked = [index for index in resting if io[index] == AT_REST]
    if marked:
        transitions = with_priors(state, transitions, marked, resting, successors_of)
    for index, name in resting.items():
        transitions = merged_pairs(transitions, index, name)
    return transitions


def with_priors(state, transitions: list, marked: list, resting: dict,
                successors_of) -> list:
    """The transitions of ``state``, whose inputs ``marked`` are at rest, where a step
    makes an interrupt on one of them active: those of every exact state the rest stands
    for (each such input at 0 or 1), a step from a state with the input at 1 that makes
    an interrupt on it active labelled ``<input> before = 1``, each transition once."""
    activated = sorted({index for transition in transitions
                        for index in watched_inputs(transition[2][4]) if index in marked})
    if not activated:
        return transitions
    io = state[2]
    result, seen = [], set()
    for priors in itertools.product((0.0, 1.0), repeat=len(activated)):
        exact = state._replace(io=io.mset(*[x for pair in zip(activated, priors)
                                            for x in pair]))
        for transition in successors_of(exact):
            now = watched_inputs(transition[2][4])
            label = tuple((f"{resting[index]} before", 1.0)
                          for index, prior in zip(activated, priors)
                          if prior and index in now) + transition[0]
            key = (label, transition[1], transition[2], transition[3])
            if key not in seen:      # (a step that does not activate it: alike from each)
                seen.add(key)
                result.append(transition._replace(label=label))
    return result


def merged_pairs(transitions: list, index: int, name: str) -> list:
    """``transitions`` where each pair that differs only in the value the step chose for
    the input ``index`` (named ``name`` in the label) leads to one state with the input
    at rest, when no active interrupt watches it there."""
    groups: dict = {}
    for position, transition in enumerate(transitions):
        label, after = transition[0], transition[2]
        value = after[2][index]
        if value == AT_REST or (name, value) not in label:
            continue
        key = (tuple((choice, None) if choice == name else (choice, chosen)
                     for choice, chosen in label), transition[1], transition[3])
        groups.setdefault(key, []).append(position)
    result = None
    for positions in groups.values():
        if len(positions) != 2:
            continue
        first, second = transitions[positions[0]][2], transitions[positions[1]][2]
        if first[2][index] == second[2][index] or index in watched_inputs(first[4]):
            continue
        rested = first._replace(io=first[2].set(index, AT_REST))
        if rested != second._replace(io=second[2].set(index, AT_REST)):
            continue                 # the step's outcome depended on the value: stored
        if result is None:
            result = list(transitions)
        for position in positions:
            result[position] = result[position]._replace(state=rested)
    return transitions if result is None else result


def resting_inputs(config, atoms) -> dict:
    """Signal index -> name of the stored inputs a check may put at rest: the digital
    ones (values 0 and 1) that are not edge inputs (``model.edge_inputs``: at 0 after
    every step already) and that no atom reads (an atom sees the stored value)."""
    if atoms.observes_signal_data:
        return {}
    return {index: name for index, name, domain in config.free_inputs
            if tuple(domain) == (0.0, 1.0) and index not in config.edge_inputs
            and index not in atoms.observed}
