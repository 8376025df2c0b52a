"""The compiled search core (``rapidmc.check.native``) against the pure Python engine.

Differential: ``rapidmc check --format json`` with ``--engine native`` and with
``--engine python`` prints the same report, timing, memory figures and the engine's
name aside (every verdict, every count, every counterexample, coverage and vacuity
warnings), on the data-driven check cases (with the run-time error search's graph
reused, as by default), on the case studies and on generated programs
(tests/reduction_programs.py, and tests/task_programs.py for several tasks; a third of
them with every property search stepping the program itself).  The
native table gives every state the id the Python table gives it; the engine choice
(``--engine``, ``RAPIDMC_ENGINE``, ``--version``) and its diagnostic when the core is
not built are pinned below.  Without the extension the differential tests are skipped
and the rest run on the Python engine.
"""
from __future__ import annotations

import contextlib
import io
import json
import os
import subprocess
import sys

import pytest
from hypothesis import given, strategies as st

from rapidmc.check import check_property, find_reachable, native
from rapidmc.check.states import StateTable
from rapidmc.cli import main

from fuzz_invoke import assert_acceptable, invoke
from fuzz_programs import programs
from reduction_programs import properties, random_program
import robot_programs
from test_fuzz import STDIN, domains, formula_texts, fuzz_settings, write
from test_fuzz import scratch_folder  # noqa: F401  (the folder write() writes in)
from test_case_studies import CASES, ROOT
from test_partial_order import write_tasks
from test_step_machine import WAITING_TASKS, waiting_arguments
from test_check_cases import verdict_cases
from test_graph_reuse import (COUNTERS, case_arguments, default_report, model_of, report,
                              without_measurements)
from test_partial_order import write_tasks

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")


def engine_report(argv: list[str], monkeypatch, engine: str, reuse: bool = True):
    """``report`` (test_graph_reuse) with ``--engine``, the engine's name dropped."""
    before = native.engine()
    try:
        code, document = report([*argv, "--engine", engine], monkeypatch, reuse)
    finally:
        native.use_engine(before)
    document.pop("command", None)            # (names the engine)
    engines = {entry["stats"].pop("engine") for entry in document.get("properties", [])}
    assert engine == native.NATIVE or engines <= {native.PYTHON}
    return code, document


def assert_same_reports(argv: list[str], monkeypatch, reuse: bool = True) -> dict:
    native_report = engine_report(argv, monkeypatch, native.NATIVE, reuse)
    assert native_report == engine_report(argv, monkeypatch, native.PYTHON, reuse)
    return native_report[1]


@needs_native
@pytest.mark.parametrize("case", verdict_cases(), ids=lambda case: case.name)
def test_check_cases_report_the_same_with_both_engines(case, monkeypatch):
    """With the graph reused.  The cases' searches that step the program again give the
    same reports too: test_graph_reuse shows stepped == reused on each engine (it runs in
    both runs of .ci/run), and this test reused(native) == reused(python).  When the
    process's engine is the native one, its side is the default run other modules share."""
    argv = case_arguments(case, monkeypatch)
    if native.engine() != native.NATIVE:
        assert_same_reports(argv, monkeypatch)
        return
    code, document = default_report(case, monkeypatch)
    document.pop("command", None)            # (as engine_report drops it)
    assert {entry["stats"].pop("engine") for entry in document.get("properties", [])} \
        <= {native.NATIVE, native.PYTHON}
    assert (code, document) == engine_report(argv, monkeypatch, native.PYTHON)


@needs_native
@pytest.mark.parametrize("name", sorted(CASES))
def test_case_studies_report_the_same_with_both_engines(name, monkeypatch):
    monkeypatch.chdir(ROOT)
    document = assert_same_reports(CASES[name].argv()[1:], monkeypatch)
    assert {entry["name"]: entry["verdict"] for entry in document["properties"]} \
        .items() >= CASES[name].verdicts.items()


