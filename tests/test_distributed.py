"""Distributed checking on a real local Ray cluster (``--workers``, ``--swarm``; issue 29).

The partitioned search must answer exactly what the one-process search answers: the
same verdicts, and after a complete search the same state, transition, deadlock and depth
counts; its counterexamples are as short and replay.  A lost worker ends the check with
RMC752 (exit 5), never a verdict; a swarm finds a planted deep error the exhaustive search
cannot reach in its bound, and never says HOLDS.

One Ray cluster (2 CPUs) serves the whole module: Ray takes seconds to start.  Without Ray
the tests skip, unless RAPIDMC_REQUIRE_RAY=1 (CI), where they fail.
"""
from __future__ import annotations

import contextlib
import io
import json
import logging
import sys
from pathlib import Path

import pytest

from rapidmc.check import find_reachable
from rapidmc.check.budget import SearchBudget
from rapidmc.check.result import HOLDS, VIOLATED
from rapidmc.cli import main
from rapidmc.diagnostics import EXIT_WORKER_LOST, UserError
from test_check_cases import SAFETY, load_case, report_of, CASES_DIR
from tool_requirements import require_tool

try:
    import ray
except ImportError:
    ray = None

ROOT = Path(__file__).resolve().parent.parent
HERE = Path(__file__).resolve().parent / "distributed"
# a few check cases: a run-time error, a deadlock, several tasks, a bound, loops that hold
CASES = ["runtime_div_input", "deadlock_waitdo_never_set", "tasks_test_and_set",
         "max_states_unknown", "loop_mod_counter", "runtime_array_index_safe"]


@pytest.fixture(scope="module")
def cluster():
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])   # (the toy model below)
    ray.init(num_cpus=2, include_dashboard=False, logging_level=logging.ERROR,
             log_to_driver=False)
    yield ray
    ray.shutdown()


class Grid:
    """A toy model: (x, y) in 0..size-1, one step right or up; the corner is the error."""

    def __init__(self, size: int):
        self.size = size

    def initial_states(self):
        return ((0, 0),)

    def successors(self, state):
        x, y = state
        moves = []
        if x + 1 < self.size:
            moves.append(("right", (x + 1, y)))
        if y + 1 < self.size:
            moves.append(("up", (x, y + 1)))
        return moves

    def failed(self, state):
        return state == (self.size - 1, self.size - 1)

    def never(self, state):
        return False


def _partitioned(cluster, system, predicate, **options):
    from rapidmc.check.distributed.search import partitioned_reachable
    return partitioned_reachable(cluster, 2, system, predicate, **options)


def test_partitioned_search_counts_what_one_process_counts(cluster):
    grid = Grid(30)
    one = find_reachable(grid, grid.never)
    spread, _, figures = _partitioned(cluster, grid, "never")
    assert one.verdict == spread.verdict == HOLDS
    for figure in ("product_states", "transitions", "max_depth", "deadlocks"):
        assert getattr(spread.stats, figure) == getattr(one.stats, figure), figure
    assert all(f["states"] > 0 for f in figures)       # both partitions own states
    assert sum(f["states"] for f in figures) == 900


def test_partitioned_counterexample_is_shortest_and_crosses_partitions(cluster):
    grid = Grid(12)
    one = find_reachable(grid, grid.failed)
    spread, _, _ = _partitioned(cluster, grid, "failed")
    assert spread.verdict == VIOLATED and len(spread.prefix) == len(one.prefix) == 23
    for before, after in zip(spread.prefix, spread.prefix[1:]):   # each step is a real move
        assert (after.label, after.state) in grid.successors(before.state)


def test_a_killed_worker_ends_the_search_without_a_verdict(cluster):
    def kill_one(actors, levels=[]):
        levels.append(1)
        if len(levels) == 5:                                  # mid-search
            cluster.kill(actors[1])
    grid = Grid(40)
    with pytest.raises(UserError) as raised:
        _partitioned(cluster, grid, "never", on_level=kill_one)
    assert raised.value.exit_code == EXIT_WORKER_LOST == 5
    assert raised.value.diagnostics[0].code.code == "RMC752"
    # the next search starts afresh on new workers
    again, _, _ = _partitioned(cluster, grid, "never")
    assert again.verdict == HOLDS and again.stats.product_states == 1600


