"""The time limit is kept inside a step with thousands of successors (issue 28).

A search reads its clock at checkpoints that come with new states; a step that offers
thousands of successors, or expansions that find mostly known states, could run far past
``--max-seconds`` (a backup with eleven stored inputs and two tasks: 4,096 successors a
step, 120 s against a 5 s limit).  Successor generation calls ``check.budget.time_check``
between two runs of a step.  These tests count clock readings instead of timing: the
budget's clock is a counter that advances one second per reading.
"""
from __future__ import annotations

import pytest

import rapidmc.check.budget as budget
from rapidmc.check import native
from rapidmc.api import CheckOptions, check, load_program
from rapidmc.check.budget import SearchBudget, stopped_in_time, time_check

ANSWERS = 3000          # TPReadNum's answers: one step with 3,000 successors
LIMIT = 20              # seconds of the counting clock


FAN_LOOP = ("        WHILE TRUE DO\n"
            "            TPReadNum answer, \"How many parts?\";\n"
            "            answer := 0;\n"
            "        ENDWHILE\n")


class CountingClock:
    """A clock that advances one second each time it is read."""

    def __init__(self):
        self.readings = 0

    def __call__(self) -> float:
        self.readings += 1
        return float(self.readings)


@pytest.fixture
def program(tmp_path):
    module = tmp_path / "fan.mod"
    # the answer is overwritten in the same (merged) step: every answer leads to the same
    # state, so the search finds no new states that would bring a checkpoint
    module.write_text("MODULE Fan\n"
                      "    VAR num answer;\n"
                      "    PROC main()\n"
                      f"{FAN_LOOP}"
                      "    ENDPROC\n"
                      "ENDMODULE\n")
    return load_program([str(module)])


def checked(program, max_seconds):
    """The two built-in checks' search results (each search has its own budget)."""
    options = CheckOptions(tp_answers=tuple(float(n) for n in range(1, ANSWERS + 1)),
                           max_seconds=max_seconds)
    report = check(program, [], options)
    return [report.result(name).result for name in ("no_runtime_error", "no_deadlock")]


def test_a_step_with_thousands_of_successors_stops_near_its_limit(program, monkeypatch):
    clock = CountingClock()
    monkeypatch.setattr(budget, "default_clock", clock)
    results = checked(program, LIMIT)
    for result in results:
        assert result.verdict == "UNKNOWN"
        assert result.reason == f"time limit {LIMIT} s reached"
        assert result.stats.transitions < ANSWERS
    # one reading per run of the step: each search stopped a few runs after its limit,
    # not after 3,000
    assert clock.readings <= len(results) * (LIMIT + 5)


def test_without_a_time_limit_the_same_step_is_searched_whole(program, monkeypatch):
    clock = CountingClock()
    monkeypatch.setattr(budget, "default_clock", clock)
    for result in checked(program, None):
        assert result.verdict == "HOLDS"
        assert result.stats.transitions >= ANSWERS


def test_time_check_outside_a_search_loop_never_stops_anything():
    spent = SearchBudget(max_seconds=1, clock=CountingClock())
    spent.over_time()
    spent.over_time()
    assert spent.reason is not None
    time_check()                         # no search running: a description of a trace
    with stopped_in_time(SearchBudget(max_seconds=None)):
        time_check()                     # a search without a time limit


ENGINES = native.ENGINES if native.available() else (native.PYTHON,)
CLIMB = 40              # states before the step with thousands of successors


@pytest.fixture
def climbing(tmp_path):
    module = tmp_path / "climb.mod"
    # CLIMB states one after another (``k`` is printed, so kept), then the fan above
    module.write_text("MODULE Climb\n"
                      "    VAR num answer;\n"
                      "    VAR num k;\n"
                      "    PROC main()\n"
                      f"        FOR i FROM 1 TO {CLIMB} DO\n"
                      "            k := i;\n"
                      "            TPWrite \"at \"\\Num:=k;\n"
                      "        ENDFOR\n"
                      f"{FAN_LOOP}"
                      "    ENDPROC\n"
                      "ENDMODULE\n")
    return load_program([str(module)])


@pytest.mark.parametrize("engine", ENGINES)
def test_a_search_stopped_inside_a_step_reports_what_it_reached(climbing, monkeypatch,
                                                                 engine):
    """The compiled loop stopped by the time limit inside a Python step once returned no
    counts: an UNKNOWN reported 0 transitions and depth 1 after thousands of states."""
    clock = CountingClock()
    monkeypatch.setattr(budget, "default_clock", clock)
    with native.engine_used(engine):
        result = checked(climbing, 4 * CLIMB)[0]
    assert result.verdict == "UNKNOWN"
    assert result.stats.model_states > CLIMB
    assert result.stats.transitions >= CLIMB
    assert result.stats.max_depth >= CLIMB
