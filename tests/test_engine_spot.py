"""Spot as the reference for the engine: the checker's verdicts against Spot's emptiness check.

A *subject* is a model prepared as ``rapidmc check`` prepares it: its
whole reachable state graph is explored with the checker's own successor
function and atom evaluation, exported as a Spot automaton
(``spot_kripke``), and intersected by Spot with Spot's automaton of the
negated property.  For every subject/formula pair and each way the checker
gets the automaton of the negation (both LTL backends, and Spot's
transition-based Büchi automaton read from HOA, as ``--automaton`` reads
a user's):

* rapidmc says HOLDS exactly when Spot's product is empty;
* a VIOLATED verdict comes with a lasso that replays through the step
  function, is a run of the explored graph, is accepted by Spot as a word
  of Kripke × ¬property, and falsifies the formula (``holds_on_lasso``,
  a third method).

Subjects: 200 seeded small programs (``small_programs``) with 5
``spot.randltl`` formulas each; the case studies with their specs (whose
verdicts and state counts must also be those of ``test_case_studies``)
and a few random formulas; the hand-checked cases of tests/check/ (their
expected verdicts too); random graphs with deadlocks and several initial
states; and, with the engine's caches evicted at every step, bounded
searches (UNKNOWN allowed, HOLDS and VIOLATED still right).

Where Spot and rapidmc disagree, the third method decides: a word Spot
finds is read back as a path of the explored graph and the formula is
evaluated on it.  Spot being wrong is reported (``Tally.spot_wrong``),
not failed; rapidmc being wrong fails.  Two deliberately broken checkers
and a deliberately broken Spot show that each side's errors are caught
and blamed on the right side.

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

from ltl_cases import random_formulas as our_random_formulas
from small_programs import small_program
from test_case_studies import CASES      # the case studies and their verdicts
from test_check_cases import load_case
from test_engine_models import Graph
from tool_requirements import require_tool
from rapidmc import ast
from rapidmc.check import HOLDS, UNKNOWN, VIOLATED, check_property
from rapidmc.check import store
from rapidmc.model.inputs import free_input_domains, observed_inputs
from rapidmc.ltl import BACKENDS, Buchi, Formula, atoms_of, parse_formula, read_hoa, to_buchi
from rapidmc.ltl.lasso import holds_on_lasso
from rapidmc.ltl.spot_backend import from_spot, spot_available, to_spot
from rapidmc.ltl.syntax import Not
from rapidmc.model.rapid_system import RapidSystem, replay
from rapidmc.model.properties import AtomCompiler, read_property_file
from rapidmc.semantics.link import build
from rapidmc.semantics.step import CheckConfig
from rapidmc.syntax import load_program, parse_text

require_tool(spot_available(), "RAPIDMC_REQUIRE_SPOT",
             "Spot's Python bindings are not installed (../shared/spot/install)")

import spot  # noqa: E402  (only after the requirement above)
from spot_kripke import (StateGraph, explore, kripke_automaton, lasso_word,  # noqa: E402
                         run_of)

ROOT = Path(__file__).resolve().parent.parent
PROGRAM_SEED = 2026
PROGRAM_COUNT = 200
FORMULAS_PER_PROGRAM = 5
ATOMS_PER_PROGRAM = 4
FROM_HOA = "hoa"
CHECKERS = (*BACKENDS, FROM_HOA)   # how the checker gets the automaton of the negation
MAX_STATES = 200_000            # far above every state graph here: no UNKNOWN expected
RANDOM_FORMULAS_PER_CASE_STUDY = 4
CHECK_CASES = Path(__file__).resolve().parent / "check"
TOY_ATOMS = ("p", "r")
TOY_SEED, TOY_COUNT, FORMULAS_PER_TOY = 7, 100, 4


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
    domains, _ = free_input_domains(program, compiler)     # defaults of free GI/AI inputs
    config = CheckConfig(program, input_domains=domains,
                         observed=observed_inputs(program, compiler))
    system = RapidSystem(program, config)
    return Subject(name, system, lambda some: compiler.valuation(some, {}), atoms,
                   lambda result: replay(system, result))


@dataclass
class Tally:
    """What the differential runs saw: verdict counts, rapidmc's errors, Spot's errors."""

    pairs: int = 0
    verdicts: dict = field(default_factory=lambda: {HOLDS: 0, VIOLATED: 0, UNKNOWN: 0})
    rapidmc_wrong: list = field(default_factory=list)
    spot_wrong: list = field(default_factory=list)

    def summary(self) -> str:
        counts = ", ".join(f"{n} {verdict}" for verdict, n in self.verdicts.items() if n)
        return (f"{self.pairs} program/formula pairs, {counts} (built-in backend; each pair "
                f"also checked with the Spot backend and Spot's automaton read from HOA); "
                f"Spot wrong on {len(self.spot_wrong)}: {self.spot_wrong[:3]}")


def spot_negation(formula: Formula):
    """Spot's automaton (its default, transition-based) of the formula's negation."""
    return spot.translate(spot.formula.Not(to_spot(formula)))


def compare(subject: Subject, formula: Formula, tally: Tally,
            max_states: Optional[int] = None) -> dict[str, str]:
    """Check ``formula`` on ``subject`` with both backends and hold the verdicts against Spot.

    Returns the verdict of each backend.  With ``max_states`` the search is
    bounded and may answer UNKNOWN, but its HOLDS and VIOLATED must still
    be right.
    """
    negated = spot_negation(formula)
    spot_run = run_of(subject.kripke, negated)
    spot_violates = False
    if spot_run is not None:
        if not subject.graph.is_run(*spot_run):
            tally.spot_wrong.append((subject.name, str(formula), "its run is not a path"))
        elif holds_on_lasso(formula, *map(subject.letters, spot_run)):
            tally.spot_wrong.append((subject.name, str(formula), "its word satisfies φ"))
        else:
            spot_violates = True
    tally.pairs += 1
    verdicts = {}
    for checker in CHECKERS:
        buchi = negation_automaton(formula, checker, negated)
        result = check_property(subject.system, buchi, subject.valuation_of(buchi.atoms),
                                max_states=max_states or MAX_STATES)
        verdicts[checker] = result.verdict
        problem = _rapidmc_problem(subject, formula, result, negated, spot_violates, tally,
                                   max_states)
        if problem is not None:
            tally.rapidmc_wrong.append((subject.name, str(formula), checker, problem))
    tally.verdicts[verdicts[CHECKERS[0]]] += 1
    return verdicts


def negation_automaton(formula: Formula, checker: str, negated) -> Buchi:
    """The automaton the checker searches with: a backend's translation of ¬φ, or (as
    ``--automaton`` would read it) Spot's transition-based Büchi automaton of ¬φ in HOA."""
    if checker == FROM_HOA:
        return read_hoa(spot.degeneralize_tba(negated).to_str("hoa"), "<spot>")
    return to_buchi(Not(formula), backend=checker)


