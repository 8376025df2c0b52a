"""An IDelete of an intnum holding 0 joins a group of tasks (``reduction.empty_deletes``).

The taeyangshim start-up handshake, in small: a commander clears its command and
waits until every worker reports Ready; each worker clears its report, waits for the
command to be clear, reports Ready and deletes its interrupts before it connects
them (the intnums hold 0 there), then serves one command, connecting an interrupt
and deleting it again.  Checked with the reduction and with ``--no-por``: the same
verdicts (HOLDS and VIOLATED, an LTL formula and ``no_deadlock``), fewer states
than with the rule off, the same reports with both engines; and a mutant taking
every IDelete of a task's own intnum as deleting nothing loses a violation (an
intnum holding a number another task's CONNECT hands out deletes that task's
interrupt).  The same handshake, its commander clearing the command twice, holds the
verdicts of ``unchanged_writes`` (a write of the value already stored); its mutant is in
tests/test_unchanged_writes.py.
"""
from __future__ import annotations

from pathlib import Path

import pytest

from rapidmc.api import load_program
from rapidmc.check import native
from rapidmc.model.reduction import empty_deletes, unchanged_writes
from rapidmc.model.reduction.partial_order import PartialOrder

from test_partial_order import (assert_rule_keeps_verdicts_and_pays, check_json, states,
                                verdicts)

needs_native = pytest.mark.skipif(not native.available(), reason="the native core is not built")

WORKER = """MODULE Worker{n}
  PERS string stCommand := "";
  PERS string stReact{{3}} := ["", "", ""];
  VAR intnum irqHome;
  VAR intnum irqHold;
  VAR num count{n} := 0;
  TRAP tHome
    count{n} := 0;
  ENDTRAP
  PROC rInit()
    stReact{{{n}}} := "";
    WaitUntil stCommand = "";
    stReact{{{n}}} := "Ready";
    IDelete irqHome;
    IDelete irqHold;
    count{n} := 0;
  ENDPROC
  PROC main()
    rInit;
    WaitUntil stCommand <> "";
    IDelete irqHome;
    CONNECT irqHome WITH tHome;
    ISignalDO do{n}, 1, irqHome;
    count{n} := count{n} + {step};
    stReact{{{n}}} := "{ack}";
    WaitUntil stCommand = "";
    IDelete irqHome;
    stReact{{{n}}} := "Ready";
  ENDPROC
ENDMODULE
"""
COMMANDER = """MODULE Commander
  PERS string stCommand := "";
  PERS string stReact{3} := ["", "", ""];
  PERS num stage := 0;
  PROC main()
    stCommand := "";
    WaitUntil stReact = ["Ready", "Ready", "Ready"];
    stage := 1;
    stCommand := "Go";
    WaitUntil stReact = ["Ack", "Ack", "Ack"];
    stage := 2;
    stCommand := "";
  ENDPROC
ENDMODULE
"""
# (name, worker 3's count step, its answer): the counts, a handshake that ends, one
# worker answering what the commander does not wait for (it waits forever)
VARIANTS = [("served", 1, "Ack"), ("counted twice", 2, "Ack"), ("wrong answer", 1, "Acked")]
FORMULAS = ['once: G "count3 <= 1"', 'staged: G "stage < 2"']
# the unreduced verdicts of (no_deadlock, once, staged) per variant
EXPECTED = {"served": ("HOLDS", "HOLDS", "VIOLATED"),
            "counted twice": ("HOLDS", "VIOLATED", "VIOLATED"),
            "wrong answer": ("VIOLATED", "HOLDS", "HOLDS")}


def task_files(folder: Path, texts) -> list[str]:
    """The check's arguments for one task per module text, the first the main task."""
    argv = []
    for number, text in enumerate(texts):
        path = folder / f"task{number}.mod"
        path.write_text(text)
        argv += [str(path)] if number == 0 else ["--add-task", str(path)]
    return argv


