"""Distributed checking on a real local Ray cluster (``--workers``, ``--swarm``; issue 29).

The partitioned search must answer exactly what the one-process search answers: the
same verdicts, and after a complete search the same state, transition, deadlock and depth
counts; its counterexamples are as short and replay (``--eager``: the same verdicts and
counts but the depth, counterexamples that replay but may be longer).  LTL properties
(OWCTY over the partitioned product) give the verdicts and product counts of the
one-process search, on random toy graphs and on check cases, with lassos of real steps
that the formula rejects.  A lost worker ends the check with RMC752 (exit 5), never a
verdict; a swarm finds a planted deep error the exhaustive search
cannot reach in its bound, and never says HOLDS.

One Ray cluster (2 CPUs) serves the whole module: Ray takes seconds to start.  Without Ray
the tests skip, unless RAPIDMC_REQUIRE_RAY=1 (CI), where they fail.
"""
from __future__ import annotations

import contextlib
import functools
import json
import logging
import os
import random
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
from pathlib import Path
from types import SimpleNamespace

import pytest

from rapidmc.check import check_property, find_reachable
from rapidmc.check.budget import SearchBudget
from rapidmc.check.distributed.cluster import LOCAL_SYSTEM_CONFIG
from rapidmc.check.result import HOLDS, VIOLATED
from rapidmc.check.transition_system import labelled_successors
from rapidmc.diagnostics import EXIT_WORKER_LOST, UserError
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.lasso import holds_on_lasso
from test_check_cases import SAFETY, load_case, report_of, CASES_DIR
from tool_requirements import require_tool
from cli_capture import run_cli

try:
    import ray
except ImportError:
    ray = None

ROOT = Path(__file__).resolve().parent.parent
HERE = Path(__file__).resolve().parent / "distributed"
# a few check cases: a run-time error, a deadlock, several tasks, a bound, loops that hold
CASES = ["runtime_div_input", "deadlock_waitdo_never_set", "tasks_test_and_set",
         "max_states_unknown", "loop_mod_counter", "runtime_array_index_safe",
         # LTL: lassos through stopped programs, until/release, HOA automata, fairness
         "loop_toggle", "ltl_until_release", "automaton_hoa", "tasks_fairness"]


@pytest.fixture(scope="module")
def cluster():
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    ray.cloudpickle.register_pickle_by_value(sys.modules[__name__])   # (the toy model below)
    ray.init(num_cpus=2, include_dashboard=False, logging_level=logging.ERROR,
             log_to_driver=False, _system_config=LOCAL_SYSTEM_CONFIG)   # (as --workers 2)
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


class RandomGraph:
    """A toy model: ``size`` states, each with 0-3 successors drawn from ``seed`` (0-successor
    states deadlock: the product repeats them), and atoms p and q true on random states."""

    def __init__(self, seed: int, size: int):
        rng = random.Random(seed)
        self.edges = [rng.sample(range(size), rng.choice((0, 1, 1, 2, 2, 3)))
                      for _ in range(size)]
        self.atoms = {"p": {s for s in range(size) if rng.random() < 0.4},
                      "q": {s for s in range(size) if rng.random() < 0.5}}

    def initial_states(self):
        return (0,)

    def successors(self, state):
        return [(f"{state}->{target}", target) for target in self.edges[state]]

    def letter(self, state) -> set:
        return {name for name, states in self.atoms.items() if state in states}


def toy_job(seed: int, size: int, formula: str):
    """(system, automaton of the formula's negation, valuation): what a worker rebuilds."""
    system = RandomGraph(seed, size)
    buchi = to_buchi(parse_formula(f"!({formula})"), backend="builtin", atoms=("p", "q"))

    def valuation(state):
        return sum(1 << index for index, atom in enumerate(buchi.atoms)
                   if state in system.atoms[atom])

    return system, buchi, valuation


def toy_model(seed: int, size: int, formula: str):
    system, buchi, valuation = toy_job(seed, size, formula)
    return SimpleNamespace(system=system, jobs=[(SimpleNamespace(name="prop"), buchi, valuation)])


TOY_FORMULAS = ["G F p", "F G q", "G (p -> F q)", "p U q", "G (p -> X !p)", "F p", "G !q",
                "(G F p) -> (G F q)", "q W p", "X X p"]


