"""Searches that remember hashes instead of states: ``--compact`` and ``--bitstate``.

Instead of storing every visited state, these searches keep states only on
their depth-first stacks and remember visited states by a 64-bit
fingerprint (``Fingerprints``: a set of ints, about 60 bytes a state) or by
two bits in a fixed bit array (``BitState``, Holzmann's supertrace: SIZE
bytes whatever the number of states).  Two different states may share a
fingerprint or all their bits, and then the second one is wrongly taken
for visited: the search may miss part of the state space.  So a search
that finds no violation never says HOLDS: its verdict is UNKNOWN with the
reason "probably holds" and the odds of a miss.  A violation found is real
(the counterexample is made of real states, replayed before it is shown).

LTL properties use the nested depth-first search of Courcoubetis, Vardi,
Wolper and Yannakakis with Holzmann's improvement (a cycle closes as soon
as the inner search reaches a state on the outer stack); safety checks
use one depth-first search.
"""
from __future__ import annotations

import math
from typing import Callable, Hashable, Optional

from .budget import SearchBudget, stopped_in_time
from .transition_system import STUTTER, TransitionSystem, labelled_successors
from .result import NO_AUTOMATON, UNKNOWN, VIOLATED, LassoStep, SearchResult, SearchStats

MASK64 = (1 << 64) - 1
COMPACT = "compact"
BITSTATE = "bitstate"
MIX = 0x9E3779B97F4A7C15


class Fingerprints:
    """Visited states as 64-bit fingerprints (``--compact``)."""

    def __init__(self):
        self.seen: set[int] = set()

    def add(self, fingerprint: int) -> bool:
        """True when the fingerprint is new (and now remembered)."""
        if fingerprint in self.seen:
            return False
        self.seen.add(fingerprint)
        return True

    def memory_bytes(self) -> int:
        import sys
        return sys.getsizeof(self.seen) + 32 * len(self.seen)

    def doubt(self, stored: int) -> str:
        """The odds that a collision hid a state (birthday bound over 2^64 fingerprints)."""
        probability = min(1.0, stored * stored / 2.0 ** 65)
        return f"64-bit fingerprints; probability that a collision hid a state <= {probability:.1e}"


