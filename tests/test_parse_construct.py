"""The parser's fast node constructors build exactly the nodes the dataclasses do."""
from __future__ import annotations

import dataclasses

import pytest

from rapidmc.syntax.construct import NODE_CLASSES, draft_class, constructor, nodes

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


@pytest.mark.parametrize("name", sorted(NODE_CLASSES))
def test_fast_constructor_builds_the_same_node(name):
    cls = NODE_CLASSES[name]
    fields = dataclasses.fields(cls)
    required = [f"v{i}" for i, f in enumerate(fields) if f.default is dataclasses.MISSING]
    every = [f"v{i}" for i in range(len(fields))]
    build = getattr(nodes, name)
    for values in (required, every):
        made, expected = build(*values), cls(*values)
        assert type(made) is cls
        assert [getattr(made, f.name) for f in fields] == [getattr(expected, f.name) for f in fields]
        assert made == expected and hash(made) == hash(expected)
    keywords = {f.name: f"k{i}" for i, f in enumerate(fields)}
    assert build(**keywords) == cls(**keywords)


def test_nodes_stay_frozen():
    span = nodes.Span("m.mod", 1, 2)
    with pytest.raises(dataclasses.FrozenInstanceError):
        span.line = 3


def test_classes_with_more_than_fields_keep_their_init():
    @dataclasses.dataclass(frozen=True, slots=True)
    class Checked:
        value: int

        def __post_init__(self):
            raise ValueError("checked")
    assert constructor(Checked) is Checked


@pytest.mark.parametrize("name", sorted(NODE_CLASSES))
def test_every_node_class_is_filled_in_as_a_draft(name):
    """The fast path (plain stores into a class of the same layout, then the class
    assigned) is open to every AST class; the slower slot setters are a fallback."""
    cls = NODE_CLASSES[name]
    draft = draft_class(cls)
    assert draft is not None and draft.__slots__ == cls.__slots__
