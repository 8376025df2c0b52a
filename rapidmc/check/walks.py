"""Random walks over a transition system: a look deeper than a bounded breadth-first search.

A breadth-first search that a bound stops has seen every state up to some depth and none
beyond.  Where every step offers many successors (inputs that change at any step, data
that another party may write at every poll), that depth is shallow: a counter that wraps
after 98 messages, or a command branch behind a start-up routine, lies far beyond it.  A
walk follows one successor at a time, so with the same effort it goes as deep as it is
long; it proves nothing about what it does not meet, but every step it takes is a step of
the system, so what it observes is reachable.

Each walk picks successors at random, with a seeded generator (the same system and seed
give the same walks).  It starts from an initial state or, every other walk, from a state
where an earlier walk found something new (``found()`` grew after observing it: a line
that had not run), so walks build on each other's progress into deep code (the first
reaches a command branch, a later one goes on from there).  Such a state was reached,
so every walk from it stays among reachable states.  Given ``novel`` (the successors
that would show something new: a step that runs a line not run before), a walk takes
such a successor when one is offered, and later walks start from the targets of the
others, the latest first, each once (a walk that shows nothing new for ``PATIENCE``
steps gives way to them): a chain of waits each ended by one value of many (a mailbox
that must read "startwork", then "gotombccd", ...) is followed value by value instead
of by luck, and what the walks reach depends far less on the order of the successors.
Three things keep a walk moving:

* a successor that is the state itself (a wait whose chosen value does not end it) is
  taken only when it is the only one, and a state whose only successor is itself (the
  program ended) ends the walk;
* a successor that shows something new is taken first;
* the environment's choices are *sticky* within a walk: the labels name the values a step
  chose (``choices(label)``: ``(name, value)`` pairs), each walk prefers, per name, the
  first value it picked, and keeps to it with a probability of its own (from
  ``STICKINESS``).  A cell whose signals and peers mostly repeat themselves is what
  reaches deep code: a wait on an output that ends the program when read 0, a mailbox
  polled 98 times before its counter wraps.  Uniform choices at every step would end or
  divert nearly every walk long before.

The engine never sees RAPID: what a label's choices are is the caller's ``choices``.
"""
from __future__ import annotations

import random
from typing import Callable, Hashable, Iterable, Optional, Sequence

from . import budget
from .transition_system import TransitionSystem, labelled_successors

# per walk, the probability of keeping to the values chosen before (one drawn per walk)
STICKINESS = (0.5, 0.9, 0.99, 1.0)
# the steps of one walk before the next starts afresh (a walk may circle in a busy loop)
WALK_LENGTH = 2000
# steps a walk goes on without showing anything new while a new step's target waits to
# be walked from (``novel``)
PATIENCE = 200

Observer = Callable[[Hashable, Sequence[tuple]], None]
Choices = Callable[[Hashable], Iterable[tuple]]


def random_walks(system: TransitionSystem, observe: Observer, steps: int,
                 choices: Choices, found: Callable[[], int], seed: int = 0,
                 length: int = WALK_LENGTH, enough: Optional[Callable[[], bool]] = None,
                 novel: Optional[Callable[[Sequence], Sequence]] = None) -> int:
    """Walk ``system`` for ``steps`` steps in all, in walks of at most ``length``; call
    ``observe(state, successors)`` at each state a walk leaves (as a search's observer),
    and stop early once ``enough()``.  ``found()``: a count that grows when an observed
    state showed something new (the walks go on from such states).  ``novel(successors)``:
    those of a state's successors that will show something new once observed (taken
    first, and walks go on from their targets).  Returns the number of walks."""
    rng = random.Random(seed)
    initial = list(system.initial_states())
    fruitful: list = []                    # states after which found() grew, in order
    frontier: list = []                    # targets of new steps no walk has gone on from
    taken = walks = 0
    while taken < steps and initial and not (enough is not None and enough()) \
            and budget.stop_requested is None:          # (a first interrupt ends the walks)
        walks += 1
        if frontier:
            state = frontier.pop()          # the latest discovery first: deepest code
        else:
            starts = fruitful if fruitful and walks % 2 == 0 else initial
            state = starts[rng.randrange(len(starts))]
        preferred: dict = {}
        stickiness = STICKINESS[rng.randrange(len(STICKINESS))]
        idle = 0
        for _ in range(min(length, steps - taken)):
            if budget.stop_requested is not None:
                break
            successors = labelled_successors(system, state)
            fresh = [one for one in novel(successors) if one[1] != state] \
                if novel is not None else []
            before = found()
            observe(state, successors)
            idle += 1
            if found() != before:
                fruitful.append(state)
                idle = 0
            taken += 1
            moving = [one for one in successors if one[1] != state]
            if not moving or (frontier and idle > PATIENCE):
                break                       # ended, stuck for good, or better started anew
            label, target = _pick(rng, fresh or moving, preferred, stickiness, choices)
            frontier.extend(one[1] for one in fresh if one[1] is not target)
            state = target
    return walks


def _pick(rng: random.Random, successors: list, preferred: dict, stickiness: float,
          choices: Choices) -> tuple:
    """A successor: one that keeps the values preferred (first picks, per name) with
    probability ``stickiness`` when there is one, else any."""
    if len(successors) == 1:
        return successors[0]
    chosen = rng.choice(successors)
    if rng.random() < stickiness:
        keeping = [one for one in successors
                   if all(preferred.get(name, value) == value for name, value in choices(one[0]))]
        if keeping:
            chosen = rng.choice(keeping)
    for name, value in choices(chosen[0]):
        preferred.setdefault(name, value)
    return chosen
