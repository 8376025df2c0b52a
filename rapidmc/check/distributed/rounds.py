"""The rounds of the partitioned search, driven by one of the workers (the leader).

A breadth-first level of the partitioned search ends only once every partition expanded its
share of it, so the search pays one exchange between the partitions per round (at least one
per level).  Models whose levels are narrow (hundreds of levels of a few hundred states)
pay that exchange more than their steps.  The driver of the check used to drive every
round: two Ray calls from the driver per round, their answers back to it, and a hop through
its process for each batch.  Now the first partition's worker drives them (``Levels``): it
submits the round's call to each other worker (their batches for each other go from actor to
actor as before), steps its own share in its own process meanwhile, and waits for the
others' figures.  The driver calls the leader once per slice of rounds (``SLICE_SECONDS``,
or one level when a test watches the levels) to check the time limit and to report progress.
On this 2-core machine a round of 20 kB batches between two actors cost 2.1-2.3 ms of wall
time and 2.7 ms of CPU of all processes relayed by the driver (bench/distributed.py
--rounds), and 1.0-1.5 ms and 1.1-1.3 ms driven by a worker (load 9).

``Levels`` runs the same in one process with every partition local (``search_here``).
"""
from __future__ import annotations

import time
from typing import Callable, Sequence

from .worker import SAFETY, call

SLICE_SECONDS = 0.25     # how long the leader runs rounds before it answers the driver

RUNNING, HOLDS_ALL, AT_LIMIT, FOUND = "running", "holds", "limit", "found"


class Levels:
    """The round loop (``partition`` module docstring).  ``parts[i]`` is called as
    ``worker.call`` calls an actor; those in ``local`` answer at once (this process's own
    partition), the others with object refs, which ``get`` turns into values (and passes
    values through)."""

    def __init__(self, parts: Sequence, local: set, get: Callable[[list], list],
                 max_states, per_level: bool):
        self.parts, self.local, self.get = list(parts), local, get
        self.count = len(self.parts)
        self.max_states, self.per_level = max_states, per_level
        self.stored = [0] * self.count
        self.transitions = self.deadlocks = self.depth = 0
        self.rounds = 0                 # rounds run (figures)
        self.watched = False
        self.advanced = True            # the round asked for began a level
        self.stepped: list = []         # per partition: its batches, then its figures
        self.consumed = True            # the figures of ``stepped`` were read
        self.fetched: dict = {}         # (sender, local target): the batch, fetched

    def begin(self, initial: bytes) -> None:
        """The first round: every partition is sent the initial states (sender -1)."""
        self.stepped = self._submit(True, lambda target: ([-1], [initial]))
        self.consumed = False

    def _submit(self, advance: bool, batches_for) -> list:
        """A round's call to every partition; those of other processes first, so that they
        step while this process steps its own."""
        count = self.count
        stepped: list = [None] * count
        order = [target for target in range(count) if target not in self.local] + \
            [target for target in range(count) if target in self.local]
        for target in order:
            senders, batches = batches_for(target)
            if target in self.local:
                batches = self.get(list(batches))
            stepped[target] = call(self.parts[target], SAFETY, "step", advance, senders,
                                   *batches, returns=count + 1)
        return stepped

    def _next_round(self) -> list:
        count, previous, fetched = self.count, self.stepped, self.fetched

        def batches_for(target: int):
            senders = [sender for sender in range(count) if sender != target]
            return senders, [fetched.get((sender, target), previous[sender][target])
                             for sender in senders]
        return self._submit(self.advanced, batches_for)

    def run(self, seconds: float) -> dict:
        """Rounds until the search ends, or for about ``seconds`` (or to the end of the
        level, ``per_level``): the figures so far and the outcome (``RUNNING``, or
        ``HOLDS_ALL``, ``AT_LIMIT``, ``FOUND`` with the (partition, id) of the target)."""
        deadline = time.monotonic() + seconds
        count = self.count
        while True:
            if self.consumed:
                self.rounds += 1
                self.stepped = self._next_round()
                self.consumed = False
            # the figures, and with them the batches other processes sent this one's
            # partitions (one wait instead of two)
            pairs = [(sender, target) for target in sorted(self.local)
                     for sender in range(count) if sender not in self.local]
            got = self.get([refs[count] for refs in self.stepped] +
                           [self.stepped[sender][target] for sender, target in pairs])
            figures, self.fetched = got[:count], dict(zip(pairs, got[count:]))
            self.consumed = True
            self.stored = [f[0] for f in figures]
            for index, f in enumerate(figures):
                if f[2] >= 0:
                    return self._answer(FOUND, (index, f[2]))
            self.transitions = sum(f[3] for f in figures)
            self.deadlocks = sum(f[4] for f in figures)
            self.watched = self.watched or any(f[6] for f in figures)
            for index, f in enumerate(figures):
                if f[5] >= 0:
                    return self._answer(FOUND, (index, f[5]))
            if self.advanced:
                if sum(f[1] for f in figures) == 0:
                    return self._answer(HOLDS_ALL)
                self.depth += 1
            if sum(self.stored) > self.max_states:
                return self._answer(AT_LIMIT)
            # the next level once every partition expanded all of this one
            self.advanced = not any(f[7] for f in figures)
            if (self.advanced and self.per_level) or time.monotonic() > deadline:
                return self._answer(RUNNING)

    def _answer(self, outcome: str, target=None) -> dict:
        return {"outcome": outcome, "target": target, "stored": self.stored,
                "transitions": self.transitions, "deadlocks": self.deadlocks,
                "depth": self.depth, "watched": self.watched}


def local_values(items: list) -> list:
    """``Levels``' ``get`` where every partition is in this process."""
    return items


def ray_values(items: list) -> list:
    """``Levels``' ``get`` in a worker: the object refs among ``items`` fetched (at once)."""
    import ray
    at = [index for index, item in enumerate(items) if isinstance(item, ray.ObjectRef)]
    if not at:
        return items
    items = list(items)
    for index, value in zip(at, ray.get([items[index] for index in at])):
        items[index] = value
    return items
