"""The staged driver gives exactly the transitions of the general one.

``step.successors`` serves states with several tasks or with interrupts
through ``staged_step`` (the inputs, the task and the timers enumerated once,
the instruction through the plain drivers on a one-task view).  These tests
explore the reachable states of multi-task and interrupt-driven programs the
way a check does (the reduction plan's projection and merge points, or none)
and compare, at every state, the staged driver's transitions and those of
``successors`` with the general driver's (every choice script run through
``step``): labels, spans, successor states, output and the waiting flag, in
order.

Programs: the models of bench/tasks.py, the data-driven check cases with
tasks or interrupts (tests/check/, with their ``--add-task`` arguments), the
two-task backup of the survey, and small programs for what those do not reach
(timers, delayed signal changes, single-shot and sleeping interrupts, IDelete,
IDisable, an uncaught error or EXIT in a task, choices inside a task's step,
stored inputs beside tasks).
"""
from __future__ import annotations

import shlex
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.diagnostics import UserError
from rapidmc.model.reduction import ALL, NONE
from rapidmc.semantics.staged_step import is_staged, staged_successors
from rapidmc.semantics.state import RUNNING
from rapidmc.semantics.step import general_driver_successors, general_successors, successors

from test_plain_step import assert_same, formulas, outcome

# The module is not marked: the bench models, the check cases and the backup are reduced models that
# number states for the proviso through the packed table where the core is built, so they
# run on both engines.  The small programs below consult no engine (the probe of
# tests/conftest.py fails them if they start to): their tests carry the mark.
ROOT = Path(__file__).resolve().parent.parent
BENCH = ROOT / "bench" / "programs"
CHECK = ROOT / "tests" / "check"
STATE_LIMIT = 1500


def compare_staged(program, props, reductions, options=None,
                   limit: int = STATE_LIMIT) -> tuple[int, int]:
    """Explore up to ``limit`` states as a check would; at each one the drivers must
    agree.  Returns how many states were staged, and how many of those the staged
    driver answered (the others it leaves to the general driver)."""
    options = dict(options or {}, reductions=reductions)
    system = api.prepare(program, props, api.CheckOptions(**options)).system
    config = system.config
    staged = answered = 0
    for state in reachable(system, limit):
        reference = outcome(general_successors, program, state, config)
        assert_same(outcome(successors, program, state, config), reference)
        if state.status == RUNNING and is_staged(program, state, config):
            staged += 1
            fast = outcome(staged_successors, program, state, config)
            if fast is not None:
                answered += 1
                # (both drivers' transitions before stored inputs are put at rest)
                assert_same(fast, outcome(general_driver_successors, program, state, config))
    return staged, answered


def reachable(system, limit: int):
    """The states a search meets first, up to ``limit`` of them (depth first); a state
    whose step stops at a routine rapidmc does not model is not expanded."""
    seen = dict.fromkeys(system.initial_states())
    todo = list(seen)
    while todo and len(seen) < limit:
        state = todo.pop()
        yield state
        try:
            found = system.successors(state)
        except UserError:
            continue
        for _, after in found:
            if after not in seen:
                seen[after] = None
                todo.append(after)


def program_files(tmp_path: Path, main: str, *tasks: str):
    """The program of module text ``main`` with each text of ``tasks`` as a further task."""
    paths = []
    for number, text in enumerate((main,) + tasks):
        path = tmp_path / f"t{number}.mod"
        path.write_text(text, encoding="latin-1")
        paths.append(str(path))
    return api.load_program(paths[:1], add_tasks=paths[1:])


BOTH = pytest.mark.parametrize("reductions", [ALL, NONE], ids=["reduced", "plain"])


# --- the bench models -------------------------------------------------------------

BENCH_MODELS = [
    (["cell_motion.mod"], ["cell_plc.mod"], 'taken: G "nPartsTaken < 4"', {}),
    (["alarm_cell.mod"], [], 'counted: G "nParts < 3"', {}),
    (["server_socket.mod"], ["server_motion.mod"], 'moves: G "nMoves < 4"',
     {"socket_messages": ("1", "2", "3", "x")}),
    (["ros_common.sys", "ros_socket.mod"], ["ros_common.sys", "ros_motion.mod"],
     'runs: G (trajReady -> F !trajReady)',
     {"socket_messages": ("-1 0 0 0 0 0 0", "2 10 0 0 0 0 0", "-3 20 0 0 0 90 0",
                          "not a point")}),
]


@BOTH
@pytest.mark.parametrize("files, task, formula, options", BENCH_MODELS,
                         ids=["two_tasks", "interrupts", "socket", "ros"])
def test_bench_models_agree(files, task, formula, options, reductions):
    program = api.load_program([str(BENCH / f) for f in files],
                               add_tasks=[",".join(str(BENCH / f) for f in task)] if task
                               else [])
    staged, answered = compare_staged(program, formulas(formula), reductions, options)
    assert staged > 0 and answered == staged


# --- the check cases with tasks or interrupts ------------------------------------

