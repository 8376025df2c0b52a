"""Spot as the reference for the engine: the checker's verdicts against Spot's emptiness check.

For seeded random programs (``small_programs``) and the case studies, the
program's whole reachable state graph is explored with the checker's own
successor function and atom evaluation (set up as ``rapidmc check`` sets
them up), exported as a Spot automaton (``spot_kripke``), and intersected
by Spot with Spot's automaton of the negated property.  For every
program/formula pair and both LTL backends:

* rapidmc says HOLDS exactly when Spot's product is empty;
* a VIOLATED verdict comes with a lasso that replays through the step
  function, that Spot accepts as a word of Kripke × ¬property, and on
  which the formula is false (``holds_on_lasso``, a third method).

Where Spot and rapidmc disagree, the third method decides: a word Spot
finds is read back as a path of the explored graph and the formula is
evaluated on it.  Spot being wrong is reported, not failed; rapidmc being
wrong fails.

Without Spot the tests skip, unless RAPIDMC_REQUIRE_SPOT=1 (CI).
"""
from __future__ import annotations

import itertools
import random
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable, Optional

import pytest

from small_programs import small_program
from spot_kripke import StateGraph, explore, kripke_automaton, lasso_word, run_of
from tool_requirements import require_tool
from rapidmc import ast
from rapidmc.check import HOLDS, VIOLATED, check_property
from rapidmc.commands.check import _observed_inputs
from rapidmc.ltl import BACKENDS, Formula, atoms_of, to_buchi
from rapidmc.ltl.lasso import holds_on_lasso
from rapidmc.ltl.spot_backend import from_spot, spot_available, to_spot
from rapidmc.ltl.syntax import Not
from rapidmc.model import RapidSystem, replay
from rapidmc.properties import AtomCompiler, read_property_file
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program, parse_text

require_tool(spot_available(), "RAPIDMC_REQUIRE_SPOT",
             "Spot's Python bindings are not installed (../shared/spot/install)")

import spot  # noqa: E402  (only after the requirement above)

ROOT = Path(__file__).resolve().parent.parent
PROGRAM_SEED = 2026
PROGRAM_COUNT = 60
FORMULAS_PER_PROGRAM = 5
ATOMS_PER_PROGRAM = 3
MAX_STATES = 200_000            # far above every state graph here: no UNKNOWN expected
CASE_STUDIES = [  # (program, environment, property file)
    ("sorter/sorter_a.mod", "sorter/plant.mod", "sorter.ltl"),
    ("sorter/sorter_b.mod", "sorter/plant.mod", "sorter.ltl"),
    ("sorter/sorter_c.mod", "sorter/plant.mod", "sorter.ltl"),
    ("sorter/sorter_a.mod", "sorter/variants/plant_reset_on_arrival.mod", "sorter.ltl"),
    ("sorter/sorter_a.mod", "sorter/variants/plant_sensors_forget.mod", "sorter.ltl"),
    ("door/door_safe.mod", "door/plant.mod", "door.ltl"),
    ("door/door_race.mod", "door/plant.mod", "door.ltl"),
]
RANDOM_FORMULAS_PER_CASE_STUDY = 4


@dataclass
class Subject:
    """A model prepared as ``rapidmc check`` prepares it, with its state graph in Spot."""

    name: str
    system: object                               # a TransitionSystem
    valuation_of: Callable[[tuple], Callable]    # atoms -> (state -> bits), as the checker's
    atoms: tuple[str, ...]
    replay: Callable = lambda result: None       # re-executes a counterexample, or raises
    graph: StateGraph = field(init=False)
    valuations: list[int] = field(init=False)    # by state id, over ``atoms``
    kripke: object = field(init=False)           # spot.twa_graph

    def __post_init__(self):
        self.graph = explore(self.system)
        valuation = self.valuation_of(self.atoms)
        self.valuations = [valuation(state) for state in self.graph.states]
        self.kripke = kripke_automaton(self.graph, self.atoms, self.valuations)

    def letters(self, state_ids) -> list[frozenset]:
        return [frozenset(a for i, a in enumerate(self.atoms) if self.valuations[s] >> i & 1)
                for s in state_ids]


def rapid_subject(name: str, program_ast: ast.Program, atoms, environment=None) -> Subject:
    """Link the program, compile ``atoms`` and pick the stored inputs as the check command does."""
    program = build(program_ast, environment=environment)
    compiler = AtomCompiler(program)
    atoms = tuple(atoms)
    compiler.valuation(atoms, {})          # notes the signals the atoms read
    config = CheckConfig(program, observed=_observed_inputs(program_ast, compiler))
    system = RapidSystem(program, config)
    return Subject(name, system, lambda some: compiler.valuation(some, {}), atoms,
                   lambda result: replay(system, result))


@dataclass
class Tally:
    """What the differential runs saw: verdict counts, rapidmc's errors, Spot's errors."""

    pairs: int = 0
    verdicts: dict = field(default_factory=lambda: {HOLDS: 0, VIOLATED: 0})
    rapidmc_wrong: list = field(default_factory=list)
    spot_wrong: list = field(default_factory=list)

    def summary(self) -> str:
        return (f"{self.pairs} program/formula pairs, {self.verdicts[HOLDS]} HOLDS, "
                f"{self.verdicts[VIOLATED]} VIOLATED (each with both backends); "
                f"Spot wrong on {len(self.spot_wrong)}: {self.spot_wrong[:3]}")


