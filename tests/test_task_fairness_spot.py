"""Spot as the reference for the fair search: generated multi-task programs, ``fairness -> φ``.

Each subject is a seeded random program of two or three RAPID tasks sharing
PERS data (waits on it, assignments, loops; now and then a wait for or a
test of the free input di1).  Its whole state graph is explored with the
checker's own successor function and exported to Spot with two more
propositions per task and position of a run, computed here from the
labelled graph and nothing else of the checker:

* ``ran0``, ``ran1``, ...: the step into this state was one of task 1, task 2, ...
  (the ``task`` choice of its label; the only running task when there is
  no choice);
* ``off0``, ``off1``, ...: the task cannot go on here (the program has stopped,
  the task has ended, or every step of the task leads back to this state).

Weak fairness between the tasks is then the LTL assumption
``GF(ran0 | off0) & GF(ran1 | off1) & ...``, and the checker's fair verdict on
φ must be Spot's verdict on ``assumption -> φ``: HOLDS exactly when Spot's
product with the negation is empty.  A fair counterexample must also be a
run of the graph, meet the assumption on its cycle (checked here, by brute
force over the cycle) and falsify φ (``holds_on_lasso``).  Both the fair search
alone (``check.fair``) and the search ``check`` runs (today's first, the fair
one when today's counterexample starves a task) are held against Spot.  The plain search
on the same pairs is tallied too, so the test shows fairness changing
verdicts (and only from VIOLATED to HOLDS).
"""
from __future__ import annotations

import random
from collections import deque

import pytest

from tool_requirements import require_tool
from rapidmc import ast
from rapidmc.check import HOLDS, VIOLATED, check_property
from rapidmc.check.fair import check_fair_property
from rapidmc.ltl import parse_formula, to_buchi
from rapidmc.ltl.lasso import holds_on_lasso
from rapidmc.ltl.spot_backend import spot_available, to_spot
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem
from rapidmc.model.properties import AtomCompiler
from rapidmc.semantics.link import Task, build
from rapidmc.semantics.state import RUNNING
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import parse_text
from rapidmc.model.fairness import TaskFairness, fair_or_plain_search

require_tool(spot_available(), "RAPIDMC_REQUIRE_SPOT",
             "Spot's Python bindings are not installed (../shared/spot/install)")

import spot  # noqa: E402
from spot_kripke import letter  # noqa: E402

SEED, PROGRAMS = 2026, 60
ATOMS = ("f", "n = 0", "n = 1")
TEMPLATES = ("G F {a}", "F G {a}", "G ({a} -> F {b})", "F {a}", "G F {a} | G F {b}",
             "G (!{a} -> F ({a} & {b}))")
STATEMENTS = ("f := TRUE;", "f := FALSE;", "f := NOT f;", "n := (n + 1) MOD 3;",
              "WaitUntil f;", "WaitUntil NOT f;", "WaitUntil n = {k};",
              "IF f THEN n := {k}; ENDIF", "IF n = {k} THEN f := NOT f; ENDIF")
INPUT_STATEMENTS = ("WaitDI di1, 1;", "IF DInput(di1) = 1 THEN f := NOT f; ENDIF")


def task_text(rng: random.Random, name: str, inputs: bool) -> str:
    choices = STATEMENTS + (INPUT_STATEMENTS if inputs else ())
    body = [rng.choice(choices).format(k=rng.randint(0, 2)) for _ in range(rng.randint(1, 4))]
    if rng.random() < 0.8:
        body = ["WHILE TRUE DO", *("  " + line for line in body), "ENDWHILE"]
    lines = [f"MODULE {name}", "  PERS bool f := FALSE;", "  PERS num n := 0;",
             "  PROC main()", *("    " + line for line in body), "  ENDPROC", "ENDMODULE"]
    return "\n".join(lines) + "\n"


def task_system(rng: random.Random, number: int, tasks: int = 2):
    """A program of ``tasks`` tasks; now and then one reads the free input di1."""
    inputs = rng.random() < 0.3
    texts = [task_text(rng, f"Task{number}x{i}", inputs) for i in range(tasks)]
    program = build(ast.Program(parse_text(texts[0], "task0.mod")),
                    tasks=[Task(f"task{i}", ast.Program(parse_text(text, f"task{i}.mod")))
                           for i, text in enumerate(texts[1:], start=1)])
    compiler = AtomCompiler(program)
    system = RapidSystem(program, CheckConfig(program))
    return system, compiler, "".join(texts)


def task_of(system: RapidSystem, state, label):
    for name, value in label[0]:
        if name == "task":
            return system.program.task_names.index(value)
    running = [i for i, stack in enumerate((state.frames,) + state.tasks) if stack]
    return running[0] if state.status == RUNNING and len(running) == 1 else None


class LabelledGraph:
    """Every reachable state, and per state its (task, successor id) edges."""

    def __init__(self, system: RapidSystem):
        self.tasks = len(system.program.task_names)
        self.states, self.ids, self.edges = [], {}, []
        self.initial = [self._intern(s) for s in system.initial_states()]
        queue = deque(self.initial)
        while queue:
            state_id = queue.popleft()
            known = len(self.states)
            state = self.states[state_id]
            self.edges.append(list(dict.fromkeys(
                (task_of(system, state, label), self._intern(target))
                for label, target in system.successors(state))))
            queue.extend(range(known, len(self.states)))
        self.off = [frozenset(task for task in range(self.tasks)
                              if state.status != RUNNING or
                              all(target == state_id for t, target in self.edges[state_id]
                                  if t == task))
                    for state_id, state in enumerate(self.states)]

    def _intern(self, state) -> int:
        if state not in self.ids:
            self.ids[state] = len(self.states)
            self.states.append(state)
        return self.ids[state]

    def fair_cycle(self, cycle: list[int]) -> bool:
        """Whether each task steps somewhere on the cycle or cannot go on in one of its states."""
        met = set().union(*(self.off[s] for s in cycle))
        for before, after in zip(cycle, cycle[1:] + cycle[:1]):
            met |= {t for t, target in self.edges[before] if target == after}
        return met >= set(range(self.tasks))


