"""The model store: valuations kept in the narrowest array that holds them, states by id."""
from __future__ import annotations

import pytest

from rapidmc.check.store import ModelStore

from test_engine_models import Chain


@pytest.mark.parametrize("values", [
    [0, 3, 255],                         # up to 8 atoms: a byte each
    [1, 300, 2],                         # up to 16
    [5, 70_000, 1],                      # up to 32
    [2, 1 << 40, 7],                     # up to 64
    [1, 1 << 70, 1 << 64, 9],            # more: Python ints
])
def test_valuations_widen_and_come_back_equal(values):
    store = ModelStore(Chain(len(values)), lambda state: values[state])
    state_id = store.initial_ids()[0]
    for _ in values:
        state_id = store.successor_ids(state_id)[0]
    assert list(store.valuations) == values
    assert [store.states[i] for i in range(len(store))] == list(range(len(values)))
    assert store.memory_bytes() > 0


def test_a_byte_per_state_for_few_atoms():
    store = ModelStore(Chain(3), lambda state: state)
    store.initial_ids()
    assert store.valuations.itemsize == 1