def _rapidmc_problem(subject, formula, result, negated, spot_violates, tally,
                     max_states) -> Optional[str]:
    """What is wrong with rapidmc's answer ``result`` (None: nothing)."""
    if result.verdict == UNKNOWN:
        return None if max_states is not None else f"UNKNOWN ({result.reason})"
    if result.stats.model_states > len(subject.graph.states):
        return f"{result.stats.model_states} model states, {len(subject.graph.states)} reachable"
    if result.verdict == HOLDS:
        return "HOLDS, but Spot found a violating run" if spot_violates else None
    try:
        subject.replay(result)
    except AssertionError as exc:
        return f"VIOLATED, but the counterexample does not replay: {exc}"
    ids = tuple([subject.graph.ids.get(step.state, -1) for step in part]
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
        environment = program.environment and ast.Program(
            parse_text(program.environment, f"small_{number}_env.mod"))
        yield rapid_subject(name, ast.Program(parse_text(program.text, name)), atoms,
                            environment), program.text + (program.environment or "")


def file_subject(program: Path, environment: Optional[Path], property_file: Path):
    """A program (and environment) file over the atoms of a property file, and its properties."""
    properties = read_property_file(str(property_file))
    atoms = dict.fromkeys(a for p in properties for a in atoms_of(p.formula))
    subject = rapid_subject(program.name, load_program([str(program)]), atoms,
                            load_program([str(environment)]) if environment else None)
    return subject, properties


def hand_checked_cases() -> list:
    """The cases of tests/check/ that run with defaults: properties, no options, no bad input."""
    cases = [load_case(folder) for folder in sorted(CHECK_CASES.iterdir())]
    return [case for case in cases if (case.folder / "props.ltl").exists() and
            not case.extra_args and case.error is None and case.xfail is None]


def toy_subjects(seed: int, count: int):
    """Seeded random graphs (``test_engine_models.Graph``) over atoms p and r: deadlocks
    (states without successors) and several initial states included."""
    rng = random.Random(seed)
    for number in range(count):
        size = rng.randint(1, 6)
        edges = {n: [(f"t{i}", rng.randrange(size)) for i in range(rng.randint(0, 3))]
                 for n in range(size)}
        initial = tuple(dict.fromkeys(rng.randrange(size) for _ in range(rng.randint(1, 2))))
        bits = [rng.randint(0, 3) for _ in range(size)]
        yield Subject(f"graph_{number}", Graph(edges, initial), lambda atoms, bits=bits: (
            lambda state: remapped(bits[state], TOY_ATOMS, atoms)), TOY_ATOMS), edges


def remapped(bits: int, source: tuple, target: tuple) -> int:
    """``bits`` over ``source`` atoms as bits over ``target`` (a subset of ``source``)."""
    return sum(1 << i for i, atom in enumerate(target) if bits >> source.index(atom) & 1)


def assert_agreement(tally: Tally, texts: dict) -> None:
    if tally.rapidmc_wrong:
        name, formula, backend, problem = tally.rapidmc_wrong[0]
        pytest.fail(f"{len(tally.rapidmc_wrong)} wrong answers; first: {name}, {formula}, "
                    f"--backend {backend}: {problem}\n{texts.get(name, '')}")


# --- the tests --------------------------------------------------------------------------


def test_engine_agrees_with_spot_on_generated_programs():
    started = time.perf_counter()
    tally, texts, states, several_initial = Tally(), {}, 0, 0
    for subject, text in generated_subjects():
        texts[subject.name] = text
        states += len(subject.graph.states)
        several_initial += len(subject.graph.initial) > 1
        for formula in random_formulas(subject.atoms, PROGRAM_SEED + len(texts),
                                       FORMULAS_PER_PROGRAM):
            compare(subject, formula, tally)
    print(f"{tally.summary()}; {states} program states; "
          f"{time.perf_counter() - started:.1f} s")
    assert_agreement(tally, texts)
    assert tally.pairs == PROGRAM_COUNT * FORMULAS_PER_PROGRAM
    # both verdicts well represented, or the comparison would prove little
    assert min(tally.verdicts[HOLDS], tally.verdicts[VIOLATED]) >= tally.pairs // 5, \
        tally.verdicts
    assert several_initial >= PROGRAM_COUNT // 20     # environments choosing in init


@pytest.mark.parametrize("key", CASES)
def test_engine_agrees_with_spot_on_case_studies(key):
    case = CASES[key]               # program, plant, spec, verdicts, reachable states
    environment = ROOT / case.env
    subject, properties = file_subject(ROOT / case.program, environment, ROOT / case.spec)
    assert len(subject.graph.states) == case.reachable_states
    tally = Tally()
    verdicts = {p.name: compare(subject, p.formula, tally) for p in properties}
    for formula in random_formulas(subject.atoms, case.reachable_states,
                                   RANDOM_FORMULAS_PER_CASE_STUDY):
        compare(subject, formula, tally)
    print(key, tally.summary(), case.reachable_states, "states")
    assert_agreement(tally, {})
    assert not tally.spot_wrong
    assert verdicts == {name: dict.fromkeys(CHECKERS, verdict)
                        for name, verdict in case.verdicts.items()}


@pytest.mark.parametrize("case", hand_checked_cases(), ids=lambda case: case.name)
def test_engine_agrees_with_spot_on_hand_checked_cases(case):
    environment = case.folder / "env.mod"
    subject, properties = file_subject(case.folder / "prog.mod",
                                       environment if environment.exists() else None,
                                       case.folder / "props.ltl")
    tally = Tally()
    verdicts = {p.name: compare(subject, p.formula, tally) for p in properties}
    assert_agreement(tally, {})
    assert not tally.spot_wrong
    assert verdicts == {name: dict.fromkeys(CHECKERS, verdict)
                        for name, verdict in case.verdicts.items() if name in verdicts}


def test_engine_agrees_with_spot_on_graphs_with_deadlocks_and_several_initial_states():
    tally, texts = Tally(), {}
    for subject, edges in toy_subjects(TOY_SEED, TOY_COUNT):
        texts[subject.name] = f"edges {edges}, initial {subject.system.initial}"
        for formula in our_random_formulas(TOY_SEED + len(texts), FORMULAS_PER_TOY, TOY_ATOMS):
            compare(subject, formula, tally)
    print(tally.summary())
    assert_agreement(tally, texts)
    assert not tally.spot_wrong
    assert min(tally.verdicts[HOLDS], tally.verdicts[VIOLATED]) >= tally.pairs // 5, \
        tally.verdicts
    shapes = [(subject.system, edges) for subject, edges in toy_subjects(TOY_SEED, TOY_COUNT)]
    assert sum(any(not out for out in edges.values()) for _, edges in shapes) >= TOY_COUNT // 4
    assert sum(len(system.initial) > 1 for system, _ in shapes) >= TOY_COUNT // 4


TINY = """MODULE Tiny
  VAR num x := 0;
  PROC main()
    x := 1;
  ENDPROC
ENDMODULE
"""


def test_kripke_words_start_at_the_initial_state_and_end_in_a_repeating_final_state():
    subject = rapid_subject("tiny.mod", ast.Program(parse_text(TINY, "tiny.mod")),
                            ("x = 0", "x = 1", "Ended()"))
    # x := 1, then main's ENDPROC, then the ended state for ever
    assert subject.graph.successors == ((1,), (2,), (2,))
    assert subject.letters(range(3)) == [{"x = 0"}, {"x = 1"}, {"x = 1", "Ended()"}]

    def spot_holds(text: str) -> bool:
        negated = spot.translate(spot.formula.Not(to_spot(parse_formula(text))))
        return run_of(subject.kripke, negated) is None
    assert spot_holds('"x = 0" & X "x = 1" & X X G "Ended()"')
    assert not spot_holds('X "x = 0"')
    assert not spot_holds('G !"Ended()"')


def mutant_tally(monkeypatch, mutate) -> Tally:
    """The comparison over some generated programs with the checker broken by ``mutate``."""
    mutate(monkeypatch)
    tally = Tally()
    for subject, _ in itertools.islice(generated_subjects(), 20):
        for formula in random_formulas(subject.atoms, PROGRAM_SEED, 3):
            compare(subject, formula, tally)
    return tally


def test_comparison_catches_a_checker_that_forgets_the_negation(monkeypatch):
    def forget_negation(patch):
        patch.setattr(__import__(__name__), "to_buchi",
                      lambda negated, backend, real=to_buchi: real(negated.operand,
                                                                   backend=backend))
    assert mutant_tally(monkeypatch, forget_negation).rapidmc_wrong


def test_comparison_catches_a_checker_that_skips_the_initial_state(monkeypatch):
    class SecondStateFirst:
        def __init__(self, system):
            self.system = system

        def initial_states(self):
            return [after for state in self.system.initial_states()
                    for _, after in self.system.successors(state)]

        def successors(self, state):
            return self.system.successors(state)

    def skip_initial_state(patch):
        patch.setattr(__import__(__name__), "check_property",
                      lambda system, *args, real=check_property, **kwargs: real(
                          SecondStateFirst(system), *args, **kwargs))
    assert mutant_tally(monkeypatch, skip_initial_state).rapidmc_wrong


def test_comparison_blames_spot_when_spot_is_wrong(monkeypatch):
    def spot_forgets_the_negation(patch):
        patch.setattr(__import__(__name__), "spot_negation",
                      lambda formula: spot.translate(to_spot(formula)))
    tally = mutant_tally(monkeypatch, spot_forgets_the_negation)
    # only the checker that searched with Spot's (broken) automaton went wrong
    assert {checker for _, _, checker, _ in tally.rapidmc_wrong} == {FROM_HOA}
    reasons = {reason for _, _, reason in tally.spot_wrong}
    assert reasons == {"its word satisfies φ", "missed rapidmc's violation"}


def test_engine_agrees_with_spot_with_tiny_caches_and_bounded_searches(monkeypatch):
    # Successor caches evicted at every step, and searches cut short: the
    # answers that remain (HOLDS, VIOLATED) must still be Spot's.
    monkeypatch.setattr(store, "SUCCESSOR_CACHE_SIZE", 1)
    monkeypatch.setattr(RapidSystem, "shared_limit", 0)
    tally = Tally()
    for subject, _ in itertools.islice(generated_subjects(), 30):
        for bound in (3, 10, 30):
            for formula in random_formulas(subject.atoms, bound, 2):
                compare(subject, formula, tally, max_states=bound)
    print(tally.summary())
    assert_agreement(tally, {})
    assert all(count > 10 for count in tally.verdicts.values()), tally.verdicts
