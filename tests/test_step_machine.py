"""The compiled core's step machine (``check/_packed.c``, ``model/packed``) against the
Python step it stands in for.

Step by step: in every state the packed table stored during a check, the machine's
successors (``PackedTable.step``), when it takes the step, are the states the model's
``successor_states`` gives, in the same order; its compiled atoms value every state as
the generated Python valuation does.  On the data-driven check cases (tests/check,
among them the ``vm_*`` cases written for the machine's arithmetic, loops, dispatch,
signals and errors), on generated programs and on the counters family.  The whole
reports of both engines are compared in tests/test_native_engine.py; here a wrong step
is caught where it happens, even when no verdict shows it.
"""
from __future__ import annotations

import contextlib
import io
import sys
from array import array
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import find_reachable, native
from rapidmc.cli import main
from rapidmc.model.packed import table as packed
from rapidmc.model.packed.bytecode import OP, ExpressionCode, Unsupported, atom_code
from rapidmc.semantics.instructions import (CallPlan, CheckedReads, ChosenWrite, ElementWrite,
                                           LeavePlan)

from reduction_programs import properties, random_program
from test_check_cases import verdict_cases
from test_graph_reuse import COUNTERS, model_of
from test_partial_order import write_tasks

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")

STEPS_TAKEN: dict[str, int] = {}          # case -> states the machine stepped (see the end)
# check cases written for the machine: it must step in each of them
MACHINE_CASES = {"vm_num_float32", "vm_for_loops", "vm_signal_reads", "vm_bool_string"}


def machine_agrees(table) -> int:
    """Assert the machine's steps and atoms on every state of ``table``; the number of
    states it stepped."""
    system = table.system
    stepped = 0
    for state_id in range(len(table)):
        found = table.step(state_id)
        state = table[state_id]
        if found is not None:
            stepped += 1
            by_machine = [table._state(*table.parts(frame, data)) for frame, data in found]
            assert by_machine == system.successor_states(state), \
                f"state {state_id}: the machine's successors differ from the Python step's"
        for index, valuation in enumerate(table._valuations):
            bits = table.evaluate(index, state_id) if table._valuation_codes[index] else None
            if bits is not None:
                assert bits == valuation(state), f"state {state_id}: atoms differ"
    return stepped


def tables_of(run) -> list:
    """The packed tables made while ``run()`` runs."""
    made = []
    original = packed.packed_table

    def spy(system):
        table = original(system)
        if table is not None:
            made.append(table)
        return table
    packed.packed_table = spy
    try:
        run()
    finally:
        packed.packed_table = original
    return made


@needs_native
@pytest.mark.parametrize("case", verdict_cases(), ids=lambda case: case.name)
def test_the_machine_steps_as_python_does_on_the_check_cases(case, monkeypatch):
    monkeypatch.chdir(case.folder)

    def check():
        with native.engine_used(native.NATIVE), contextlib.redirect_stdout(io.StringIO()), \
                contextlib.redirect_stderr(io.StringIO()):
            main(case.argv())
    STEPS_TAKEN[case.name] = sum(machine_agrees(table) for table in tables_of(check))
    if case.name in MACHINE_CASES:
        assert STEPS_TAKEN[case.name] > 0, f"the machine took no step in {case.name}"


@needs_native
@pytest.mark.parametrize("seed", range(20))
def test_the_machine_steps_as_python_does_on_generated_programs(seed, tmp_path):
    formula = properties(seed, seed % 2 == 1)[0]
    model = model_of(random_program(seed, numeric_updates=seed % 3 == 0), formula, tmp_path,
                     api.CheckOptions(max_states=5000))
    _, _, valuation = model.jobs[0]
    graphs: list = []
    with native.engine_used(native.NATIVE):
        find_reachable(model.system, model.system.failed, max_states=5000,
                       explored=graphs.append, valuations=[valuation])
    if graphs and isinstance(graphs[0].states, native._native.PackedTable):
        STEPS_TAKEN[f"random {seed}"] = machine_agrees(graphs[0].states)


