"""The hash-partitioned breadth-first search: one Ray actor per partition, run in levels.

``partitioned_reachable`` answers what ``reachability.find_reachable`` answers (the
shortest path to a state the predicate marks; HOLDS after the whole state space; UNKNOWN at
a bound), with the states split among ``Partition`` actors by their canonical hash.  The
search goes in rounds (``partition`` module docstring): in each, every partition stores
what it was sent in the round before and expands at most ``partition.ROUND`` states of the
current level, sorting their successors by owner (one batch per owner, handed from actor to
actor through Ray's object store, never through this process; the batch for itself it
keeps).  A level ends once every partition expanded its share; a level that stores nothing
new ends a complete search.  The first partition's worker drives the rounds
(``rounds.Levels``; an eager search's calls without lock-step, ``flow.Flow``); this
process asks it for a slice of rounds at a time.

A violation is found in the level of its depth, as in the one-process search, so the path is
as short; it is rebuilt by following parent links from partition to partition, and its
labels by stepping the model along it here (as ``reachability`` does), so it replays.

A complete search stores exactly the reachable states and counts each transition once: the
same states, transitions, deadlocks and depth as one process.  The state limit is checked
after each round, the time limit after each slice of rounds (a round may store more than
the limit before the search stops: UNKNOWN either way).

An ``eager`` search (``--eager``, ``partition`` module docstring) needs fewer rounds: the
same verdicts and the same states, transitions and deadlocks after a complete search, but a
counterexample may be longer than one process's, and the depth is not counted (0).

A worker that dies (killed, out of memory, crashed node) ends the search with the
``WORKER_LOST`` diagnostic and its exit code: never with a verdict.
"""
from __future__ import annotations

import contextlib
from typing import Callable, Optional

from ...diagnostics import EXIT_WORKER_LOST, WORKER_LOST, error
from ..budget import SearchBudget
from ..result import HOLDS, NO_AUTOMATON, UNKNOWN, VIOLATED, LassoStep, SearchResult, SearchStats
from ..transition_system import TransitionSystem, transition_label
from ..native import state_table
from .codec import data_owners_fit
from .partition import NO_PARENT, SystemSource, encode_batch, unlink
from .rounds import AT_LIMIT, FOUND, HOLDS_ALL, SLICE_SECONDS
from .worker import SAFETY, Worker, call

ENGINE = "distributed"


def partitioned_reachable(ray, partitions: int, system: TransitionSystem, predicate: str, *,
                          deadlock_is_target: bool = False, watch: Optional[str] = None,
                          budget: Optional[SearchBudget] = None,
                          on_level: Optional[Callable[[list], None]] = None,
                          rebuild: Optional[Callable[[], TransitionSystem]] = None,
                          eager: bool = False, by_data: Optional[bool] = None) -> tuple:
    """(SearchResult, whether ``watch`` said True for some state, per-partition figures).

    ``predicate`` and ``watch`` name methods of ``system`` (the actors call them on their
    copy of it).  ``on_level(actors)`` is called before each level (tests kill one there).
    ``rebuild``: a picklable function that builds ``system`` in a worker's process (else
    the system itself is pickled to the workers).  ``eager``: rounds without levels.
    ``by_data``: states owned by their global data (``codec``), or by the whole state;
    None: as ``data_owners_fit`` decides from the first states.
    """
    budget = budget if budget is not None else SearchBudget()
    if by_data is None:
        by_data = data_owners_fit(system, state_table(system, packed=True), partitions)
    actors = actors_of(ray, partitions)
    shared = ray.put(SystemSource(system if rebuild is None else None, rebuild))
    try:
        with worker_failures(ray):
            ray.get([call(actor, SAFETY, "start", index, partitions, shared, predicate,
                          deadlock_is_target, watch, by_data, eager)
                     for index, actor in enumerate(actors)])
            return _Rounds(ray, actors, system, budget, on_level, eager).run()
    except BaseException:
        drop_actors(ray)         # (one may be dead; the next search starts afresh)
        raise
    finally:
        for actor in _ACTORS.get("actors", ()):
            call(actor, SAFETY, "clear")


_ACTORS: dict = {}     # the actors of this Ray session: "session", "actors"

# A worker's C library allocates from one arena (glibc's ``MALLOC_ARENA_MAX``): Ray's
# threads (about twenty) each took an arena of their own, where the memory a round's
# batches passed through stayed reserved after it was freed (counters N=9: a worker's peak
# RSS 161-168 MB with them, 149-159 MB with one arena, at the same CPU time)
WORKER_ENVIRONMENT = {"env_vars": {"MALLOC_ARENA_MAX": "1"}}


def actors_of(ray, partitions: int) -> list:
    """``partitions`` ``worker.Worker`` actors, kept for the next search of the same Ray
    session (an actor costs a process start, a second or more)."""
    session = ray.get_runtime_context().get_job_id()
    if _ACTORS.get("session") != session or len(_ACTORS.get("actors", ())) != partitions:
        drop_actors(ray)
        actor_class = ray.remote(num_cpus=1, runtime_env=WORKER_ENVIRONMENT)(Worker)
        _ACTORS.update(session=session,
                       actors=[actor_class.remote() for _ in range(partitions)])
    return _ACTORS["actors"]


def drop_actors(ray) -> None:
    for actor in _ACTORS.pop("actors", ()):
        try:
            ray.kill(actor)
        except Exception:         # (a session already shut down took them with it)
            pass
    _ACTORS.pop("session", None)


