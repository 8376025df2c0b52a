"""The callbacks written for each grammar rule select the children as Lark's tree builder
does: checked against a plain reading of the rule's child plan, for every rule."""
from __future__ import annotations

import pytest

from rapidmc.syntax.parser import rapid_parser
from rapidmc.syntax.reductions import ChildPlan

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

RULES = sorted(rapid_parser().rules, key=str)


def expected_children(plan: ChildPlan, entries: list) -> list:
    """Lark's shaping, step by step: Nones for absent optional parts, spliced ``_rule``
    lists, dropped punctuation."""
    children: list = []
    for index, splice, nones in plan.kept:
        children += [None] * nones
        children += entries[index] if splice else [entries[index]]
    return children + [None] * plan.nones_after


def sample_entries(plan: ChildPlan) -> list:
    """Distinct values for a stack slice; a spliced entry is a list of two."""
    spliced = {index for index, splice, _ in plan.kept if splice}
    return [[f"s{index}a", f"s{index}b"] if index in spliced else f"e{index}"
            for index in range(plan.size)]


@pytest.mark.parametrize("rule", RULES, ids=str)
def test_written_selection_matches_the_plan(rule):
    plan = ChildPlan.of(rule)
    expected = expected_children(plan, sample_entries(plan))
    select = plan.selector()
    entries = sample_entries(plan)     # fresh: a first spliced list is extended in place
    assert (entries if select is None else select(entries)) == expected
    received = []
    reduce = plan.function(lambda *arguments: received.append(arguments) or "node")
    assert reduce(sample_entries(plan)) == "node"
    assert received[0][0] == expected
