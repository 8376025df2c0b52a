"""One process against a local Ray cluster of 2 workers (``--workers 2``, issue 29).

Usage: python bench/distributed.py [--issue] [--eager] [--counters 6,7] [--modulo 4] [--only NAME]
                                   [--workers 2] [--ltl] [--split] [--rounds [--payload B]]
                                   [--start-memory] [--pair] [--owners data|state]

For each model, each in a fresh process: the run-time error search of a check (breadth-first,
the whole reachable state space, since these programs have no run-time error), once in one
process (``find_reachable``, the default engine) and once hash-partitioned over the workers
(``check.distributed.search``).  Models: the whole-controller family of bench/tasks.py (two
tasks sharing PERS data, interrupts, a socket server, a ROS server: steps mostly in Python)
and bench/check.py's counters family (N inputs, N counters modulo K: the compiled step
machine where it is built).

Columns: states; breadth-first levels; wall seconds of one process and of the workers (Ray's
start-up apart) and their ratio; CPU seconds of the one process, of each worker (the whole
process) and of that, in ``Partition.step`` (the rest is Ray's); the CPU speed-up (one
process's CPU over the busier worker's: the wall speed-up on free cores, Ray's waits apart);
bytes sent to other workers per state; peak RSS of the one process and of each worker (ru_maxrss,
nothing subtracted: a worker's counts the pages of Ray's object store it touched) and the
larger worker's against the one process's; each worker's share of the states.  Then the
whole-controller family's totals (the issue's 1.7x target) and ``uptime`` before and after:
the machine may be shared, where wall times mean little and CPU times are the figures.

``--eager``: the workers search with ``--eager`` (rounds without breadth-first levels; the
levels column is then the rounds).  ``--owners data`` / ``--owners state``: the workers' states
are owned by their data (a packed model's data segment, else the global data part: a step
that writes no global data stays with its worker) or by the whole state, instead of as the
search decides from the first states (``codec.data_owners_fit``).

``--issue``: only the issue's figures, the whole-controller family and counters N=10 (a few
minutes on a quiet 2-core machine).

``--ltl``: the same for each whole-controller model's LTL property (bench/tasks.py's), a
property of each case study (specs/) and the counters' (``G`` of every counter below the
modulo), all of which hold, so the whole product is searched: in one process
(``check_property``, partial-order reduction off as on a cluster) against OWCTY on the
workers (``owcty``), with the one process's CPU seconds against the busier worker's.

``--start-memory``: a worker's memory as it starts (a plain process and a Ray actor): RSS
after numpy, the search's modules, the counters N=10 model and its table.

Each worker's idle time (wall seconds outside its calls) and how long none, one or both
workers were inside a call are printed under each model.

``--split``: without Ray, two partitions driven in one process (``partition.search_here``,
eager with ``--eager``): their CPU seconds together against one process's, and the bytes
they sent per state.

``--pair``: what two busy cores cost per unit of work on this machine, without Ray or
partitions: each model's one-process search alone, then two of the same search at once (two
processes), the CPU seconds of each.  Two workers spend at least the pair's CPU per state
(each steps its share with the other core busy), so the wall speed-up of 2 workers on 2 cores
is at most 2 x (alone / pair), whatever the distribution costs on top (run it on a quiet
machine: on a loaded one, "alone" shares its core too).

``--rounds``: Ray's own cost of a round, without a model: two actors exchange a batch of
``--payload`` bytes per round, (a) relayed by the driver (it calls each actor with the
other's batch, an object the driver owns, as its argument: the search before
``rounds.Levels``), (b) from actor to actor (each actor calls the other's ``deliver``, an
asyncio actor waits in ``step`` until its batch arrived; the driver calls ``step`` only) and
(c) driven by a worker, as the search does now (the first actor calls the other's ``step``
and steps its own share meanwhile; the driver calls it once): wall, driver and worker CPU
milliseconds per round.
"""
from __future__ import annotations

