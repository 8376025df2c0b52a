"""An UNKNOWN built-in check says how far its search came (issue 27).

On a whole controller a bounded search often stops while the tasks are still in their
start-up; "UNKNOWN (time limit reached; 19,355 states)" alone does not tell a cell engineer
that no production cycle was searched.  Under an UNKNOWN breadth-first search the report
names the depth reached and where each task stands in the last state stored (text, and
``deepest_state`` in JSON); HOLDS and VIOLATED name none.
"""
from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from cli_capture import run_cli
from rapidmc.check import native

ENGINES = native.ENGINES if native.available() else (native.PYTHON,)

# The robot task counts for ever after its start-up; the logger meets it at the barrier,
# then polls the count.  Each count is a new state: no bound is ever enough.
ROBOT = """MODULE Robot
    VAR syncident ready;
    PERS tasks both{2} := [["T_ROB1"],["T_LOG"]];
    PERS num count := 0;
    PROC main()
        Setup;
        WaitSyncTask ready, both;
        WHILE TRUE DO
            count := count + 1;
        ENDWHILE
    ENDPROC
    PROC Setup()
        count := 0;
    ENDPROC
ENDMODULE
"""

LOGGER = """MODULE Logger
    VAR syncident ready;
    PERS tasks both{2};
    PERS num count;
    PROC main()
        WaitSyncTask ready, both;
        WHILE TRUE DO
            IF count > 1000000 TPWrite "many parts";
            WaitTime 1;
        ENDWHILE
    ENDPROC
ENDMODULE
"""


def backup(root: Path) -> Path:
    (root / "BACKINFO").mkdir(parents=True)
    (root / "BACKINFO" / "backinfo.txt").write_text(
        ">>SYSTEM_ID:\nrapidmc test cell\n\n>>TASK1: (T_ROB1,,)\n\n>>TASK2: (T_LOG,,)\n\n"
        ">>EOF:\n")
    (root / "SYSPAR").mkdir()
    (root / "SYSPAR" / "SYS.cfg").write_text(
        'SYS:CFG_1.0:6:0::\n#\nCAB_TASKS:\n\n      -Name "T_ROB1" -Type "NORMAL" -MotionTask\n\n'
        '      -Name "T_LOG" -Type "NORMAL"\n')
    for task, name, text in (("TASK1", "Robot", ROBOT), ("TASK2", "Logger", LOGGER)):
        folder = root / "RAPID" / task / "PROGMOD"
        folder.mkdir(parents=True)
        (folder / f"{name}.mod").write_text(text)
    return root


@pytest.mark.parametrize("engine", ENGINES)
def test_an_unknown_check_names_where_each_task_stands(tmp_path, engine):
    cell = backup(tmp_path / "cell")
    captured = run_cli(["check", cell, "--max-states", "60", "--engine", engine,
                        "--format", "json", "--quiet"])
    assert captured.code == 3
    for entry in json.loads(captured.out)["properties"]:
        assert entry["verdict"] == "UNKNOWN"
        places = {place["task"]: place for place in entry["deepest_state"]}
        assert list(places) == ["T_ROB1", "T_LOG"]
        robot, logger = places["T_ROB1"], places["T_LOG"]
        # the robot counts in main's loop; the logger waits in its own
        assert (robot["routine"], robot["statement"]) == ("main", "count := count + 1;")
        assert Path(robot["file"]).name == "Robot.mod"
        assert logger["routine"] == "main" and logger["line"] > 6      # past the barrier
        assert entry["stats"]["max_depth"] > 10


def test_the_text_report_says_how_far_the_search_came(tmp_path):
    cell = backup(tmp_path / "cell")
    captured = run_cli(["check", cell, "--max-states", "60", "--quiet"])
    lines = captured.out.splitlines()
    verdict = lines.index(next(line for line in lines if line.startswith("no_runtime_error:")))
    below = lines[verdict + 1]
    assert below.startswith("  searched to depth ")
    assert "last state stored: T_ROB1 in main (Robot.mod:" in below
    assert "T_LOG in main (Logger.mod:" in below


@pytest.mark.parametrize("engine", ENGINES)
def test_an_unknown_ltl_property_says_where_its_search_stood(tmp_path, engine):
    cell = backup(tmp_path / "cell")
    (tmp_path / "p.ltl").write_text('G F "count > 5"\n')
    captured = run_cli(["check", cell, "--ltl", tmp_path / "p.ltl", "--max-states", "60",
                        "--engine", engine, "--format", "json", "--quiet"])
    entry = json.loads(captured.out)["properties"][-1]
    assert (entry["name"], entry["verdict"]) == ('G F "count > 5"', "UNKNOWN")
    assert [(place["task"], place["routine"]) for place in entry["deepest_state"]] == \
        [("T_ROB1", "main"), ("T_LOG", "main")]


def test_a_complete_search_names_no_deepest_state(tmp_path):
    program = tmp_path / "once.mod"
    program.write_text("MODULE Once\n    PROC main()\n        TPWrite \"hello\";\n"
                       "    ENDPROC\nENDMODULE\n")
    captured = run_cli(["check", program, "--format", "json", "--quiet"])
    assert captured.code == 0
    assert all(entry["deepest_state"] is None
               for entry in json.loads(captured.out)["properties"])
    assert "searched to depth" not in run_cli(["check", program, "--quiet"]).out


def test_junit_and_sarif_say_how_far_the_search_came(tmp_path):
    cell = backup(tmp_path / "cell")
    junit = tmp_path / "checks.xml"
    sarif = run_cli(["check", cell, "--max-states", "60", "--format", "sarif", "--quiet",
                     "--junit", junit])
    messages = [result["message"]["text"] for run in json.loads(sarif.out)["runs"]
                for result in run["results"] if "UNKNOWN" in result["message"]["text"]]
    assert messages and all("last state stored: T_ROB1 in main (Robot.mod:" in message
                            for message in messages)
    assert "; searched to depth " in messages[0]
    skipped = [case.find("skipped") for case in ET.parse(junit).getroot().iter("testcase")]
    texts = [element.text for element in skipped if element is not None]
    assert texts and all("(searched to depth " in text and "T_LOG in main" in text
                         for text in texts)