# every other seed: graphs of 6 to 36 states (each distributed search starts its workers
# anew, which costs far more than the graph; the odd seeds only added sizes in between)
@pytest.mark.parametrize("seed", range(0, 12, 2))
def test_owcty_answers_what_one_process_answers(cluster, seed):
    """Distributed OWCTY against the one-process search on random graphs and formulas: the
    same verdict; on HOLDS the same product states and transitions; on VIOLATED a lasso
    of real steps that the formula rejects."""
    from rapidmc.check.distributed.owcty import partitioned_accepting_cycle
    size = 6 + seed * 3
    for formula in TOY_FORMULAS:
        system, buchi, valuation = toy_job(seed, size, formula)
        one = check_property(system, buchi, valuation, max_states=None)
        spread, figures = partitioned_accepting_cycle(
            cluster, 2, system, buchi, valuation, "prop",
            functools.partial(toy_model, seed, size, formula))
        assert spread.verdict == one.verdict, (seed, formula)
        if one.verdict == HOLDS:
            assert spread.stats.product_states == one.stats.product_states, (seed, formula)
            assert spread.stats.transitions == one.stats.transitions, (seed, formula)
            continue
        steps = spread.prefix + spread.cycle
        moves = [(step.label, step.state) for step in steps[1:]] + \
            [(spread.closing_label, spread.cycle[0].state)]
        for before, move in zip(steps, moves):
            assert move in labelled_successors(system, before.state), (seed, formula)
        letters = [system.letter(step.state) for step in spread.prefix]
        loop = [system.letter(step.state) for step in spread.cycle]
        assert not holds_on_lasso(parse_formula(formula), letters, loop), (seed, formula)


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


@pytest.mark.parametrize("eager", [False, True])
def test_a_killed_worker_ends_the_search_without_a_verdict(cluster, eager):
    def kill_one(actors, levels=[]):
        levels.append(1)
        if len(levels) == 5:                                  # mid-search
            cluster.kill(actors[1])
    grid = Grid(40)
    with pytest.raises(UserError) as raised:
        _partitioned(cluster, grid, "never", on_level=kill_one, eager=eager)
    assert raised.value.exit_code == EXIT_WORKER_LOST == 5
    assert raised.value.diagnostics[0].code.code == "RMC752"
    # the next search starts afresh on new workers
    again, _, _ = _partitioned(cluster, grid, "never")
    assert again.verdict == HOLDS and again.stats.product_states == 1600


def _counters(inputs: int) -> str:
    """RAPID: ``inputs`` counters modulo 4, each stepped while its input is 1."""
    lines = ["MODULE Counters"]
    lines += [f"  VAR signaldi in{i};\n  VAR num c{i} := 0;" for i in range(inputs)]
    lines += ["  PROC main()"] + [f'    AliasIO "IN{i}", in{i};' for i in range(inputs)]
    lines += ["    WHILE TRUE DO"]
    lines += [f"      IF in{i} = 1 c{i} := (c{i} + 1) MOD 4;" for i in range(inputs)]
    lines += ["    ENDWHILE", "  ENDPROC", "ENDMODULE", ""]
    return "\n".join(lines)


def test_a_local_clusters_batches_pass_outside_the_object_store(cluster, tmp_path):
    """Counters N=7 (114,695 states): the wide levels' batches are above Ray's default
    100 KiB for objects passed inline, so by default they went through the shared object
    store and each worker mapped about 3.5 MB of its pages (measured).  The local
    cluster's settings (``LOCAL_SYSTEM_CONFIG``, as ``--workers N`` starts it) pass them in
    the calls' messages: the same states, and no more than a few pages mapped."""
    from dataclasses import replace
    from rapidmc import api
    from rapidmc.check.distributed.search import partitioned_reachable
    path = tmp_path / "counters.mod"
    path.write_text(_counters(7))
    options = api.CheckOptions()
    options = replace(options, reductions=replace(options.reductions, partial_order=False))
    model = api.prepare(api.load_program([str(path)]), [], options)
    one = find_reachable(model.system, model.system.failed, max_states=None)
    spread, _, figures = partitioned_reachable(cluster, 2, model.system, "failed",
                                               budget=SearchBudget(None),
                                               rebuild=api.system_recipe(model))
    assert spread.verdict == one.verdict == HOLDS
    assert spread.stats.product_states == one.stats.product_states == 114_695
    assert all(f["sent_bytes"] > 1_000_000 for f in figures)
    assert all(f["peak_shared_kb"] < 1024 for f in figures), figures


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


