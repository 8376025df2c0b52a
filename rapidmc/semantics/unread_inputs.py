"""Stored inputs a step neither reads nor watches: chosen once, left at rest.

A step of the staged driver (``staged_step``) runs once per valuation of the stored
inputs: with five of them, 32 runs.  An input at rest where unwatched
(``resting_inputs``) or an edge input (``edge_inputs``) matters to a step only where the
step reads it (``Instruction.signals_read``; any signal where it reads one by signal
data or a parameter) or an active interrupt watches the input before or
after the step (its edge queues the interrupt or starts the TRAP).  Elsewhere the exact
model's two successors that differ only in its value lead to one state: the input at
rest (``merged_pairs``), or at 0 for an edge input (``edges_at_rest``).  So such a step
runs with the input's first value only, its label names no value for it (the
counterexample shows a value where one matters), and its target keeps the input at rest
(an edge input at 0).

The state graph is the one of the model with every valuation but for two things.
Transitions that lead to the same state as a kept one, and differ from it in the value
of an input nothing looked at, are gone.  And a waiting task's step (one that changes
nothing but the input: ``idle_steps_dropped`` drops the one that keeps its value, so the
pair is broken and nothing is put at rest) leads to the state with the input at rest,
where that model goes to the state with the other value stored: both stand for the
controller's states with the input at either value, and nothing but a later edge test
tells them apart, which ``with_priors`` takes from both values.  The verdicts are the
same (the differential test).

Which inputs a step leaves unchosen is decided before it runs, from the state: the
instruction does not read them, no active interrupt watches them.  An interrupt the step
itself makes active (ISignalDI, IWatch) is seen after the step with the first values:
the interrupt table a step leaves does not depend on the values of inputs its
instruction does not read (an edge starts a TRAP only through an interrupt active before,
and starting one only puts an interrupt to sleep), so that one run tells; the step then
chooses every value.  ``--inputs-every-step`` keeps the model with every valuation
(tests/test_unread_inputs.py compares the two).
"""
from __future__ import annotations

from typing import Optional

from .resting_inputs import AT_REST, watched_inputs


class Kept:
    """For a set of inputs left unchosen: whether each valuation runs, its label,
    and the ``mset`` arguments that put the resting ones at rest."""

    __slots__ = ("runs", "labels", "rest")

    def __init__(self, runs: tuple, labels: tuple, rest: tuple):
        self.runs = runs
        self.labels = labels
        self.rest = rest


class InputChoices:
    """The stored inputs of a configuration that a step may leave unchosen."""

    def __init__(self, program, config):
        free = config.free_inputs
        self.positions = {index: position for position, (index, _, _) in enumerate(free)}
        self.resting = config.resting_inputs
        reducible = set(self.resting) | set(config.edge_inputs)
        if program.environment_reads_io:
            reducible = set()            # the environment's routine reads them
        self.reducible = frozenset(i for i in reducible if i in self.positions)
        self.valuations = config.input_valuations
        self.labels = config.input_labels
        self.label_numbers = {label: number for number, label in enumerate(self.labels)}
        self.first = tuple(domain[0] for _, _, domain in free)
        self.kept_by_left: dict = {}

    def unchosen(self, program, state, task: int) -> frozenset:
        """The inputs the step of ``task`` from ``state`` may leave unchosen: those its
        instruction does not read (none when it reads a signal it does not name:
        ``Instruction.signals_read``) and no active interrupt watches.  Only
        with several tasks: one task's step may go on with a merged run, whose later
        instructions may read signals."""
        if not self.reducible or not state[10]:
            return frozenset()
        stack = state[0] if task == 0 else state[10][task - 1]
        frame = stack[-1]
        instruction = program.routines[frame[0]].code[frame[1]]
        left = self.reducible
        if instruction.reads_io:
            read = instruction.signals_read
            if read is None:
                return frozenset()
            left = left - read
        return left - watched_inputs(state[4])

    def kept(self, left: frozenset) -> Kept:
        """The valuations a step that leaves ``left`` unchosen runs (those inputs at their
        first value), their labels without those inputs."""
        found = self.kept_by_left.get(left)
        if found is None:
            positions = {self.positions[index] for index in left}
            first = self.first
            runs = tuple(all(valuation[p] == first[p] for p in positions)
                         for valuation in self.valuations)
            labels = tuple(tuple(entry for p, entry in enumerate(label) if p not in positions)
                           for label in self.labels)
            rest = tuple(x for index in sorted(left) if index in self.resting
                         for x in (index, AT_REST))
            found = self.kept_by_left[left] = Kept(runs, labels, rest)
        return found


def input_choices(program, config) -> Optional[InputChoices]:
    """The configuration's ``InputChoices`` (None: every step chooses every value), made
    once per configuration and program."""
    if not config.inputs_where_read or not config.free_inputs:
        return None
    cached = config.input_choices
    if cached is None or cached[0] is not program:
        cached = config.input_choices = (program, InputChoices(program, config))
    choices = cached[1]
    return choices if choices.reducible else None


def watches_any(transitions, left: frozenset) -> bool:
    """Whether an active interrupt watches one of ``left`` after one of ``transitions``."""
    return any(not left.isdisjoint(watched_inputs(transition[2][4]))
               for transition in transitions)


def rested(transitions: list, rest: tuple) -> list:
    """``transitions`` with the inputs ``rest`` names (``mset`` arguments) at rest."""
    if not rest:
        return transitions
    return [transition._replace(state=transition[2]._replace(io=transition[2][2].mset(*rest)))
            for transition in transitions]


def unchosen_dropped(program, state, transitions: list, config) -> tuple:
    """The general driver's ``transitions`` of ``state`` (every valuation) as the staged
    driver gives them with inputs left unchosen: per task, those with its unchosen
    inputs at their first value, without them in the label, the resting ones at rest;
    and the positions of those (``staged_step.idle_steps_dropped``'s ``standing``)."""
    choices = input_choices(program, config)
    if choices is None or not transitions or not state[10]:
        return transitions, set()
    stacks = (state[0],) + state[10]
    runnable = [i for i, stack in enumerate(stacks) if stack]
    names = program.task_names
    by_task: dict = {}
    for position, transition in enumerate(transitions):
        name = next((value for key, value in transition[0] if key == "task"), None)
        task = runnable[0] if name is None or len(runnable) == 1 else names.index(name)
        by_task.setdefault(task, []).append(position)
    result = list(transitions)
    dropped, standing = set(), set()
    count = len(choices.positions)
    for task, positions in by_task.items():
        left = choices.unchosen(program, state, task)
        if not left:
            continue
        kept = choices.kept(left)
        numbers = choices.label_numbers
        chosen = {position: numbers[transitions[position][0][:count]]
                  for position in positions}
        first_runs = [transitions[p] for p in positions if chosen[p] == 0]
        if watches_any(first_runs, left):
            continue                     # the step makes an interrupt on one active
        for position in positions:
            number = chosen[position]
            if not kept.runs[number]:
                dropped.add(position)
                continue
            transition = transitions[position]
            transition = transition._replace(
                label=kept.labels[number] + transition[0][count:])
            result[position] = rested([transition], kept.rest)[0]
            standing.add(position)
    final, where = [], set()
    for position, transition in enumerate(result):
        if position not in dropped:
            if position in standing:
                where.add(len(final))
            final.append(transition)
    return final, where