import argparse
import json
import logging
import pickle
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

from check import counters_formula, counters_program  # noqa: E402  (bench/check.py)
from tasks import MODELS, load      # noqa: E402  (bench/tasks.py)

from rapidmc import api  # noqa: E402


def _start_ray(ray, workers: int) -> float:
    """Start a local Ray cluster of ``workers`` CPUs, quietly; the seconds it took."""
    started = time.perf_counter()
    from rapidmc.check.distributed.cluster import LOCAL_SYSTEM_CONFIG   # (as --workers N)
    ray.init(num_cpus=workers, include_dashboard=False, logging_level=logging.ERROR,
             log_to_driver=False, _system_config=LOCAL_SYSTEM_CONFIG)
    return time.perf_counter() - started


def tree_cpu(root: int) -> dict[int, tuple[str, float]]:
    """CPU seconds (user + system) of ``root`` and of every live process below it, by pid,
    with each one's name (Linux /proc): the driver, Ray's own processes (``raylet``,
    ``gcs_server``, its agents) and the workers, whose CPU all comes out of the same cores."""
    import os
    tick = os.sysconf("SC_CLK_TCK")
    found: dict[int, tuple[int, str, float]] = {}
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as stat:
                text = stat.read()
        except OSError:
            continue
        name = text[text.index("(") + 1:text.rindex(")")]
        fields = text[text.rindex(")") + 2:].split()
        found[int(entry)] = (int(fields[1]), name, (int(fields[11]) + int(fields[12])) / tick)
    below, grew = {root}, True
    while grew:
        grew = False
        for pid, (parent, _, _) in found.items():
            if parent in below and pid not in below:
                below.add(pid)
                grew = True
    return {pid: found[pid][1:] for pid in below if pid in found}


def cpu_by_kind(before: dict, after: dict, driver: int, workers) -> dict[str, float]:
    """The CPU seconds each kind of process spent between two ``tree_cpu`` readings: the
    driver, the workers, and Ray's other processes by name."""
    spent: dict[str, float] = {}
    for pid, (name, seconds) in after.items():
        kind = "driver" if pid == driver else "workers" if pid in workers else name
        spent[kind] = spent.get(kind, 0.0) + seconds - before.get(pid, (name, 0.0))[1]
    return spent


def model_of(name: str, modulo: int):
    """The model, partial-order reduction off as on a cluster (its cycle proviso depends on
    the search order: with it, the two searches would store different states)."""
    if name.startswith("counters N="):
        inputs = int(name.split("=")[1])
        folder = tempfile.mkdtemp()
        path = Path(folder) / "counters.mod"
        path.write_text(counters_program(inputs, modulo))
        return api.prepare(api.load_program([str(path)]), [], unreduced_order(api.CheckOptions()))
    _, files, tasks, _, options = next(model for model in MODELS if model[0] == name)
    return api.prepare(load(files, tasks), [], unreduced_order(api.CheckOptions(**options)))


def unreduced_order(options):
    from dataclasses import replace
    return replace(options, reductions=replace(options.reductions, partial_order=False))


def pickled_bytes(system, sample: int = 300) -> float:
    """The mean pickled size of the first states breadth-first (what a batch carries)."""
    seen, frontier = [], list(system.initial_states())
    while frontier and len(seen) < sample:
        state = frontier.pop(0)
        seen.append(state)
        frontier.extend(after for _, after in system.successors(state))
    return sum(len(pickle.dumps(state, protocol=5)) for state in seen) / len(seen)


# (name, case study, program, property of specs/STUDY.ltl): properties that hold
STUDIES = (("sorter A P2", "sorter", "sorter_a.mod", "P2"),
           ("door safe D2", "door", "door_safe.mod", "D2"))


