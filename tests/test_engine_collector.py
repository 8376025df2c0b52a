"""The cycle collector during a search: survivors frozen at checkpoints, garbage still
collected, everything handed back when the search ends."""
from __future__ import annotations

import gc

from rapidmc.check import HOLDS, check_property, find_reachable
from rapidmc.check.collector import freeze_survivors, frozen_while_searching
from rapidmc.ltl import parse_formula, to_buchi


class Litter:
    """A counter modulo ``size`` whose step leaves a reference cycle behind, like a
    step function whose working objects point at each other."""

    live = 0

    def __init__(self, size: int):
        self.size = size
        self.most_live = 0
        self.most_frozen = 0

    def initial_states(self):
        return (0,)

    def successors(self, state):
        Cycle()
        self.most_live = max(self.most_live, Litter.live)
        if state % 1000 == 0:                      # (counting frozen objects walks them)
            self.most_frozen = max(self.most_frozen, gc.get_freeze_count())
        return (("inc", (state + 1) % self.size), ("skip", (state + 2) % self.size))


class Cycle:
    def __init__(self):
        Litter.live += 1
        self.me = self

    def __del__(self):
        Litter.live -= 1


def test_a_search_freezes_survivors_and_hands_them_back():
    model = Litter(20_000)
    result = check_property(model, to_buchi(parse_formula("!(G a)")), lambda state: 1)
    assert result.verdict == HOLDS
    assert model.most_frozen > 0                   # checkpoints froze what the search keeps
    assert gc.get_freeze_count() == 0              # and the end of the search unfroze it


def test_the_garbage_of_the_step_is_collected_during_the_search():
    gc.collect()
    model = Litter(20_000)
    result = find_reachable(model, lambda state: False)
    assert result.verdict == HOLDS and result.stats.product_states == 20_000
    assert model.most_live < 2_000                 # not one per state
    assert gc.get_freeze_count() == 0


def test_searches_inside_searches_keep_the_objects_frozen_until_the_outer_one_ends():
    with frozen_while_searching():
        with frozen_while_searching():
            freeze_survivors()
        assert gc.get_freeze_count() > 0
    assert gc.get_freeze_count() == 0
    freeze_survivors()                             # outside a search: does nothing
    assert gc.get_freeze_count() == 0