@pytest.mark.parametrize("name", CASES[:6])
def test_check_case_on_two_eager_workers(cluster, name, monkeypatch, tmp_path):
    """``--eager``: the same verdicts and counts as one process but the depth; its
    counterexamples replay (they may be longer than one process's)."""
    case = load_case(CASES_DIR / name)
    object.__setattr__(case, "extra_args", case.extra_args + ("--no-por",))
    _, alone = report_of(case, monkeypatch)
    spread_case = load_case(CASES_DIR / name)
    object.__setattr__(spread_case, "extra_args",
                       case.extra_args + ("--workers", "2", "--eager"))
    _, spread = report_of(spread_case, monkeypatch)
    _same_builtin_answers(alone, spread, eager=True)
    violated = [p["name"] for p in spread["properties"]
                if p["name"] in SAFETY and p["verdict"] == "VIOLATED"]
    if violated:
        monkeypatch.chdir(CASES_DIR / name)
        trace = tmp_path / "trace.json"
        trace.write_text(json.dumps(spread))
        for check in violated:
            code, out, err = run_cli(["replay", str(trace), "--property", check])
            assert code == 0, out + err


def test_eager_asks_for_workers():
    program = str(CASES_DIR / "runtime_div_input" / "prog.mod")
    for option in ([], ["--swarm", "2"]):
        code, _, err = run_cli(["check", program, "--quiet", "--eager", *option])
        assert code == 2 and "--eager" in err, err


@pytest.mark.parametrize("eager", [False, True])
@pytest.mark.parametrize("study, program", [("sorter", "sorter_b.mod"),
                                            ("door", "door_race.mod")])
def test_case_study_on_two_workers(cluster, study, program, eager, monkeypatch):
    """The built-in checks and the study's LTL properties (specs/), against --no-por
    (``eager``: with --eager)."""
    monkeypatch.chdir(ROOT / "case_studies" / study)
    argv = ["check", program, "--env", "plant.mod", "--ltl", str(ROOT / "specs" / f"{study}.ltl"),
            "--format", "json", "--quiet"]
    _same_builtin_answers(_json(argv + ["--no-por"]),
                          _json(argv + ["--workers", "2"] + ["--eager"] * eager), eager=eager)


@pytest.mark.parametrize("name, check", [("runtime_div_input", "no_runtime_error"),
                                         ("deadlock_waitdo_never_set", "no_deadlock")])
def test_counterexample_of_two_workers_replays(cluster, name, check, tmp_path, monkeypatch):
    monkeypatch.chdir(CASES_DIR / name)
    report = _json(["check", "prog.mod", "--format", "json", "--quiet", "--workers", "2"])
    assert _verdicts(report)[check] == "VIOLATED"
    trace = tmp_path / "trace.json"
    trace.write_text(json.dumps(report))
    code, out, err = run_cli(["replay", str(trace), "--property", check])
    assert code == 0, out + err


def test_lasso_below_many_accepting_states_on_no_cycle_replays(cluster, tmp_path,
                                                              monkeypatch):
    """The lasso takes one spread however many accepting states OWCTY leaves that lie on no
    cycle: here 4,096 (over 2,000 per partition) come breadth-first before the one that
    does, where the lasso used to try them one by one and gave up after 1,024 per
    partition with an internal error."""
    monkeypatch.chdir(HERE)
    report = _json(["check", "accepting_below_a_cycle.mod", "--ltl", "accepting_below_a_cycle.ltl",
                    "--format", "json", "--quiet", "--workers", "2"])
    found = _by_name(report)["finally_done"]
    assert (found["verdict"], found["stats"]["engine"]) == ("VIOLATED", "distributed-owcty")
    trace = tmp_path / "trace.json"
    trace.write_text(json.dumps(report))
    code, out, err = run_cli(["replay", str(trace), "--property", "finally_done"])
    assert code == 0, out + err
    assert "the counterexample replays" in out + err


def test_swarm_finds_a_planted_deep_error_the_exhaustive_search_cannot_reach(cluster):
    program = str(HERE / "deep_error.mod")
    bound = ["--max-states", "5000", "--format", "json", "--quiet"]
    exhaustive = _json(["check", program, *bound])
    assert _verdicts(exhaustive)["no_runtime_error"] == "UNKNOWN"
    swarm = _json(["check", program, *bound, "--swarm", "2"])
    verdicts = _verdicts(swarm)
    assert verdicts["no_runtime_error"] == "VIOLATED"
    assert verdicts["no_deadlock"] == "UNKNOWN"                # a swarm never says HOLDS
    runtime = next(p for p in swarm["properties"] if p["name"] == "no_runtime_error")
    assert len(runtime["trace"]["prefix"]) > 1200             # deep: 300 rounds of the loop