def case_arguments(case: Path) -> list[str]:
    args = case / "args"
    if not args.is_file():
        return []
    lines = [line for line in args.read_text().splitlines() if not line.startswith("#")]
    return shlex.split(" ".join(lines))


def input_domains(argv: list[str]) -> dict:
    """The ``--input-domain NAME=v1,v2`` options of a case's arguments."""
    domains = {}
    for option, value in zip(argv, argv[1:]):
        if option == "--input-domain":
            name, values = value.split("=")
            domains[name] = tuple(float(v) for v in values.split(","))
    return domains


STAGED_CASES = sorted(case for case in CHECK.iterdir()
                      if (case / "prog.mod").is_file() and (case / "props.ltl").is_file() and
                      ("--add-task" in case_arguments(case) or
                       "CONNECT" in (case / "prog.mod").read_text()))


@pytest.mark.engine_independent
def test_the_check_cases_include_tasks_and_interrupts():
    names = {case.name for case in STAGED_CASES}
    assert {"tasks_fairness", "tasks_no_fairness", "interrupt_alarm"} <= names


@pytest.mark.parametrize("case", STAGED_CASES, ids=lambda path: path.name)
def test_check_cases_agree(case):
    argv = case_arguments(case)
    tasks = [str(case / argv[i + 1]) for i, arg in enumerate(argv) if arg == "--add-task"]
    program = api.load_program([str(case / "prog.mod")], add_tasks=tasks)
    props = api.read_properties(str(case / "props.ltl"))
    options = {"input_domains": input_domains(argv)}
    for reductions in (ALL, NONE):
        staged, answered = compare_staged(program, props, reductions, options)
        # a task reading another's robot (tasks_crobt_named_task) steps through the general
        # driver only: a view carries its own task's robot
        assert (staged == 0) if program.reads_task_robots else (staged > 0)


def test_backup_of_two_tasks_agrees():
    backup = ROOT / "tests" / "realworld" / "survey5" / "twin_backup"
    program = api.load_program([str(backup)], all_tasks=True)
    props = formulas('taken: G "nPartsTaken <= nPartsFed"')
    for reductions in (ALL, NONE):
        staged, answered = compare_staged(program, props, reductions,
                                          {"input_domains": {"giPartType": (1.0, 2.0)}})
        assert answered == staged > 0


# --- small programs for the rest ------------------------------------------------

TIMERS = """MODULE Timers
  VAR intnum tick;
  VAR intnum once;
  VAR intnum edge;
  VAR signaldi di1;
  VAR signaldo do1;
  VAR num ticks := 0;
  VAR num edges := 0;
  PROC main()
    AliasIO "DI1", di1;
    AliasIO "DO1", do1;
    CONNECT tick WITH OnTick;
    ITimer 1, tick;
    CONNECT once WITH OnOnce;
    ITimer \\Single, 2, once;
    CONNECT edge WITH OnEdge;
    ISignalDI \\Single, di1, 2, edge;
    WHILE TRUE DO
      PulseDO \\PLength:=0.5, do1;
      SetDO \\SDelay:=0.2, do1, 1;
      IDisable;
      ticks := ticks MOD 2;
      IEnable;
      IF edges > 1 THEN
        ISleep tick;
        IWatch tick;
      ENDIF
    ENDWHILE
  ENDPROC
  TRAP OnTick
    ticks := ticks + 1;
  ENDTRAP
  TRAP OnOnce
    IDelete tick;
  ENDTRAP
  TRAP OnEdge
    edges := (edges + 1) MOD 3;
  ENDTRAP
ENDMODULE
"""

DELETED = """MODULE Deleted
  ! Once the only interrupt is deleted, the steps merge again (the general driver's case;
  ! an interrupt on a signal would keep the inputs in states, and then nothing merges).
  VAR intnum alarm;
  VAR num n := 0;
  VAR num m := 0;
  PROC main()
    CONNECT alarm WITH OnAlarm;
    ITimer 1, alarm;
    WaitTime 1;
    IDelete alarm;
    m := 1;
    WHILE TRUE DO
      n := (n + m) MOD 3;
    ENDWHILE
  ENDPROC
  TRAP OnAlarm
    n := 2;
  ENDTRAP
ENDMODULE
"""


@pytest.mark.engine_independent
@BOTH
@pytest.mark.parametrize("text", [TIMERS, DELETED], ids=["timers", "deleted"])
def test_interrupt_forms_agree(tmp_path, text, reductions):
    program = program_files(tmp_path, text)
    staged, answered = compare_staged(program, formulas('n: G "TRUE"'), reductions)
    assert staged > 0 and answered > 0


@pytest.mark.engine_independent
def test_a_merged_run_after_the_last_interrupt_is_left_to_the_general_driver(tmp_path):
    program = program_files(tmp_path, DELETED)
    staged, answered = compare_staged(program, formulas('n: G "n < 3"'), ALL)
    assert staged > answered > 0