@needs_native
def test_a_controller_of_two_robots_reports_the_same_with_both_engines(monkeypatch):
    """tests/task_backups/robots: T_ROB1 and T_ROB2 each keep their own robot in the state."""
    case = ROOT / "tests" / "task_backups" / "robots"
    document = assert_same_reports([str(case / "backup"), "--ltl", str(case / "props.ltl")],
                                   monkeypatch)
    verdicts = {entry["name"]: entry["verdict"] for entry in document["properties"]}
    assert verdicts["rob1_own_side"] == "HOLDS" and verdicts["both_at_p10"] == "VIOLATED"


@needs_native
@pytest.mark.parametrize("seed", range(12))
def test_generated_programs_report_the_same_with_both_engines(seed, tmp_path, monkeypatch):
    (tmp_path / "random.mod").write_text(random_program(seed))
    (tmp_path / "props.ltl").write_text("\n".join(properties(seed, seed % 2 == 1)) + "\n")
    monkeypatch.chdir(tmp_path)
    argv = ["random.mod", "--ltl", "props.ltl", "--max-states", "20000"]
    document = assert_same_reports(argv, monkeypatch, reuse=seed % 3 != 0)
    assert document["properties"], "the program's properties were checked"


@needs_native
@pytest.mark.parametrize("seed", range(4))
def test_robot_programs_without_the_position_report_the_same_with_both_engines(
        seed, tmp_path, monkeypatch):
    """tests/robot_programs.py: moves that leave the robot where it is (its position is read
    back only to move again, model.robot_tracking) give both engines the same report."""
    (tmp_path / "prog.mod").write_text(robot_programs.random_program(seed))
    monkeypatch.chdir(tmp_path)
    argv = ["prog.mod", *[word for text in robot_programs.properties(seed)
                          for word in ("--formula", text)], "--max-states", "3000"]
    document = assert_same_reports(argv, monkeypatch, reuse=seed % 2 == 0)
    assert any(entry["assumes"] for entry in document["properties"])


@needs_native
@pytest.mark.parametrize("seed", [*range(6), *range(90, 96)])
def test_generated_tasks_report_the_same_with_both_engines(seed, tmp_path, monkeypatch):
    """Programs of several tasks (tests/task_programs.py; from seed 90 mostly on their own
    data): the partial-order reduction's ample sets and local runs give both engines the
    same states, counts and counterexamples."""
    argv = write_tasks(tmp_path, seed, local=seed >= 90)
    document = assert_same_reports(argv, monkeypatch, reuse=seed % 3 != 0)
    assert document["properties"], "the program's properties were checked"


@needs_native
@fuzz_settings(40)
@given(programs(), st.data())
def test_fuzzed_programs_answer_the_same_with_both_engines(program, data):
    """The fuzzer's generated programs (tests/test_fuzz.py), checked by both engines: the
    same exit code, stderr and JSON report (measurements and the engine's name aside)."""
    path = write("engines.mod", program.text)
    formula = data.draw(formula_texts(program.atoms))
    # (a state bound, no time bound: a time bound could stop the engines at different states)
    argv = ["check", "--max-states", "2000", "--quiet", *domains(program.text), "--format",
            "json", "--formula", "p: G F true", "--formula", f"q: {formula}", path]
    outcomes = {}
    before = native.engine()
    try:
        for engine in native.ENGINES:
            outcome = invoke(argv + ["--engine", engine], STDIN)
            assert_acceptable(outcome)
            outcomes[engine] = (outcome.exit_code, outcome.stderr, comparable(outcome.stdout))
    finally:
        native.use_engine(before)
    assert outcomes[native.NATIVE] == outcomes[native.PYTHON]


def comparable(stdout: str):
    """A JSON report without what differs between engines (or the text, when not JSON)."""
    try:
        document = json.loads(stdout)
    except ValueError:
        return stdout
    document.pop("command", None)
    for entry in document.get("properties", []):
        entry["stats"].pop("engine", None)
    return without_measurements(document)