def test_without_ray_the_options_name_the_extra(monkeypatch):
    monkeypatch.setitem(sys.modules, "ray", None)            # import ray fails
    program = str(CASES_DIR / "runtime_div_input" / "prog.mod")
    for option in (["--workers", "2"], ["--ray", "auto"], ["--swarm", "3"]):
        code, _, err = run_cli(["check", program, "--quiet", *option])
        assert code == 2 and "[RMC751]" in err and "pip install 'rapidmc[ray]'" in err, err


def _same_builtin_answers(alone: dict, spread: dict, eager: bool = False) -> None:
    """The same verdicts; after a complete search the same counts (the built-in checks:
    states, transitions, deadlocks, depth; LTL properties searched without fairness: product
    states and transitions), and safety counterexamples as short (``eager``: neither the
    depth nor the counterexamples' length)."""
    first, second = _by_name(alone), _by_name(spread)
    assert _verdicts(alone) == _verdicts(spread)
    for name, one in first.items():
        other = second[name]
        figures = ("product_states", "transitions", "deadlocks") + ("max_depth",) * \
            (not eager) if name in SAFETY else ("product_states", "transitions")
        if one["verdict"] == "HOLDS" and one["stats"]["engine"] != "python-fair":
            for figure in figures:
                assert one["stats"][figure] == other["stats"][figure], (name, figure)
        if name in SAFETY and one["verdict"] == "VIOLATED" and not one["trace"]["cycle"] \
                and not eager:
            assert len(one["trace"]["prefix"]) == len(other["trace"]["prefix"]), name
        refair = f"the cycle the cluster found for {name} starves a task"
        if name not in SAFETY and other["verdict"] != "UNKNOWN" and \
                not any(refair in warning["message"] for warning in spread["warnings"]):
            assert other["stats"]["engine"] == "distributed-owcty", name   # not one process


def _by_name(report: dict) -> dict:
    return {p["name"]: p for p in report["properties"]}


def _verdicts(report: dict) -> dict:
    return {p["name"]: p["verdict"] for p in report["properties"]}


def _json(argv: list[str]) -> dict:
    code, out, err = run_cli(argv)
    assert code in (0, 1, 3), err
    return json.loads(out)


def test_a_cycle_that_starves_a_task_is_searched_again_fairly_with_a_note(cluster,
                                                                            monkeypatch):
    """Weak fairness between tasks is never dropped on a cluster: the unfair cycles the
    workers find are searched again in one process, and a note names the property."""
    monkeypatch.chdir(CASES_DIR / "tasks_fairness")
    code, out, err = run_cli(["check", "prog.mod", "--ltl", "props.ltl", "--add-task", "b.mod",
                              "--workers", "2", "--quiet"])
    assert code == 1, err
    assert "the cycle the cluster found for seen_again starves a task" in err
    assert "[RMC753]" in err


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


def test_ray_address_joins_a_running_cluster(tmp_path):
    """``--ray ADDRESS`` joins a cluster that ``ray start --head`` runs (its own processes,
    stopped afterwards by ending that command), and answers as one process does."""
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    port = _free_port()
    # a cluster of this test's own: its own temporary folder, and no token from ~/.ray
    env = dict(os.environ, RAY_AUTH_MODE="disabled")
    temp = tempfile.mkdtemp(prefix="/tmp/rmc")           # (Ray's socket paths must be short)
    head = subprocess.Popen(
        [sys.executable, "-m", "ray.scripts.scripts", "start", "--head", f"--port={port}",
         "--node-ip-address=127.0.0.1", "--num-cpus=2", "--include-dashboard=false",
         "--disable-usage-stats", f"--temp-dir={temp}", "--block"],
        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=env, start_new_session=True)
    try:
        case = CASES_DIR / "loop_toggle"
        run = subprocess.run(
            [sys.executable, "-m", "rapidmc", "check", "prog.mod", "--ltl", "props.ltl",
             "--ray", f"127.0.0.1:{port}", "--format", "json", "--quiet"],
            cwd=case, env=env, capture_output=True, text=True, timeout=600)
        assert run.returncode == 1, run.stderr[-2000:]
        report = json.loads(run.stdout)
        expected = dict(line.split() for line in (case / "expected").read_text().splitlines()
                        if line.strip() and not line.startswith("#"))
        assert _verdicts(report) == expected
        engines = {p["stats"]["engine"] for p in report["properties"]}
        assert engines == {"distributed", "distributed-owcty"}
    finally:
        head.send_signal(signal.SIGTERM)                 # (ray start --block stops its node)
        try:
            head.wait(timeout=90)
        except subprocess.TimeoutExpired:
            os.killpg(head.pid, signal.SIGKILL)
            head.wait()
        shutil.rmtree(temp, ignore_errors=True)