@needs_native
@needs_native
@pytest.mark.parametrize("seed", [0, 2, 6, 41, 71, 90, 93])
def test_the_machine_steps_one_task_of_several_as_python_does(seed, tmp_path, monkeypatch):
    """Programs of several tasks without the partial-order reduction
    (tests/task_programs.py): in every state, the successors the machine gives (its own
    steps of the tasks it can take, Python's of the others, idle steps dropped) are the
    Python step's; it takes some task's step in each program."""
    argv = write_tasks(tmp_path, seed, procedures=40 <= seed < 70, arrays=70 <= seed < 90,
                       local=seed >= 90)
    monkeypatch.chdir(tmp_path)

    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(["check", *argv, "--no-por", "--engine", "native", "--format", "json"])
    tables = tables_of(check)
    assert tables and all(table.tasks > 1 for table in tables)
    assert sum(machine_agrees(table) for table in tables) > 0
    assert sum(table.counts()["task_machine_steps"] for table in tables) > 0


# programs of several tasks whose waits, barriers and socket set-up the machine steps
# (WaitUntil with and without \MaxTime and \TimeFlag, WaitSyncTask from a PERS task
# list, SocketCreate/Bind/Listen/Close): a task backup (tests/task_backups), a check case
# (tests/check) or a program of tests/step_machine_tasks, with its arguments
WAITING_TASKS = {
    "sync_both": ["task_backups/sync_both/backup", "--ltl", "task_backups/sync_both/props.ltl"],
    "sync_skip": ["task_backups/sync_skip/backup"],
    "alone_barriers": ["task_backups/alone_barriers/backup"],
    "barrier_timeout": ["task_backups/timeout/backup", "--ltl",
                        "task_backups/timeout/props.ltl"],
    "logger_time_out": ["check/tasks_logger_time_out/prog.mod", "--add-task",
                        "check/tasks_logger_time_out/logger.mod", "--no-socket-timeouts",
                        "--socket-messages", "run", "--socket-messages", "home"],
    # sockets set up and closed (the machine's writes of constants), one in the wrong state
    "sockets": ["step_machine_tasks/sockets/sockets.mod", "--add-task",
                "step_machine_tasks/sockets/phases.mod"],
    # waits on free inputs chosen where read: a try's choices, the idle step's state
    "free_inputs": ["step_machine_tasks/free_inputs/waits.mod", "--add-task",
                    "step_machine_tasks/free_inputs/mover.mod"],
    # (without time-outs of connections the machine connects too)
    "sockets_no_timeouts": ["step_machine_tasks/sockets/sockets.mod", "--add-task",
                            "step_machine_tasks/sockets/phases.mod", "--no-socket-timeouts"],
}


def waiting_arguments(name: str) -> list[str]:
    here = Path(__file__).resolve().parent
    return [str(here / arg) if "/" in arg else arg for arg in WAITING_TASKS[name]]


@needs_native
@pytest.mark.parametrize("name", sorted(WAITING_TASKS))
def test_the_machine_steps_waits_and_barriers_as_python_does(name):
    """Unreduced searches of tasks that wait and meet at barriers: in every state the
    machine's successors (a wait's idle step kept or dropped as ``idle_steps_dropped``
    drops it) are the Python step's, and the machine took the waits' steps."""
    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(["check", *waiting_arguments(name), "--no-por", "--engine", "native",
                  "--format", "json"])
    tables = tables_of(check)
    assert tables and all(table.tasks > 1 for table in tables)
    assert sum(machine_agrees(table) for table in tables) > 0
    waits = [(routine, pc) for table in tables for routine, code in enumerate(table._routines)
             if code is not None for pc, instruction in
             enumerate(table.program.routines[routine].code)
             if getattr(instruction, "machine", None) is not None and
             array("i", code[2])[pc] >= 0 and
             array("i", code[3])[array("i", code[2])[pc]] != OP["UNSUPPORTED"]]
    if name != "barrier_timeout":           # (a barrier with \TimeOut is Python's)
        assert waits, "no wait or barrier compiled for the machine"


