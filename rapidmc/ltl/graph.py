"""Strongly connected components of finite graphs, iteratively (no recursion limit).

Example::

    >>> graph = {1: [2], 2: [1, 3], 3: []}
    >>> sorted(sorted(c) for c in strongly_connected_components([1], graph.__getitem__))
    [[1, 2], [3]]
"""
from __future__ import annotations

from typing import Callable, Hashable, Iterable, Sequence, TypeVar

Node = TypeVar("Node", bound=Hashable)


def strongly_connected_components(roots: Iterable[Node],
                                  successors: Callable[[Node], Sequence[Node]]
                                  ) -> list[list[Node]]:
    """Tarjan's algorithm over the nodes reachable from ``roots``.

    Components come out in reverse topological order (a component is listed
    before every component that can reach it).
    """
    index: dict[Node, int] = {}
    lowlink: dict[Node, int] = {}
    on_stack: set[Node] = set()
    stack: list[Node] = []
    components: list[list[Node]] = []
    for root in roots:
        if root in index:
            continue
        work = [(root, iter(successors(root)))]
        _visit(root, index, lowlink, stack, on_stack)
        while work:
            node, pending = work[-1]
            for successor in pending:
                if successor not in index:
                    _visit(successor, index, lowlink, stack, on_stack)
                    work.append((successor, iter(successors(successor))))
                    break
                if successor in on_stack:
                    lowlink[node] = min(lowlink[node], index[successor])
            else:
                work.pop()
                if work:
                    parent = work[-1][0]
                    lowlink[parent] = min(lowlink[parent], lowlink[node])
                if lowlink[node] == index[node]:
                    components.append(pop_component(node, stack, on_stack))
    return components


def _visit(node, index, lowlink, stack, on_stack) -> None:
    index[node] = lowlink[node] = len(index)
    stack.append(node)
    on_stack.add(node)


def pop_component(root, stack: list, on_stack: set) -> list:
    """Take the component of ``root`` off the Tarjan stack (its members, last pushed first)."""
    component = []
    while True:
        node = stack.pop()
        on_stack.discard(node)
        component.append(node)
        if node == root:
            return component


def is_cyclic(component: Sequence[Node], successors: Callable[[Node], Sequence[Node]]) -> bool:
    """Whether a component holds a cycle (more than one node, or a self-loop)."""
    return len(component) > 1 or component[0] in successors(component[0])
