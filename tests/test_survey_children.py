"""The survey script shows what a rapidmc child printed when it failed (bench/survey_programs.py).

A child's stderr once went to /dev/null, so a traceback behind an exit code other than 4
was invisible in the survey's rows.  A traceback now makes the row ``internal``, whatever
the exit code, with the traceback's last lines as its detail.
"""
import importlib.util
import sys
from pathlib import Path

import pytest

SCRIPT = Path(__file__).resolve().parents[1] / "bench" / "survey_programs.py"


@pytest.fixture(scope="module")
def survey():
    spec = importlib.util.spec_from_file_location("survey_programs_under_test", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    yield module
    del sys.modules[spec.name]


def _row(survey):
    return survey.Program(name="cell", command=["cell.mod"], files=[])


@pytest.mark.parametrize("exit_code", [2, 3, 4])
def test_a_traceback_makes_the_row_internal_whatever_the_exit_code(survey, exit_code):
    row = _row(survey)
    code, report = survey.run_child(
        [sys.executable, "-c",
         "import sys\ndef load():\n    raise KeyError('T_ROB1')\n"
         f"try:\n    load()\nexcept KeyError:\n    import traceback; traceback.print_exc()\n"
         f"print('{{}}'); sys.exit({exit_code})"], 60, row)
    assert code == exit_code and report == {}
    survey._classify(row, code, report)
    assert row.outcome == "internal"
    assert row.detail.startswith("KeyError: 'T_ROB1' <- ") and "in load" in row.detail


def test_a_diagnostic_on_stderr_leaves_the_row_to_its_exit_code(survey):
    row = _row(survey)
    code, report = survey.run_child(
        [sys.executable, "-c",
         "import sys, json\nprint('cell.mod:3:7: error: unknown name [RMC201]', file=sys.stderr)\n"
         "print(json.dumps({'errors': [{'code': 'RMC201', 'message': 'unknown name'}]}))\n"
         "sys.exit(2)"], 60, row)
    survey._classify(row, code, report)
    assert (row.outcome, row.trace) == ("load error", "")
    assert row.detail.startswith("RMC201")


def test_an_unknown_row_says_how_far_its_search_came(survey):
    row = _row(survey)
    place = {"task": "T_ROB1", "routine": "r_RRC_InitCell", "file": "RRC_Control_Rob.sys",
             "line": 87, "statement": "WaitSyncTask id_RRC_InitCtrl,tl_RRC_All;"}
    ended = dict(place, task="T_LOG", routine="", line=0)
    report = {"properties": [{"name": "no_runtime_error", "verdict": "UNKNOWN",
                              "stats": {"model_states": 12077, "max_depth": 158},
                              "deepest_state": [place, ended]}]}
    survey._classify(row, 3, report)
    assert (row.outcome, row.states) == ("unknown", 12077)
    assert row.detail == "depth 158: T_ROB1 r_RRC_InitCell:87, T_LOG ended"