@needs_native
@pytest.mark.parametrize("max_states", [1, 7, 40])
def test_bounded_searches_stop_at_the_same_state(max_states, tmp_path):
    model = model_of(COUNTERS, 'P: G ("c0 < 3" & "c1 < 3")', tmp_path)
    _, buchi, valuation = model.jobs[0]
    results = {}
    for engine in native.ENGINES:
        with native.engine_used(engine):
            results[engine] = (
                find_reachable(model.system, model.system.failed, max_states=max_states),
                check_property(model.system, buchi, valuation, max_states=max_states))
    for python, compiled in zip(results[native.PYTHON], results[native.NATIVE]):
        assert (python.verdict, python.reason) == (compiled.verdict, compiled.reason)
        assert without_measurements(python.stats.as_dict()) | {"engine": None} == \
            without_measurements(compiled.stats.as_dict()) | {"engine": None}
    assert results[native.NATIVE][1].stats.engine == native.NATIVE


@needs_native
def test_a_property_of_more_than_64_atoms_reports_the_same(tmp_path, monkeypatch):
    """Valuations beyond 64 bits (the compiled core keeps 64 per state): the native engine
    leaves such a search's loop to Python, with the same report."""
    (tmp_path / "prog.mod").write_text(COUNTERS)
    atoms = " | ".join(f'"c0 < {k}"' for k in range(1, 71))
    (tmp_path / "props.ltl").write_text(f"wide: G ({atoms})\nnarrow: G \"c0 < 5\"\n")
    monkeypatch.chdir(tmp_path)
    document = assert_same_reports(["prog.mod", "--ltl", "props.ltl"], monkeypatch)
    assert {entry["name"]: entry["verdict"] for entry in document["properties"]} == \
        {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "wide": "HOLDS",
         "narrow": "HOLDS"}


@needs_native
def test_the_native_table_gives_every_state_the_python_tables_id(tmp_path):
    model = model_of(COUNTERS, 'P: G "c0 < 3"', tmp_path)
    graphs = []
    find_reachable(model.system, model.system.failed, explored=graphs.append)
    states = [graphs[0].states[i] for i in range(len(graphs[0]))]
    python, compiled = StateTable(model.system), native.NativeStateTable(model.system)
    for state in states + states[::-1]:
        assert python.intern(state) == compiled.intern(state)
    assert len(python) == len(compiled) == len(states)
    assert [compiled[i] for i in range(len(states))] == states
    assert compiled.intern(model.system.initial_states()[0], add=False) == (0, False)
    unknown = states[0]._replace(errno=12345.0)
    assert compiled.intern(unknown, add=False) == python.intern(unknown, add=False) == (-1, True)
    with pytest.raises(IndexError):
        compiled[len(states)]
    assert compiled.memory_bytes() > compiled.native_bytes() >= 8 * len(states)


def test_the_engine_is_chosen_by_name_and_refused_when_not_built(monkeypatch):
    with pytest.raises(ValueError):
        native.use_engine("fast")
    with native.engine_used(native.PYTHON):
        assert native.engine() == native.PYTHON
        assert not native.native_search()
    monkeypatch.setattr(native, "_native", None)
    with pytest.raises(ValueError):
        native.use_engine(native.NATIVE)
    assert "native core not built" in native.description()


def test_engine_native_without_the_core_is_a_diagnostic(monkeypatch, tmp_path):
    (tmp_path / "prog.mod").write_text(COUNTERS)
    monkeypatch.setattr(native, "_native", None)
    err = io.StringIO()
    with contextlib.redirect_stderr(err), contextlib.redirect_stdout(io.StringIO()):
        code = main(["check", str(tmp_path / "prog.mod"), "--engine", "native", "--quiet"])
    assert code == 2
    assert "[RMC750]" in err.getvalue() and "--engine python" in err.getvalue()