MAIN_TASK = """MODULE Robot
  PERS num shared := 0;
  PERS bool go := FALSE;
  VAR signaldi di1;
  VAR intnum alarm;
  VAR num seen := 0;
  VAR num answer := 0;
  PROC main()
    AliasIO "DI1", di1;
    CONNECT alarm WITH OnAlarm;
    ISignalDI di1, 1, alarm;
    WHILE shared < 3 DO
      WaitUntil go \\MaxTime:=1 \\TimeFlag:=timedOut;
      TPReadFK answer, "part?", "a", "b", stEmpty, stEmpty, stEmpty;
      go := FALSE;
    ENDWHILE
    EXIT;
  ENDPROC
  TRAP OnAlarm
    seen := (seen + 1) MOD 2;
  ENDTRAP
  VAR bool timedOut := FALSE;
ENDMODULE
"""

HELPER_TASK = """MODULE Helper
  PERS num shared;
  PERS bool go;
  VAR num k := 0;
  PROC main()
    FOR i FROM 1 TO 3 DO
      WaitUntil NOT go;
      shared := shared + 1;
      go := TRUE;
      k := 1 / (3 - shared);
    ENDFOR
  ERROR
    IF ERRNO = ERR_DIVZERO THEN
      k := -1;
      TRYNEXT;
    ENDIF
  ENDPROC
ENDMODULE
"""

FAILING_TASK = """MODULE Failing
  PERS num shared;
  VAR num x := 0;
  PROC main()
    WaitUntil shared >= 1;
    x := 1 / (shared - 1);
    Stop;
  ENDPROC
ENDMODULE
"""


@pytest.mark.engine_independent
@BOTH
@pytest.mark.parametrize("tasks", [[HELPER_TASK], [HELPER_TASK, FAILING_TASK]],
                         ids=["two", "three"])
def test_tasks_with_interrupts_choices_and_ends_agree(tmp_path, tasks, reductions):
    """Interrupts in the main task beside other tasks, TPReadFK and wait timeouts inside
    a task's step, a handler with TRYNEXT, EXIT, Stop and an uncaught error in a task."""
    program = program_files(tmp_path, MAIN_TASK, *tasks)
    staged, answered = compare_staged(program, formulas('s: G "shared <= 3"'), reductions)
    assert answered == staged > 0


MOVING_MAIN = """MODULE MovingMain
  PERS num shared := 0;
  VAR signaldi di1;
  VAR intnum alarm;
  CONST robtarget p1 := [[900,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  PROC main()
    AliasIO "DI1", di1;
    CONNECT alarm WITH OnAlarm;
    ISignalDI di1, 1, alarm;
    MoveJ p1, v1000, fine, tool0;
    WaitUntil shared >= 1;
    MoveL Offs(p1, 0, 0, CPos().z), v1000, fine, tool0;
  ENDPROC
  TRAP OnAlarm
    MoveJ Offs(p1, 10, 0, 0), v1000, fine, tool0;
  ENDTRAP
ENDMODULE
"""

MOVING_FAILING = """MODULE MovingFailing
  PERS num shared;
  CONST robtarget p2 := [[50,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR num x := 0;
  PROC main()
    MoveJ p2, v1000, fine, tool0;
    shared := 1;
    WaitUntil shared >= 2;
    x := 1 / (shared - 2);
  ENDPROC
ENDMODULE
"""


@pytest.mark.engine_independent
@BOTH
def test_two_motion_tasks_each_with_its_robot_agree(tmp_path, reductions):
    """Each task moves its own robot (semantics.robots): the views carry the task's robot,
    a TRAP in the main task moves the main task's, and an uncaught error after a move
    leaves every robot in the failed state as the general driver does."""
    program = program_files(tmp_path, MOVING_MAIN, MOVING_FAILING, MOVING_FAILING.replace(
        "MovingFailing", "Third").replace("shared := 1;", "shared := 2;"))
    assert program.robot_per_task and program.motion_tasks == (0, 1, 2)
    staged, answered = compare_staged(program, formulas('s: G "shared <= 3"'), reductions)
    assert answered == staged > 0


@pytest.mark.engine_independent
def test_stored_inputs_beside_tasks_agree(tmp_path):
    """A property that reads an input keeps it in states: every step chooses it first."""
    program = program_files(tmp_path, MAIN_TASK, HELPER_TASK)
    props = formulas('s: G ("shared <= 3" | DI1)')
    for reductions in (ALL, NONE):
        staged, answered = compare_staged(program, props, reductions)
        assert answered == staged > 0


def test_the_staged_driver_answers_every_state_of_a_two_task_cell():
    """The staged driver is the one multi-task checks run on (the general one is left
    the states it cannot answer: an environment reaction, a merged run to follow)."""
    program = api.load_program([str(BENCH / "cell_motion.mod")],
                               add_tasks=[str(BENCH / "cell_plc.mod")])
    system = api.prepare(program, formulas('t: G "nPartsTaken < 4"')).system
    states = list(reachable(system, 500))
    for state in states:
        assert is_staged(program, state, system.config)
        assert staged_successors(program, state, system.config) is not None
    assert len(states) > 100