def compiled_plans(tables: list, kind: type) -> list:
    """(routine, pc) of the instructions whose machine plan is a ``kind`` and compiled to
    the machine's code (not UNSUPPORTED) in ``tables``."""
    return [(routine, pc) for table in tables for routine, code in enumerate(table._routines)
            if code is not None for pc, instruction in
            enumerate(table.program.routines[routine].code)
            if isinstance(getattr(instruction, "machine", None), kind) and
            array("i", code[2])[pc] >= 0 and
            array("i", code[3])[array("i", code[2])[pc]] != OP["UNSUPPORTED"]]


# programs of several tasks with one kind of statement the machine steps beside Python's
# (tests/step_machine_tasks): the kind's machine plan, the program's arguments, how many
# of its statements compile for the machine
MACHINE_KINDS = {
    # SocketReceive \Str (a message chosen from the site's domain, on a connected socket
    # only; with \Time Python's, which may time out)
    "receive": (ChosenWrite, ["step_machine_tasks/receive/server.mod", "--add-task",
                              "step_machine_tasks/sockets/phases.mod", "--no-socket-timeouts",
                              "--socket-messages", "go", "--socket-messages", "stop",
                              "--socket-messages", "x"], 2),
    # moves where the robot's position is left out (arguments evaluated, elements' indexes
    # checked; a target computed by a function call is Python's)
    "moves": (CheckedReads, ["step_machine_tasks/moves/mover.mod", "--add-task",
                             "step_machine_tasks/sockets/phases.mod"], 3),
    # writes of array elements (a small array and one of 32 or more items, found by its
    # items' hashes; an aggregate computed), one out of range; components of elements
    "elements": (ElementWrite, ["step_machine_tasks/elements/writer.mod", "--add-task",
                                "step_machine_tasks/sockets/phases.mod"], 7),
    # calls of procedures with IN arguments (a num rounded, a bool, a string; from a FOR
    # loop; two deep) and their ends (ENDPROC, RETURN): the machine pushes and pops the
    # task's frame; a VAR or optional parameter and a function are Python's
    "calls": ((CallPlan, LeavePlan), ["step_machine_tasks/calls/caller.mod", "--add-task",
                                      "step_machine_tasks/sockets/phases.mod"], 11),
}


@needs_native
@pytest.mark.parametrize("name", sorted(MACHINE_KINDS))
@pytest.mark.parametrize("reduced", [False, True], ids=["unreduced", "reduced"])
def test_the_machine_steps_each_kind_it_takes_as_python_does(name, reduced):
    """The statements of the kind compile for the machine, and in every state of every
    search, reduced or not, where the machine steps, its successors are the Python step's
    (and ``PartialOrder``'s)."""
    kind, arguments, count = MACHINE_KINDS[name]
    here = Path(__file__).resolve().parent
    argv = ["check", *(str(here / arg) if "/" in arg else arg for arg in arguments),
            "--engine", "native", "--format", "json"] + ([] if reduced else ["--no-por"])

    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(argv)
    tables = tables_of(check)
    assert tables and all(table.tasks > 1 for table in tables)
    assert len(set(compiled_plans(tables, kind))) == count
    assert sum(machine_agrees(table) for table in tables) > 0
    assert sum(table.counts()["task_machine_steps"] for table in tables) > 0
    if reduced and name == "calls":
        # the machine's local runs went on through its own calls and returns, as
        # ``LocalRuns.run_on`` does (``_went_on``), and their targets agreed above
        assert sum(table.counts()["run_frame_steps"] for table in tables) > 0


