"""Which tasks wait (``model.task_waits``): the same verdicts in every model of the inputs.

A task waits when none of its steps changes anything of its own: the values of the
stored free inputs its step chose, and the interrupts their edges queue for other tasks,
are the environment's.  Before, "changes nothing" meant "leads to the same state", and the
models differ there: the edge model keeps an edge input at 0 and drops an edge another
task serves, while ``--exact-edges`` and ``--inputs-every-step`` store the value and queue
the interrupt, so a waiting task's step changed the state and the task never counted as
waiting (a missed deadlock: HOLDS for ``no_deadlock`` with ``--exact-edges``).

The cases are data (tests/task_waits/cases.txt): two-task programs waiting on PERS flags
and on inputs, TRAPs on edges, WaitUntil reading an input, WaitDI.  Each gives the
expected verdicts of ``no_deadlock`` and of a liveness property in the three models, on
both engines; with the old definition (a mutant) a case fails.
"""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_capture import run_cli
from rapidmc.check import native
from rapidmc.model import fairness, task_waits

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)
MODELS = {"edge": [], "exact": ["--exact-edges"], "every_step": ["--inputs-every-step"]}
CASES_FILE = Path(__file__).parent / "task_waits" / "cases.txt"
LIVE = ["--formula", 'live: F "done = 1"']


def read_cases(text: str) -> dict:
    """name -> (expected verdicts, {file name: module text}) of each ``[case NAME]`` block."""
    cases: dict = {}
    for block in text.split("\n[case ")[1:]:
        head, *files = block.split("\n-- ")
        lines = head.splitlines()
        expect = next(line for line in lines if line.startswith("expect:"))
        verdicts = dict(pair.split("=") for pair in expect.split(":", 1)[1].split())
        modules = {}
        for part in files:
            name, _, module = part.partition("\n")
            modules[name.strip()] = module.rstrip("\n") + "\n"
        cases[lines[0].rstrip("]")] = (verdicts, modules)
    return cases


CASES = read_cases(CASES_FILE.read_text())


def _verdicts(folder: Path, modules: dict, options: list[str]) -> dict:
    names = list(modules)
    for name, module in modules.items():
        (folder / name).write_text(module)
    argv = ["check", str(folder / names[0])]
    for name in names[1:]:
        argv += ["--add-task", str(folder / name)]
    document = json.loads(run_cli(argv + LIVE + options + ["--format", "json", "--quiet"]).out)
    return {p["name"]: p["verdict"] for p in document["properties"]
            if p["name"] in ("no_deadlock", "live")}


@pytest.mark.parametrize("engine", ENGINES)
@pytest.mark.parametrize("name", sorted(CASES))
def test_every_model_gives_the_same_verdicts(tmp_path, name, engine):
    expected, modules = CASES[name]
    for model, options in MODELS.items():
        found = _verdicts(tmp_path, modules, options + ["--engine", engine])
        assert found == expected, (name, model)


def _changed_state(self, task, before, after) -> bool:
    return after != before


@pytest.mark.parametrize("name", ["served_edge", "pers_after_edge"])
def test_the_old_definition_misses_the_deadlock_in_the_exact_model(tmp_path, monkeypatch,
                                                                   name):
    expected, modules = CASES[name]
    monkeypatch.setattr(task_waits.TaskWaits, "own_change", _changed_state)
    assert _verdicts(tmp_path, modules, MODELS["edge"]) == expected
    assert _verdicts(tmp_path, modules, MODELS["exact"])["no_deadlock"] == "HOLDS"


def test_a_task_whose_idle_step_is_dropped_still_steps_in_the_fair_search(tmp_path,
                                                                        monkeypatch):
    """``input_never_comes``: the model drops A's step with ``diGo = 0`` (it changes
    nothing while B can go on), so without ``TaskFairness.idling`` the fair search sees no
    step of A but the one that sets ``done``, and ``F "done = 1"`` HOLDS in every model:
    a run the environment allows (``diGo`` at 0 for ever) missed."""
    expected, modules = CASES["input_never_comes"]
    assert _verdicts(tmp_path, modules, MODELS["edge"]) == expected
    monkeypatch.setattr(fairness.TaskFairness, "idling", lambda self, state, tasks: frozenset())
    for options in MODELS.values():
        assert _verdicts(tmp_path, modules, options)["live"] == "HOLDS"


def test_the_loop_says_where_a_task_that_only_idles_waits(tmp_path):
    """The counterexample of ``input_never_comes`` shows only B's steps: its report says
    that A stands at its WaitDI, whose steps change nothing."""
    _, modules = CASES["input_never_comes"]
    for name, module in modules.items():
        (tmp_path / name).write_text(module)
    out = run_cli(["check", "a.mod", "--add-task", "b.mod", *LIVE], cwd=tmp_path).out
    live = out[out.index("live: VIOLATED"):]
    assert "in the loop, main task waits at a.mod:4 (WaitDI diGo, 1;): its steps there " \
        "change nothing" in live


def test_the_cases_file_reads():
    assert set(CASES) >= {"served_edge", "pers_after_edge", "waituntil_input", "waitdi",
                          "waitdi_watched", "input_never_comes"}
    for verdicts, modules in CASES.values():
        assert set(verdicts) == {"no_deadlock", "live"} and len(modules) == 2
