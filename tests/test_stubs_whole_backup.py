"""``check BACKUP --stubs`` on a whole backup: the tasks' missing names are inferred once
(issue 28).

Both tasks of a backup load an option's modules the backup does not hold: a PERS of the
option's record type, one of its routines, one of its constants. Each task's uses show
part of them. Inferred task by task, the two tasks got two records of one name with
different components, and the PERS they share failed with RMC206 (a PickMaster backup,
``pm_projectinfo``). Inferred from both tasks' uses, every task declares the same
record, constant and routine, and the backup loads and reaches verdicts. A single task's
stubs are what they were.
"""
from __future__ import annotations

import re

import pytest

from cli_capture import run_cli, verdicts_and_states
from rapidmc.load.stubs import stub_module, stub_modules
from rapidmc.syntax import parse_text
from test_backup import make_backup

# Task 1 names the record's .name, passes a num and a string to the routine, and sizes an
# array by the constant with a four-part value; it declares partdata and sState.
CELL = """MODULE Cell
  PERS cellinfo info;
  PERS partdata part := [2.5, "box"];
  PERS string sState := "idle";
  RECORD partdata
    num weight;
    string label;
  ENDRECORD
  VAR num counts{MAX_PARTS} := [0, 0, 0, 0];

  PROC main()
    CellLog 1, "start";
    info.name := "weld";
    counts{MAX_PARTS} := part.weight;
    sState := "busy";
  ENDPROC
ENDMODULE
"""

# Task 2 names .count and .ready, passes two names nothing else types and a switch, runs a
# loop to the constant, and uses partdata and sState without declaring them.
SERVER = """MODULE Server
  PERS cellinfo info;
  PERS partdata part;

  PROC main()
    CellLog nCode, sText \\Warn;
    FOR i FROM 1 TO MAX_PARTS DO
      info.count := info.count + 1;
    ENDFOR
    IF sState = sReady THEN
      info.ready := TRUE;
    ENDIF
    IF info.ready AND part.label = "box" THEN
      TPWrite "ready";
    ENDIF
  ENDPROC
ENDMODULE
"""


def declarations(text: str) -> dict:
    """Name -> its declaration's lines (without the comments) in a module of stubs."""
    found, name = {}, None
    for line in text.splitlines()[1:-1]:
        line = line.strip()
        head = re.match(r"(?:RECORD|PROC|FUNC \w+|ALIAS \w+|(?:PERS|CONST|VAR) \w+) (\w+)",
                        line)
        if head:
            name = head.group(1)
            found[name] = [re.sub(r" !.*", "", line)]
        elif line and not line.startswith("!") and name is not None:
            found[name].append(line)
    return found


def task_stubs() -> tuple[dict, dict]:
    cell, server = (parse_text(text, f"{name}.mod") for name, text in
                    (("Cell", CELL), ("Server", SERVER)))
    first, second = stub_modules([(cell, "Missing"), (server, "Missing")])
    return declarations(first.text), declarations(second.text)


def test_a_record_both_tasks_miss_has_the_components_both_use():
    first, second = task_stubs()
    record = ["RECORD cellinfo", "string name;", "num count;", "bool ready;", "ENDRECORD"]
    assert first["cellinfo"] == second["cellinfo"] == record


def test_a_routine_and_a_constant_both_tasks_miss_are_declared_alike():
    first, second = task_stubs()
    assert first["CellLog"] == second["CellLog"] == \
        ["PROC CellLog(num p1, string p2, \\switch Warn)", "ENDPROC"]
    assert first["MAX_PARTS"] == second["MAX_PARTS"] == ["CONST num MAX_PARTS := 4;"]
    # task 1's call types task 2's arguments, which nothing in task 2 types
    assert second["nCode"] == ["PERS num nCode := 0;"]
    assert second["sText"] == ['PERS string sText := "";']