def controller_family_tables(tmp_path, reduced: bool) -> list:
    """The packed tables of a check of bench/controllers.py's family (buffers of 4, the
    three kinds of command, 2,000 states per search), reduced or not."""
    sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "bench"))
    try:
        from controllers import family_arguments, family_property, write_backup
    finally:
        sys.path.remove(str(Path(__file__).resolve().parent.parent / "bench"))
    write_backup(tmp_path / "cell", 4)
    (tmp_path / "cell.ltl").write_text(f"moves: {family_property(2)}\n")
    argv = ["check", str(tmp_path / "cell"), *family_arguments(3, reduced=reduced), "--ltl",
            str(tmp_path / "cell.ltl"), "--max-states", "2000", "--engine", "native",
            "--format", "json"]

    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(argv)
    return tables_of(check)


@needs_native
def test_the_machine_takes_most_steps_of_the_controller_family(tmp_path):
    """bench/controllers.py's family, unreduced: with the barriers and the logger's timed
    wait in the machine, it takes most single tasks' steps (before: 41 %), each as the
    Python step takes it."""
    tables = controller_family_tables(tmp_path, reduced=False)
    assert sum(machine_agrees(table) for table in tables) > 0
    machine = sum(table.counts()["task_machine_steps"] for table in tables)
    python = sum(table.counts()["task_python_steps"] for table in tables)
    assert machine > 2 * python, (machine, python)


@needs_native
def test_the_reduced_controller_family_steps_task_by_task(tmp_path):
    """The family with the partial-order reduction (the default): where one task takes a
    step the machine leaves to Python, Python steps that task alone, runs it on through
    its local instructions and, where it is an ample candidate, decides its ample set
    (``python_task_successors``, ``python_task_ample``); the machine takes the other
    tasks' steps.  No state is stepped whole in Python (before: 36 % of the single tasks'
    steps were taken so), and in every state of every search the successors are those
    of the Python step and ``PartialOrder``."""
    tables = controller_family_tables(tmp_path, reduced=True)
    assert tables and all(isinstance(table, packed.PackedSearch) for table in tables)
    counts = tables[0].counts()
    assert counts["python_steps"] == 0, counts
    assert counts["task_python_steps"] > 0 and counts["task_machine_steps"] > 0, counts
    # ``teach``'s call and return are merged into the machine's local runs: Python takes
    # under 1 % of the single tasks' steps (before: every run through the call)
    assert counts["run_frame_steps"] > 0, counts
    assert counts["task_python_steps"] * 100 < counts["task_machine_steps"], counts
    assert sum(machine_agrees(table) for table in tables) == \
        sum(len(table) for table in tables)


REDUCED_SEEDS = [0, 2, 6, 41, 71, 90, 91, 93, 95, 97]
REDUCED_STEPS: dict[int, int] = {}


@needs_native
@pytest.mark.parametrize("seed", REDUCED_SEEDS)
def test_the_machine_chooses_the_ample_sets_python_chooses(seed, tmp_path, monkeypatch):
    """Programs of several tasks with the partial-order reduction (the default): every
    search of the check keeps its states in one shared packed table, and in every state
    each search stored, the machine's successors (the ample set of one task, its steps
    run on through its local instructions, or every task's) are those the Python step and
    ``PartialOrder`` give, under the one numbering of states the proviso reads."""
    argv = write_tasks(tmp_path, seed, procedures=40 <= seed < 70, arrays=70 <= seed < 90,
                       local=seed >= 90)
    monkeypatch.chdir(tmp_path)

    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(["check", *argv, "--engine", "native", "--format", "json"])
    tables = tables_of(check)
    assert tables and all(isinstance(table, packed.PackedSearch) for table in tables)
    assert len({id(table.table) for table in tables}) == 1     # one table per check
    for table in tables:
        STEPS_TAKEN[f"reduced {seed}"] = machine_agrees(table)
    counts = tables[0].counts()
    REDUCED_STEPS[seed] = (counts["task_machine_steps"], counts["rows_reused"])