def compare(subject: Subject, formula: Formula, tally: Tally) -> None:
    """Check ``formula`` on ``subject`` with both backends and hold the verdicts against Spot."""
    negated = spot.translate(spot.formula.Not(to_spot(formula)))
    spot_run = run_of(subject.kripke, negated)
    spot_violates = spot_run is not None and subject.graph.is_run(*spot_run) and \
        not holds_on_lasso(formula, *map(subject.letters, spot_run))
    if spot_run is not None and not spot_violates:
        tally.spot_wrong.append((subject.name, str(formula), "word satisfies the formula"))
    tally.pairs += 1
    for backend in BACKENDS:
        problem = _rapidmc_problem(subject, formula, backend, negated, spot_violates, tally)
        if problem is not None:
            tally.rapidmc_wrong.append((subject.name, str(formula), backend, problem))


def _rapidmc_problem(subject, formula, backend, negated, spot_violates, tally) -> Optional[str]:
    """What is wrong with rapidmc's answer for one backend (None: nothing)."""
    buchi = to_buchi(Not(formula), backend=backend)
    result = check_property(subject.system, buchi, subject.valuation_of(buchi.atoms),
                            max_states=MAX_STATES)
    if result.verdict not in (HOLDS, VIOLATED):
        return f"verdict {result.verdict} ({result.reason})"
    if backend == BACKENDS[0]:
        tally.verdicts[result.verdict] += 1
    if result.verdict == HOLDS:
        return "HOLDS, but Spot found a violating run" if spot_violates else None
    subject.replay(result)
    ids = tuple([subject.graph.ids[step.state] for step in part]
                for part in (result.prefix, result.cycle))
    if not subject.graph.is_run(*ids):
        return "VIOLATED, but the counterexample is not a run of the state graph"
    if holds_on_lasso(formula, *map(subject.letters, ids)):
        return "VIOLATED, but the formula holds on the counterexample"
    if not spot_violates:
        tally.spot_wrong.append((subject.name, str(formula), "missed rapidmc's violation"))
        return None
    word = lasso_word(subject.kripke, subject.atoms, *(
        [subject.valuations[s] for s in part] for part in ids))
    if not word.intersects(spot.product(subject.kripke, negated)):
        return "Spot rejects the counterexample as a word of Kripke x not-property"
    return None



# --- the subjects and their formulas ----------------------------------------------------


def random_formulas(atoms, seed: int, count: int) -> list[Formula]:
    """``count`` seeded ``spot.randltl`` formulas over ``atoms`` (constants left out)."""
    generator = spot.randltl(list(atoms), seed=seed, tree_size=(4, 14))
    chosen = (f for f in generator if not (f.is_tt() or f.is_ff()))
    return [from_spot(f) for f in itertools.islice(chosen, count)]


def generated_subjects():
    """(subject, program text) for each seeded small program, over a few of its atoms."""
    rng = random.Random(PROGRAM_SEED)
    for number in range(PROGRAM_COUNT):
        program = small_program(rng)
        atoms = rng.sample(program.atoms, ATOMS_PER_PROGRAM)
        name = f"small_{number}.mod"
        yield rapid_subject(name, ast.Program(parse_text(program.text, name)), atoms), \
            program.text


def case_study_subject(program: str, environment: str, spec: str):
    """The case study as a subject over its spec's atoms, and the spec's formulas."""
    properties = read_property_file(str(ROOT / "specs" / spec))
    formulas = [p.formula for p in properties]
    atoms = dict.fromkeys(a for f in formulas for a in atoms_of(f))
    subject = rapid_subject(f"{program} with {environment}",
                            load_program([str(ROOT / "case_studies" / program)]), atoms,
                            load_program([str(ROOT / "case_studies" / environment)]))
    return subject, formulas


def assert_agreement(tally: Tally, texts: dict) -> None:
    if tally.rapidmc_wrong:
        name, formula, backend, problem = tally.rapidmc_wrong[0]
        pytest.fail(f"{len(tally.rapidmc_wrong)} wrong answers; first: {name}, {formula}, "
                    f"--backend {backend}: {problem}\n{texts.get(name, '')}")


# --- the tests --------------------------------------------------------------------------


def test_engine_agrees_with_spot_on_generated_programs():
    started = time.perf_counter()
    tally, texts, states = Tally(), {}, 0
    for subject, text in generated_subjects():
        texts[subject.name] = text
        states += len(subject.graph.states)
        for number, formula in enumerate(random_formulas(
                subject.atoms, PROGRAM_SEED + len(texts), FORMULAS_PER_PROGRAM)):
            compare(subject, formula, tally)
    print(f"{tally.summary()}; {states} program states; "
          f"{time.perf_counter() - started:.1f} s")
    assert_agreement(tally, texts)
    assert tally.pairs == PROGRAM_COUNT * FORMULAS_PER_PROGRAM
    # both verdicts well represented, or the comparison would prove little
    assert min(tally.verdicts.values()) >= tally.pairs // 5, tally.verdicts


@pytest.mark.parametrize("program, environment, spec", CASE_STUDIES,
                         ids=[f"{p}+{e}" for p, e, _ in CASE_STUDIES])
def test_engine_agrees_with_spot_on_case_studies(program, environment, spec):
    subject, formulas = case_study_subject(program, environment, spec)
    formulas += random_formulas(subject.atoms, len(subject.graph.states),
                                RANDOM_FORMULAS_PER_CASE_STUDY)
    tally = Tally()
    for formula in formulas:
        compare(subject, formula, tally)
    print(subject.name, tally.summary(), len(subject.graph.states), "states")
    assert_agreement(tally, {})
    assert not tally.spot_wrong
