"""A model's whole state graph as a Spot automaton, the engine's reference (no tests here).

``explore(system)`` walks every reachable state of a ``TransitionSystem``
breadth-first with the model's own ``successors`` (the function the
checker calls), and ``kripke_automaton`` turns the graph into a
``spot.twa_graph`` whose language is the set of words the checker reads
on the model's runs (``rapidmc.ltl.buchi`` and ``check.product``: the
word of a run is the valuation of *every* state, starting with the
initial one).  The automaton has one extra start state ``start`` and one
state per model state; the edge into model state ``s`` carries the
valuation of ``s`` (from ``start`` into each initial state, and from each
state into each of its successors), so a run of the automaton reads the
valuations of the model states it visits, in order.  (Labelling each
edge with its *target's* valuation, rather than its source's, needs no
copy of the initial states' edges when there are several initial states,
as an environment's ``init`` can make.)  Every run is accepting
(acceptance ``t``).

Terminal states: a finished RAPID program has a self-loop (its final state
repeats for ever); a state without successors (a deadlock) is given one
too, the stutter extension the engine uses (``check.model``).

``run_of(kripke, negated)`` reads an accepting run of Kripke × automaton
back as a lasso of model-state ids, so that a third method (``holds_on_lasso``) can
judge a word Spot found.
"""
from __future__ import annotations

from collections import deque
from dataclasses import dataclass
from typing import Hashable, Optional, Sequence

import buddy
import spot


@dataclass(frozen=True)
class StateGraph:
    """Reachable states by id (discovery order), initial ids, successor ids per state."""

    states: tuple[Hashable, ...]
    ids: dict[Hashable, int]
    initial: tuple[int, ...]
    successors: tuple[tuple[int, ...], ...]

    def is_run(self, prefix: Sequence[int], cycle: Sequence[int]) -> bool:
        """Whether ``prefix cycle^ω`` (state ids, -1: none) is a run from an initial state."""
        path = list(prefix) + list(cycle)
        return bool(cycle) and path[0] in self.initial and -1 not in path and all(
            after in self.successors[before]
            for before, after in zip(path, path[1:] + [cycle[0]]))


def explore(system) -> StateGraph:
    """Every state reachable from ``system.initial_states()``; a deadlock gets a self-loop."""
    ids: dict[Hashable, int] = {}
    states: list[Hashable] = []
    successors: list[tuple[int, ...]] = []

    def intern(state) -> int:
        if state not in ids:
            ids[state] = len(states)
            states.append(state)
        return ids[state]
    initial = tuple(dict.fromkeys(intern(s) for s in system.initial_states()))
    queue = deque(initial)
    while queue:
        state_id = queue.popleft()
        targets = [target for _, target in system.successors(states[state_id])]
        known = len(states)
        out = tuple(dict.fromkeys(intern(target) for target in targets)) or (state_id,)
        successors.append(out)
        queue.extend(range(known, len(states)))
    return StateGraph(tuple(states), ids, initial, tuple(successors))


def kripke_automaton(graph: StateGraph, atoms: Sequence[str], valuations: Sequence[int]):
    """The words of ``graph``'s runs over ``atoms`` (``valuations[id]``: bit i for atom i)."""
    automaton = spot.make_twa_graph(spot._bdd_dict)
    variables = [automaton.register_ap(atom) for atom in atoms]
    letters = [letter(variables, bits) for bits in valuations]
    start = automaton.new_states(len(graph.states) + 1)
    automaton.set_init_state(start)
    for state_id in graph.initial:
        automaton.new_edge(start, state_id + 1, letters[state_id])
    for state_id, out in enumerate(graph.successors):
        for target in out:
            automaton.new_edge(state_id + 1, target + 1, letters[target])
    return automaton


def letter(variables: Sequence[int], bits: int):
    """The BDD of one full valuation: variable i positive exactly when bit i is set."""
    result = buddy.bddtrue
    for i, variable in enumerate(variables):
        result &= buddy.bdd_ithvar(variable) if bits >> i & 1 else buddy.bdd_nithvar(variable)
    return result


def lasso_word(kripke, atoms: Sequence[str], prefix: Sequence[int], cycle: Sequence[int]):
    """The word ``prefix cycle^ω`` of valuations (bits over ``atoms``) as a Spot automaton."""
    variables = [kripke.register_ap(atom) for atom in atoms]
    word = spot.twa_word(kripke.get_dict())
    for bits in prefix:
        word.prefix.append(letter(variables, bits))
    for bits in cycle:
        word.cycle.append(letter(variables, bits))
    return word.as_automaton()


def run_of(kripke, negated) -> Optional[tuple[list[int], list[int]]]:
    """An accepting run of ``kripke`` × ``negated`` as model-state ids (prefix, cycle)."""
    product = spot.product(kripke, negated)
    run = product.accepting_run()
    if run is None:
        return None
    pairs = product.get_product_states()

    def model_ids(steps) -> list[int]:
        ids = [pairs[product.state_number(step.s)][0] - 1 for step in steps]
        return [state_id for state_id in ids if state_id >= 0]     # drop the start state
    return model_ids(run.prefix), model_ids(run.cycle)
