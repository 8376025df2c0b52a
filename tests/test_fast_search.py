"""The search's fast paths change nothing a check reports (differential tests).

A check's fast paths: target states without labels (``successor_states``),
the fused step's entries, the generated valuation of atoms (``fused_atoms``),
states collapsed into component ids (``check.states``), the product's guard
tables (``Product.tables``, written out in the emptiness search) and the
successor cache dropped where it does not pay (``ModelStore``).  Each test runs
every property of generated programs twice, once as the search runs it and
once with all of those off (labels built and dropped, states kept whole,
every atom evaluated on a ``Machine``, automaton edges tested one by one),
and compares verdicts, state and transition counts and the counterexample
lassos; the guard tables and the successor cache also alone.  The fused step's entries
are also run with so small a line budget that they go on in the dispatch
loop after one block.
"""
from __future__ import annotations

from unittest import mock

import pytest

from rapidmc import api
from rapidmc.check import check_property, product, store
from rapidmc.check.budget import SearchBudget
from rapidmc.check.emptiness import search_accepting_cycle
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.reduction import ALL, NONE
from rapidmc.semantics import fused_step

from reduction_programs import properties, random_program
from test_plain_step import FUSED_FORMS, compare_drivers, formulas, load
from test_reduction import counters

MAX_STATES = 20_000
# Unreduced, the generated programs of seeds 8 and 12, and SLICED_WRITES, grow without end
# (data that only the reductions slice away): their plain searches stop at any bound.
# Bounded at 5,000 states, they run every line and branch of rapidmc's Python code that
# 20,000 run (measured with coverage.py, branch coverage, native engine; at 2,000 the
# successor cache's review is not reached yet), at a quarter of the cost.  Searches that
# end need up to 20,000 (seed 11).
GROWING_PLAIN_SEEDS, GROWING_PLAIN_STATES = {8, 12}, 5_000

# A cycle counter and a log nothing reads (sliced, written with total values: the fused
# step's unlabelled entries skip those writes), a ratio nothing reads written with a
# division that fails once ``d`` is 0 (sliced too, but never skipped: the step must fail).
SLICED_WRITES = """MODULE Logged
  VAR signaldi in0;
  VAR num c := 0;
  VAR num d := 2;
  VAR num total := 0;
  VAR num ratio := 0;
  VAR string log := "";
  PROC main()
    AliasIO "IN0", in0;
    WHILE TRUE DO
      IF in0 = 1 THEN
        c := (c + 1) MOD 3;
        d := d - 1;
      ENDIF
      total := total + 1;
      log := "cycle " + NumToStr(total, 0);
      ratio := 1 / d;
      IF d < -1 d := 2;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


class Unhurried(RapidSystem):
    """The same system searched without the fast paths of the search (see above)."""

    split_state = None                  # states kept whole in a dict
    successor_states = None             # the store drops the labels of ``successors``


def outcomes(model, system, fast: bool, max_states: int = MAX_STATES) -> list:
    """Per property: verdict, product states, transitions and the lasso."""
    found = []
    for _, buchi, valuation in model.jobs:
        if not fast:
            valuation = model.atoms.valuation(buchi.atoms, {}, memo=False)
        with mock.patch.object(product, "TABLE_LIMIT", product.TABLE_LIMIT if fast else 0):
            result = check_property(system, buchi, valuation, max_states=max_states)
        lasso = [(step.label, step.state, step.automaton_state)
                 for step in result.prefix + result.cycle]
        found.append((result.verdict, result.stats.product_states, result.stats.transitions,
                      lasso, result.closing_label))
    return found


def assert_same_checks(program, props, reductions, max_states: int = MAX_STATES) -> None:
    model = api.prepare(program, props, api.CheckOptions(reductions=reductions))
    system = model.system
    slow = Unhurried(system.program, system.plain_config, system.plan)
    assert outcomes(model, system, True, max_states) == \
        outcomes(model, slow, False, max_states)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
@pytest.mark.parametrize("seed", range(16))
def test_generated_programs_check_alike(tmp_path, seed, reductions):
    program = load(tmp_path, random_program(seed))
    growing = reductions == NONE and seed in GROWING_PLAIN_SEEDS
    assert_same_checks(program, formulas(*properties(seed, with_next=seed % 2 == 1)),
                       reductions, GROWING_PLAIN_STATES if growing else MAX_STATES)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_counters_check_alike(tmp_path, reductions):
    program = load(tmp_path, counters(3, statistics=True))
    assert_same_checks(program, formulas('b: G ("c0 < 4" & "c1 < 4")', 'v: G "c2 < 3"'),
                       reductions)


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_entries_past_their_budget_agree(tmp_path, monkeypatch, reductions):
    """Entries cut after one block go on in the dispatch loop, with the same result."""
    monkeypatch.setattr(fused_step, "ENTRY_LINES", 1)
    for text, formula in ((FUSED_FORMS, 'b: G "n < 5"'), (counters(3), 'b: G "c0 < 4"'),
                          (counters(3, statistics=True),
                           'b: G ("c0 < 4" & "c1 < 4" & "c2 < 4")'),
                          (SLICED_WRITES, 'b: G "c < 3"')):
        program = load(tmp_path, text)
        plain, fused = compare_drivers(program, formulas(formula), reductions)
        assert fused > 0


def assert_alike_with(program, props, module, **values) -> None:
    """The checks of ``props`` as the search runs them and with ``module``'s attributes
    set to ``values``."""
    model = api.prepare(program, props, api.CheckOptions(reductions=ALL))
    usual = outcomes(model, model.system, True)
    with mock.patch.multiple(module, **values):
        patched = api.prepare(program, props, api.CheckOptions(reductions=ALL))
        assert outcomes(patched, patched.system, True) == usual


@pytest.mark.parametrize("seed", range(0, 16, 3))
def test_guard_tables_check_alike(tmp_path, seed):
    """Automaton successors from the guard tables, or each edge's guard tested."""
    program = load(tmp_path, random_program(seed))
    assert_alike_with(program, formulas(*properties(seed, with_next=True)), product,
                      TABLE_LIMIT=0)


