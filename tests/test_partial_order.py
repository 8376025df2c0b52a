"""Partial-order reduction keeps every verdict (issue 20): differential tests.

``rapidmc check`` runs in-process with partial-order reduction (the default)
and with ``--no-por`` on generated programs of several tasks
(tests/task_programs.py: some mostly on the tasks' own data, which loop on
local steps and run on through several), on every data-driven check case of
several tasks, on every footprint case and on every task backup case; the
verdicts must agree, the built-in checks included.  Besides: it switches off,
with a note, for a property with X, and five independent tasks need as few
states as SPIN stores.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from rapidmc.api import load_program
from rapidmc.model.reduction.partial_order import LOCAL, SHARED, VISIBLE, PartialOrder
from rapidmc.model.reduction.relevance import atom_keys_of

from task_programs import random_tasks, task_properties
from test_check_cases import run_check, verdict_cases
from test_task_backups import CASES as BACKUP_CASES, run_check as run_backup_check
from cli_capture import run_cli

MULTI_TASK_CASES = [case for case in verdict_cases() if "--add-task" in case.extra_args]


def check_json(argv: list[str]) -> dict:
    return json.loads(run_cli(["check", *argv, "--format", "json", "--quiet"]).out)


def verdicts(document: dict) -> dict[str, str]:
    return {p["name"]: p["verdict"] for p in document["properties"]}


def states(document: dict) -> dict[str, int]:
    return {p["name"]: p["stats"]["product_states"] for p in document["properties"]}


def assert_rule_keeps_verdicts_and_pays(argv: list[str], expected: tuple[str, ...],
                                        rule_off) -> dict[str, str]:
    """One reduction rule's differential: the reduced search, ``--no-por`` and the search
    with the rule switched off (``rule_off()``, a monkeypatch) give the same verdicts, the
    unreduced ones of (no_deadlock, once, staged) are ``expected``, and the rule pays:
    reduced < rule off < unreduced in the run-time-error search's states."""
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    found = verdicts(full)
    assert (found["no_deadlock"], found["once"], found["staged"]) == expected
    assert verdicts(reduced) == found
    rule_off()
    without = check_json(argv)
    assert verdicts(without) == found
    assert states(reduced)["no_runtime_error"] < states(without)["no_runtime_error"] < \
        states(full)["no_runtime_error"]
    return found


def write_tasks(folder: Path, seed: int, procedures: bool = False,
                arrays: bool = False, local: bool = False, calls: bool = False) -> list[str]:
    argv = []
    for number, text in enumerate(random_tasks(seed, procedures, arrays, local, calls),
                                  start=1):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 1 else ["--add-task", str(path)]
    spec = folder / "props.ltl"
    spec.write_text("\n".join(task_properties(seed)) + "\n")
    # the generated tasks read PERS no task writes (``shared``) and their properties name it:
    # the fixed reading keeps such data at its initial value, as when the seeds were chosen
    # (read as data written outside, a wait on it ends and some seeds pass 30,000 states)
    return argv + ["--ltl", str(spec), "--max-states", "30000", "--fixed-outside-data"]


def assert_reduced_search_agrees(argv: list[str], seed: int) -> None:
    """The reduced and the full search of ``argv`` give the same verdicts and coverage."""
    if seed % 4 == 3:
        argv = argv + ["--no-fairness"]        # every run: the plain search alone
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values(), states(full)
    assert verdicts(reduced) == verdicts(full)
    assert never_reached(reduced) == never_reached(full)      # coverage: the same lines


@pytest.mark.parametrize("seed", range(40))
def test_generated_tasks_keep_their_verdicts(tmp_path, seed):
    argv = write_tasks(tmp_path, seed)
    assert_reduced_search_agrees(argv, seed)


@pytest.mark.parametrize("seed", range(40, 70))
def test_generated_tasks_with_procedures_keep_their_verdicts(tmp_path, seed):
    """Steps that enter and leave a task's own procedures are ample too (ENDPROC is local)."""
    argv = write_tasks(tmp_path, seed, procedures=True)
    assert_reduced_search_agrees(argv, seed)


