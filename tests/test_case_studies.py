"""The case studies under case_studies/: verdicts, exit codes and counterexamples.

Each case runs ``rapidmc check PROGRAM --env PLANT --ltl SPEC`` in-process
(``rapidmc.cli.main``), as text and as ``--format json``, from the
repository root so that file names in the output are the ones the READMEs
show.  ``CASES`` is the table of expected verdicts; the counterexample
tests read the JSON trace back into the signal values of every step and
check that the trace really shows the violation and its cause.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Mapping, Sequence

import pytest

from rapidmc.cli import main

ROOT = Path(__file__).resolve().parent.parent
SORTER = ROOT / "case_studies" / "sorter"
DOOR = ROOT / "case_studies" / "door"
MULTIMOVE = ROOT / "case_studies" / "multimove"

HOLDS, VIOLATED = "HOLDS", "VIOLATED"


@dataclass(frozen=True)
class Case:
    """One ``rapidmc check`` run and the verdict expected for each property."""

    program: str
    env: str
    spec: str
    verdicts: Mapping[str, str]
    reachable_states: int

    def argv(self, *extra: str) -> list[str]:
        """The command line, with the built-in LTL translator whether or not Spot is installed."""
        return ["check", self.program, "--env", self.env, "--ltl", self.spec,
                "--backend", "builtin", *extra]

    @property
    def exit_code(self) -> int:
        return 1 if VIOLATED in self.verdicts.values() else 0


def sorter_case(program: str, states: int, p1: str, p2: str, p3: str,
                plant: str = "plant.mod") -> Case:
    return Case(f"case_studies/sorter/{program}", f"case_studies/sorter/{plant}",
                "specs/sorter.ltl", {"P1": p1, "P2": p2, "P3": p3}, states)


def door_case(program: str, states: int, d1: str, d2: str) -> Case:
    return Case(f"case_studies/door/{program}", "case_studies/door/plant.mod",
                "specs/door.ltl", {"D1": d1, "D2": d2}, states)


def multimove_case(backup: str, states: int, mutex: str, gives_back: str) -> Case:
    verdicts = {"zone_mutex": mutex, "no_motion_door_open": HOLDS, "rob1_answered": HOLDS,
                "rob2_answered": HOLDS, "rob1_gives_back": gives_back,
                "rob2_gives_back": gives_back, "zone_box_mutex": mutex,
                "rob1_zone_granted": HOLDS, "rob2_zone_granted": HOLDS}
    return Case(f"case_studies/multimove/{backup}", "case_studies/multimove/door.mod",
                "case_studies/multimove/cell.ltl", verdicts, states)


# reachable_states: states of program and plant together that an exhaustive
# search visits (the model states of every property that HOLDS).
CASES = {
    "sorter_a": sorter_case("sorter_a.mod", 931, HOLDS, HOLDS, HOLDS),
    "sorter_b": sorter_case("sorter_b.mod", 466, HOLDS, VIOLATED, VIOLATED),
    "sorter_c": sorter_case("sorter_c.mod", 144, HOLDS, HOLDS, VIOLATED),
    # Plant variants of the README's "Modelling choices": program A seems wrong.
    "sorter_a_reset_on_arrival": sorter_case("sorter_a.mod", 1722, VIOLATED, VIOLATED, HOLDS,
                                             plant="variants/plant_reset_on_arrival.mod"),
    "sorter_a_sensors_forget": sorter_case("sorter_a.mod", 783, HOLDS, VIOLATED, HOLDS,
                                           plant="variants/plant_sensors_forget.mod"),
    "door_safe": door_case("door_safe.mod", 28, HOLDS, HOLDS),
    "door_race": door_case("door_race.mod", 35, VIOLATED, HOLDS),
    "multimove_fixed": multimove_case("fixed", 2157, HOLDS, HOLDS),
    "multimove_faulty": multimove_case("faulty", 4810, VIOLATED, VIOLATED),
}

VIOLATIONS = [(case, name) for case, c in CASES.items()
              for name, verdict in c.verdicts.items() if verdict == VIOLATED]


# --- running the tool ------------------------------------------------------------


def run_check(case: Case, capsys, *extra: str) -> tuple[int, str]:
    """(exit code, stdout) of ``rapidmc check`` on ``case``, run from the repository root."""
    capsys.readouterr()
    code = main(case.argv(*extra))
    return code, capsys.readouterr().out


@pytest.fixture
def at_root(monkeypatch):
    monkeypatch.chdir(ROOT)


class Outputs(dict):
    """(exit code, stdout) of ``rapidmc check`` with ``extra`` on each case, run from the
    repository root when a test first asks for that case: several tests read the same run,
    and under pytest-xdist a worker runs only the cases its tests ask for."""

    def __init__(self, *extra: str):
        super().__init__()
        self.extra = extra

    def __missing__(self, key: str) -> tuple[int, str]:
        out, previous = io.StringIO(), os.getcwd()
        os.chdir(ROOT)
        try:
            with contextlib.redirect_stdout(out):
                code = main(CASES[key].argv(*self.extra))
        finally:
            os.chdir(previous)
        self[key] = code, out.getvalue()
        return self[key]


class JsonReports(dict):
    """The JSON report of each case, its exit code as the field "exit code"."""

    def __init__(self):
        super().__init__()
        self.outputs = Outputs("--format", "json")

    def __missing__(self, key: str) -> dict:
        code, output = self.outputs[key]
        assert output, f"{key}: rapidmc check printed no report (exit code {code})"
        self[key] = json.loads(output)
        self[key]["exit code"] = code        # (not a field of the report)
        return self[key]


# One of each per process: pytest-xdist's work stealing can run a module's tests on a worker
# in several stretches, and a module-scoped fixture would run the cases again for each.
TEXT_OUTPUTS, JSON_REPORTS = Outputs(), JsonReports()


@pytest.fixture
def text_outputs() -> Outputs:
    """The text report of every case, run once per worker."""
    return TEXT_OUTPUTS


@pytest.fixture
def json_reports() -> JsonReports:
    """The JSON report of every case and its exit code, run once per worker."""
    return JSON_REPORTS


def verdicts_in_text(output: str) -> dict[str, str]:
    """``{name: verdict}`` from the verdict lines ``P1: HOLDS (851 states, 0.12 s)``."""
    return dict(re.findall(r"^(\w+): (HOLDS|VIOLATED|UNKNOWN) \(", output, re.MULTILINE))


def split_verdicts(case: Case, verdicts: Mapping[str, str]) -> tuple[dict, set]:
    """(verdicts of the spec's properties, verdicts of rapidmc's built-in checks)."""
    ours = {name: verdict for name, verdict in verdicts.items() if name in case.verdicts}
    built_in = {verdict for name, verdict in verdicts.items() if name not in case.verdicts}
    return ours, built_in


def property_report(report: dict, name: str) -> dict:
    [entry] = [p for p in report["properties"] if p["name"] == name]
    return entry


# --- reading a trace back -------------------------------------------------------------

# The names a trace may use for each physical signal: its own, or the
# program's data object bound to it with AliasIO.
SIGNAL_NAMES = {
    "C_IN": ("C_IN", "c_in"), "C_OUT": ("C_OUT", "c_out"),
    "S_1": ("S_1", "s1"), "S_2": ("S_2", "s2"), "S_3": ("S_3", "s3"), "S_4": ("S_4", "s4"),
    "GRIPPER": ("GRIPPER", "do_grip"),
    "DOOR_CLOSED": ("DOOR_CLOSED", "door_closed"), "DOOR_LOCK": ("DOOR_LOCK", "door_lock"),
    "ROBOT_MOVED": ("ROBOT_MOVED",),
}


class Valuation:
    """The values shown for one step of a trace (every change up to that step)."""

    def __init__(self, values: Mapping[str, str]):
        self.values = dict(values)

    def signal(self, physical: str) -> bool:
        """Whether ``physical`` reads 1 in this step, found under any name it may be shown by."""
        wanted = {name.upper() for name in SIGNAL_NAMES[physical]}
        found = [value for key, value in self.values.items() if _last_identifier(key) in wanted]
        assert found, f"the trace shows no value of {physical} (names shown: {sorted(self.values)})"
        return all(str(value).strip() in ("1", "TRUE") for value in found)

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Valuation) and self.values == other.values


def _last_identifier(key: str) -> str:
    match = re.search(r"[A-Za-z_][A-Za-z0-9_]*$", key.strip())
    return match.group(0).upper() if match else key.upper()


@dataclass(frozen=True)
class Lasso:
    """A counterexample as values per step: ``states[loop:]`` repeats for ever."""

    steps: Sequence[dict]
    states: Sequence[Valuation]
    loop: int
    closing: Valuation

    def after(self, index: int) -> Valuation:
        """The state that follows ``states[index]`` on the infinite run."""
        return self.states[index + 1] if index + 1 < len(self.states) else self.states[self.loop]


def read_lasso(trace: dict) -> Lasso:
    """Fold the per-step changes of a JSON trace into the full values of every step."""
    steps = [*trace["prefix"], *trace["cycle"]]
    values: dict[str, str] = {}
    states = []
    for step in steps:
        values.update(step["changes"])
        states.append(Valuation(values))
    closing = dict(values)
    closing.update(trace["closing"]["changes"])
    loop = [step["index"] for step in steps].index(trace["loop_start"])
    return Lasso(steps, states, loop, Valuation(closing))


def response_violated(p: Callable[[Valuation], bool], q: Callable[[Valuation], bool]):
    """Whether a lasso violates ``G(p -> F q)``: some p-state is never followed by a q-state."""
    def violated(lasso: Lasso) -> bool:
        return any(p(state) and not any(q(later) for later in lasso.states[min(i, lasso.loop):])
                   for i, state in enumerate(lasso.states))
    return violated


def next_violated(p: Callable[[Valuation], bool], q: Callable[[Valuation], bool]):
    """Whether a lasso violates ``G(p -> X q)``: some p-state is followed by a non-q-state."""
    def violated(lasso: Lasso) -> bool:
        return any(p(state) and not q(lasso.after(i)) for i, state in enumerate(lasso.states))
    return violated


def passed(s: Valuation) -> bool:
    return s.signal("S_1") and s.signal("S_2")


# How each property's violation shows on the run (the formulas of specs/*.ltl).
VIOLATION_SHOWN = {
    "P1": response_violated(lambda s: not s.signal("C_IN") and passed(s),
                            lambda s: s.signal("S_3") and not s.signal("S_4")),
    "P2": response_violated(lambda s: not s.signal("C_IN") and not passed(s),
                            lambda s: not s.signal("S_3") and s.signal("S_4")),
    "P3": response_violated(lambda s: s.signal("S_3") != s.signal("S_4"),
                            lambda s: s.signal("C_OUT")),
    "D1": next_violated(lambda s: not s.signal("DOOR_CLOSED"),
                        lambda s: not s.signal("ROBOT_MOVED")),
    "rob1_gives_back": response_violated(lambda s: s.values["grant1"] == "TRUE",
                                         lambda s: s.values["req1"] == "FALSE"),
    "rob2_gives_back": response_violated(lambda s: s.values["grant2"] == "TRUE",
                                         lambda s: s.values["req2"] == "FALSE"),
    "zone_mutex": lambda lasso: any(one and two for one, two in zip(
        in_zone(lasso, "Rob1.mod"), in_zone(lasso, "Rob2.mod"))),
    "zone_box_mutex": lambda lasso: any(
        state.values.get("T_ROB1.robot TCP") == state.values.get("T_ROB2.robot TCP") == P_ZONE
        for state in lasso.states),
}
P_ZONE = "[900,0,300]"      # pZone of both robot tasks of case_studies/multimove


def in_zone(lasso: Lasso, module: str) -> list[bool]:
    """Per state of the lasso: whether the robot of task module ``module`` is in its routine
    WorkInZone (it has called it and not yet left it at its ENDPROC)."""
    inside, shown = False, []
    for step in lasso.steps:
        location = step["location"]
        if location and Path(location["file"]).name == module:
            if step["source"] == "WorkInZone;":
                inside = True
            elif step["source"] == "ENDPROC":
                inside = False
        shown.append(inside)
    return shown


def line_of(path: Path, text: str, occurrence: int = 1) -> int:
    """The 1-based number of the line holding the ``occurrence``-th ``text`` in ``path``."""
    hits = [number for number, line in enumerate(path.read_text().splitlines(), 1) if text in line]
    return hits[occurrence - 1]


def step_line(step: dict) -> int | None:
    return step["location"]["line"] if step["location"] else None


# --- verdicts and exit codes ------------------------------------------------------------


@pytest.mark.parametrize("key", CASES)
def test_text_report_gives_the_expected_verdicts_and_exit_code(key, text_outputs):
    """The spec's verdicts as expected; the built-in checks (run-time errors, deadlocks) hold."""
    case = CASES[key]
    code, output = text_outputs[key]
    ours, built_in = split_verdicts(case, verdicts_in_text(output))
    assert ours == case.verdicts
    assert built_in == {HOLDS}
    assert code == case.exit_code


