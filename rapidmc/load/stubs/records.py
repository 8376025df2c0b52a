"""The components of a RECORD the stubs declare, from its names and its shape.

Two kinds of evidence shape a missing record type. The program's uses name
components (``part.length``, ``job.name``), each with a type when the use
tells one. A value declared or assigned whole (``PERS partdata p := [120,
80, "box", TRUE]``) fixes how many components there are and the type of each
position; the record must take that value, so the count is fixed. The names
are then placed onto the positions: a name with a type onto a position of
that type, a name ``c3`` onto the third, in the order of first use where the
types leave a choice; positions no name takes keep the names ``c1``, ``c2``
... Names no position can take (more names than positions, or no position of
their type) are left out and reported, rather than making a record the value
no longer fits (issue 28).

Example::

    >>> from rapidmc.load.stubs.names import TypeInfo
    >>> num, text = TypeInfo("num"), TypeInfo("string")
    >>> same = lambda info, slot: info is None or slot is None or info.key == slot.key
    >>> place([("label", text), ("length", num), ("width", None)], [num, num, text], same)
    {'label': 2, 'length': 0, 'width': 1}
"""
from __future__ import annotations

import re
from typing import Callable, Optional

from .names import TypeInfo

# The components the stubs name after their position in a value (``c1``, ``c2`` ...).
POSITIONAL_COMPONENT = re.compile(r"c[0-9]+")

# The type of a component known only to have components of its own (``g.JointG.extax``):
# it takes a position that holds a record, and that position's type.
SOME_RECORD = TypeInfo("(a record)")


def place(names: list, slots: list, fits: Callable) -> dict:
    """``name -> position`` (0-based) for ``(name, type or None)`` ``names`` onto the
    ``slots`` (types or None): as many names as can be placed, each name in turn on the
    first position that fits and still lets the most names after it be placed. A name
    ``cN`` goes to position N only."""
    edges = {name: sorted((i for i, slot in enumerate(slots)
                           if _allowed(name, info, i, slot, fits)),
                          key=lambda i: info is not None and slots[i] is None)
             for name, info in names}    # a position of the name's type before an unknown one
    order = [name for name, _ in names]
    placed: dict = {}
    free = set(range(len(slots)))
    best = _matching_size(order, free, edges)
    for number, name in enumerate(order):
        rest = order[number + 1:]
        for slot in edges[name]:
            if slot in free and \
                    1 + _matching_size(rest, free - {slot}, edges) == best - len(placed):
                placed[name] = slot
                free.discard(slot)
                break
    return placed


def _allowed(name: str, info, position: int, slot, fits: Callable) -> bool:
    if POSITIONAL_COMPONENT.fullmatch(name):
        return int(name[1:]) == position + 1 and fits(info, slot)
    return fits(info, slot)


def _matching_size(names: list, free: set, edges: dict) -> int:
    """How many of ``names`` can be placed at once on the ``free`` positions."""
    from networkx import Graph
    from networkx.algorithms.bipartite import hopcroft_karp_matching
    graph = Graph()
    tops = [("name", name) for name in names]
    graph.add_nodes_from(tops)
    graph.add_nodes_from(("slot", slot) for slot in free)
    graph.add_edges_from((("name", name), ("slot", slot))
                         for name in names for slot in edges[name] if slot in free)
    return len(hopcroft_karp_matching(graph, top_nodes=tops)) // 2


def arrange(named: dict, shape: Optional[list], fits: Callable) -> tuple[dict, list]:
    """``(components, left out)``: the record's ``component -> type or None`` in order,
    and the names it could not place. Without a shape the components are the names."""
    if shape is None:
        return dict(named), []
    placed = place(list(named.items()), shape, fits)
    at = {slot: name for name, slot in placed.items()}
    components = {}
    for position, slot in enumerate(shape):
        name = at.get(position)
        if name is None:
            components[f"c{position + 1}"] = slot
        else:
            info = named[name]
            components[name] = slot if info is None or info is SOME_RECORD else info
    return components, [name for name in named if name not in placed]
