"""File instructions on a task's own iodev are independent (``reduction.syntax_footprint``).

The SpGantry taeyangshim start-up, in small: each worker opens a log of its own, writes
the controller's date and time (CDate, CTime: the check's one fixed moment) and a count
into it, closes it, reports Ready, and waits for the commander's stage.  Files are the
environment (``library.files``: nothing another task reads), so Open, Write and Close of
an ``iodev`` of the task's own, whose other arguments read only data no other task
writes, commute with every other task's step.  Checked with the reduction and with
``--no-por``: the same verdicts (HOLDS and VIOLATED, LTL formulas and ``no_deadlock``,
whose ``waits(T)`` sees a worker that never gets its stage), fewer states than with
file instructions shared, the same reports with both engines; and a mutant taking every
file instruction as independent, whatever its arguments read, loses a violation.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.api import load_program
from rapidmc.check import native
from rapidmc.model.reduction import syntax_footprint
from rapidmc.model.reduction.partial_order import PartialOrder
from rapidmc.model.reduction.syntax_footprint import LOCAL, SHARED

from test_empty_deletes import task_files
from test_partial_order import assert_rule_keeps_verdicts_and_pays, check_json, verdicts

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")

WORKER = """MODULE Worker{n}
  PERS num ready{{3}} := [0, 0, 0];
  PERS num stage := 0;
  VAR iodev logfile;
  VAR num count{n} := 0;
  PROC main()
    Open "HOME:/task{n}.txt", logfile \\Write;
    Write logfile, "Task{n} (" + CDate() + " " + CTime() + ")";
    count{n} := count{n} + {step};
    Write logfile, "count " \\Num:=count{n};
    Close logfile;
    ready{{{n}}} := 1;
    WaitUntil stage = {awaited};
    Open "HOME:/task{n}.txt", logfile \\Append;
    Write logfile, "stage reached";
    Close logfile;
  ENDPROC
ENDMODULE
"""
COMMANDER = """MODULE Commander
  PERS num ready{3} := [0, 0, 0];
  PERS num stage := 0;
  PROC main()
    WaitUntil ready = [1, 1, 1];
    stage := 1;
  ENDPROC
ENDMODULE
"""
# (name, worker 3's count step, the stage it waits for): as written, counting twice, a
# worker waiting for a stage that never comes (it waits forever)
VARIANTS = [("logged", 1, 1), ("counted twice", 2, 1), ("never staged", 1, 2)]
FORMULAS = ['once: G "count3 <= 1"', 'staged: G "stage < 1"']


def write_loggers(folder: Path, step: int, awaited: int) -> list[str]:
    argv = task_files(folder, [COMMANDER] + [
        WORKER.format(n=n, step=step if n == 3 else 1, awaited=awaited if n == 3 else 1)
        for n in (1, 2, 3)])
    for formula in FORMULAS:
        argv += ["--formula", formula]
    return argv


FILE_PROCEDURES = frozenset({"OPEN", "CLOSE", "WRITE", "WRITEBIN", "WRITESTRBIN",
                             "WRITERAWBYTES", "CLEARIOBUFF", "REWIND"})


def files_shared(monkeypatch) -> None:
    """The rule off: file instructions shared, as before it."""
    monkeypatch.setattr(syntax_footprint, "_ARGUMENTS_ONLY",
                        syntax_footprint._ARGUMENTS_ONLY - FILE_PROCEDURES)


@pytest.mark.parametrize("name, step, awaited", VARIANTS)
def test_loggers_keep_their_verdicts(tmp_path, monkeypatch, name, step, awaited):
    expected = {"logged": ("HOLDS", "HOLDS", "VIOLATED"),
                "counted twice": ("HOLDS", "VIOLATED", "VIOLATED"),
                "never staged": ("VIOLATED", "HOLDS", "VIOLATED")}[name]
    found = assert_rule_keeps_verdicts_and_pays(write_loggers(tmp_path, step, awaited),
                                                expected, lambda: files_shared(monkeypatch))
    assert found["no_runtime_error"] == "HOLDS"

@needs_native
@pytest.mark.parametrize("name, step, awaited", VARIANTS[::2])
def test_loggers_report_the_same_with_both_engines(tmp_path, monkeypatch, name, step,
                                                   awaited):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_loggers(tmp_path, step, awaited), monkeypatch)
    assert document["properties"]


READER = """MODULE Reader
  PERS num idx := 1;
  VAR iodev f;
  VAR num values{2} := [10, 20];
  PROC main()
    Open "HOME:/values.txt", f \\Write;
    Write f, "value " \\Num:=values{idx};
    Close f;
  ENDPROC
ENDMODULE
"""
SETTER = """MODULE Setter
  PERS num idx := 1;
  PROC main()
    idx := 3;
  ENDPROC
ENDMODULE
"""


def test_a_write_reading_another_tasks_data_is_shared(tmp_path, monkeypatch):
    """The differential tests can fail: with every file instruction taken as independent
    (its arguments not read), the reader's Write of ``values{idx}`` alone is ample while
    the setter has not run, so the setter's ``idx := 3`` before it (ERR_OUTOFBND) is
    never reached."""
    argv = task_files(tmp_path, (READER, SETTER))
    assert verdicts(check_json(argv))["no_runtime_error"] == "VIOLATED"
    assert verdicts(check_json(argv + ["--no-por"]))["no_runtime_error"] == "VIOLATED"
    predefined = syntax_footprint.StatementFootprints._predefined

    def eager(self, task, routine, call):
        return LOCAL if call.name.key in FILE_PROCEDURES else \
            predefined(self, task, routine, call)
    monkeypatch.setattr(syntax_footprint.StatementFootprints, "_predefined", eager)
    assert verdicts(check_json(argv))["no_runtime_error"] == "HOLDS"


def test_file_instructions_footprints(tmp_path):
    argv = task_files(tmp_path, (READER, SETTER))
    program = load_program([argv[0]], add_tasks=[argv[2]])
    order = PartialOrder(program, set())
    main = next(routine for routine in program.routines
                if routine.name.upper() == "MAIN" and order.task_of_routine(routine.index) == 0)
    by_line = {instruction.span.line: order.footprint(0, main.index, pc)
               for pc, instruction in enumerate(main.code) if instruction.span is not None}
    assert by_line[6] == LOCAL          # Open of its own iodev
    assert by_line[7] == SHARED         # Write reading idx, which the setter writes
    assert by_line[8] == LOCAL          # Close
    argv = write_loggers(tmp_path, 1, 1)
    program = load_program([argv[0]], add_tasks=argv[2:8:2])
    order = PartialOrder(program, set())
    worker = next(routine for routine in program.routines
                  if routine.name.upper() == "MAIN" and order.task_of_routine(
                      routine.index) == 1)
    footprints = {instruction.span.line: order.footprint(1, worker.index, pc)
                  for pc, instruction in enumerate(worker.code)
                  if instruction.span is not None}
    assert [footprints[line] for line in (7, 8, 10, 11)] == [LOCAL] * 4   # CDate, CTime too