@pytest.mark.parametrize("key", CASES)
def test_json_report_gives_the_expected_verdicts(key, json_reports):
    case = CASES[key]
    verdicts = {p["name"]: p["verdict"] for p in json_reports[key]["properties"]}
    ours, built_in = split_verdicts(case, verdicts)
    assert ours == case.verdicts
    assert built_in == {HOLDS}


@pytest.mark.parametrize("key", CASES)
def test_exhaustive_searches_visit_every_reachable_state(key, capsys, at_root):
    """The state count of each program with its plant (reductions off: every state of the
    semantics), the same for every property that holds."""
    _, output = run_check(CASES[key], capsys, "--format", "json", "--no-reduce")
    counts = {p["name"]: p["stats"]["model_states"]
              for p in json.loads(output)["properties"] if p["verdict"] == HOLDS}
    assert counts == dict.fromkeys(counts, CASES[key].reachable_states)


@pytest.mark.parametrize("key", CASES)
def test_json_exit_code_matches_the_text_one(key, json_reports):
    assert json_reports[key]["exit code"] == CASES[key].exit_code


# --- counterexamples --------------------------------------------------------------------


@pytest.mark.parametrize("key, name", VIOLATIONS)
def test_counterexample_loop_closes_on_its_first_state(key, name, json_reports):
    """Replaying the printed changes, the closing step returns to the loop's first state."""
    lasso = read_lasso(property_report(json_reports[key], name)["trace"])
    assert lasso.closing == lasso.states[lasso.loop]