def write_handshake(folder: Path, step: int, ack: str, commander: str = COMMANDER,
                    worker: str = WORKER) -> list[str]:
    """The commander and three workers, worker 3 counting ``step`` and answering ``ack``,
    with ``FORMULAS``."""
    argv = task_files(folder, [commander] + [
        worker.format(n=n, step=step if n == 3 else 1, ack=ack if n == 3 else "Ack")
        for n in (1, 2, 3)])
    for formula in FORMULAS:
        argv += ["--formula", formula]
    return argv


# the commander clearing its command twice: the first write, of the value stored, goes on
# to the second, which goes on where every worker is Ready (``unchanged_writes``)
CLEARING_TWICE = COMMANDER.replace('    stCommand := "";\n',
                                   '    stCommand := "";\n    stCommand := "";\n', 1)
# (the commander, the rule the handshake exercises)
RULES = {"empty deletes": (COMMANDER, empty_deletes.EmptyDeletes),
         "unchanged writes": (CLEARING_TWICE, unchanged_writes.UnchangedWrites)}


@pytest.mark.parametrize("rule", RULES)
@pytest.mark.parametrize("name, step, ack", VARIANTS)
def test_start_up_handshakes_keep_their_verdicts(tmp_path, monkeypatch, name, step, ack,
                                                 rule):
    commander, rule_class = RULES[rule]
    assert_rule_keeps_verdicts_and_pays(
        write_handshake(tmp_path, step, ack, commander), EXPECTED[name],
        lambda: monkeypatch.setattr(rule_class, "reader", lambda self, *where: None))


@needs_native
@pytest.mark.parametrize("rule", RULES)
@pytest.mark.parametrize("name, step, ack", VARIANTS[::2])
def test_start_up_handshakes_report_the_same_with_both_engines(tmp_path, monkeypatch, name,
                                                               step, ack, rule):
    from test_native_engine import assert_same_reports
    document = assert_same_reports(write_handshake(tmp_path, step, ack, RULES[rule][0]),
                                   monkeypatch)
    assert document["properties"]


DELETER = """MODULE Deleter
  VAR intnum irqA := 1;
  PROC main()
    IDelete irqA;
  ENDPROC
ENDMODULE
"""
CONNECTER = """MODULE Connecter
  VAR intnum irqB;
  TRAP tB
    irqB := irqB;
  ENDTRAP
  PROC main()
    CONNECT irqB WITH tB;
    ISignalDO do2, 1, irqB;
  ENDPROC
ENDMODULE
"""
TICKER = """MODULE Ticker
  VAR num tick := 0;
  PROC main()
    WHILE TRUE DO
      tick := (tick + 1) MOD 2;
    ENDWHILE
  ENDPROC
ENDMODULE
"""


def write_deleter(folder: Path) -> list[str]:
    """A task deleting interrupt number 1 (its intnum starts at 1), a task connecting one
    (it gets number 1 when it connects first) and ordering it, a task ticking."""
    return task_files(folder, (DELETER, CONNECTER, TICKER))


def test_an_idelete_of_a_number_taken_as_empty_loses_a_violation(tmp_path, monkeypatch):
    """The differential tests can fail: with every IDelete of a task's own intnum taken as
    deleting nothing, the deleter's step alone is ample at the start, runs before the
    connecter's CONNECT, and ISignalDO's ERR_UNKINO (the deleter deleted the connecter's
    interrupt number 1) is never reached."""
    argv = write_deleter(tmp_path)
    assert verdicts(check_json(argv))["no_runtime_error"] == "VIOLATED"
    assert verdicts(check_json(argv + ["--no-por"]))["no_runtime_error"] == "VIOLATED"
    always_idle(monkeypatch, empty_deletes.EmptyDeletes)
    assert verdicts(check_json(argv))["no_runtime_error"] == "HOLDS"


