"""``rapidmc replay TRACE.json``: a saved counterexample re-executed on the program.

Data-driven: every counterexample of every hand-checked case (tests/check/)
and of the case studies is saved with ``check --format json`` and replayed
to its end (exit 0).  A program edited after the check stops the replay
with RMC507 at the step that no longer fits; unusable trace files are
RMC508.
"""
from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

from rapidmc.cli import main
from test_check_cases import verdict_cases

ROOT = Path(__file__).resolve().parent.parent
CASES = {case.name: case for case in verdict_cases()
         if "VIOLATED" in case.verdicts.values()}
STUDIES = {
    "sorter_b": ["case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod",
                 "--ltl", "specs/sorter.ltl"],
    "sorter_c": ["case_studies/sorter/sorter_c.mod", "--env", "case_studies/sorter/plant.mod",
                 "--ltl", "specs/sorter.ltl"],
    "door_race": ["case_studies/door/door_race.mod", "--env", "case_studies/door/plant.mod",
                  "--ltl", "specs/door.ltl"],
}


def save_report(capsys, argv: list[str], path: Path) -> dict:
    main(argv)
    path.write_text(capsys.readouterr().out)
    return json.loads(path.read_text())


def replay(capsys, *argv: str) -> tuple[int, str, str]:
    code = main(["replay", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def replay_every_violation(capsys, report: dict, path: Path) -> list[str]:
    violated = [p["name"] for p in report["properties"] if p["verdict"] == "VIOLATED"]
    for name in violated:
        code, _, err = replay(capsys, str(path), "--property", name)
        trace = next(p["trace"] for p in report["properties"] if p["name"] == name)
        steps = len(trace["prefix"]) + len(trace["cycle"]) + bool(trace["closing"])
        assert code == 0, err
        assert f"{name}: the counterexample replays: {steps} steps" in err
    return violated


@pytest.mark.parametrize("name", CASES)
def test_every_counterexample_of_the_check_cases_replays(name, monkeypatch, capsys, tmp_path):
    case = CASES[name]
    monkeypatch.chdir(case.folder)
    report = save_report(capsys, case.argv(), tmp_path / "trace.json")
    assert replay_every_violation(capsys, report, tmp_path / "trace.json")


@pytest.mark.parametrize("study", STUDIES)
def test_every_counterexample_of_the_case_studies_replays(study, monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    report = save_report(capsys, ["check", *STUDIES[study], "--quiet", "--format", "json"],
                         tmp_path / "trace.json")
    assert replay_every_violation(capsys, report, tmp_path / "trace.json")


def test_steps_go_to_stderr_and_flexpendant_output_to_stdout(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(tmp_path)
    Path("prog.mod").write_text('MODULE M\n  VAR num n := 0;\n  PROC main()\n'
                                '    WHILE TRUE DO\n      TPWrite "tick";\n      n := 1 - n;\n'
                                '    ENDWHILE\n  ENDPROC\nENDMODULE\n')
    save_report(capsys, ["check", "prog.mod", "--formula", 'never_one: G "n = 0"', "--quiet",
                         "--format", "json"], tmp_path / "trace.json")
    code, out, err = replay(capsys, "trace.json")
    assert code == 0
    assert out.splitlines() == ["tick", "tick"]     # the loop: n becomes 1, then 0 again
    assert "step 1  initial state" in err and "prog.mod:5  TPWrite \"tick\";" in err
    assert "n = 1" in err
    code, out, err = replay(capsys, "trace.json", "--quiet")
    assert (code, out.splitlines()) == (0, ["tick", "tick"]) and "initial state" not in err


def test_an_edited_program_stops_the_replay_at_the_step_that_no_longer_fits(monkeypatch, capsys,
                                                                            tmp_path):
    for name in ("case_studies", "specs"):
        shutil.copytree(ROOT / name, tmp_path / name)
    monkeypatch.chdir(tmp_path)
    save_report(capsys, ["check", *STUDIES["sorter_b"], "--quiet", "--format", "json"],
                tmp_path / "trace.json")
    program = Path("case_studies/sorter/sorter_b.mod")
    lines = program.read_text().splitlines()
    assert lines[80].strip() == "MoveJ a, v, zone, gripper;"      # line 81: back to A
    lines[80] = lines[80].replace("MoveJ a,", "MoveJ b,")
    program.write_text("\n".join(lines) + "\n")
    code, _, err = replay(capsys, "trace.json", "--property", "P2", "--quiet")
    assert code == 2
    assert ("case_studies/sorter/sorter_b.mod:81:17: error: the program no longer follows the "
            "counterexample of 'P2' at step 22 [RMC507]") in err
    assert "note: the trace executes: case_studies/sorter/sorter_b.mod:81  MoveJ a, v, zone, " \
           "gripper;" in err
    assert "note: the program can execute: case_studies/sorter/sorter_b.mod:81  MoveJ b" in err


@pytest.mark.parametrize("content, message", [
    ("not json", "is not JSON"),
    ('{"schema": "other"}', "is not a report of 'rapidmc check --format json'"),
    ('{"schema": "rapidmc-check/1", "command": null, "properties": []}',
     "holds no counterexample"),
])
def test_unusable_trace_files_are_diagnostics(content, message, capsys, tmp_path):
    path = tmp_path / "trace.json"
    path.write_text(content)
    code, _, err = replay(capsys, str(path))
    assert code == 2 and message in err and "[RMC508]" in err


def test_a_property_without_counterexample_is_named(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    save_report(capsys, ["check", *STUDIES["sorter_b"], "--quiet", "--format", "json"],
                tmp_path / "trace.json")
    code, _, err = replay(capsys, str(tmp_path / "trace.json"), "--property", "P1")
    assert code == 2 and "property 'P1' is HOLDS" in err
    code, _, err = replay(capsys, str(tmp_path / "trace.json"), "--property", "P9")
    assert code == 2 and "has no property 'P9'" in err


def test_replay_from_another_directory_says_where_to_run_it(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    save_report(capsys, ["check", *STUDIES["door_race"], "--quiet", "--format", "json"],
                tmp_path / "trace.json")
    monkeypatch.chdir(tmp_path)
    code, _, err = replay(capsys, "trace.json")
    assert code == 2 and "[RMC001]" in err
    assert "note: the program is rebuilt from the check command recorded in 'trace.json' " \
           "(check case_studies/door/door_race.mod" in err
    assert "run replay from the directory check ran in" in err