def ltl_model_of(name: str, modulo: int = 4):
    """The model with its LTL property, partial-order reduction off (as on a cluster)."""
    options = unreduced_order(api.CheckOptions())
    if name.startswith("counters N="):
        inputs = int(name.split("=")[1])
        path = Path(tempfile.mkdtemp()) / "counters.mod"
        path.write_text(counters_program(inputs, modulo))
        return api.prepare(api.load_program([str(path)]),
                           [api.property_from_text(f"bound: {counters_formula(inputs, modulo)}")],
                           options)
    study = next((study for study in STUDIES if study[0] == name), None)
    if study is not None:
        _, folder, program, prop = study
        root = Path(__file__).resolve().parent.parent
        properties = [p for p in api.read_properties(str(root / "specs" / f"{folder}.ltl"))
                      if p.name == prop]
        files = [str(root / "case_studies" / folder / f) for f in (program, "plant.mod")]
        return api.prepare(api.load_program(files[:1], files[1:]), properties, options)
    _, files, tasks, formula, options = next(model for model in MODELS if model[0] == name)
    return api.prepare(load(files, tasks), [api.property_from_text(formula)],
                       unreduced_order(api.CheckOptions(**options)))


def measure_ltl(name: str, mode: str, modulo: int, workers: int) -> dict:
    model = ltl_model_of(name, modulo)
    prop, buchi, valuation = model.jobs[0]
    if mode == "ltl-single":
        from rapidmc.check import check_property
        started, cpu = time.perf_counter(), time.process_time()
        result = check_property(model.system, buchi, valuation, max_states=None)
        return {"verdict": result.verdict, "states": result.stats.product_states,
                "seconds": time.perf_counter() - started, "cpu": time.process_time() - cpu,
                "max_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}
    import ray
    from rapidmc.check.budget import SearchBudget
    from rapidmc.check.distributed.owcty import partitioned_accepting_cycle
    start_seconds = _start_ray(ray, workers)
    recipe = api.model_recipe(model)
    partitioned_accepting_cycle(ray, workers, model.system, buchi, valuation, prop.name, recipe,
                                budget=SearchBudget(1))          # (actors start, model built)
    started = time.perf_counter()
    result, figures = partitioned_accepting_cycle(ray, workers, model.system, buchi, valuation,
                                                  prop.name, recipe, budget=SearchBudget(None))
    seconds = time.perf_counter() - started
    ray.shutdown()
    return {"verdict": result.verdict, "states": result.stats.product_states,
            "seconds": seconds, "start_seconds": start_seconds,
            "sent": sum(f["sent"] for f in figures), "pickled": pickled_bytes(model.system),
            "sent_bytes": sum(f.get("sent_bytes", 0) for f in figures),
            "worker_rss_kb": [f["max_rss_kb"] for f in figures],
            "worker_cpu": [f["cpu_seconds"] for f in figures],
            "worker_states": [f["states"] for f in figures]}


def measure_split(name: str, modulo: int) -> dict:
    """CPU seconds of a worker's parts, two partitions driven here (module docstring)."""
    from rapidmc.check import find_reachable
    from rapidmc.check.distributed.partition import search_here
    system = model_of(name, modulo).system
    started = time.process_time()
    single = find_reachable(system, system.failed, max_states=None)
    cpu = {"single": time.process_time() - started}
    system = model_of(name, modulo).system      # (afresh: the model's caches are warm)
    started = time.process_time()
    parts, _, _ = search_here(system, 2, eager=EAGER)
    cpu["split"] = time.process_time() - started
    states = sum(len(part.table) for part in parts)
    assert states == single.stats.product_states
    return {"states": states, "cpu": cpu, "codec": type(parts[0].codec).__name__,
            "bytes": sum(part.sent_bytes for part in parts)}


def measure(name: str, mode: str, modulo: int, workers: int) -> dict:
    """One measurement in this process (the parent runs each in a fresh one)."""
    if mode.startswith("ltl-"):
        return measure_ltl(name, mode, modulo, workers)
    if mode == "split":
        return measure_split(name, modulo)
    model = model_of(name, modulo)
    system = model.system
    if mode == "single":
        from rapidmc.check import find_reachable
        started, cpu = time.perf_counter(), time.process_time()
        result = find_reachable(system, system.failed, max_states=None)
        seconds = time.perf_counter() - started
        return {"verdict": result.verdict, "states": result.stats.product_states,
                "seconds": seconds, "engine": result.stats.engine,
                "cpu": time.process_time() - cpu,
                "max_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}
    import ray
    from rapidmc.check.budget import SearchBudget
    from rapidmc.check.distributed.search import partitioned_reachable
    start_seconds = _start_ray(ray, workers)
    # the actors' processes start here, outside the timed search (as in one process's import)
    recipe = api.system_recipe(model)        # (each worker builds the system itself)
    partitioned_reachable(ray, workers, system, "failed", budget=SearchBudget(1),
                          rebuild=recipe, eager=EAGER, by_data=OWNERS)
    import os
    cpu_before = tree_cpu(os.getpid())
    started = time.perf_counter()
    driver_cpu = time.process_time()
    result, _, figures = partitioned_reachable(ray, workers, system, "failed",
                                               budget=SearchBudget(None), rebuild=recipe,
                                               eager=EAGER, by_data=OWNERS)
    seconds = time.perf_counter() - started
    driver_cpu = time.process_time() - driver_cpu
    every_cpu = cpu_by_kind(cpu_before, tree_cpu(os.getpid()), os.getpid(),
                            {f["pid"] for f in figures})
    ray.shutdown()
    return {"verdict": result.verdict, "states": result.stats.product_states,
            "seconds": seconds, "start_seconds": start_seconds, "driver_cpu": driver_cpu,
            "every_cpu": every_cpu, "levels": figures[0]["rounds"] if EAGER else
            result.stats.max_depth + 1,
            "sent": sum(f["sent"] for f in figures),
            "sent_bytes": sum(f["sent_bytes"] for f in figures),
            "worker_rss_kb": [f["max_rss_kb"] for f in figures],
            "worker_start_rss_kb": [f["start_rss_kb"] for f in figures],
            "worker_private_kb": [f["peak_private_kb"] for f in figures],
            "worker_bytes": [f["bytes"] for f in figures],
            "worker_link_file": [f["link_file_bytes"] for f in figures],
            "worker_cpu": [f["cpu_seconds"] for f in figures],
            "worker_step_cpu": [f["step_seconds"] for f in figures],
            "worker_step_thread": [f["step_thread"] for f in figures],
            "worker_idle": [f["wall_seconds"] - f["step_wall"] for f in figures],
            "worker_calls": [f["calls"] for f in figures],
            "stepping": stepping_together([f["spans"] for f in figures]),
            "worker_states": [f["states"] for f in figures]}


def measure_start_memory() -> None:
    """bench/worker_memory.py's stages in a fresh plain process and in a Ray actor."""
    run = subprocess.run([sys.executable, str(HERE / "worker_memory.py")],
                         capture_output=True, text=True, check=True)
    print(run.stdout.strip(), flush=True)


def stepping_together(spans: list) -> list:
    """Wall seconds in which 0, 1, ... of the workers were inside a call (``spans``: each
    worker's calls' wall-clock starts and ends), from the first call's start to the last
    one's end: where the lock-step rounds made them step in turn, and the waits."""
    edges = sorted((moment, change) for calls in spans for start, end in calls
                   for moment, change in ((start, 1), (end, -1)))
    seconds = [0.0] * (len(spans) + 1)
    inside, before = 0, edges[0][0] if edges else 0.0
    for moment, change in edges:
        seconds[inside] += moment - before
        inside, before = inside + change, moment
    return seconds


class _Relayed:
    """(a) a round as the search runs it: the batch comes in as the driver's argument."""

    def __init__(self, payload: int):
        self.payload = payload

    def cpu(self) -> float:
        return time.process_time()

    def step(self, *batches):
        return b"x" * self.payload, b"", len(batches)


class _Pushed:
    """(b) a round from actor to actor: ``step`` waits for the peer's batch, then sends
    its own to the peer directly."""

    def __init__(self, payload: int):
        import asyncio
        self.payload, self.inbox, self.arrived = payload, [], asyncio.Event()

    def cpu(self) -> float:
        return time.process_time()

    def meet(self, peer) -> None:
        self.peer = peer

    async def deliver(self, batch: bytes) -> None:
        self.inbox.append(batch)
        self.arrived.set()

    async def step(self, expected: int) -> int:
        while len(self.inbox) < expected:
            self.arrived.clear()
            await self.arrived.wait()
        del self.inbox[:expected]
        self.peer.deliver.remote(b"x" * self.payload)
        return expected


class _Leading(_Relayed):
    """(c) a round as the search runs it now (``rounds.Levels``): the first actor calls the
    other's ``step`` with its batch, steps its own share meanwhile, and takes the other's
    batch from the answer; the driver calls ``lead`` once."""

    def meet(self, peer) -> None:
        self.peer = peer

    def lead(self, rounds: int) -> int:
        import ray
        stepped = self.peer.step.options(num_returns=3).remote()
        mine = self.step()
        for _ in range(rounds):
            ray.get(stepped[2])
            batch = ray.get(stepped[0])
            stepped = self.peer.step.options(num_returns=3).remote(mine[0])
            mine = self.step(batch)
        ray.get(stepped[2])
        return rounds


def measure_rounds(payload: int, rounds: int = 300) -> None:
    import ray
    _start_ray(ray, 2)
    for name in ("relayed by the driver", "actor to actor", "driven by a worker") * 2:
        pushed, leading = name == "actor to actor", name == "driven by a worker"
        actor_class = ray.remote(num_cpus=1)(
            _Pushed if pushed else _Leading if leading else _Relayed)
        actors = [actor_class.remote(payload) for _ in range(2)]
        if pushed or leading:
            ray.get([actor.meet.remote(actors[1 - i]) for i, actor in enumerate(actors)])
        ray.get([actor.step.remote(0) if pushed else actor.cpu.remote() for actor in actors])
        cpu = ray.get([actor.cpu.remote() for actor in actors])
        driver, started = time.process_time(), time.perf_counter()
        stepped = [actor.step.options(num_returns=3).remote() for actor in actors] \
            if not (pushed or leading) else None
        if leading:
            ray.get(actors[0].lead.remote(rounds))
        for _ in range(0 if leading else rounds):
            if pushed:
                ray.get([actor.step.remote(1) for actor in actors])
                continue
            ray.get([refs[2] for refs in stepped])
            stepped = [actor.step.options(num_returns=3).remote(stepped[1 - i][0])
                       for i, actor in enumerate(actors)]
        if stepped is not None:
            ray.get([refs[2] for refs in stepped])
        wall, driver = time.perf_counter() - started, time.process_time() - driver
        workers = [after - before for before, after in
                   zip(cpu, ray.get([actor.cpu.remote() for actor in actors]))]
        print(f"{name:22} {payload:>8} B: wall {1e3 * wall / rounds:5.2f} ms a round, "
              f"driver {1e3 * driver / rounds:5.2f} ms, workers "
              f"{_each([1e3 * w / rounds for w in workers], '.2f')} ms", flush=True)
        for actor in actors:
            ray.kill(actor)
    ray.shutdown()


EAGER = False            # (--eager: the workers' searches are eager)
OWNERS = None            # (--owners data | state: True | False; None: the search decides)


def fresh(name: str, mode: str, modulo: int, workers: int) -> dict:
    run = subprocess.run([sys.executable, __file__, "--measure", name, mode,
                          "--modulo", str(modulo), "--workers", str(workers)] +
                         ["--eager"] * EAGER +
                         ([] if OWNERS is None else ["--owners", "data" if OWNERS else "state"]),
                         capture_output=True, text=True, check=True)
    return json.loads(run.stdout.strip().splitlines()[-1])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--counters", default="6,7", help="N of the counters family")
    parser.add_argument("--modulo", type=int, default=4)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--only", default=None, help="only the models whose name holds this")
    parser.add_argument("--ltl", action="store_true", help="time the LTL searches instead")
    parser.add_argument("--split", action="store_true",
                        help="where a worker's CPU time goes (no Ray)")
    parser.add_argument("--issue", action="store_true",
                        help="the issue's figures only: the whole-controller family and "
                             "counters N=10 (a few minutes on a quiet machine)")
    parser.add_argument("--rounds", action="store_true",
                        help="Ray's cost of a round: the driver relaying batches against "
                             "actors sending them to each other")
    parser.add_argument("--payload", type=int, default=20000,
                        help="bytes of a batch for --rounds")
    parser.add_argument("--eager", action="store_true",
                        help="the workers search eagerly (rounds without levels)")
    parser.add_argument("--start-memory", action="store_true",
                        help="a worker's memory as it starts, stage by stage")
    parser.add_argument("--owners", choices=("data", "state"), default=None,
                        help="the workers' states owned by their data or the whole state")
    parser.add_argument("--pair", action="store_true",
                        help="one search alone against two of it at once (the cores' cost)")
    parser.add_argument("--measure", nargs=2, default=None, help=argparse.SUPPRESS)
    args = parser.parse_args()
    global EAGER, OWNERS
    EAGER = args.eager
    OWNERS = None if args.owners is None else args.owners == "data"
    if args.start_memory:
        measure_start_memory()
        return
    if args.rounds:
        print(f"uptime at the start: {uptime()}", flush=True)
        measure_rounds(args.payload)
        print(f"uptime at the end: {uptime()}")
        return
    if args.issue:
        args.counters, args.ltl, args.split, args.only = "10", False, False, None
    if args.measure is not None:
        print(json.dumps(measure(*args.measure, args.modulo, args.workers)))
        return
    names = [model[0] for model in MODELS] + \
        [study[0] for study in STUDIES if args.ltl] + \
        [f"counters N={n}" for n in args.counters.split(",") if n]
    names = [name for name in names if not args.only or args.only in name]
    if args.split:
        print_split(names, args.modulo)
        return
    if args.pair:
        print_pair(names, args.modulo)
        return
    print(f"uptime at the start: {uptime()}", flush=True)
    if args.ltl:
        print_ltl(names, args.modulo, args.workers)
    else:
        print_safety(names, args.modulo, args.workers)
    print(f"uptime at the end: {uptime()}")


def uptime() -> str:
    return subprocess.run(["uptime"], capture_output=True, text=True).stdout.strip()


def print_safety(names, modulo: int, workers: int) -> None:
    """One process against the workers, per model, then the whole-controller family's totals
    (the issue's speed target) and each worker's peak RSS against one process's."""
    print(f"{'model':16} {'states':>9} {'levels':>6} {'1 proc s':>8} {f'{workers} wkr s':>8} "
          f"{'wall x':>6} {'1 CPU s':>7} {'wkr CPU s':>11} {'in step s':>11} {'drv s':>5} "
          f"{'CPU x':>6} {'B/state':>7} {'RSS 1 MB':>8} {'RSS wkr MB':>11} {'RSS %':>5} {'balance':>7}",
          flush=True)
    family = {"single": 0.0, "workers": 0.0, "single_cpu": 0.0, "worker_cpu": 0.0}
    for name in names:
        single = fresh(name, "single", modulo, workers)
        spread = fresh(name, "workers", modulo, workers)
        assert (single["verdict"], single["states"]) == (spread["verdict"], spread["states"])
        states = single["states"]
        busiest = max(spread["worker_cpu"])
        heaviest = max(spread["worker_rss_kb"])
        print(f"{name:16} {states:>9,} {spread['levels']:>6} {single['seconds']:>8.2f} "
              f"{spread['seconds']:>8.2f} {single['seconds'] / spread['seconds']:>5.2f}x "
              f"{single['cpu']:>7.2f} {_each(spread['worker_cpu'], '.1f'):>11} "
              f"{_each(spread['worker_step_cpu'], '.1f'):>11} {spread['driver_cpu']:>5.1f} "
              f"{single['cpu'] / busiest:>5.2f}x "
              f"{spread['sent_bytes'] / states:>7.0f} {single['max_rss_kb'] / 1024:>8.0f} "
              f"{_each([kb / 1024 for kb in spread['worker_rss_kb']], '.0f'):>11} "
              f"{100 * heaviest / single['max_rss_kb']:>5.0f} "
              f"{_each([100 * n / states for n in spread['worker_states']], '.0f'):>7}",
              flush=True)
        every = spread["every_cpu"]
        total = sum(every.values())
        others = ", ".join(f"{kind} {seconds:.2f}" for kind, seconds in
                           sorted(every.items(), key=lambda item: -item[1]) if seconds >= 0.005)
        print(f"{'':16} every process: {total:.2f} s of CPU, {total / single['cpu']:.2f}x one "
              f"process's ({others})", flush=True)
        print(f"{'':16} idle (wall seconds outside the steps, from the start of the search): "
              f"{_each(spread['worker_idle'], '.2f')} s of {spread['seconds']:.2f} s; "
              f"{spread['levels']} rounds; calls served {_each(spread['worker_calls'], 'd')}; "
              f"workers stepping (none/one/both...) {_each(spread['stepping'], '.2f')} s; "
              f"CPU of the stepping thread in the calls "
              f"{_each(spread['worker_step_thread'], '.2f')} s (the rest of a worker's: Ray's "
              f"threads and Ray's calls)", flush=True)
        print(f"{'':16} worker memory: {_each([kb / 1024 for kb in spread['worker_start_rss_kb']], '.0f')}"
              f" MB at the start, peak {_each([kb / 1024 for kb in spread['worker_rss_kb']], '.0f')}"
              f" MB (anonymous and file pages read after calls, Ray's shared object store apart: "
              f"{_each([kb / 1024 for kb in spread['worker_private_kb']], '.0f')} MB); the table "
              f"and the parent links in memory {_each([b / 2 ** 20 for b in spread['worker_bytes']], '.0f')}"
              f" MB, the links' files {_each([b / 2 ** 20 for b in spread['worker_link_file']], '.0f')} MB",
              flush=True)
        if not name.startswith("counters"):
            family["every_cpu"] = family.get("every_cpu", 0.0) + total
            family["single"] += single["seconds"]
            family["workers"] += spread["seconds"]
            family["single_cpu"] += single["cpu"]
            family["worker_cpu"] += busiest
    if family["workers"]:
        print(f"whole-controller family: {family['single']:.2f} s in one process, "
              f"{family['workers']:.2f} s on {workers} workers: "
              f"{family['single'] / family['workers']:.2f}x wall; CPU: "
              f"{family['single_cpu']:.2f} s against {family['worker_cpu']:.2f} s of the "
              f"busier worker: {family['single_cpu'] / family['worker_cpu']:.2f}x; every process "
              f"of the cluster: {family['every_cpu']:.2f} s, "
              f"{family['every_cpu'] / family['single_cpu']:.2f}x one process's CPU (1.7x "
              f"wall on {workers} cores needs at most {workers / 1.7:.2f}x)")


def _each(values, form: str) -> str:
    return "/".join(format(value, form) for value in values)


def print_ltl(names, modulo: int, workers: int) -> None:
    modes = ("ltl-single", "ltl-workers")
    print(f"{'model':16} {'states':>9} {'1 proc s':>8} {f'{workers} wkr s':>8} "
          f"{'speed-up':>8} {'us/state':>8} {'start s':>7} {'sent/st':>7} {'B sent/st':>9} "
          f"{'pickled B':>9} "
          f"{'RSS 1 MB':>8} {'RSS wkr MB':>12} {'balance':>9} {'1 CPU s':>7} {'wkr CPU s':>11} "
          f"{'CPU x':>6}")
    for name in names:
        single = fresh(name, modes[0], modulo, workers)
        spread = fresh(name, modes[1], modulo, workers)
        assert (single["verdict"], single["states"]) == (spread["verdict"], spread["states"])
        states = single["states"]
        rss = "/".join(f"{kb / 1024:.0f}" for kb in spread["worker_rss_kb"])
        balance = "/".join(f"{100 * s / states:.0f}" for s in spread["worker_states"])
        cpu = "/".join(f"{seconds:.1f}" for seconds in spread["worker_cpu"])
        print(f"{name:16} {states:>9,} {single['seconds']:>8.2f} {spread['seconds']:>8.2f} "
              f"{single['seconds'] / spread['seconds']:>7.2f}x "
              f"{1e6 * single['seconds'] / states:>8.0f} {spread['start_seconds']:>7.1f} "
              f"{spread['sent'] / states:>7.2f} {spread['sent_bytes'] / states:>9.0f} "
              f"{spread['pickled']:>9.0f} "
              f"{single['max_rss_kb'] / 1024:>8.0f} {rss:>12} {balance:>9} "
              f"{single['cpu']:>7.2f} {cpu:>11} "
              f"{single['cpu'] / max(spread['worker_cpu']):>5.2f}x", flush=True)


def print_pair(names, modulo: int, repeat: int = 2) -> None:
    """``--pair`` (module docstring): per model, ``repeat`` times: one search alone, then two
    at once; CPU seconds of each, and the pair's mean against the alone's."""
    print(f"uptime at the start: {uptime()}", flush=True)
    print(f"{'model':16} {'alone CPU s':>11} {'pair CPU s':>11} {'pair x':>6}", flush=True)
    totals = [0.0, 0.0]
    for name in names:
        for _ in range(repeat):
            alone = fresh(name, "single", modulo, 1)["cpu"]
            both = [subprocess.Popen([sys.executable, __file__, "--measure", name, "single",
                                      "--modulo", str(modulo)], stdout=subprocess.PIPE,
                                     text=True) for _ in range(2)]
            pair = [json.loads(run.communicate()[0].strip().splitlines()[-1])["cpu"]
                    for run in both]
            mean = sum(pair) / 2
            totals[0] += alone
            totals[1] += mean
            print(f"{name:16} {alone:>11.2f} {_each(pair, '.2f'):>11} {mean / alone:>5.2f}x",
                  flush=True)
    if totals[0]:
        print(f"all: {totals[0]:.2f} s alone, {totals[1]:.2f} s each of a pair: "
              f"{totals[1] / totals[0]:.2f}x; so 2 workers on 2 cores reach at most "
              f"{2 * totals[0] / totals[1]:.2f}x in wall time")
    print(f"uptime at the end: {uptime()}")


def print_split(names, modulo: int) -> None:
    print(f"{'model':16} {'states':>9} {'1 proc s':>8} {'2 parts s':>9} {'sum/2 s':>8} "
          f"{'CPU x':>6} {'B sent/st':>9} codec")
    for name in names:
        found = fresh(name, "split", modulo, 2)
        cpu, states = found["cpu"], found["states"]
        print(f"{name:16} {states:>9,} {cpu['single']:>8.2f} {cpu['split']:>9.2f} "
              f"{cpu['split'] / 2:>8.2f} {2 * cpu['single'] / cpu['split']:>5.2f}x "
              f"{found['bytes'] / states:>9.0f} {found['codec']}", flush=True)


if __name__ == "__main__":
    main()