@pytest.mark.parametrize("seed", range(70, 90))
def test_generated_tasks_on_arrays_and_named_data_keep_their_verdicts(tmp_path, seed):
    """Conditions on arrays indexed by data (read from their syntax) and data reached by
    name in the task's own scope (GetDataVal, SetDataVal) keep the reduction on."""
    argv = write_tasks(tmp_path, seed, arrays=True)
    assert_reduced_search_agrees(argv, seed)


@pytest.mark.parametrize("seed", range(90, 120))
def test_generated_tasks_mostly_on_their_own_data_keep_their_verdicts(tmp_path, seed):
    """Tasks that loop on steps of their own: the cycle proviso keeps the other tasks'
    steps (a reduction without it loses states here), and steps run on through several
    local instructions (``local_runs``), stopping before one that fails."""
    argv = write_tasks(tmp_path, seed, local=True)
    assert_reduced_search_agrees(argv, seed)


@pytest.mark.parametrize("seed", range(120, 160))
def test_generated_tasks_with_calls_and_updates_keep_their_verdicts(tmp_path, seed):
    """Instructions judged from their syntax (``syntax_footprint``): element and component
    writes, Incr, calls with arguments by value and by reference (a write through a
    reference to shared data stays dependent), functions, TPWrite, WaitTime."""
    argv = write_tasks(tmp_path, seed, calls=True)
    assert_reduced_search_agrees(argv, seed)


def never_reached(document: dict) -> set:
    return {(w["location"]["file"], w["location"]["line"]) for w in document["warnings"]
            if w["code"] == "RMC701"}


@pytest.mark.parametrize("case", MULTI_TASK_CASES, ids=lambda case: case.name)
def test_check_cases_of_several_tasks_keep_their_verdicts(case, monkeypatch):
    _, reduced, _ = run_check(case, monkeypatch)
    full_case = type(case)(**{**case.__dict__, "extra_args": case.extra_args + ("--no-por",)})
    _, full, _ = run_check(full_case, monkeypatch)
    assert verdicts(json.loads(reduced)) == verdicts(json.loads(full))