@pytest.mark.parametrize("key, name", VIOLATIONS)
def test_counterexample_shows_the_violation(key, name, json_reports):
    lasso = read_lasso(property_report(json_reports[key], name)["trace"])
    assert VIOLATION_SHOWN[name](lasso)


def test_sorter_b_p2_trace_drops_a_rejected_pinion_at_c1(json_reports):
    """B/P2: a pinion some sensor rejected is carried by the flag_2 branch to C1 and dropped there."""
    lasso = read_lasso(property_report(json_reports["sorter_b"], "P2")["trace"])
    program = SORTER / "sorter_b.mod"
    wrong_move = line_of(program, "MoveJ c1, v, zone, gripper;", occurrence=2)
    releases = {line_of(program, "SetDO do_grip, 0;"), line_of(program, "Drop;", occurrence=2)}
    drops = [i for i, state in enumerate(lasso.states)
             if state.signal("S_3") and (i == 0 or not lasso.states[i - 1].signal("S_3"))]
    assert drops, "no step sets S_3"
    drop = drops[0]
    assert step_line(lasso.steps[drop]) in releases
    at_drop = lasso.states[drop]
    assert not passed(at_drop) and not at_drop.signal("S_4")
    moves = [step_line(step) for step in lasso.steps[:drop] if "MoveJ" in (step["source"] or "")]
    assert moves[-1] == wrong_move


