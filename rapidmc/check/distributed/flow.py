"""The rounds of an eager search without lock-step: each worker steps while it has work.

An eager search (``--eager``, ``partition`` module docstring) stores a worker's own
successors at once and expands them in the same call; only the successors other workers
own travel.  Run in lock-step rounds (``rounds.Levels``: every worker steps, then all
exchange), a worker that ran out of work waited for the slowest one every round, and on
the narrow models the work went back and forth: a round's successors for the other worker
were its work of the next round, while the first had exhausted its own, so the two workers
stepped in turn, not together (the ROS server on the Python engine: in 157 rounds one
worker stepped and the other waited, about half of the search's time each).

``Flow`` drives the same calls without a barrier.  The leader (the first worker) keeps up
to two calls in flight to each other worker: one it steps, one queued behind it with the
batches sent to it since, so it goes on at once; a call steps for at most ``PEER_SECONDS``
of CPU (less while the leader has little work left of its own), or until the worker has
nothing left, and answers with its batches for the others and its figures.  Between its own short slices (``LEADER_SECONDS``; shorter while another
worker has nothing to do, so that what it sends that worker goes out soon) the leader takes
the answers that arrived, without waiting, and passes their batches on (as object refs,
from actor to actor).  Every batch passes the leader, which so knows when the search is
over: no call in flight, no batch to deliver, and no worker with a stored state it has not
expanded.  Batches from one worker to another are delivered in the order they were
written (the codecs number values and nodes from one batch to the next).

``Levels``' ``get`` turns values and refs into values; ``ready`` tells which of the calls'
figures (refs, or values in one process) can be read without waiting.
"""
from __future__ import annotations

import time
from collections import deque
from typing import Callable, Sequence

from .rounds import AT_LIMIT, FOUND, HOLDS_ALL, RUNNING
from .worker import SAFETY, call

PEER_SECONDS = 0.1      # CPU seconds a call to another worker steps at most
PEER_SECONDS_SHORT = 0.02    # ... while the leader has less than that left to step
LEADER_SECONDS = 0.02    # ... a slice of the leader's own steps, between two looks
LEADER_SECONDS_IDLE = 0.005    # ... while some other worker has nothing to step
IN_FLIGHT = 2            # calls to one worker at once: the one it steps, the next one