@pytest.mark.parametrize("case", sorted(p for p in BACKUP_CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_task_backups_keep_their_verdicts(case, tmp_path):
    _, reduced, _ = run_backup_check(case, case / "backup")
    options = tmp_path / "args"
    args = case / "args"
    options.write_text((args.read_text() if args.exists() else "") + "\n--no-por\n")
    for name in ("props.ltl",):
        if (case / name).exists():
            (tmp_path / name).write_text((case / name).read_text())
    _, full, _ = run_backup_check(tmp_path, case / "backup")
    assert {n: p["verdict"] for n, p in reduced.items()} == \
        {n: p["verdict"] for n, p in full.items()}


INDEPENDENT = """MODULE Independent{n}
  VAR num count{n} := 0;
  PROC main()
    FOR i FROM 1 TO 12 DO
      count{n} := count{n} + 1;
    ENDFOR
  ENDPROC
ENDMODULE
"""


def independent_tasks(folder: Path, count: int) -> list[str]:
    argv = []
    for n in range(1, count + 1):
        path = folder / f"independent{n}.mod"
        path.write_text(INDEPENDENT.format(n=n))
        argv += [str(path)] if n == 1 else ["--add-task", str(path)]
    return argv


def test_five_independent_tasks_need_few_states(tmp_path):
    argv = independent_tasks(tmp_path, 5) + ["--formula", 'bounded: G "count1 <= 12"']
    document = check_json(argv)
    assert verdicts(document) == {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS",
                                  "bounded": "HOLDS"}
    # SPIN 6.5.2 stores 71 (bench/por.py): a step runs on through the FOR step after it
    # (``local_runs``), so each task takes 14 steps, one after another
    assert max(states(document).values()) <= 71
    full = check_json(argv + ["--no-por", "--max-states", "20000"])
    assert verdicts(full)["no_runtime_error"] == "UNKNOWN"     # every order: too many


def test_a_property_with_next_turns_it_off_with_a_note(tmp_path):
    argv = independent_tasks(tmp_path, 2) + ["--formula", 'n: G ("count1 = 1" -> X "count1 >= 1")']
    document = check_json(argv)
    assert any(w["code"] == "RMC732" for w in document["warnings"])
    assert states(document) == states(check_json(argv + ["--no-por"]))


READER = """MODULE Reader
  PERS num count := 0;
  PERS num seen := 0;
  VAR num copy := 0;
  PROC main()
    copy := count;
    copy := copy * 2;
    seen := copy;
  ENDPROC
ENDMODULE
"""
WRITER = """MODULE Writer
  PERS num count := 0;
  PROC main()
    count := 1;
  ENDPROC
ENDMODULE
"""


def test_a_read_of_data_another_task_writes_is_not_reordered(tmp_path):
    """copy := count reads data the writer task writes: it is no ample step, so the run in
    which the writer goes first (seen = 2) is kept."""
    (tmp_path / "reader.mod").write_text(READER)
    (tmp_path / "writer.mod").write_text(WRITER)
    argv = [str(tmp_path / "reader.mod"), "--add-task", str(tmp_path / "writer.mod"),
            "--formula", 'never_two: G "seen <> 2"', "--formula", 'never_zero: G "seen = 0"']
    expected = {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "never_two": "VIOLATED",
                "never_zero": "VIOLATED"}
    assert verdicts(check_json(argv)) == verdicts(check_json(argv + ["--no-por"])) == expected


FOOTPRINT_CASES = Path(__file__).resolve().parent / "por_footprints"
_MARK = re.compile(r"!\s*(LOCAL|VISIBLE|SHARED)\s*$")


@pytest.mark.parametrize("case", sorted(p for p in FOOTPRINT_CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_each_instruction_has_the_footprint_its_line_names(case):
    """Every line ending in ``! LOCAL``, ``! VISIBLE`` or ``! SHARED`` compiles to
    instructions of that footprint (``PartialOrder.footprint``), with the atoms of
    ``atoms`` (one per line); the first file is the main task, each other one a task."""
    files = sorted(case.glob("*.mod"))
    program = load_program([str(files[0])], add_tasks=[str(f) for f in files[1:]])
    atoms = (case / "atoms").read_text().splitlines()
    order = PartialOrder(program, atom_keys_of(atoms))
    names = {LOCAL: "LOCAL", VISIBLE: "VISIBLE", SHARED: "SHARED"}
    entries = (program.entry,) + tuple(program.task_entries)
    expected, found = {}, {}
    for task, path in enumerate(files):
        for number, line in enumerate(path.read_text().splitlines(), start=1):
            mark = _MARK.search(line)
            if mark:
                expected[(path.name, number)] = {mark.group(1)}
        for index in _routines_of_task(program, entries[task]):
            for pc, instruction in enumerate(program.routines[index].code):
                span = instruction.span
                if span is not None and Path(span.file).name == path.name:
                    found.setdefault((path.name, span.line), set()).add(
                        names[order.footprint(task, index, pc)])
    assert {key: found.get(key) for key in expected} == expected


def _routines_of_task(program, entry: int) -> list[int]:
    """The routines of the task whose entry routine is ``entry`` (those of its modules)."""
    namespace = program.routines[entry].namespace
    return [index for index, routine in enumerate(program.routines)
            if routine.namespace == namespace]


@pytest.mark.parametrize("case", sorted(p for p in FOOTPRINT_CASES.iterdir() if p.is_dir()),
                         ids=lambda p: p.name)
def test_footprint_cases_keep_their_verdicts(case):
    """The same programs, checked with ``G atom`` and ``F atom`` per atom: the same
    verdicts with and without the reduction."""
    files = sorted(case.glob("*.mod"))
    argv = [str(files[0])] + [x for f in files[1:] for x in ("--add-task", str(f))]
    for number, atom in enumerate((case / "atoms").read_text().splitlines()):
        argv += ["--formula", f"always{number}: G {atom}", "--formula", f"once{number}: F {atom}"]
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert "UNKNOWN" not in verdicts(full).values()
    assert verdicts(reduced) == verdicts(full)
