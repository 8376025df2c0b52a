"""ISignalAI/AO's rule (staged_step.analog_reached): the condition holds and the value differs
from the reference by more than DeltaValue; the reference then moves, and \\DPos/\\DNeg pick
the direction that orders the interrupt."""
from __future__ import annotations

import pytest

from rapidmc.semantics.staged_step import analog_reached, aio_condition_met

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ABOVE_HIGH, BELOW_HIGH, ABOVE_LOW, BELOW_LOW, BETWEEN, OUTSIDE, ALWAYS = range(1, 8)


def samples(condition, high, low, delta, direction, start, values):
    """The values among ``values`` (one per step, from the reference ``start``) that order
    the interrupt."""
    source = ("analog", 0, condition, high, low, delta, direction, start, False)
    ordered = []
    for value in values:
        reached, source = analog_reached(source, value)
        if reached:
            ordered.append(value)
    return ordered


@pytest.mark.parametrize("condition, value, met", [
    (ABOVE_HIGH, 6, True), (ABOVE_HIGH, 5, False), (BELOW_HIGH, 4, True), (BELOW_HIGH, 5, False),
    (ABOVE_LOW, 2, True), (ABOVE_LOW, 1, False), (BELOW_LOW, 0, True), (BELOW_LOW, 1, False),
    (BETWEEN, 1, True), (BETWEEN, 5, True), (BETWEEN, 6, False), (OUTSIDE, 0, True),
    (OUTSIDE, 3, False), (ALWAYS, 3, True)])
def test_each_condition_compares_with_its_limit(condition, value, met):
    assert aio_condition_met(condition, 5, 1, value) is met


def test_with_delta_zero_every_new_value_meeting_the_condition_orders_it():
    # 10 again after 0 is no difference from the reference (10, kept while 0 is below)
    assert samples(ABOVE_HIGH, 5, 0, 0, 0, 0, [10, 0, 10, 7, 10]) == [10, 7, 10]


def test_delta_and_direction_follow_the_reference():
    # between 2.2 and 6.1, more than 1.0 upwards (\DPos): falling moves the reference too
    assert samples(BETWEEN, 6.1, 2.2, 1.0, 1, 5, [3.5, 2.4, 3.0, 3.6, 7, 5.5]) == [3.6, 5.5]
    assert samples(BETWEEN, 6.1, 2.2, 1.0, -1, 5, [3.5, 2.4, 3.0, 3.6, 7, 5.5]) == [3.5, 2.4]
    assert samples(BETWEEN, 6.1, 2.2, 1.0, 0, 5, [3.5, 2.4, 3.0, 3.6, 7, 5.5]) == \
        [3.5, 2.4, 3.6, 5.5]