@pytest.mark.parametrize("seed", range(1, 16, 3))
def test_successor_cache_reviews_check_alike(tmp_path, seed):
    """The successor cache dropped and tried again every few expansions, or always kept."""
    program = load(tmp_path, random_program(seed))
    assert_alike_with(program, formulas(*properties(seed, with_next=True)), store,
                      CACHE_TRIAL=2, CACHE_WORTH=1, CACHE_REST=3)


def test_successor_cache_dropped_where_it_does_not_pay(tmp_path, monkeypatch):
    """A safety property that holds pairs each state with one automaton state: no hits.
    (The cache is ``successor_ids``'; the compiled cycle search that steps the machine
    itself, ``Product.native_machine``, asks it nothing, so it is left out here.)"""
    monkeypatch.setattr(store, "CACHE_TRIAL", 16)
    monkeypatch.setattr(product.Product, "native_machine", lambda self: None)
    program = load(tmp_path, counters(3))
    model = api.prepare(program, formulas('b: G "c0 < 4"'), api.CheckOptions(reductions=ALL))
    _, buchi, valuation = model.jobs[0]
    states = store.ModelStore(model.system, valuation)
    found = search_accepting_cycle(product.Product(states, buchi),
                                   SearchBudget(MAX_STATES, None, None))
    assert found.verdict == "HOLDS"
    assert len(states) > 16 and not states._caching


def test_skipped_writes_are_the_total_writes_to_sliced_data(tmp_path):
    program = load(tmp_path, SLICED_WRITES)
    model = api.prepare(program, formulas('b: G "c < 3"'), api.CheckOptions(reductions=ALL))
    skipped = {span.line for span in model.system.config.skipped_writes}
    lines = SLICED_WRITES.splitlines()
    assert skipped == {number for number, line in enumerate(lines, 1)
                       if line.lstrip().startswith(("total :=", "log :="))}   # not ratio :=
    unreduced = api.prepare(program, formulas('b: G "c < 3"'), api.CheckOptions(reductions=NONE))
    assert not unreduced.system.config.skipped_writes


# ``t`` is written before it is read in each pass of the loop: dead (reset) where the
# steps stop, at the input's test.
DEAD_TEMPORARY = """MODULE Dead
  VAR signaldi in0;
  VAR num c := 0;
  VAR num t := 0;
  PROC main()
    AliasIO "IN0", in0;
    WHILE TRUE DO
      IF in0 = 1 THEN
        c := (c + 1) MOD 3;
      ENDIF
      t := c + 1;
      IF t > 2 c := 0;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("text, formula, unprojected", [
    # the projection resets only the cycle counter and the log, whose writes are skipped
    # (c1, dead at the end of main, after the endless loop, where no step stops)
    (counters(2, statistics=True), 'b: G "c0 < 4"', True),
    # the ratio is sliced too, but its failing division is not skipped
    (SLICED_WRITES, 'b: G ("c < 3" & "d > -5")', False),
    # dead data (not sliced) is reset where the steps stop
    (DEAD_TEMPORARY, 'b: G "c < 3"', False)], ids=["statistics", "ratio", "dead"])
def test_fused_targets_are_left_unprojected_only_where_projected_already(
        tmp_path, text, formula, unprojected):
    model = api.prepare(load(tmp_path, text), formulas(formula),
                        api.CheckOptions(reductions=ALL))
    assert model.system.project is not None
    assert (model.system.project_fused is None) == unprojected
    plain, fused = compare_drivers(load(tmp_path, text), formulas(formula), ALL)
    assert fused > 0


@pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])
def test_skipped_writes_check_alike(tmp_path, reductions):
    """States without the skipped writes (``successor_states``) and with them (the
    labelled ``successors``), projected: the same checks, the failing division found."""
    program = load(tmp_path, SLICED_WRITES)
    props = formulas('b: G "c < 3"', 'f: G F "c = 0"', 'n: G ("c = 1" -> X "c <> 2")',
                     'd: G "d > -5"')
    assert_same_checks(program, props, reductions,
                       GROWING_PLAIN_STATES if reductions == NONE else MAX_STATES)
    plain, fused = compare_drivers(program, props, reductions)
    assert plain > fused > 0