@contextlib.contextmanager
def worker_failures(ray):
    """A lost worker as the ``WORKER_LOST`` diagnostic; an exception the model raised in a
    worker (``RayTaskError``) as that exception, as if the search had run here."""
    try:
        yield
    except ray.exceptions.RayTaskError as exc:
        cause = exc.cause if isinstance(exc.cause, Exception) else None
        if cause is None or isinstance(cause, ray.exceptions.RayError):
            raise _worker_lost(cause or exc) from None
        raise cause from None
    except ray.exceptions.RayError as exc:
        raise _worker_lost(exc) from None


def _worker_lost(exc: Exception):
    summary = str(exc).strip().splitlines()[0] if str(exc).strip() else type(exc).__name__
    return error(WORKER_LOST, f"a search worker was lost ({type(exc).__name__}): the search "
                 "is incomplete and gives no verdict", None, summary[:300],
                 exit_code=EXIT_WORKER_LOST)


class _Rounds:
    """Drives the search from the check's process: the first worker runs the rounds
    (``rounds.Levels``), each round's batches going from actor to actor; this process asks
    it for a slice of rounds at a time, checks the time limit and reports progress between
    slices, and rebuilds the counterexample."""

    def __init__(self, ray, actors, system, budget: SearchBudget, on_level,
                 eager: bool = False):
        self.ray, self.actors, self.system, self.eager = ray, actors, system, eager
        self.budget, self.on_level = budget, on_level
        self.count = len(actors)
        self.stored = [0] * self.count
        self.transitions = self.deadlocks = 0
        self.depth = 0
        self.watched = False
        self.target: Optional[tuple[int, int]] = None   # (partition, id) the predicate marked

    def run(self) -> tuple:
        ray, leader = self.ray, self.actors[0]
        # every partition is sent the initial states and keeps those it owns
        initial = encode_batch((list(self.system.initial_states()), []))
        ray.get(call(leader, SAFETY, "lead", self.actors[1:], initial, self.budget.max_states,
                     self.on_level is not None))
        while True:
            answer = ray.get(call(leader, SAFETY, "rounds", SLICE_SECONDS))
            self.stored = answer["stored"]
            self.transitions, self.deadlocks = answer["transitions"], answer["deadlocks"]
            self.depth = answer["depth"]
            self.watched = answer["watched"]
            outcome = answer["outcome"]
            if outcome == FOUND:
                self.target = answer["target"]
                return self._result(VIOLATED, self._path(*self.target))
            if outcome == HOLDS_ALL:
                return self._result(HOLDS)
            self._note_balance()
            if outcome == AT_LIMIT:
                self.budget.reason = f"state limit {self.budget.max_states} reached"
            elif not self.budget.checkpoint(sum(self.stored), self.transitions, self.depth):
                pass                                  # (the time limit: reason is set)
            if self.budget.reason is not None:
                return self._result(UNKNOWN)
            if self.on_level is not None:
                self.on_level(self.actors)

    def _note_balance(self) -> None:
        """The progress line's per-worker balance: each worker's share of the states."""
        progress, total = self.budget.progress, sum(self.stored)
        if progress is not None and total:
            shares = "/".join(f"{100 * stored / total:.0f}" for stored in self.stored)
            progress.note = f"{self.count} workers, states {shares} %"

    def _path(self, partition: int, state_id: int) -> list[LassoStep]:
        """The steps from an initial state to the target, across partitions."""
        states = []
        while True:
            state, parent = self.ray.get(call(self.actors[partition], SAFETY, "step_back",
                                              state_id))
            states.append(state)
            if parent == NO_PARENT:
                break
            partition, state_id = unlink(parent)
        states.reverse()
        steps = [LassoStep(None, states[0], NO_AUTOMATON)]
        for previous, current in zip(states, states[1:]):
            label = transition_label(self.system, previous, current)
            steps.append(LassoStep(label, current, NO_AUTOMATON))
        return steps

    def _result(self, verdict: str, path=None) -> tuple:
        self.ray.get(call(self.actors[0], SAFETY, "settle"))
        figures = self.ray.get([call(actor, SAFETY, "figures") for actor in self.actors])
        stored = sum(f["states"] for f in figures)
        memory = sum(f["bytes"] for f in figures)
        stats = SearchStats(product_states=stored, model_states=stored,
                            transitions=self.transitions,
                            max_depth=0 if self.eager else self.depth,
                            deadlocks=self.deadlocks,
                            bytes_per_state=memory / stored if stored else 0.0, engine=ENGINE)
        stats.seconds = self.budget.finish()
        reason = self.budget.reason if verdict == UNKNOWN else None
        result = SearchResult(verdict, reason, path or [], [], stats)
        return result, self.watched, figures


def reachable(ray, cluster, system: TransitionSystem, predicate: str, *,
              watch: Optional[str] = None, max_states=None, max_seconds=None,
              progress=None, storage=None, rebuild=None) -> tuple[SearchResult, bool]:
    """The distributed search ``cluster`` asks for (partitioned, or a swarm): the result and
    whether ``watch`` said True of some expanded state (a swarm watches nothing: False)."""
    from ..budget import DEFAULT_MAX_STATES
    budget = SearchBudget(DEFAULT_MAX_STATES if max_states is None else max_states,
                          max_seconds, progress)
    if cluster.swarm:
        from .swarm import swarm_reachable
        return swarm_reachable(ray, cluster.swarm, system, predicate, budget, storage,
                               rebuild), False
    result, watched, _ = partitioned_reachable(ray, cluster.partitions(ray), system, predicate,
                                               watch=watch, budget=budget, rebuild=rebuild,
                                               eager=cluster.eager)
    return result, watched