class Flow:
    """The calls of an eager search (module docstring); as ``rounds.Levels`` for the
    partition's ``lead`` and ``rounds``."""

    def __init__(self, parts: Sequence, local: set, get: Callable[[list], list],
                 ready: Callable[[list, float], list], max_states, per_level: bool):
        self.parts, self.local, self.get, self.ready = list(parts), local, get, ready
        self.count = count = len(self.parts)
        self.max_states, self.per_level = max_states, per_level
        self.latest: list = [None] * count     # each worker's last figures
        self.stored = [0] * count
        self.left = [0] * count                # states stored and not yet expanded, last told
        self.calls = [deque() for _ in range(count)]   # calls in flight, oldest first
        self.pending: list = [[] for _ in range(count)]   # (sender, batch) to deliver
        self.rounds = 0                        # calls to other workers (figures)
        self.depth = 0                         # (not counted in an eager search)
        self.outcome = None

    def begin(self, initial: bytes) -> None:
        """Every worker is sent the initial states (sender -1); it keeps those it owns."""
        for target in range(self.count):
            self.pending[target].append((-1, initial))

    def run(self, seconds: float) -> dict:
        """Calls until the search ends, or for about ``seconds`` (one step of the leader's
        where a test watches the rounds, ``per_level``): the figures so far and the outcome
        (``rounds.Levels.run``).  Calls in flight go on stepping while the leader answers."""
        deadline = time.monotonic() + seconds
        while self.outcome is None:
            self._collect(0.0)
            if self.outcome is not None:
                break
            self._submit()
            if not self._own_slice():
                if not any(self.calls) and not any(self.pending) and not any(self.left):
                    self.outcome = (HOLDS_ALL, None)
                    break
                self._collect(max(0.0, deadline - time.monotonic()))
            if self.per_level or time.monotonic() > deadline:
                return self._answer(RUNNING)
        self.drain()
        return self._answer(*self.outcome)

    def drain(self) -> None:
        """Wait for the calls in flight (their figures count; their batches are dropped)."""
        for target, calls in enumerate(self.calls):
            while calls:
                self._figures_of(target, calls.popleft(), keep=False)

    def _submit(self) -> None:
        """A call to each other worker that may have work and has less than ``IN_FLIGHT``
        calls: one that was sent batches, or that had states left when it last answered.
        It steps for ``PEER_SECONDS``, or ``PEER_SECONDS_SHORT`` where the leader's own
        states left would take less than that, so that it soon has the calls' answers."""
        mine = self.latest[0]
        seconds = PEER_SECONDS_SHORT if mine is None or \
            self.left[0] * mine[9] < PEER_SECONDS else PEER_SECONDS
        for target in range(1, self.count):
            calls, pending = self.calls[target], self.pending[target]
            if len(calls) >= IN_FLIGHT or not (pending or self.left[target]):
                continue
            self.pending[target] = []
            senders = [sender for sender, _ in pending]
            batches = [batch for _, batch in pending]
            if target in self.local:
                batches = self.get(batches)
            calls.append(call(self.parts[target], SAFETY, "flow", seconds, senders,
                              *batches, returns=self.count + 1))
            self.rounds += 1

    def _own_slice(self) -> bool:
        """A slice of the leader's own steps, if it has any: whether it had."""
        pending = self.pending[0]
        if not pending and not self.left[0]:
            return False
        self.pending[0] = []
        idle = any(not calls and not self.left[target] and not self.pending[target]
                   for target, calls in enumerate(self.calls) if target)
        answer = call(self.parts[0], SAFETY, "flow",
                      LEADER_SECONDS_IDLE if idle else LEADER_SECONDS,
                      [sender for sender, _ in pending],
                      *self.get([batch for _, batch in pending]), returns=self.count + 1)
        self._take(0, answer, answer[self.count])
        return True

    def _collect(self, wait: float) -> None:
        """Take the answers of the calls that have ended (each worker's in the order of the
        calls), waiting up to ``wait`` seconds for one if none has."""
        count = self.count
        if not any(self.calls):
            return
        ended = set(self.ready([refs[count] for target, calls in enumerate(self.calls)
                                if target not in self.local for refs in calls], wait))
        for target, calls in enumerate(self.calls):
            while calls and self.outcome is None and \
                    (target in self.local or calls[0][count] in ended):
                self._figures_of(target, calls.popleft(), keep=True)

    def _figures_of(self, target: int, refs, keep: bool) -> None:
        figures, mine = self.get([refs[self.count], refs[0]])
        if keep:
            self._take(target, [mine, *refs[1:]], figures)
        else:
            self._note(target, figures)

    def _take(self, sender: int, batches, figures) -> None:
        """An answer of ``sender``: its figures, and its batches to deliver."""
        self._note(sender, figures)
        if self.outcome is not None:
            return
        pieces = figures[8]
        for target in range(self.count):
            if target != sender and pieces[target]:
                self.pending[target].append((sender, batches[target]))

    def _note(self, sender: int, figures) -> None:
        self.latest[sender] = figures
        self.stored[sender], self.left[sender] = figures[0], figures[7]
        if self.outcome is None:
            for at in (2, 5):               # the predicate's state, a deadlock target
                if figures[at] >= 0:
                    self.outcome = (FOUND, (sender, figures[at]))
                    return
            if self.max_states is not None and sum(self.stored) > self.max_states:
                self.outcome = (AT_LIMIT, None)

    def _answer(self, outcome: str, target=None) -> dict:
        known = [f for f in self.latest if f is not None]
        return {"outcome": outcome, "target": target, "stored": list(self.stored),
                "transitions": sum(f[3] for f in known),
                "deadlocks": sum(f[4] for f in known), "depth": self.depth,
                "watched": any(f[6] for f in known)}


def ray_ready(refs: list, wait: float) -> list:
    """``Flow``'s ``ready`` in a worker: those of ``refs`` that are ready, waiting up to
    ``wait`` seconds for the first."""
    import ray
    if not refs:
        return []
    ended, _ = ray.wait(refs, num_returns=1, timeout=wait)
    if ended and len(refs) > 1:
        ended, _ = ray.wait(refs, num_returns=len(refs), timeout=0)
    return ended


def local_ready(refs: list, wait: float) -> list:
    """``Flow``'s ``ready`` where every partition is in this process: all."""
    return refs
