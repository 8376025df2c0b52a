"""Tree-compressed storage (check.nodes): each subvalue interned once, ids equal exactly when
trees are equal, a one-element write re-interns only its path, memory counted as added.
Each holds for the Python table and for the native one (``_nodes.c``), which give the same
ids."""
from __future__ import annotations

from pyrsistent import pvector
import pytest

from rapidmc.check.native import NativeNodeTable
from rapidmc.check.nodes import NodeTable
from rapidmc.check.states import StateTable
from rapidmc.semantics.state import Frame

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

TABLES = [NodeTable, pytest.param(NativeNodeTable, marks=pytest.mark.skipif(
    NativeNodeTable is None, reason="the native core is not built"))]
BUFFER = tuple((float(i), (float(i), 0.0, 600.0), "p%d" % i) for i in range(512))


class SplitModel:
    split_state = staticmethod(lambda state: state)
    join_state = staticmethod(tuple)


def written(buffer: tuple, index: int, element) -> tuple:
    """The array after a step writes one element (the others handed on unchanged)."""
    return buffer[:index] + (element,) + buffer[index + 1:]


@pytest.mark.parametrize("tables", TABLES)
def test_equal_trees_have_one_id_and_one_canonical_object(tables):
    nodes = tables()
    first = nodes.node(BUFFER)
    copy = tuple((a, tuple(b), str(c)) for a, b, c in BUFFER)
    assert nodes.node(copy) == first
    assert nodes.value(first) == BUFFER
    assert nodes.node(written(BUFFER, 7, (1.0, (2.0, 0.0, 600.0), "q"))) != first


@pytest.mark.parametrize("tables", TABLES)
def test_leaves_python_finds_equal_but_rapid_does_not_are_different_nodes(tables):
    nodes = tables()
    assert nodes.node((True,)) != nodes.node((1,))
    assert type(nodes.value(nodes.node((1,)))[0]) is int


@pytest.mark.parametrize("tables", TABLES)
def test_tuple_subclasses_and_vectors_come_back_as_their_own_type(tables):
    nodes = tables()
    frame = Frame(3, 4, (1.0, "a"))
    vector = pvector([frame, (1.0,)])
    assert type(nodes.value(nodes.node(frame))) is Frame
    back = nodes.value(nodes.node(vector))
    assert back == vector and type(back) is type(vector) and type(back[0]) is Frame


@pytest.mark.parametrize("tables", TABLES)
def test_a_one_element_write_shares_every_other_element_and_adds_only_its_path(tables):
    nodes = tables()
    canonical = nodes.value(nodes.node(BUFFER))
    before = len(nodes)
    after = written(canonical, 100, (100.0, (999.0, 0.0, 600.0), "p100"))
    changed = nodes.value(nodes.node(after))
    # the new array, the new record and its new position (x = 999.0 is a new leaf too)
    assert len(nodes) - before == 4
    assert all(changed[i] is canonical[i] for i in range(512) if i != 100)
    assert changed[100][2] is canonical[100][2]


@pytest.mark.parametrize("tables", TABLES)
def test_memory_is_counted_as_nodes_are_added_and_not_when_known_values_come_again(tables):
    nodes = tables()
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


@pytest.mark.parametrize("tables", TABLES)
def test_ids_stay_exact_over_many_short_lived_values(tables):
    # canonical objects live as long as the table, so an id found there is never that of
    # a later, different object that happens to reuse a freed one's address
    nodes = tables()
    seen: dict = {}
    for round_ in range(3):
        for i in range(2000):
            value = (float(i % 97), (float(i % 89), str(i % 7)))
            assert seen.setdefault(value, nodes.node(value)) == nodes.node(value)
    assert len(set(seen.values())) == len(seen)


def test_both_tables_give_the_same_ids_and_canonical_values():
    if NativeNodeTable is None:
        pytest.skip("the native core is not built")
    values = [BUFFER, written(BUFFER, 3, (0.0, (-0.0, 0.0, 600.0), "p3")), (True, 1, 1.0),
              Frame(1, 2, (0.0, None)), (1, 2, (0.0, None), 0, -1, 0, -1),
              pvector([(1.0,), "x"]), pvector([(1.0,), "x"]), float("nan"), (-0.0, 0.0), (),
              ((), Frame(0, 0, ()))]
    python, native = NodeTable(), NativeNodeTable()
    assert python.ids(values) == native.ids(values)
    assert len(python) == len(native)
    for node_id in range(len(python)):
        assert type(python.value(node_id)) is type(native.value(node_id))
        assert repr(python.value(node_id)) == repr(native.value(node_id))
