"""Turning an accepting strongly connected component into a short lasso.

When the emptiness search finds an accepting cycle it knows the DFS path
to the component's root and the set of product states in the component.
The prefix is that DFS path; the cycle is a shortest path inside the
component from the root to an accepting state and a shortest path back
(at least one step), both found by breadth-first search.  Labels are
recovered by asking the model again, so the search itself stores none.
"""
from __future__ import annotations

from collections import deque
from typing import Callable, Collection, Hashable, Iterable, Optional

from .product import Product
from .result import LassoStep

LabelledKey = tuple[Optional[Hashable], int]


def shortest_path(successors: Callable[[int], Iterable[LabelledKey]], source: int,
                  is_goal: Callable[[int], bool], allowed: Collection[int],
                  min_steps: int) -> list[LabelledKey]:
    """A shortest path ``[(None, source), (label, key), …]`` to a goal, staying in ``allowed``."""
    if min_steps == 0 and is_goal(source):
        return [(None, source)]
    parents: dict[int, Optional[LabelledKey]] = {source: None}
    queue = deque([source])
    while queue:
        key = queue.popleft()
        for label, successor in successors(key):
            if successor not in allowed:
                continue
            if is_goal(successor):
                return _walk_back(parents, key) + [(label, successor)]
            if successor not in parents:
                parents[successor] = (label, key)
                queue.append(successor)
    raise AssertionError("the component has no path to a goal state")


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


def build_lasso(product: Product, dfs_path: list[int], component: Collection[int]
                ) -> tuple[list[LassoStep], list[LassoStep], Hashable]:
    """(prefix, cycle, closing label) for a component rooted at ``dfs_path[-1]``."""
    root = dfs_path[-1]
    successors = product.labelled_successor_keys
    to_accepting = shortest_path(successors, root, product.is_accepting, component, 0)
    accepting = to_accepting[-1][1]
    back = shortest_path(successors, accepting, lambda key: key == root, component, 1)
    loop = to_accepting + back[1:-1]
    prefix = product.path_steps(dfs_path[:-1], None)
    entry_label = product.label_between(dfs_path[-2], root) if len(dfs_path) > 1 else None
    cycle = [product.lasso_step(key, label) for label, key in loop]
    cycle[0].label = entry_label
    return prefix, cycle, back[-1][0]