class BitState:
    """Visited states as two bits each in an array of ``size`` bytes (``--bitstate``)."""

    def __init__(self, size: int):
        bits = 1 << max(3, (size * 8).bit_length() - 1)      # a power of two
        self.bits = bytearray(bits // 8)
        self.mask = bits - 1

    def add(self, fingerprint: int) -> bool:
        bits, mask = self.bits, self.mask
        first = fingerprint & mask
        second = ((fingerprint * MIX) & MASK64) >> 20 & mask
        new = not (bits[first >> 3] >> (first & 7) & 1 and bits[second >> 3] >> (second & 7) & 1)
        bits[first >> 3] |= 1 << (first & 7)
        bits[second >> 3] |= 1 << (second & 7)
        return new

    def memory_bytes(self) -> int:
        return len(self.bits)

    def doubt(self, stored: int) -> str:
        bits = self.mask + 1
        miss = (1.0 - math.exp(-2.0 * stored / bits)) ** 2
        return (f"bit-state hashing, {bits:,} bits for {stored:,} states (hash factor "
                f"{bits / max(stored, 1):,.0f}); probability that a new state was taken for "
                f"visited <= {miss:.1e}")


def visited_sets(storage: tuple, count: int) -> list:
    """``count`` visited sets for ``storage`` = (COMPACT,) or (BITSTATE, bytes) (split evenly)."""
    if storage[0] == COMPACT:
        return [Fingerprints() for _ in range(count)]
    return [BitState(max(1, storage[1] // count)) for _ in range(count)]


def fingerprint(state: Hashable, automaton_state: int = 0) -> int:
    return ((hash(state) & MASK64) ^ (automaton_state * MIX)) * MIX & MASK64


def probably_holds(visited, stored: int) -> str:
    return f"no violation found: probably holds ({visited.doubt(stored)})"


def hashed_reachable(system: TransitionSystem, predicate: Callable[[Hashable], bool],
                     visited, budget: SearchBudget) -> SearchResult:
    """A path to a state where ``predicate`` holds, by depth-first search."""
    stats = SearchStats()
    stack: list[list] = []                 # [label, state, successors, position]

    def push(label, state) -> bool:
        stats.product_states += 1
        stack.append([label, state, list(labelled_successors(system, state)), 0])
        stats.transitions += len(stack[-1][2])
        stats.max_depth = max(stats.max_depth, len(stack))
        return predicate(state)

    found = False
    with stopped_in_time(budget):      # found stays False when the time is up
        for initial in system.initial_states():
            if found or budget.reason is not None:
                break
            if visited.add(fingerprint(initial)):
                found = push(None, initial)
            while stack and not found:
                frame = stack[-1]
                if frame[3] == len(frame[2]):
                    stack.pop()
                    continue
                label, successor = frame[2][frame[3]]
                frame[3] += 1
                if label is STUTTER:
                    continue
                if visited.add(fingerprint(successor)):
                    if not budget.may_store(stats.product_states):
                        break
                    if stats.product_states >= budget.next_checkpoint and not budget.checkpoint(
                            stats.product_states, stats.transitions, len(stack)):
                        break
                    found = push(label, successor)
    return _finish(stats, visited, budget,
                   [LassoStep(f[0], f[1], NO_AUTOMATON) for f in stack] if found else None)


def hashed_accepting_cycle(system: TransitionSystem, buchi, valuation, visited_outer,
                           visited_inner, budget: SearchBudget) -> SearchResult:
    """Nested depth-first search for an accepting cycle of model × ``buchi``."""
    search = _NestedSearch(system, buchi, valuation, visited_outer, visited_inner, budget)
    lasso = None
    with stopped_in_time(budget):
        lasso = search.run()
    return _finish(search.stats, visited_outer, budget, None, lasso)


def _finish(stats: SearchStats, visited, budget: SearchBudget, path, lasso=None) -> SearchResult:
    stats.seconds = budget.finish()
    stats.model_states = stats.product_states
    stats.bytes_per_state = visited.memory_bytes() / max(stats.product_states, 1)
    if path is not None:
        return SearchResult(VIOLATED, None, path, [], stats)
    if lasso is not None:
        prefix, cycle, closing = lasso
        return SearchResult(VIOLATED, None, prefix, cycle, stats, closing)
    if budget.reason is not None:
        return SearchResult(UNKNOWN, budget.reason, stats=stats)
    return SearchResult(UNKNOWN, probably_holds(visited, stats.product_states), stats=stats)


class _NestedSearch:
    """Outer and inner depth-first searches over (model state, automaton state)."""

    def __init__(self, system, buchi, valuation, outer, inner, budget: SearchBudget):
        self.system, self.valuation, self.budget = system, valuation, budget
        self.outer, self.inner = outer, inner
        self.edges = [tuple((e.positive, e.negative, e.target) for e in out)
                      for out in buchi.edges]
        self.initial = buchi.initial
        self.accepting = set(buchi.accepting)
        self.stats = SearchStats()
        self.on_stack: dict[int, int] = {}     # fingerprint -> depth on the outer stack

    def targets(self, q: int, state) -> list[int]:
        value = self.valuation(state)
        return [target for positive, negative, target in self.edges[q]
                if value & positive == positive and not value & negative]

    def successors(self, state, q: int) -> list[tuple]:
        return [(label, successor, target)
                for label, successor in labelled_successors(self.system, state)
                for target in self.targets(q, successor)]

    def run(self):
        if not self.edges:
            return None
        for initial in self.system.initial_states():
            for q in self.targets(self.initial, initial):
                found = self.outer_search(initial, q)
                if found is not None or self.budget.reason is not None:
                    return found
        return None

    def outer_search(self, initial, q0: int):
        stack: list[list] = []                 # [label, state, q, fingerprint, successors, position]
        budget, stats = self.budget, self.stats

        def push(label, state, q, print_) -> None:
            stats.product_states += 1
            self.on_stack[print_] = len(stack)
            successors = self.successors(state, q)
            stats.transitions += len(successors)
            stack.append([label, state, q, print_, successors, 0])
            stats.max_depth = max(stats.max_depth, len(stack))

        self.outer_stack = stack
        first = fingerprint(initial, q0)
        if not self.outer.add(first):
            return None
        push(None, initial, q0, first)
        while stack:
            frame = stack[-1]
            if frame[5] < len(frame[4]):
                label, state, q = frame[4][frame[5]]
                frame[5] += 1
                print_ = fingerprint(state, q)
                if self.outer.add(print_):
                    if not budget.may_store(stats.product_states):
                        return None
                    if stats.product_states >= budget.next_checkpoint and not budget.checkpoint(
                            stats.product_states, stats.transitions, len(stack)):
                        return None
                    push(label, state, q, print_)
                continue
            if frame[2] in self.accepting:
                closing = self.inner_search(frame[1], frame[2])
                if closing is not None:
                    return self.lasso(stack, *closing)
            stack.pop()
            self.on_stack.pop(frame[3], None)
        return None

    def inner_search(self, seed, seed_q: int):
        """(index on the outer stack, inner path) of a cycle through the seed, or None."""
        stack = [[None, seed, seed_q, self.successors(seed, seed_q), 0]]
        while stack:
            frame = stack[-1]
            if frame[4] == len(frame[3]):
                stack.pop()
                continue
            label, state, q = frame[3][frame[4]]
            frame[4] += 1
            print_ = fingerprint(state, q)
            depth = self.on_stack.get(print_)
            if depth is not None and self.outer_stack[depth][1] == state and \
                    self.outer_stack[depth][2] == q:
                return depth, [(f[0], f[1], f[2]) for f in stack[1:]] + [(label, state, q)]
            if self.inner.add(print_):
                stack.append([label, state, q, self.successors(state, q), 0])
                self.stats.transitions += len(stack[-1][3])
        return None

    @staticmethod
    def lasso(stack: list, depth: int, inner: list):
        """Prefix up to the outer-stack state the cycle returns to; the cycle; its last label."""
        steps = [LassoStep(f[0], f[1], f[2]) for f in stack]
        loop = steps[depth:] + [LassoStep(label, state, q) for label, state, q in inner[:-1]]
        closing_label = inner[-1][0]
        return steps[:depth], loop, closing_label