def always_idle(monkeypatch, rule_class) -> None:
    """The mutant of a per-state rule (``IdleSteps``): each instruction it judges is taken
    as idle in every state."""
    found = rule_class._find

    def eager(self, *where):
        reader = found(self, *where)
        return None if reader is None else (lambda stack, state: True)
    monkeypatch.setattr(rule_class, "_find", eager)


def test_only_an_idelete_of_data_no_other_task_writes_is_judged_per_state(tmp_path):
    argv = write_handshake(tmp_path, 1, "Ack")
    program = load_program([argv[0]], add_tasks=argv[2:8:2])
    order = PartialOrder(program, set())
    worker = next(routine for routine in program.routines
                  if routine.name.upper() == "RINIT" and order.task_of_routine(
                      routine.index) == 1)
    deletes = [pc for pc, instruction in enumerate(worker.code)
               if instruction.span is not None and instruction.span.line in (14, 15)]
    assert len(deletes) == 2
    for pc in deletes:
        reader = order.groups.deletes.reader(1, worker.index, pc)
        assert reader is not None and order.groups.may_join(1, worker.index, pc)
        assert order.groups.conflicts(1, worker.index, pc) is None  # (shared, statically)
    # not another task's, not an assignment
    assert order.groups.deletes.reader(2, worker.index, deletes[0]) is None
    assert order.groups.deletes.reader(1, worker.index, deletes[1] + 1) is None


def test_an_idelete_of_data_another_task_writes_is_not(tmp_path):
    texts = ("MODULE A\n  PERS num irqShared := 0;\n  PROC main()\n    IDelete irqShared;\n"
             "  ENDPROC\nENDMODULE\n",
             "MODULE B\n  PERS num irqShared := 0;\n  PROC main()\n    irqShared := 3;\n"
             "  ENDPROC\nENDMODULE\n",
             "MODULE C\n  VAR num tick := 0;\n  PROC main()\n    tick := 1;\n"
             "  ENDPROC\nENDMODULE\n")
    argv = task_files(tmp_path, texts)
    program = load_program([argv[0]], add_tasks=argv[2::2])
    order = PartialOrder(program, set())
    assert order.groups.deletes.reader(0, program.entry, 0) is None
    assert not order.groups.may_join(0, program.entry, 0)
    # nor a constant written to it (``unchanged_writes``): the IDelete writes it too
    writer = program.task_entries[0]
    assert order.groups.writes.reader(1, writer, 0) is None


LOCAL_WORKER = """MODULE Worker{n}
  PERS num flag := 0;
  VAR num count{n} := 0;
  TRAP tHome
    count{n} := 0;
  ENDTRAP
  PROC rInit()
    VAR intnum irqLocal;
    VAR num before := 0;
    before := 1;
    IDelete irqLocal;
    count{n} := count{n} + 1;
    IDelete irqLocal;
    CONNECT irqLocal WITH tHome;
    IDelete irqLocal;
  ENDPROC
  PROC main()
    rInit;
    flag := flag + 1;
  ENDPROC
ENDMODULE
"""


def test_an_idelete_of_routine_data_is_judged_per_state(tmp_path, monkeypatch):
    """Three tasks deleting a routine's intnum before and after connecting it, then adding
    to a shared count: the same verdicts as ``--no-por``, fewer states than without."""
    argv = task_files(tmp_path, [LOCAL_WORKER.format(n=n) for n in (1, 2, 3)]) + \
        ["--formula", 'counted: G "flag < 3"']
    reduced, full = check_json(argv), check_json(argv + ["--no-por"])
    assert verdicts(full) == verdicts(reduced) == {
        "no_runtime_error": "HOLDS", "no_deadlock": "HOLDS", "counted": "VIOLATED"}
    monkeypatch.setattr(empty_deletes.EmptyDeletes, "reader", lambda self, *where: None)
    assert states(reduced)["no_runtime_error"] < states(check_json(argv))["no_runtime_error"]