@pytest.mark.parametrize("name", CASES)
def test_check_case_on_two_workers(cluster, name, monkeypatch):
    """The same answers and counts as one process searching unreduced: on a cluster the
    partial-order reduction is off (its cycle proviso depends on the search order)."""
    case = load_case(CASES_DIR / name)
    object.__setattr__(case, "extra_args", case.extra_args + ("--no-por",))
    _, alone = report_of(case, monkeypatch)
    spread_case = load_case(CASES_DIR / name)
    object.__setattr__(spread_case, "extra_args", case.extra_args + ("--workers", "2"))
    _, spread = report_of(spread_case, monkeypatch)
    _same_builtin_answers(alone, spread)


@pytest.mark.parametrize("study, program", [("sorter", "sorter_b.mod"),
                                            ("door", "door_race.mod")])
def test_case_study_on_two_workers(cluster, study, program, monkeypatch):
    monkeypatch.chdir(ROOT / "case_studies" / study)
    argv = ["check", program, "--env", "plant.mod", "--format", "json", "--quiet"]
    _same_builtin_answers(_json(argv), _json(argv + ["--workers", "2"]))


@pytest.mark.parametrize("name, check", [("runtime_div_input", "no_runtime_error"),
                                         ("deadlock_waitdo_never_set", "no_deadlock")])
def test_counterexample_of_two_workers_replays(cluster, name, check, tmp_path, monkeypatch):
    monkeypatch.chdir(CASES_DIR / name)
    report = _json(["check", "prog.mod", "--format", "json", "--quiet", "--workers", "2"])
    assert _verdicts(report)[check] == "VIOLATED"
    trace = tmp_path / "trace.json"
    trace.write_text(json.dumps(report))
    code, out, err = _run(["replay", str(trace), "--property", check])
    assert code == 0, out + err


def test_swarm_finds_a_planted_deep_error_the_exhaustive_search_cannot_reach(cluster):
    program = str(HERE / "deep_error.mod")
    bound = ["--max-states", "20000", "--format", "json", "--quiet"]
    exhaustive = _json(["check", program, *bound])
    assert _verdicts(exhaustive)["no_runtime_error"] == "UNKNOWN"
    swarm = _json(["check", program, *bound, "--swarm", "2"])
    verdicts = _verdicts(swarm)
    assert verdicts["no_runtime_error"] == "VIOLATED"
    assert verdicts["no_deadlock"] == "UNKNOWN"                # a swarm never says HOLDS
    runtime = next(p for p in swarm["properties"] if p["name"] == "no_runtime_error")
    assert len(runtime["trace"]["prefix"]) > 6000             # deep: 1500 rounds of the loop


def test_without_ray_the_options_name_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "ray", None)            # import ray fails
    program = str(CASES_DIR / "runtime_div_input" / "prog.mod")
    for option in (["--workers", "2"], ["--ray", "auto"], ["--swarm", "3"]):
        code, _, err = _run(["check", program, "--quiet", *option])
        assert code == 2 and "[RMC751]" in err and "pip install 'rapidmc[ray]'" in err, err


def _same_builtin_answers(alone: dict, spread: dict) -> None:
    first, second = _by_name(alone), _by_name(spread)
    assert _verdicts(alone) == _verdicts(spread)
    for name in SAFETY:
        one, other = first[name], second[name]
        if one["verdict"] == "HOLDS" and one["stats"]["engine"] != "python-fair":
            for figure in ("product_states", "transitions", "max_depth", "deadlocks"):
                assert one["stats"][figure] == other["stats"][figure], (name, figure)
        if one["verdict"] == "VIOLATED" and not one["trace"]["cycle"]:
            assert len(one["trace"]["prefix"]) == len(other["trace"]["prefix"]), name


def _by_name(report: dict) -> dict:
    return {p["name"]: p for p in report["properties"]}


def _verdicts(report: dict) -> dict:
    return {p["name"]: p["verdict"] for p in report["properties"]}


def _json(argv: list[str]) -> dict:
    code, out, err = _run(argv)
    assert code in (0, 1, 3), err
    return json.loads(out)


def _run(argv: list[str]) -> tuple[int, str, str]:
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue(), err.getvalue()