def test_engine_holds_for_its_command_only(tmp_path):
    # rapidmc check --engine python, called in this process (as tests and editors do),
    # leaves the engine the process had: a later search in it is not silently on Python
    (tmp_path / "prog.mod").write_text(COUNTERS)
    before = native.engine()
    with contextlib.redirect_stdout(io.StringIO()):
        main(["check", str(tmp_path / "prog.mod"), "--engine", native.PYTHON, "--quiet"])
    assert native.engine() == before


def test_the_python_engine_is_named_in_the_json_stats(tmp_path):
    (tmp_path / "prog.mod").write_text(COUNTERS)
    out = io.StringIO()
    before = native.engine()
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            main(["check", str(tmp_path / "prog.mod"), "--engine", "python",
                  "--formula", 'P: G "c0 < 3"', "--format", "json", "--quiet"])
    finally:
        native.use_engine(before)
    engines = {entry["stats"]["engine"] for entry in json.loads(out.getvalue())["properties"]}
    assert engines == {native.PYTHON}


@pytest.mark.parametrize("variable, expected", [("python", "python"), ("", None)])
def test_version_names_the_engine_the_environment_chooses(variable, expected):
    environment = {"RAPIDMC_ENGINE": variable}
    done = subprocess.run([sys.executable, "-m", "rapidmc", "--version"], capture_output=True,
                          text=True, env={**os.environ, **environment})
    assert done.returncode == 0
    expected = expected or (native.NATIVE if native.available() else native.PYTHON)
    assert f"search engine {expected} " in done.stdout
    assert ("native core built" if native.available() else "native core not built") \
        in done.stdout


@needs_native
@pytest.mark.parametrize("seed", [0, 1, 2, 5, 41, 44, 71, 76])
def test_reduced_task_programs_report_the_same_with_both_engines(seed, tmp_path, monkeypatch):
    """tests/test_partial_order.py's generated tasks (plain, with procedures, on arrays),
    searched with the partial-order reduction: its cycle proviso remembers states by key,
    which the native engine computes in C, so both must choose the same steps: the same
    verdicts and counts."""
    argv = write_tasks(tmp_path, seed, procedures=40 <= seed < 70, arrays=seed >= 70)
    assert_same_reports(argv, monkeypatch, reuse=seed % 2 == 0)


@needs_native
@pytest.mark.parametrize("seed", [0, 1, 3, 6, 41, 44, 71, 76, 90, 93])
def test_unreduced_task_programs_report_the_same_with_both_engines(seed, tmp_path,
                                                                   monkeypatch):
    """Without the partial-order reduction a program of several tasks is searched on the
    packed table, the step machine taking each task's instruction where it can and Python
    the others' (``_packed.c``'s ``tasks_step``): the same verdicts, counts,
    counterexamples and coverage as the Python engine (plain tasks, with procedures, on
    arrays, mostly on their own data)."""
    argv = write_tasks(tmp_path, seed, procedures=40 <= seed < 70, arrays=70 <= seed < 90,
                       local=seed >= 90)
    assert_same_reports(argv + ["--no-por"], monkeypatch, reuse=seed % 2 == 0)


@needs_native
@pytest.mark.parametrize("name", sorted(WAITING_TASKS))
def test_unreduced_waits_and_barriers_report_the_same_with_both_engines(name, monkeypatch):
    """Tasks that wait and meet at barriers (tests/test_step_machine.py's
    ``WAITING_TASKS``), unreduced: the machine takes the waits' steps, idle ones
    included, and the reports (verdicts, counts, counterexamples, coverage) are the
    Python engine's."""
    assert_same_reports(waiting_arguments(name) + ["--no-por"], monkeypatch)


def family_check(folder, size: int, max_states: int) -> list[str]:
    """The arguments of a check of bench/controllers.py's family (buffers of ``size``,
    three kinds of command, its LTL property), the backup written into ``folder``."""
    sys.path.insert(0, str(ROOT / "bench"))
    try:
        from controllers import family_arguments, family_property, write_backup
    finally:
        sys.path.remove(str(ROOT / "bench"))
    write_backup(folder / "cell", size)
    (folder / "cell.ltl").write_text(f"moves: {family_property(2)}\n")
    return [str(folder / "cell"), *family_arguments(3), "--ltl", str(folder / "cell.ltl"),
            "--max-states", str(max_states)]