def test_door_race_d1_trace_moves_after_the_door_opened_between_test_and_lock(json_reports):
    """door_race/D1: the robot's move is taken from a state where the door is open."""
    lasso = read_lasso(property_report(json_reports["door_race"], "D1")["trace"])
    program = DOOR / "door_race.mod"
    moving = [i for i in range(len(lasso.states))
              if not lasso.states[i].signal("DOOR_CLOSED") and lasso.after(i).signal("ROBOT_MOVED")]
    assert moves_from_line(lasso, moving[0]) == line_of(program, "MoveJ pick")


def test_multimove_mutex_trace_names_both_tasks_entering_the_zone(json_reports):
    """faulty/zone_mutex: a robot enters the zone while the other is inside, each having
    passed its own zone_busy test; the steps name their tasks (the inputs choose T_ROB1 and
    T_ROB2)."""
    report = property_report(json_reports["multimove_faulty"], "zone_mutex")
    lasso = read_lasso(report["trace"])
    both = next(i for i, (one, two) in enumerate(zip(in_zone(lasso, "Rob1.mod"),
                                                     in_zone(lasso, "Rob2.mod"))) if one and two)
    entered = [step for step in lasso.steps[:both + 1] if step["source"] == "WorkInZone;"]
    assert {step["inputs"]["task"] for step in entered[-2:]} == {"T_ROB1", "T_ROB2"}
    tests = {step["inputs"]["task"] for step in lasso.steps[:both + 1]
             if step["source"] == "WaitUntil NOT zone_busy;"}
    assert tests == {"T_ROB1", "T_ROB2"}
    assert report["atoms"] == [
        {"atom": 'InRoutine(T_ROB1, "WorkInZone")', "tasks": ["T_ROB1"]},
        {"atom": 'InRoutine(T_ROB2, "WorkInZone")', "tasks": ["T_ROB2"]}]


