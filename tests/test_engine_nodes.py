"""Tree-compressed storage (check.nodes): each subvalue interned once, ids equal exactly when
trees are equal, a one-element write re-interns only its path, memory counted as added."""
from __future__ import annotations

from pyrsistent import pvector
import pytest

from rapidmc.check.nodes import NodeTable
from rapidmc.check.states import StateTable
from rapidmc.semantics.state import Frame

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

BUFFER = tuple((float(i), (float(i), 0.0, 600.0), "p%d" % i) for i in range(512))


class SplitModel:
    split_state = staticmethod(lambda state: state)
    join_state = staticmethod(tuple)


def written(buffer: tuple, index: int, element) -> tuple:
    """The array after a step writes one element (the others handed on unchanged)."""
    return buffer[:index] + (element,) + buffer[index + 1:]


def test_equal_trees_have_one_id_and_one_canonical_object():
    nodes = NodeTable()
    first = nodes.node(BUFFER)
    copy = tuple((a, tuple(b), str(c)) for a, b, c in BUFFER)
    assert nodes.node(copy) == first
    assert nodes.value(first) == BUFFER
    assert nodes.node(written(BUFFER, 7, (1.0, (2.0, 0.0, 600.0), "q"))) != first


def test_leaves_python_finds_equal_but_rapid_does_not_are_different_nodes():
    nodes = NodeTable()
    assert nodes.node((True,)) != nodes.node((1,))
    assert type(nodes.value(nodes.node((1,)))[0]) is int


def test_tuple_subclasses_and_vectors_come_back_as_their_own_type():
    nodes = NodeTable()
    frame = Frame(3, 4, (1.0, "a"))
    vector = pvector([frame, (1.0,)])
    assert type(nodes.value(nodes.node(frame))) is Frame
    back = nodes.value(nodes.node(vector))
    assert back == vector and type(back) is type(vector) and type(back[0]) is Frame


def test_a_one_element_write_shares_every_other_element_and_adds_only_its_path():
    nodes = NodeTable()
    canonical = nodes.value(nodes.node(BUFFER))
    before = len(nodes)
    after = written(canonical, 100, (100.0, (999.0, 0.0, 600.0), "p100"))
    changed = nodes.value(nodes.node(after))
    # the new array, the new record and its new position (x = 999.0 is a new leaf too)
    assert len(nodes) - before == 4
    assert all(changed[i] is canonical[i] for i in range(512) if i != 100)
    assert changed[100][2] is canonical[100][2]


def test_memory_is_counted_as_nodes_are_added_and_not_when_known_values_come_again():
    nodes = NodeTable()
    canonical = nodes.value(nodes.node(BUFFER))
    counted, known = nodes.memory_bytes(), len(nodes)
    assert counted > 512 * 3 * 8
    nodes.node(canonical)
    nodes.node(canonical[:256] + canonical[256:])
    assert nodes.memory_bytes() == counted and len(nodes) == known


def test_states_with_big_arrays_share_their_unchanged_elements_in_the_state_table():
    table = StateTable(SplitModel())
    state = (0, BUFFER, ("robot",))
    table.intern(state)
    stored = table[0][1]
    step = (1, written(stored, 5, (5.0, (7.0, 0.0, 600.0), "p5")), ("robot",))
    assert table.intern(step) == (1, True)
    assert table.intern((1, written(BUFFER, 5, (5.0, (7.0, 0.0, 600.0), "p5")), ("robot",))) \
        == (1, False)
    assert all(table[1][1][i] is stored[i] for i in range(512) if i != 5)


class CountingNodes(NodeTable):
    """A node table that counts the values it is asked about (its recursion included)."""

    calls = 0

    def node(self, value) -> int:
        self.calls += 1
        return super().node(value)


def test_a_value_added_with_an_equal_copy_of_a_known_leaf_is_found_again_by_identity():
    nodes = CountingNodes()
    nodes.node((1.5,))
    record = (float("1.5"), float("7.0"))    # its first leaf is not the canonical 1.5
    first = nodes.node(record)
    assert nodes.value(first) is not record     # the canonical record is built of canonical leaves
    nodes.calls = 0
    assert nodes.node(record) == first and nodes.calls == 1      # the state hands it on
    handed_on = nodes.value(nodes.node(((record, 3.0))))
    assert handed_on[0] is nodes.value(first)


def test_ids_stay_exact_over_many_short_lived_values():
    # canonical objects live as long as the table, so an id found there is never that of
    # a later, different object that happens to reuse a freed one's address
    nodes = NodeTable()
    seen: dict = {}
    for round_ in range(3):
        for i in range(2000):
            value = (float(i % 97), (float(i % 89), str(i % 7)))
            assert seen.setdefault(value, nodes.node(value)) == nodes.node(value)
    assert len(set(seen.values())) == len(seen)