def test_a_type_or_pers_one_task_declares_is_taken_as_it_declares_it():
    first, second = task_stubs()
    assert "partdata" not in first and "sState" not in first
    assert second["partdata"] == ["RECORD partdata", "num weight;", "string label;",
                                  "ENDRECORD"]
    # task 1's PERS: task 2's declaration is of the same object, its value task 1's
    assert second["sState"] == ["PERS string sState;"]
    assert second["sReady"] == ['PERS string sReady := "";']


def test_a_single_tasks_stubs_are_its_own_uses_only():
    alone = declarations(stub_module(parse_text(SERVER, "Server.mod"), "Missing").text)
    assert alone["cellinfo"] == ["RECORD cellinfo", "num count;", "bool ready;", "ENDRECORD"]
    assert alone["partdata"] == ["RECORD partdata", "string label;", "ENDRECORD"]
    assert alone["MAX_PARTS"] == ["PERS num MAX_PARTS := 0;"]
    assert alone["sText"] == ["PERS num sText := 0;"]     # num assumed: nothing types it
    assert alone["sState"] == ["PERS num sState := 0;"]


@pytest.fixture
def backup(tmp_path):
    return make_backup(tmp_path, {"TASK1": {"PROGMOD/Cell.mod": CELL},
                                  "TASK2": {"PROGMOD/Server.mod": SERVER}})


def test_the_whole_backup_loads_with_stubs_and_reaches_verdicts(backup):
    found = verdicts_and_states([backup, "--stubs"])
    assert {name: verdict for name, (verdict, _) in found.items()} == \
        {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}


def test_without_stubs_the_backup_does_not_load(backup):
    code, _, err = run_cli(["check", backup, "--quiet"])
    assert code == 2 and ("[RMC202]" in err or "[RMC201]" in err), err


# As PickMaster's two tasks: one declares the PERS with a nested value, the other names
# the components and passes the nested part to its own routine, whose parameter's record
# (of the option too) its uses name component by component.
VALUED = """MODULE Server
  PERS jobinfo job := ["job 1", [TRUE, ["a.mod", "b.mod"]]];
  PROC main()
    TPWrite job.Name;
  ENDPROC
ENDMODULE
"""

NAMED = """MODULE Manager
  PERS jobinfo job;
  PROC main()
    IF job.Robot.Load THEN
      LoadAll job.Robot.Files;
    ENDIF
  ENDPROC
  PROC LoadAll(fileinfo files)
    IF files.File1 <> "" AND files.File2 <> "" THEN
      TPWrite files.File1;
    ENDIF
  ENDPROC
ENDMODULE
"""


@pytest.mark.parametrize("order", [(VALUED, NAMED), (NAMED, VALUED)],
                         ids=["valued first", "named first"])
def test_a_part_of_a_declared_value_takes_the_record_another_task_names_it_by(order):
    first, second = (declarations(stubs.text) for stubs in stub_modules(
        [(parse_text(text, f"m{number}.mod"), "Missing") for number, text in enumerate(order)]))
    robot = first["jobinfo"][2].split()[0]   # invented: named after a place or a name
    assert first["jobinfo"] == second["jobinfo"] == \
        ["RECORD jobinfo", "string Name;", f"{robot} Robot;", "ENDRECORD"]
    assert first[robot] == second[robot] == \
        [f"RECORD {robot}", "bool Load;", "fileinfo Files;", "ENDRECORD"]
    assert first["fileinfo"] == second["fileinfo"] == \
        ["RECORD fileinfo", "string File1;", "string File2;", "ENDRECORD"]


def test_the_two_tasks_with_a_shared_nested_pers_load(tmp_path):
    backup = make_backup(tmp_path, {"TASK1": {"PROGMOD/Manager.mod": NAMED},
                                    "TASK2": {"PROGMOD/Server.mod": VALUED}})
    found = verdicts_and_states([backup, "--stubs"])
    assert {name: verdict for name, (verdict, _) in found.items()} == \
        {"no_runtime_error": "HOLDS", "no_deadlock": "HOLDS"}
