"""The reachable state graph of a RAPID program as a networkx graph.

``state_graph(model)`` explores the program's transition system breadth
first (``find_reachable`` looking for nothing, so the usual bounds apply)
and records every state and transition: a ``networkx.MultiDiGraph`` whose
nodes are numbered in discovery order (0 is the first initial state) and
carry

* ``location``: ``file:line`` of the statement the main task executes next
  (``ended`` / ``failed`` once it has stopped), ``routine`` its routine;
* ``tasks``: the same for further tasks, ``task: file:line`` joined by ``; ``;
* ``changed``: the data, signals and robot items whose value differs from
  the first initial state, ``name = value`` joined by ``; ``;
* ``initial`` and, for the product, ``automaton_state`` and ``accepting``;

and whose edges carry ``line`` (``file:line`` executed), ``source``,
``inputs`` (``name = value`` joined by ``; ``) and ``output``.  With a
property, ``product_graph`` records the product with the automaton of the
property's negation instead (the graph the emptiness search explores).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Hashable, Optional, Sequence

import networkx as nx

from ..check import find_reachable
from ..check.budget import DEFAULT_MAX_STATES
from ..check.transition_system import labelled_successors
from ..check.product import Product
from ..check.store import ModelStore
from ..semantics.state import ENDED, FAILED, STOPPED

SEPARATOR = "; "


@dataclass
class StateGraph:
    graph: nx.MultiDiGraph
    complete: bool
    reason: Optional[str]        # the bound that stopped the search, when not complete

    def summary(self) -> dict[str, int]:
        """States, edges, strongly connected components (all, and those with a cycle), terminal states."""
        graph = self.graph
        components = list(nx.strongly_connected_components(graph))
        cyclic = [c for c in components if len(c) > 1 or graph.has_edge(*(2 * [next(iter(c))]))]
        terminal = [n for n in graph if all(target == n for _, target in graph.out_edges(n))]
        return {"states": graph.number_of_nodes(), "edges": graph.number_of_edges(),
                "components": len(components), "cyclic_components": len(cyclic),
                "terminal": len(terminal)}


class _Recorder:
    """Observer of the breadth-first search: numbers states, adds nodes and edges."""

    def __init__(self, describe_node, describe_edge):
        self.graph = nx.MultiDiGraph()
        self.ids: dict[Hashable, int] = {}
        self.describe_node = describe_node
        self.describe_edge = describe_edge

    def node(self, state: Hashable) -> int:
        number = self.ids.get(state)
        if number is None:
            number = self.ids[state] = len(self.ids)
            self.graph.add_node(number, **self.describe_node(state))
        return number

    def __call__(self, state: Hashable, successors: Sequence[tuple[Hashable, Hashable]]) -> None:
        source = self.node(state)
        for label, target in successors:
            self.graph.add_edge(source, self.node(target), **self.describe_edge(label))


def state_graph(model, max_states: Optional[int] = DEFAULT_MAX_STATES,
                max_seconds: Optional[float] = None, progress=None) -> StateGraph:
    """The program's reachable states and transitions (``model``: an ``api.Model``)."""
    views = _Views(model)
    recorder = _Recorder(views.state, views.transition)
    return _explore(_Deadlocks(model.system), recorder, max_states, max_seconds, progress)


def product_graph(model, property_name: str, max_states: Optional[int] = DEFAULT_MAX_STATES,
                  max_seconds: Optional[float] = None, progress=None) -> StateGraph:
    """The product of the program with the automaton of the property's negation."""
    _, buchi, valuation = next(job for job in model.jobs if job[0].name == property_name)
    product = Product(ModelStore(model.system, valuation), buchi)
    views = _Views(model)

    def describe(key: int) -> dict:
        state_id, automaton_state = product.split(key)
        return {**views.state(product.store.states[state_id]),
                "automaton_state": automaton_state,
                "accepting": product.is_accepting(key)}

    recorder = _Recorder(describe, views.transition)
    return _explore(_ProductSystem(product), recorder, max_states, max_seconds, progress)


def _explore(system, recorder: _Recorder, max_states, max_seconds, progress) -> StateGraph:
    for state in system.initial_states():
        recorder.node(state)
        recorder.graph.nodes[recorder.ids[state]]["initial"] = True
    result = find_reachable(system, lambda state: False, observe=recorder, progress=progress,
                            max_states=max_states, max_seconds=max_seconds)
    for number in recorder.graph:
        recorder.graph.nodes[number].setdefault("initial", False)
    return StateGraph(recorder.graph, result.reason is None, result.reason)


class _Deadlocks:
    """The program's system, a state without successors repeating itself (as in the checker)."""

    def __init__(self, system):
        self.system = system

    def initial_states(self):
        return self.system.initial_states()

    def successors(self, state):
        return labelled_successors(self.system, state)


class _ProductSystem:
    """A product as a transition system over its integer keys."""

    def __init__(self, product: Product):
        self.product = product

    def initial_states(self):
        return self.product.initial_keys()

    def successors(self, key: int):
        return self.product.labelled_successor_keys(key)


class _Views:
    """Node and edge attributes in RAPID terms (``RapidDescriber`` plus locations)."""

    def __init__(self, model):
        self.program = model.program
        self.describer = model.describer
        self.first: Optional[dict] = None

    def state(self, state) -> dict:
        view = dict(self.describer.describe_state(state))
        if self.first is None:
            self.first = view
        changed = [f"{name} = {value}" for name, value in view.items()
                   if self.first.get(name) != value]
        location, routine = self._location(state.frames, state.status)
        tasks = [f"{name}: {self._location(stack, None)[0]}"
                 for name, stack in zip(self.program.task_names[1:], state.tasks)]
        return {"location": location, "routine": routine, "tasks": SEPARATOR.join(tasks),
                "changed": SEPARATOR.join(changed)}

    def _location(self, frames, status) -> tuple[str, str]:
        if status == ENDED:
            return "ended", ""
        if status == FAILED:
            return "failed", ""
        if status == STOPPED:
            location, routine = self._location(frames, None)
            return f"stopped before {location}", routine
        if not frames:
            return "ended", ""
        routine = self.program.routines[frames[-1].routine]
        span = routine.code[frames[-1].pc].span
        return (f"{span.file}:{span.line}" if span else "", routine.name)

    def transition(self, label) -> dict:
        if not isinstance(label, tuple):                 # STUTTER: a state without successors
            return {"line": "", "source": "(stays: no successor)", "inputs": "", "output": ""}
        info = self.describer.describe_transition(label)
        inputs = SEPARATOR.join(f"{name} = {value}" for name, value in info.inputs.items())
        return {"line": info.location, "source": info.source, "inputs": inputs,
                "output": info.output or ""}