def test_multimove_zone_box_trace_moves_each_robot_by_its_own_task(json_reports):
    """faulty/zone_box_mutex, stated on the two robots' TCPs: each task's move changes its
    own robot's position only (T_ROB1.robot TCP by Rob1.mod's steps, T_ROB2.robot TCP by
    Rob2.mod's), and the atoms name their tasks."""
    report = property_report(json_reports["multimove_faulty"], "zone_box_mutex")
    lasso = read_lasso(report["trace"])
    movers = {name: {Path(step["location"]["file"]).name for step in lasso.steps
                     if name in step["changes"] and step["location"]}
              for name in ("T_ROB1.robot TCP", "T_ROB2.robot TCP")}
    assert movers == {"T_ROB1.robot TCP": {"Rob1.mod"}, "T_ROB2.robot TCP": {"Rob2.mod"}}
    assert [atom["tasks"] for atom in report["atoms"]] == [["T_ROB1"], ["T_ROB2"]]


def moves_from_line(lasso: Lasso, index: int) -> int | None:
    """The source line of the step taken from ``states[index]``."""
    following = lasso.steps[index + 1] if index + 1 < len(lasso.steps) else lasso.steps[lasso.loop]
    return step_line(following)


# --- the README shows what the tool prints -------------------------------------------------

SECONDS = re.compile(r"\d[\d,]*\.\d+ s\b")


def normalise_times(text: str) -> str:
    return SECONDS.sub("T s", text)


def test_sorter_readme_first_command_is_a_check_with_the_plant():
    readme = (SORTER / "README.md").read_text()
    first_block = re.search(r"```\n(.*?)```", readme, re.DOTALL).group(1)
    command = first_block.strip().splitlines()[0]
    case = CASES["sorter_b"]
    assert command == f"rapidmc check {case.program} --env {case.env} --ltl {case.spec}"


@pytest.mark.parametrize("readme, key", [(SORTER / "README.md", "sorter_b"),
                                         (SORTER / "README.md", "sorter_c"),
                                         (DOOR / "README.md", "door_race")])
def test_readme_shows_the_counterexamples_in_full_as_printed(readme, key, text_outputs):
    _, output = text_outputs[key]
    assert normalise_times(output) in normalise_times(readme.read_text())


def test_multimove_readme_excerpt_is_printed_in_order(text_outputs):
    """The README's zone_mutex excerpt: its lines are the check's output, in order."""
    readme = (MULTIMOVE / "README.md").read_text()
    block = re.search(r"```\n(zone_mutex: VIOLATED.*?)```", readme, re.DOTALL).group(1)
    _, output = text_outputs["multimove_faulty"]
    lines = normalise_times(output).splitlines()
    position = 0
    for line in normalise_times(block).splitlines():
        if line.strip() == "...":
            continue
        position = lines.index(line, position) + 1
