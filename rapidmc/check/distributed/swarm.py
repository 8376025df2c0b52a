"""Swarm verification (Holzmann, Joshi and Groce): many diversified partial searches at once.

``--swarm N`` runs N depth-first bitstate searches (``hashed.hashed_reachable``) as Ray
tasks.  Each member has its own seed, which orders the successors of every state its own
way (a permutation drawn from the seed and the state's canonical bytes, so the same in any
process) and salts the hash its bit table uses, so the members run into different parts of
a state space too large for one exhaustive search.  The first violation stops the others;
its path is made of real states and replays like any other.

A swarm never says HOLDS: without a violation the verdict is UNKNOWN, and the reason says
how many states the members visited together (members overlap, so fewer distinct ones).
"""
from __future__ import annotations

import hashlib
import random
from typing import Optional

from ..budget import SearchBudget
from ..hashed import BITSTATE, MASK64, MIX, BitState, hashed_reachable
from ..result import UNKNOWN, VIOLATED, SearchResult, SearchStats
from .canonical import canonical_bytes
from .partition import SystemSource

DEFAULT_MEMBER_BYTES = 16 << 20          # each member's bit table without --bitstate


class Diversified:
    """``system`` with each state's successors in an order drawn from ``seed``."""

    def __init__(self, system, seed: int):
        self.system, self.seed = system, seed
        for name in ("failed", "stuck"):
            if hasattr(system, name):
                setattr(self, name, getattr(system, name))

    def initial_states(self):
        return self.system.initial_states()

    def successors(self, state):
        successors = list(self.system.successors(state))
        digest = hashlib.blake2b(canonical_bytes(state), digest_size=8,
                                 salt=self.seed.to_bytes(8, "little")).digest()
        random.Random(digest).shuffle(successors)
        return successors


class SaltedBits:
    """A bit table whose hash is salted with the member's seed."""

    def __init__(self, size: int, seed: int):
        self.bits, self.salt = BitState(size), (seed * MIX + 1) & MASK64

    def add(self, fingerprint: int) -> bool:
        return self.bits.add(((fingerprint ^ self.salt) * MIX) & MASK64)

    def memory_bytes(self) -> int:
        return self.bits.memory_bytes()

    def doubt(self, stored: int) -> str:
        return self.bits.doubt(stored)


def member(source, predicate: str, seed: int, size: int, max_states, max_seconds) -> SearchResult:
    """One member's search (run as a Ray task; ``source``: a ``partition.SystemSource``)."""
    system = source.build()
    diversified = Diversified(system, seed)
    return hashed_reachable(diversified, getattr(system, predicate), SaltedBits(size, seed),
                            SearchBudget(max_states, max_seconds))


def swarm_reachable(ray, members: int, system, predicate: str, budget: SearchBudget,
                    storage: Optional[tuple] = None, rebuild=None) -> SearchResult:
    """The first violation any of ``members`` searches finds, else UNKNOWN with coverage."""
    from .search import drop_actors, worker_failures
    drop_actors(ray)                  # (a partitioned search's actors would hold the CPUs)
    size = storage[1] if storage is not None and storage[0] == BITSTATE else DEFAULT_MEMBER_BYTES
    task = ray.remote(num_cpus=1)(member)
    shared = ray.put(SystemSource(system if rebuild is None else None, rebuild))
    max_states = budget.max_states if budget.max_states != float("inf") else None
    pending = [task.remote(shared, predicate, seed, size, max_states, budget.max_seconds)
               for seed in range(1, members + 1)]
    finished: list[SearchResult] = []
    try:
        with worker_failures(ray):
            while pending:
                done, pending = ray.wait(pending, num_returns=1)
                result = ray.get(done[0])
                finished.append(result)
                if result.verdict == VIOLATED:
                    result.stats.seconds = budget.finish()
                    return result
    finally:
        for ref in pending:
            ray.cancel(ref, force=True)
    stats = SearchStats(product_states=sum(r.stats.product_states for r in finished),
                        transitions=sum(r.stats.transitions for r in finished),
                        max_depth=max((r.stats.max_depth for r in finished), default=0),
                        engine="swarm")
    stats.model_states = stats.product_states
    stats.seconds = budget.finish()
    bounded = sum(1 for r in finished if r.reason and "limit" in r.reason)
    stopped = f", {bounded} of them stopped at a bound" if bounded else ""
    reason = (f"swarm of {members} randomized bitstate searches found no violation; they "
              f"visited {stats.product_states:,} states together (overlapping){stopped}; "
              "a swarm never proves a property")
    return SearchResult(UNKNOWN, reason, stats=stats)
