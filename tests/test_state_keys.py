"""model.state_keys: equal states get equal keys, however their parts were built, and the
native engine's keys (hashes remembered in C) are the Python engine's."""
from pyrsistent import pvector
import pytest

from rapidmc.check import native
from rapidmc.model import state_keys
from rapidmc.model.state_keys import StateKeys
from rapidmc.semantics.state import Frame, Interrupts, State


BOTH = pytest.mark.parametrize("in_c", [False, pytest.param(True, marks=pytest.mark.skipif(
    not native.available(), reason="the native core is not built"))], ids=["python", "native"])


def cell_state(slot: int, stored: float) -> State:
    """A state whose global data holds a buffer of 512 records (built afresh each call)."""
    buffer = tuple(((float(i), 0.0, stored if i == slot else 0.0), (1.0, 0.0, 0.0, 0.0))
                   for i in range(512))
    frames = (Frame(0, 3, (1.0, "cmd")),)
    return State(frames, pvector([buffer, 2.0, "idle"]), pvector([0, 1]), (), Interrupts(),
                 tasks=((Frame(1, 0, ()),),))


@BOTH
def test_equal_states_built_apart_get_equal_keys(in_c):
    keys = StateKeys(in_c)
    first, second = cell_state(7, 5.0), cell_state(7, 5.0)
    assert first == second and first[1][0] is not second[1][0]
    assert keys.key(first) == keys.key(second) == StateKeys().key(second)


@BOTH
def test_a_key_is_the_same_after_the_remembered_parts_are_forgotten(monkeypatch, in_c):
    monkeypatch.setattr(state_keys, "KNOWN_LIMIT", 2)      # forgets at every third part
    keys = StateKeys(in_c)
    state = cell_state(3, 1.0)
    assert keys.key(state) == keys.key(state) == keys.key(cell_state(3, 1.0))


@BOTH
def test_one_element_written_gives_another_key(in_c):
    keys = StateKeys(in_c)
    before = cell_state(7, 5.0)
    written = before._replace(store=before[1].set(0, cell_state(7, 6.0)[1][0]))
    assert keys.key(before) != keys.key(written)
    assert keys.key(before._replace(frames=(Frame(0, 4, (1.0, "cmd")),))) != keys.key(before)


@pytest.mark.skipif(not native.available(), reason="the native core is not built")
def test_the_native_keys_are_the_python_keys():
    # the partial-order reduction's cycle proviso looks keys up: the same numbers make the
    # same choices on both engines, collisions included
    python, in_c = StateKeys(False), StateKeys(True)
    states = [cell_state(slot, value) for slot in (0, 7, 511) for value in (0.0, -0.0, 2.5)]
    states.append(states[0]._replace(tasks=((), (Frame(2, 1, ("x", True)),))))
    for state in states + states:
        assert python.key(state) == in_c.key(state)