def test_an_address_with_no_cluster_is_a_diagnostic(monkeypatch):
    """Ray's failure to join (here: refused) is RMC754 with exit 2, not an internal error."""
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    from rapidmc.check.distributed import Cluster, cluster as joining

    def refuse(**options):
        raise ConnectionError("Failed to connect to Ray cluster at 127.0.0.1:9")
    monkeypatch.setattr(joining, "_answers", lambda address, seconds: None)   # (Ray is asked)
    monkeypatch.setattr(ray, "is_initialized", lambda: False)
    monkeypatch.setattr(ray, "init", refuse)
    with pytest.raises(UserError) as raised:
        with Cluster(address="127.0.0.1:9").session():
            pass
    assert raised.value.exit_code == 2
    assert raised.value.diagnostics[0].code.code == "RMC754"


def test_a_local_cluster_that_does_not_start_is_a_diagnostic(monkeypatch):
    """Ray's processes timing out at start-up (a loaded machine) end --workers with RMC755 and
    exit 5, no verdict, never an internal error."""
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    from rapidmc.check.distributed import Cluster

    def time_out(**options):
        raise Exception("The current node timed out during startup. This could happen "
                        "because some of the Ray processes failed to startup.")
    monkeypatch.setattr(ray, "is_initialized", lambda: False)
    monkeypatch.setattr(ray, "init", time_out)
    with pytest.raises(UserError) as raised:
        with Cluster(workers=2).session():
            pass
    assert raised.value.exit_code == 5
    found = raised.value.diagnostics[0]
    assert found.code.code == "RMC755"
    assert "--workers: the local Ray cluster did not start" in found.message
    assert any("timed out during startup" in note for note in found.notes)


def test_a_host_that_does_not_exist_is_a_diagnostic_not_a_hang():
    """``--ray notahost:1``: Ray would retry for minutes; the check ends at once with RMC754
    and exit 2 (the timeout is a hang's, far above the wait it allows)."""
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    run = subprocess.run([sys.executable, "-m", "rapidmc", "check", "prog.mod", "--ray",
                          "notahost:1", "--quiet"], cwd=CASES_DIR / "loop_toggle",
                         capture_output=True, text=True, timeout=100)
    assert run.returncode == 2, run.stderr[-2000:]
    assert "--ray notahost:1: no Ray cluster to join there [RMC754]" in run.stderr


@pytest.mark.parametrize("reply, why", [(None, "no answer within 1 s"),
                                        (b"HTTP/1.1 400 Bad Request\r\n\r\n",
                                         "answers, but not as a Ray cluster does")])
def test_an_address_that_does_not_answer_as_ray_is_a_diagnostic(monkeypatch, reply, why):
    """A port that accepts but says nothing, or answers another protocol: RMC754 within the
    wait (``CONNECT_SECONDS``, here 1 s), and Ray is never asked (it would retry for
    minutes)."""
    require_tool(ray is not None, "RAPIDMC_REQUIRE_RAY", "Ray is not installed (the 'ray' extra)")
    from rapidmc.check.distributed import Cluster, cluster as joining

    def asked(**options):
        raise AssertionError("Ray was asked to join an address that does not answer as Ray")
    monkeypatch.setattr(joining, "CONNECT_SECONDS", 1)
    monkeypatch.setattr(ray, "is_initialized", lambda: False)
    monkeypatch.setattr(ray, "init", asked)
    with socket.socket() as listener:
        listener.bind(("127.0.0.1", 0))
        listener.listen(1)
        port = listener.getsockname()[1]

        def serve():
            peer, _ = listener.accept()
            with peer, contextlib.suppress(OSError):    # (the prober may reset it)
                if reply is not None:
                    peer.recv(64)
                    peer.sendall(reply)
                while peer.recv(64):       # (until the prober hangs up)
                    pass
        server = threading.Thread(target=serve, daemon=True)
        server.start()
        with pytest.raises(UserError) as raised:
            with Cluster(address=f"127.0.0.1:{port}").session():
                pass
    assert raised.value.exit_code == 2
    assert raised.value.diagnostics[0].code.code == "RMC754"
    assert why in str(raised.value.diagnostics[0])