@needs_native
def test_the_machine_chose_ample_sets_in_the_local_programs():
    """(After the test above.)  The programs mostly on the tasks' own data (seeds 90 on)
    have states whose ample set the machine chose and stepped itself, and later searches
    of a check took rows an earlier one kept instead of stepping again."""
    local = [steps for seed, steps in REDUCED_STEPS.items() if seed >= 90]
    if not local:
        pytest.skip("the reduced programs were not run")
    assert sum(machine for machine, _ in local) > 0
    assert sum(reused for _, reused in REDUCED_STEPS.values()) > 0


@needs_native
def test_the_counters_are_stepped_by_the_machine_alone_but_for_aliasio(tmp_path):
    """The benchmark's family: every state but the AliasIO calls' is the machine's, and the
    graph it keeps is the Python engine's, row for row and value for value."""
    model = model_of(COUNTERS, 'P: G ("c0 < 3" & "c1 < 3")', tmp_path)
    _, _, valuation = model.jobs[0]
    graphs = {}
    for engine in native.ENGINES:
        found: list = []
        with native.engine_used(engine):
            result = find_reachable(model.system, model.system.failed, explored=found.append,
                                    valuations=[valuation])
        assert result.verdict == "HOLDS"
        graphs[engine] = found[0]
    table = graphs[native.NATIVE].states
    counts = table.counts()
    assert counts["python_steps"] == 2 and counts["machine_steps"] == len(table) - 2
    for graph in (graphs[native.NATIVE], graphs[native.PYTHON]):
        graph.rows = (graph.starts.tolist(), graph.targets.tolist(), bytes(graph.deadlocked),
                      list(graph.valuations[valuation]))
    assert graphs[native.NATIVE].rows == graphs[native.PYTHON].rows
    assert [table[i] for i in range(len(table))] == \
        [graphs[native.PYTHON].states[i] for i in range(len(table))]
    assert machine_agrees(table) == len(table) - 2


def test_expression_sources_compile_to_the_machines_code():
    """The sources ``semantics.expressions`` writes, and what falls back to Python."""
    ids: dict = {}

    def value_id(value):
        return ids.setdefault((type(value), value), len(ids))

    code = ExpressionCode(value_id, {"_k1": 4.0}, store_length=3)
    assert code.compile("_int_mod(_to_num(store[2] + _k1), _k1)") == [
        OP["LOAD_STORE"], 2, OP["CONST"], 0, OP["ADD"], OP["TO_NUM"], OP["CONST"], 0,
        OP["INT_MOD"]]
    assert code.compile("(_read(cx, store[0]) == _k1)") == [
        OP["LOAD_STORE"], 0, OP["READ_DYN"], OP["CONST"], 0, OP["EQ"]]
    assert code.compile("bool((not locals_[1]) | (-store[1] < _k1))")[-1] == OP["OR"]
    # an aggregate (``expressions._Aggregate``'s source): its items, then the tuple
    assert code.compile("((_to_num(locals_[0]), _k1, ), store[1], )") == [
        OP["LOAD_LOCAL"], 0, OP["TO_NUM"], OP["CONST"], 0, OP["BUILD_TUPLE"], 2,
        OP["LOAD_STORE"], 1, OP["BUILD_TUPLE"], 2]
    for source in ("_concat(store[0], store[1])", "_k1(store[0])", "store[9]", "store[0].x",
                   "store[0] if store[1] else store[2]", "unknown_name"):
        with pytest.raises(Unsupported):
            code.compile(source)


def test_atoms_compile_each_between_its_begin_and_end():
    ids: dict = {}
    code = atom_code([(1, "(store[0] < _k)", {"_k": 4.0}), (4, "store[1]", {})],
                     lambda value: ids.setdefault(value, len(ids)), store_length=2)
    assert code[0] == OP["ATOM_BEGIN"] and code[code[1]] == OP["ATOM_BEGIN"]
    assert code[code[1] - 2:code[1]] == array("i", [OP["ATOM_END"], 0])
    assert code[-3:] == array("i", [OP["ATOM_END"], 2, OP["END"]])
    assert atom_code([(1, "locals_[0]", {})], lambda value: 0, 1) is None   # routine data