def fair_kripke(graph: LabelledGraph, valuations: list[int]):
    """The graph's words over ATOMS, ran0 ran1 ..., off0 off1 ... (one of each per task)."""
    automaton = spot.make_twa_graph(spot._bdd_dict)
    tasks = range(graph.tasks)
    variables = [automaton.register_ap(atom) for atom in
                 ATOMS + tuple(f"ran{t}" for t in tasks) + tuple(f"off{t}" for t in tasks)]
    width = len(ATOMS)

    def bits(state_id: int, task) -> int:
        ran = 1 << (width + task) if task is not None else 0
        off = sum(1 << (width + graph.tasks + t) for t in graph.off[state_id])
        return valuations[state_id] | ran | off
    start = automaton.new_states(len(graph.states) + 1)
    automaton.set_init_state(start)
    for state_id in graph.initial:
        automaton.new_edge(start, state_id + 1, letter(variables, bits(state_id, None)))
    for state_id, edges in enumerate(graph.edges):
        for task, target in edges:
            automaton.new_edge(state_id + 1, target + 1, letter(variables, bits(target, task)))
    return automaton


def spot_fair_violation(kripke, formula, tasks: int) -> bool:
    assumption = " & ".join(f"G F (ran{t} | off{t})" for t in range(tasks))
    negated = spot.formula(f"!({assumption} -> ({to_spot(formula)}))")
    return not spot.product(kripke, spot.translate(negated)).is_empty()


def formulas(rng: random.Random) -> list:
    texts = []
    for template in TEMPLATES:
        a, b = rng.sample(ATOMS, 2)
        texts.append(template.format(a=_atom(a), b=_atom(b)))
    return [parse_formula(text) for text in texts]


def _atom(atom: str) -> str:
    return atom if atom.isidentifier() else f'"{atom}"'


@pytest.mark.parametrize("tasks, programs", [(2, PROGRAMS), (3, PROGRAMS // 3)])
def test_fair_verdicts_are_spots_under_the_fairness_assumption(tasks, programs):
    rng = random.Random(SEED + tasks)
    tally = {"pairs": 0, "fair": {HOLDS: 0, VIOLATED: 0}, "changed": 0}
    for number in range(programs):
        system, compiler, text = task_system(rng, number, tasks)
        graph = LabelledGraph(system)
        valuation = compiler.valuation(ATOMS, {})
        kripke = fair_kripke(graph, [valuation(state) for state in graph.states])
        fairness = TaskFairness(system)
        for formula in formulas(rng):
            buchi = to_buchi(Not(formula))
            atoms_valuation = compiler.valuation(buchi.atoms, {})
            fair = check_fair_property(system, buchi, atoms_valuation, fairness,
                                       max_states=100_000)
            plain = check_property(system, buchi, atoms_valuation, max_states=100_000)
            combined = fair_or_plain_search(system, buchi, atoms_valuation, fairness, None,
                                            {"max_states": 100_000})
            where = f"program {number}, {to_spot(formula)}:\n{text}"
            expected = VIOLATED if spot_fair_violation(kripke, formula, tasks) else HOLDS
            assert fair.verdict == combined.verdict == expected, where
            assert not (plain.verdict == HOLDS and fair.verdict == VIOLATED), where
            for result in (fair, combined):
                if result.verdict == VIOLATED:
                    _assert_fair_counterexample(graph, compiler, formula, result, where)
            tally["pairs"] += 1
            tally["fair"][fair.verdict] += 1
            tally["changed"] += plain.verdict != fair.verdict
    # the generated programs exercise both answers, and fairness changes some verdicts
    assert min(tally["fair"].values()) > tally["pairs"] // 5, tally
    assert tally["changed"] > tally["pairs"] // 30, tally


def _assert_fair_counterexample(graph: LabelledGraph, compiler, formula, result, where):
    prefix = [graph.ids[step.state] for step in result.prefix]
    cycle = [graph.ids[step.state] for step in result.cycle]
    path = prefix + cycle
    assert path[0] in graph.initial, where
    assert all(any(target == after for _, target in graph.edges[before])
               for before, after in zip(path, path[1:] + cycle[:1])), where
    assert graph.fair_cycle(cycle), f"unfair cycle: {where}"
    valuation = compiler.valuation(ATOMS, {})

    def letters(ids):
        return [frozenset(a for i, a in enumerate(ATOMS)
                          if valuation(graph.states[s]) >> i & 1) for s in ids]
    assert not holds_on_lasso(formula, letters(prefix), letters(cycle)), where


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_the_graph_fairness_agrees_with_the_checkers(seed):
    """The oracle's own ``off`` (every step of the task loops back) is the checker's
    ``excused`` on every reachable state: both read the same semantics."""
    rng = random.Random(seed)
    for number in range(10):
        system, _, text = task_system(rng, number, 2 + seed % 2)
        graph = LabelledGraph(system)
        fairness = TaskFairness(system)
        for state_id, state in enumerate(graph.states):
            assert fairness.excused(state) == graph.off[state_id], text
