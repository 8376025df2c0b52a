"""The collapsed state table: every state comes back equal, ids are dense and stable."""
from __future__ import annotations

import itertools

import pytest

from rapidmc.check.states import StateTable

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


class SplitModel:
    """States (pc, data, signals, rest) split into their four parts."""

    @staticmethod
    def split_state(state):
        return state

    @staticmethod
    def join_state(parts):
        return tuple(parts)


STATES = [(pc, (float(a), "x" * b), (0.0,), ("robot", -1.5))
          for pc, a, b in itertools.product(range(5), range(4), range(3))]


@pytest.mark.parametrize("system", [SplitModel(), object()], ids=["collapsed", "whole"])
def test_states_come_back_equal_with_dense_stable_ids(system):
    table = StateTable(system)
    ids = [table.intern(state) for state in STATES]
    assert ids == [(i, True) for i in range(len(STATES))]
    assert [table.intern(state) for state in STATES] == [(i, False) for i in range(len(STATES))]
    assert [table[i] for i in range(len(STATES))] == STATES
    assert len(table) == len(STATES)


def test_lookup_without_adding_leaves_the_table_unchanged():
    table = StateTable(SplitModel())
    table.intern(STATES[0])
    assert table.intern(STATES[1], add=False) == (-1, True)
    assert len(table) == 1 and table.intern(STATES[0], add=False) == (0, False)


def test_collapsed_states_take_less_memory_than_whole_ones():
    collapsed, whole = StateTable(SplitModel()), StateTable(object())
    for state in STATES * 2:
        collapsed.intern(state)
        whole.intern(state)
    assert collapsed.memory_bytes() < whole.memory_bytes()


def test_the_searches_over_one_model_rebuild_states_of_the_same_objects():
    # a model's successors kept by one search are compared with the states another search
    # rebuilds: equal parts are then the very same objects, found equal at once
    model = SplitModel()
    first, second, elsewhere = StateTable(model), StateTable(model), StateTable(SplitModel())
    state = STATES[7]
    built_apart = (state[0], (float(state[1][0]), "x" * len(state[1][1])), (0.0,),
                   ("robot", -1.5))
    first.intern(state)
    second.intern(built_apart)
    elsewhere.intern(built_apart)
    assert second[0][1] is first[0][1] and second[0][3] is first[0][3]
    assert elsewhere[0][1] is not first[0][1] and elsewhere[0] == first[0]
