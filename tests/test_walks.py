"""Random walks over a transition system (``rapidmc.check.walks``): the coverage probes'
look beyond a bounded breadth-first search.  A walk observes only states it reaches by
the system's own steps, keeps to the environment's first choices within a walk (so a
choice that undoes progress at every step still lets some walk go deep), and repeats
itself for the same seed."""
from __future__ import annotations

import pytest

from rapidmc.check import walks
from rapidmc.check.walks import random_walks

pytestmark = pytest.mark.engine_independent      # no RAPID search: see tests/conftest.py

DEPTH = 200


class Ladder:
    """A counter that a signal read at every step moves up (1) or resets (0); a wait that
    stays put is offered too.  Depth 200 needs 200 ups in a row: a uniform choice at each
    step gets there with chance 2**-200."""

    def initial_states(self):
        return (0,)

    def successors(self, state):
        if state == DEPTH:
            return ((((), "top"), state),)          # ended: its only step stays put
        return (((("signal", 1.0),), "up"), state + 1), \
            (((("signal", 0.0),), "reset"), 0), \
            ((("wait",), "wait"), state)


def seen_by(steps: int, seed: int = 0) -> list:
    """The states the walks observe, in order; a walk found something when it went
    higher than any before."""
    seen: list = []
    highest = [0]

    def observe(state, successors):
        seen.append(state)
        highest[0] = max(highest[0], state)

    random_walks(Ladder(), observe, steps,
                 lambda label: label[0] if label[0] and label[0][0] != "wait" else (),
                 lambda: highest[0], seed=seed)
    return seen


def test_sticky_choices_let_a_walk_reach_what_uniform_choices_never_do(monkeypatch):
    assert DEPTH in seen_by(40000)         # (about one walk in six keeps to "up")
    monkeypatch.setattr(walks, "STICKINESS", (0.0,))
    assert max(seen_by(40000)) < 40


def test_a_walk_moves_by_the_systems_steps_or_starts_where_walks_went_before():
    seen = seen_by(3000)
    assert seen[0] == 0
    for number, (before, after) in enumerate(zip(seen, seen[1:])):
        # up, reset, or a new walk from the start or from a state seen before (a state
        # some walk reached)
        assert after in (before + 1, 0) or after in seen[:number + 1]


def test_walks_repeat_themselves_for_a_seed_and_stop_at_their_steps():
    assert seen_by(2000, seed=3) == seen_by(2000, seed=3)
    assert seen_by(2000, seed=3) != seen_by(2000, seed=4)
    assert len(seen_by(777)) == 777


class Mailbox:
    """Two chains of waits behind a fork, each stage ended by one value of ``VALUES`` (the
    others send the cell back to the start: a command it does not expect): the value
    differs stage by stage, so neither uniform nor sticky choices get far.  A state is
    (chain, stage)."""

    VALUES = 5
    STAGES = 30

    def initial_states(self):
        return (("fork", 0),)

    def successors(self, state):
        chain, stage = state
        if chain == "fork":
            return (((("branch", "a"),), "a"), ("a", 0)), (((("branch", "b"),), "b"), ("b", 0))
        if stage == self.STAGES:
            return ((((), "end"), state),)
        return tuple((((("mailbox", value),), "read"),
                      (chain, stage + 1) if value == stage % self.VALUES else ("fork", 0))
                     for value in range(self.VALUES))


def walked_by(steps: int, guided: bool) -> set:
    """The states the walks observe on ``Mailbox``; with ``guided``, they are told which
    successors lead to a state not observed yet (``novel``)."""
    seen: set = set()
    random_walks(Mailbox(), lambda state, successors: seen.add(state), steps,
                 lambda label: label[0], lambda: len(seen),
                 novel=(lambda successors: [one for one in successors if one[1] not in seen])
                 if guided else None)
    return seen


def test_a_walk_takes_the_steps_that_show_something_new():
    ends = {("a", Mailbox.STAGES), ("b", Mailbox.STAGES)}
    # each end is 31 right values in a row (chance 5**-30 per try unguided)
    assert not ends & walked_by(20000, guided=False)
    # guided: a walk climbs one chain, a later one the other
    assert ends <= walked_by(1000, guided=True)


def test_a_stop_requested_ends_the_walks(monkeypatch):
    # the coverage probes walk after the verdicts; a first interrupt (a CPU time limit's
    # SIGXCPU) ends the walks at once, so the report of the verdicts reached comes first
    from rapidmc.check import budget
    monkeypatch.setattr(budget, "stop_requested", "interrupted by SIGXCPU")
    assert seen_by(3000) == []
    monkeypatch.setattr(budget, "stop_requested", None)
    assert len(seen_by(3000)) == 3000
