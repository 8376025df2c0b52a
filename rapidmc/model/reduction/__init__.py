"""State-space reductions that keep every verdict: sliced data, dead data, merged steps.

* ``relevance`` / ``totality``: which data can influence anything a check
  observes (cone of influence); the rest is *sliced*.
* ``liveness``: data that will be written before it is read (*dead*), per
  program point.
* ``projection``: sliced data reset in every stored state, dead data where
  it is dead.
* ``merging``: instructions that may run in the same transition as the one
  before (statement merging).
* ``expansion``: a counterexample of the reduced model re-executed on the
  unreduced one, so traces show every line and every value.
* ``partial_order``: with several tasks, steps on a task's own data are not
  interleaved with the other tasks' (ample sets).

``plan_reductions(program, config, atoms, formulas, reductions)`` decides
what applies to one check; ``RapidSystem`` applies the plan.
"""
from __future__ import annotations

import argparse
from dataclasses import dataclass, field
from typing import Iterable, Optional

from ...diagnostics import ORDER_REDUCTION, Diagnostic
from ...semantics.edge_traps import own_edges
from ...semantics.program import Program
from .counters import NO_COUNTERS, find_counters
from .merging import LOCATION_ATOMS, _has_next, merge_points, merging_allowed
from .unread_outputs import OutputResets, unread_outputs
from .partial_order import PartialOrder, reaches_data_by_name
from .liveness import DeadData
from .projection import Projection
from .relevance import NO_SLICING, Slicing, atom_keys_of, find_slicing


@dataclass(frozen=True)
class Reductions:
    """Which reductions a check may use (all by default)."""

    slice_data: bool = True
    dead_data: bool = True
    merge_steps: bool = True
    partial_order: bool = True


ALL = Reductions()
NONE = Reductions(slice_data=False, dead_data=False, merge_steps=False, partial_order=False)


@dataclass(frozen=True)
class Plan:
    """What one check applies: the projection of states and the merge points."""

    reductions: Reductions = NONE
    slicing: Slicing = NO_SLICING
    projection: Optional[Projection] = None
    merge_points: dict = field(default_factory=dict)
    order: Optional[PartialOrder] = None     # ample sets between tasks (None: every order)
    notes: tuple = ()                        # Diagnostics: a reduction left off, and why

    @property
    def active(self) -> bool:
        """Whether stored states or transitions differ from the unreduced model's (a
        counterexample is then re-executed on it, ``expansion``)."""
        return self.projection is not None or bool(self.merge_points) or \
            self.order is not None and self.order.runs is not None


NO_PLAN = Plan()


def plan_reductions(program: Program, config, atoms: Iterable[str],
                    formulas: Iterable[Optional[object]],
                    reductions: Reductions = ALL) -> Plan:
    """The reductions that keep every verdict of properties over ``atoms``.

    ``formulas``: the properties' formulas (None for a property given as an
    automaton, whose stutter invariance is unknown).
    """
    atoms = tuple(atoms)
    keys = atom_keys_of(atoms)
    formulas = list(formulas)
    counters = find_counters(program) if reductions.slice_data and \
        stutter_blind(formulas, keys) else NO_COUNTERS
    slicing = find_slicing(program, atoms, getattr(config, "robot_untracked", False),
                           counters) if reductions.slice_data else NO_SLICING
    dead = DeadData(program, keys) if reductions.dead_data else None
    if dead is not None and dead.empty:
        dead = None
    projection = Projection(program, slicing, dead) if not slicing.empty or dead else None
    outputs = unread_outputs(program, keys) if reductions.slice_data else ()
    if outputs:
        projection = OutputResets(outputs, projection)
    points: dict = {}
    if reductions.merge_steps and None not in formulas and \
            merging_allowed(program, formulas, keys, bool(config.free_inputs)):
        points = merge_points(program, keys)
    order, notes = None, ()
    if reductions.partial_order and program.task_entries:
        order, notes = _partial_order(program, config, formulas, keys,
                                      reductions.merge_steps, projection)
    return Plan(reductions, slicing, projection, points, order, notes)


def stutter_blind(formulas: list, keys: set[str]) -> bool:
    """Whether the properties' verdicts are the same on runs that differ by steps that
    change only the program counter and sliced data: no X, no automaton given whole, no
    atom naming a location."""
    return None not in formulas and not keys & LOCATION_ATOMS and \
        not any(_has_next(formula) for formula in formulas)


def _partial_order(program: Program, config, formulas: list, keys: set[str],
                   merge: bool, projection: Optional[Projection]) -> tuple:
    """The partial-order reduction of a program of several tasks, when it keeps every
    verdict of these properties (``partial_order``), and a note when a property with X
    turns it off.  ``merge``: a task's step goes on through its local instructions
    (``local_runs``), whose states ``projection`` maps as the search's."""
    if any(formula is not None and _has_next(formula) for formula in formulas):
        return None, (Diagnostic(ORDER_REDUCTION, "partial-order reduction is off: a property "
                                 "uses X (next), whose verdict depends on the interleaving "
                                 "of the tasks' steps", severity="note"),)
    if None in formulas or program.environment_react is not None or \
            program.environment_init is not None or inputs_stored(config) or \
            keys & LOCATION_ATOMS or reaches_data_by_name(program):
        return None, ()
    return PartialOrder(program, keys, merge, projection), ()


def inputs_stored(config) -> bool:
    """Whether a free input keeps the value a step chose in the state after it, so that
    every step would change the state.  A served edge input does not (``edge_traps``):
    every state after a step keeps it at 0, and its edge starts a TRAP of the task whose
    step chose it or is dropped, so a step of one task neither queues another's interrupt
    nor leaves a value another task's step would see (``interrupt_owners``)."""
    served = own_edges(config)
    return any(index not in served for index, _, _ in config.free_inputs)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """The command-line switches that turn reductions off."""
    group = parser.add_argument_group("reductions (all on by default; verdicts never change)")
    group.add_argument("--no-reduce", action="store_true",
                       help="explore the program as written: no sliced data, no merged steps")
    group.add_argument("--no-slice", action="store_true",
                       help="keep data that nothing observable depends on in every state")
    group.add_argument("--no-dead", action="store_true",
                       help="keep values that will be written before they are read")
    group.add_argument("--no-merge", action="store_true",
                       help="one transition per instruction (no merged steps)")
    group.add_argument("--no-por", action="store_true",
                       help="with several tasks: every interleaving of their steps (no "
                            "partial-order reduction)")


def from_arguments(args: argparse.Namespace) -> Reductions:
    if getattr(args, "no_reduce", False):
        return NONE
    return Reductions(slice_data=not getattr(args, "no_slice", False),
                      dead_data=not getattr(args, "no_dead", False),
                      merge_steps=not getattr(args, "no_merge", False),
                      partial_order=not getattr(args, "no_por", False))
