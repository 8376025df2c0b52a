"""Turning an accepting strongly connected component into a short lasso.

When the emptiness search finds an accepting cycle it knows the DFS path
to the component's root and the set of product states in the component.
The prefix is a shortest path through the explored states into the
component (found by a breadth-first search given a modest budget; the DFS
path when that runs out); the cycle is a shortest path inside the
component from the entry state to an accepting state and a shortest path
back (at least one step), both found by breadth-first search.  Labels are
recovered by asking the model again, so the search itself stores none.
"""
from __future__ import annotations

from collections import deque
from typing import Callable, Collection, Container, Hashable, Iterable, Optional

from .product import Product
from .result import LassoStep

LabelledKey = tuple[Optional[Hashable], int]


def shortest_path(successors: Callable[[int], Iterable[LabelledKey]], sources: Iterable[int],
                  is_goal: Callable[[int], bool], allowed: Container[int], min_steps: int,
                  max_expansions: Optional[int] = None) -> Optional[list[LabelledKey]]:
    """A shortest path ``[(None, source), (label, key), …]`` to a goal, staying in ``allowed``.

    None when there is none, or none within ``max_expansions`` expanded states.
    """
    parents: dict[int, Optional[LabelledKey]] = {}
    for source in sources:
        if min_steps == 0 and is_goal(source):
            return [(None, source)]
        parents.setdefault(source, None)
    queue = deque(parents)
    while queue and (max_expansions is None or max_expansions > 0):
        if max_expansions is not None:
            max_expansions -= 1
        key = queue.popleft()
        for label, successor in successors(key):
            if successor not in allowed:
                continue
            if is_goal(successor):
                return _walk_back(parents, key) + [(label, successor)]
            if successor not in parents:
                parents[successor] = (label, key)
                queue.append(successor)
    return None


def _walk_back(parents: dict[int, Optional[LabelledKey]], key: int) -> list[LabelledKey]:
    """The path from the search source to ``key`` recorded in ``parents``."""
    path: list[LabelledKey] = []
    at = key
    while (parent := parents[at]) is not None:
        label, previous = parent
        path.append((label, at))
        at = previous
    path.append((None, at))
    path.reverse()
    return path


def build_lasso(product: Product, dfs_path: list[int], component: Collection[int],
                explored: Container[int]) -> tuple[list[LassoStep], list[LassoStep], Hashable]:
    """(prefix, cycle, closing label) for a component reached by ``dfs_path``."""
    entry = shortest_entry(product, dfs_path, component, explored)
    root = entry[-1][1]
    successors = product.labelled_successor_keys
    to_accepting = shortest_path(successors, [root], product.is_accepting, component, 0)
    back = to_accepting and shortest_path(successors, [to_accepting[-1][1]],
                                          lambda key: key == root, component, 1)
    if not back:
        raise AssertionError("the accepting component is not strongly connected")
    loop = to_accepting + back[1:-1]
    prefix = [product.lasso_step(key, label) for label, key in entry[:-1]]
    cycle = [product.lasso_step(key, label) for label, key in loop]
    cycle[0].label = entry[-1][0]
    return prefix, cycle, back[-1][0]


def build_bad_prefix(product: Product, dfs_path: list[int],
                     explored: Container[int]) -> list[LassoStep]:
    """The steps of a bad prefix: a shortest path through explored states to a state from
    which every run violates the property (``Product.universal``), else ``dfs_path``, which
    ends in one."""
    ends_bad = _BadEnds(product)
    return [product.lasso_step(key, label) for label, key in
            shortest_entry(product, dfs_path, ends_bad, _ExploredOrBadEnd(explored, ends_bad))]


class _BadEnds:
    """``key in ends_bad``: a product state that ends a bad prefix."""

    def __init__(self, product: Product):
        self.product = product

    def __contains__(self, key: int) -> bool:
        return self.product.is_universal(key)


class _ExploredOrBadEnd:
    """Where the path to a bad end may go: explored states, and the bad end itself (the
    search notes one when it sees it, before storing it)."""

    def __init__(self, explored: Container[int], ends_bad: _BadEnds):
        self.explored = explored
        self.ends_bad = ends_bad

    def __contains__(self, key: int) -> bool:
        return key in self.explored or key in self.ends_bad


def shortest_entry(product: Product, dfs_path: list[int], component: Container[int],
                    explored: Container[int]) -> list[LabelledKey]:
    """A shortest path through explored states into the component, else the DFS path.

    The breadth-first search asks the model again for every state it
    expands, so it may expand only a few times as many states as the DFS
    path is long (the DFS path costs one expansion per step to label).
    """
    limit = 4 * len(dfs_path) + 1000
    entry = shortest_path(product.labelled_successor_keys, product.initial_keys(),
                          component.__contains__, explored, 0, limit)
    if entry is not None and len(entry) <= len(dfs_path):
        return entry
    labels = [None] + [product.label_between(before, after)
                       for before, after in zip(dfs_path, dfs_path[1:])]
    return list(zip(labels, dfs_path))
