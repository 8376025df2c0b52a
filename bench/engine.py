"""Benchmark of the model-checking engine on a scalable synthetic model.

Model: ``inputs`` boolean inputs chosen freely at every step, and
``counters`` nested counters modulo ``modulo`` (an odometer) that advance
only in steps where input 0 is set.  States: 2^inputs × modulo^counters.

Property (liveness, holds, so the whole product is explored): if input 0
is set infinitely often, all counters are zero infinitely often:
``G F a -> G F z``.

Prints the verdict, product states/s for the whole search, the share of
time spent in the model (successors + valuation, measured separately) and
the engine's own rate without it, then bytes per stored product state
measured with tracemalloc (a second run; tracemalloc slows Python down).

    python bench/engine.py --inputs 2 --counters 2 --modulo 100
"""
from __future__ import annotations

import argparse
import time
import tracemalloc

from rapidmc.check import check_property
from rapidmc.ltl import parse_formula, to_buchi

PROPERTY = "G F a -> G F z"


class Odometer:
    """State (input bits, counter_0, …): see the module docstring."""

    def __init__(self, inputs: int, counters: int, modulo: int):
        self.choices = range(1 << inputs)
        self.counters = counters
        self.modulo = modulo

    def initial_states(self):
        return ((0,) + (0,) * self.counters,)

    def successors(self, state):
        advanced = self.advance(state[1:]) if state[0] & 1 else state[1:]
        return [(bits, (bits,) + advanced) for bits in self.choices]

    def advance(self, counters: tuple) -> tuple:
        digits = list(counters)
        for position in range(len(digits)):
            digits[position] = (digits[position] + 1) % self.modulo
            if digits[position]:
                break
        return tuple(digits)


def valuation_for(buchi):
    """Bits of atoms a (input 0 set) and z (all counters zero) in the automaton's order."""
    tests = {"a": lambda state: state[0] & 1, "z": lambda state: not any(state[1:])}
    predicates = [(1 << index, tests[name]) for index, name in enumerate(buchi.atoms)]
    return lambda state: sum(bit for bit, holds in predicates if holds(state))


class CountingModel:
    """The model, counting how often the engine expands a state."""

    def __init__(self, model):
        self.model = model
        self.expansions = 0

    def initial_states(self):
        return self.model.initial_states()

    def successors(self, state):
        self.expansions += 1
        return self.model.successors(state)


def seconds_per_call(function, states) -> float:
    started = time.perf_counter()
    for state in states:
        function(state)
    return (time.perf_counter() - started) / max(len(states), 1)


def reachable_states(model):
    seen = dict.fromkeys(model.initial_states())
    frontier = list(seen)
    while frontier:
        state = frontier.pop()
        for _, successor in model.successors(state):
            if successor not in seen:
                seen[successor] = None
                frontier.append(successor)
    return list(seen)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--inputs", type=int, default=2)
    parser.add_argument("--counters", type=int, default=2)
    parser.add_argument("--modulo", type=int, default=100)
    parser.add_argument("--max-states", type=int, default=5_000_000)
    args = parser.parse_args()

    model = CountingModel(Odometer(args.inputs, args.counters, args.modulo))
    buchi = to_buchi(parse_formula(f"!({PROPERTY})"))
    valuation = valuation_for(buchi)
    result = check_property(model, buchi, valuation, max_states=args.max_states)
    stats = result.stats
    print(f"model: {args.inputs} inputs x {args.counters} counters mod {args.modulo}; "
          f"property {PROPERTY}; automaton {buchi.state_count} states")
    print(f"verdict {result.verdict}: {stats.product_states:,} product states, "
          f"{stats.model_states:,} model states, {stats.transitions:,} transitions, "
          f"depth {stats.max_depth:,}")
    print(f"search: {stats.seconds:.2f} s, {stats.states_per_second:,.0f} product states/s")

    states = reachable_states(model.model)
    in_model = (model.expansions * seconds_per_call(model.model.successors, states)
                + stats.model_states * seconds_per_call(valuation, states))
    engine_only = max(stats.seconds - in_model, 1e-9)
    print(f"model: {model.expansions:,} expansions, about {in_model:.2f} s (timed separately); "
          f"engine alone: "
          f"{stats.product_states / engine_only:,.0f} product states/s")

    tracemalloc.start()
    result = check_property(model, buchi, valuation, max_states=args.max_states)
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    print(f"memory: peak {peak / 2**20:,.1f} MiB, "
          f"{peak / result.stats.product_states:,.0f} bytes per stored product state "
          f"(model state tuples included)")


if __name__ == "__main__":
    main()