@needs_native
def test_a_whole_controller_reports_the_same_with_both_engines(tmp_path, monkeypatch):
    """bench/controllers.py's family (two motion tasks with buffers of records, a logger,
    PERS flags and barriers), reduced, bounded by states: the same report on both engines."""
    argv = family_check(tmp_path, 16, 3000)
    assert_same_reports(argv, monkeypatch)
    # unreduced: on the packed table, the machine stepping the tasks it can
    assert_same_reports(argv + ["--no-por"], monkeypatch)


# one task that calls a procedure: the single task's machine leaves the call and its end
# to Python, half of the states
ONE_TASK_CALLS = """MODULE One
  VAR num n := 0;
  VAR num total := 0;
  PROC main()
    WHILE TRUE DO
      n := (n + 1) MOD 4;
      bump n;
    ENDWHILE
  ENDPROC
  PROC bump(num k)
    total := (total + k) MOD 5;
  ENDPROC
ENDMODULE
"""


@needs_native
@pytest.mark.parametrize("program", ["family", "calls"])
def test_the_cycle_search_steps_the_machine_in_the_compiled_core(program, tmp_path,
                                                                 monkeypatch):
    """A property search over a packed table computes the product's successors in C
    (``Product.native_machine``): Python's ``successor_keys`` is never asked, and
    ``python_successor_keys`` only for the states the machine leaves to Python (a call
    in a program of one task); the graph not reused, the report is the Python
    engine's."""
    from rapidmc.check.product import Product
    if program == "family":
        argv = family_check(tmp_path, 8, 2000)
    else:
        (tmp_path / "one.mod").write_text(ONE_TASK_CALLS)
        argv = [str(tmp_path / "one.mod"), "--formula", 'low: G "total < 10"']
    asked = {"successor_keys": 0, "python_successor_keys": 0}
    for name in asked:
        original = getattr(Product, name)

        def counted(self, key, original=original, name=name):
            asked[name] += 1
            return original(self, key)
        monkeypatch.setattr(Product, name, counted)
    code, document = engine_report(argv, monkeypatch, native.NATIVE, reuse=False)
    assert asked["successor_keys"] == 0, asked
    assert (asked["python_successor_keys"] > 0) == (program == "calls"), asked
    monkeypatch.undo()
    assert (code, document) == engine_report(argv, monkeypatch, native.PYTHON, reuse=False)


@needs_native
@pytest.mark.parametrize("reduced", [False, True], ids=["unreduced", "reduced"])
def test_the_packed_loop_finds_a_deadlock_of_tasks_as_python_does(reduced, monkeypatch):
    """Two tasks that call procedures and then wait for each other's flag
    (tests/step_machine_tasks/stuck), the graph not reused: the deadlock search tests each
    new state in the packed loop (``machine_stuck``: every successor of the machine's step
    is the state itself), asking Python's predicate only where the machine does not step;
    the report (the deadlock, its counterexample, the counts) is the Python engine's."""
    from rapidmc.model.packed import table as packed
    asked: list[int] = []
    holds = packed.PackedStateTable.predicate_holds

    def counted(table, state_id):
        asked.append(state_id)
        return holds(table, state_id)
    monkeypatch.setattr(packed.PackedStateTable, "predicate_holds", counted)
    here = ROOT / "tests" / "step_machine_tasks" / "stuck"
    argv = [str(here / "first.mod"), "--add-task", str(here / "second.mod")] + \
        ([] if reduced else ["--no-por"])
    document = assert_same_reports(argv, monkeypatch, reuse=False)
    verdicts = {entry["name"]: entry for entry in document["properties"]}
    assert verdicts["no_deadlock"]["verdict"] == "VIOLATED"
    states = verdicts["no_deadlock"]["stats"]["model_states"]
    assert len(asked) < states / 2, (len(asked), states)     # (every state: Python decides)