@needs_native
def test_the_machine_took_steps_in_most_check_cases():
    """(Runs last in this file.) The comparisons above mean something only if the machine
    stepped: it takes steps in most check cases and generated programs this process ran
    (under pytest-xdist, the share of them this worker ran; the cases written for the
    machine are asserted where they run, above)."""
    if len(STEPS_TAKEN) < 20:
        pytest.skip("run with the whole file")
    stepped = [name for name, steps in STEPS_TAKEN.items() if steps]
    assert len(stepped) >= len(STEPS_TAKEN) // 2, sorted(set(STEPS_TAKEN) - set(stepped))


@needs_native
def test_arrays_are_one_value_exactly_when_equal():
    """The packed table finds a tuple of 32 items or more (an array) by its items' hashes,
    each remembered by address: equal arrays (other objects, numbers equal by ``==``, an
    element written and written back) are one value, and one written element another."""
    table = native._native.PackedTable()

    def ids(*values) -> list[int]:
        return list(array("I", table.value_ids(values)))
    row = tuple((float(i), (0.0, 1.0)) for i in range(512))
    same = tuple((float(i), (0.0, 1.0)) for i in range(512))
    ints = tuple((i, (0, True)) for i in range(512))
    written = row[:7] + ((7.5, (0.0, 1.0)),) + row[8:]
    back = written[:7] + (row[7],) + written[8:]
    first, equal, by_number, other, again = ids(row, same, ints, written, back)
    assert first == equal == by_number == again != other
    numbers = ids(tuple(float(i) for i in range(64)), tuple(float(i) for i in range(64)),
                  tuple(range(64)), tuple(float(i) for i in range(1, 65)))
    assert numbers[0] == numbers[1] == numbers[2] != numbers[3]
    assert table.values(array("I", [first, other]).tobytes()) == (row, written)


# a buffer of 40 nums that one task writes element by element (the machine's writes) and
# reads (so no projection resets it), beside a task that moves a PERS flag
BUFFER_WRITER = """MODULE Buffer
  VAR num buffer{40};
  VAR num slot := 0;
  VAR num seen := 0;
  PERS num phase;
  PROC main()
    WHILE TRUE DO
      slot := slot MOD 40 + 1;
      buffer{slot} := (slot + phase) MOD 2;
      IF buffer{41 - slot} = 1 seen := 1 - seen;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


@needs_native
def test_arrays_the_machine_writes_are_the_values_python_makes(tmp_path):
    """The machine's write of an element of an array of 32 items or more changes the
    array's hash by that element's two parts and makes no tuple where the table holds the
    array written (``big_replaced_id``): in every state of a check of a task that writes
    a buffer of 40 nums, each global datum, rebuilt from new tuples, has the id the
    state's data segment holds."""
    (tmp_path / "buffer.mod").write_text(BUFFER_WRITER)
    phases = Path(__file__).resolve().parent / "step_machine_tasks" / "sockets" / "phases.mod"

    def check():
        with contextlib.redirect_stdout(io.StringIO()):
            main(["check", str(tmp_path / "buffer.mod"), "--add-task", str(phases),
                  "--engine", "native", "--format", "json", "--no-por",
                  "--max-states", "3000"])

    def rebuilt(value):
        return tuple(rebuilt(item) for item in value) if type(value) is tuple else value
    tables = tables_of(check)
    assert sum(machine_agrees(table) for table in tables) > 0
    arrays = set()
    for table in tables:
        for state_id in range(len(table)):
            data = tuple(table[state_id][1])
            arrays.update(value for value in data if type(value) is tuple and len(value) == 40)
            _, held = table.segments(*table.key(state_id)[:2])
            assert table.value_ids(tuple(rebuilt(value) for value in data)) == held, \
                f"state {state_id}"
    assert len(arrays) > 50
