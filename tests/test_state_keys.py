"""model.state_keys: equal states get equal keys, however their parts were built."""
from pyrsistent import pvector

from rapidmc.model import state_keys
from rapidmc.model.state_keys import StateKeys
from rapidmc.semantics.state import Frame, Interrupts, State


def cell_state(slot: int, stored: float) -> State:
    """A state whose global data holds a buffer of 512 records (built afresh each call)."""
    buffer = tuple(((float(i), 0.0, stored if i == slot else 0.0), (1.0, 0.0, 0.0, 0.0))
                   for i in range(512))
    frames = (Frame(0, 3, (1.0, "cmd")),)
    return State(frames, pvector([buffer, 2.0, "idle"]), pvector([0, 1]), (), Interrupts(),
                 tasks=((Frame(1, 0, ()),),))


def test_equal_states_built_apart_get_equal_keys():
    keys = StateKeys()
    first, second = cell_state(7, 5.0), cell_state(7, 5.0)
    assert first == second and first[1][0] is not second[1][0]
    assert keys.key(first) == keys.key(second) == StateKeys().key(second)


def test_a_key_is_the_same_after_the_remembered_parts_are_forgotten(monkeypatch):
    monkeypatch.setattr(state_keys, "KNOWN_LIMIT", 2)      # forgets at every third part
    keys = StateKeys()
    state = cell_state(3, 1.0)
    assert keys.key(state) == keys.key(state) == keys.key(cell_state(3, 1.0))


def test_one_element_written_gives_another_key():
    keys = StateKeys()
    before = cell_state(7, 5.0)
    written = before._replace(store=before[1].set(0, cell_state(7, 6.0)[1][0]))
    assert keys.key(before) != keys.key(written)
    assert keys.key(before._replace(frames=(Frame(0, 4, (1.0, "cmd")),))) != keys.key(before)
