"""``rapidmc check`` on the hand-checked cases under tests/check/.

Each folder tests/check/<case>/ is one run of the checker, from inside the
folder (so file names in the output and in ``args`` are the folder's own):

* ``prog.mod`` — the program (always passed; leave it out to test a missing
  program file);
* ``*.sys`` — further modules of the program (system modules, an encrypted one), passed
  after prog.mod in name order;
* ``env.mod`` — an environment module, passed with ``--env`` when present;
* ``props.ltl`` — the properties, passed with ``--ltl`` when present; its
  comments say how each verdict was derived by hand;
* ``args`` — extra command-line options (shell quoting; lines starting with ``#``
  are comments, in every data file);
* ``expected`` — one ``NAME VERDICT`` line per property (a bare formula's name is its text), the built-in
  ``no_runtime_error`` and ``no_deadlock`` included; or, for bad input,
  ``ERROR RMCnnn [FILE:LINE]``: the diagnostic code (and where it points)
  expected on stderr;
* ``exit`` — the exit code; by default 2 for an ERROR case, else 1 if any
  verdict is VIOLATED, 3 if any is UNKNOWN, 0 otherwise.

A VIOLATED verdict must come with a lasso: a non-empty cycle (or, for a property, a
bad prefix: a path after whose last step every run violates it), and every step
that names a source line names a real line of prog.mod with its text.

A case whose verdict shows a checker bug carries a file ``xfail`` saying
what the bug is; it runs as ``xfail(strict=True)``, so it fails loudly once
the bug is fixed.
"""
from __future__ import annotations

import json
import re
import shlex
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import pytest

from rapidmc.check import native
from cli_capture import run_cli

CASES_DIR = Path(__file__).resolve().parent / "check"
VERDICTS = ("HOLDS", "VIOLATED", "UNKNOWN")
SAFETY = ("no_runtime_error", "no_deadlock")     # built-in checks: a path to the error
PROGRAM = "prog.mod"


@dataclass(frozen=True)
class ExpectedError:
    code: str                  # RMC401
    where: Optional[str]       # "props.ltl:3", or None when the position is not pinned


@dataclass(frozen=True)
class Case:
    name: str
    folder: Path
    verdicts: dict             # property name -> verdict, in file order
    error: Optional[ExpectedError]
    extra_args: tuple
    exit_code: int
    xfail: Optional[str]

    def argv(self) -> list[str]:
        argv = ["check", PROGRAM, *sorted(p.name for p in self.folder.glob("*.sys"))]
        if (self.folder / "env.mod").exists():
            argv += ["--env", "env.mod"]
        if (self.folder / "props.ltl").exists():
            argv += ["--ltl", "props.ltl"]
        # the format last, as tests/test_graph_reuse.py's ``report`` puts it: the same command
        # line (the report names it), so that module can compare with the shared report
        return argv + [*self.extra_args, "--format", "json", "--quiet"]


def _data_lines(path: Path) -> list[str]:
    if not path.exists():
        return []
    lines = []
    for line in path.read_text(encoding="latin-1").splitlines():
        line = line.strip()
        if line and not line.startswith("#"):
            lines.append(line)
    return lines


def _parse_expected(folder: Path) -> tuple[dict, Optional[ExpectedError]]:
    verdicts: dict[str, str] = {}
    expected_error = None
    for line in _data_lines(folder / "expected"):
        words = line.split()
        if words[0] == "ERROR":
            words = line.split(maxsplit=2)       # the place may hold spaces: <--formula 2>:1
            assert len(words) in (2, 3), f"{folder.name}/expected: bad line {line!r}"
            expected_error = ExpectedError(words[1], words[2] if len(words) == 3 else None)
            continue
        name, _, verdict = line.rpartition(" ")    # a bare formula's name holds spaces
        assert name.strip() and verdict in VERDICTS, f"{folder.name}/expected: {line!r}"
        verdicts[name.strip()] = verdict
    assert bool(verdicts) != bool(expected_error), \
        f"{folder.name}/expected: give verdicts or one ERROR line"
    return verdicts, expected_error


def _default_exit(verdicts: dict, expected_error: Optional[ExpectedError]) -> int:
    if expected_error is not None:
        return 2
    if "VIOLATED" in verdicts.values():
        return 1
    if "UNKNOWN" in verdicts.values():
        return 3
    return 0


def load_case(folder: Path) -> Case:
    verdicts, expected_error = _parse_expected(folder)
    args: list[str] = []
    for line in _data_lines(folder / "args"):
        args.extend(shlex.split(line))
    exit_lines = _data_lines(folder / "exit")
    exit_code = int(exit_lines[0]) if exit_lines else _default_exit(verdicts, expected_error)
    xfail_lines = _data_lines(folder / "xfail")
    xfail = " ".join(xfail_lines) if (folder / "xfail").exists() else None
    return Case(folder.name, folder, verdicts, expected_error, tuple(args), exit_code, xfail)


def all_cases() -> list:
    params = []
    for folder in sorted(p for p in CASES_DIR.iterdir() if p.is_dir()):
        case = load_case(folder)
        marks = [pytest.mark.xfail(strict=True, reason=case.xfail)] if case.xfail else []
        params.append(pytest.param(case, id=case.name, marks=marks))
    return params


def verdict_cases() -> list[Case]:
    """The cases that expect verdicts (no input error, no known bug), for other test files."""
    cases = [load_case(folder) for folder in sorted(CASES_DIR.iterdir()) if folder.is_dir()]
    return [case for case in cases if case.error is None and case.xfail is None]


def report_of(case: Case, monkeypatch) -> tuple[int, dict]:
    """The exit code and the JSON report of a verdict case."""
    code, stdout, _ = run_check(case, monkeypatch)
    return code, json.loads(stdout)


# (folder, command line, engine) -> (exit code, stdout, stderr) of the default check
_DEFAULT_RUNS: dict[tuple, tuple[int, str, str]] = {}


def run_check(case: Case, monkeypatch) -> tuple[int, str, str]:
    """Exit code, stdout and stderr of ``rapidmc check`` on a case with its own options, run
    from its folder on this process's engine.

    Several modules compare this default run with another computation (reduced, without the
    reused graph, on the other engine, ...).  The run is deterministic, so each process runs
    it once per case and engine and hands out the same text; the other side of each
    comparison is still computed by its module.  The text is immutable, callers parse their
    own copy."""
    monkeypatch.chdir(case.folder)
    argv = case.argv()
    key = (case.folder, tuple(argv), native.engine())
    if key not in _DEFAULT_RUNS:
        _DEFAULT_RUNS[key] = tuple(run_cli(argv))
    return _DEFAULT_RUNS[key]


# --- what a result must look like ---------------------------------------------

def assert_real_lasso(name: str, trace: Optional[dict], folder: Path) -> None:
    """A violation's trace is a lasso (a path ending at the error for the built-in safety
    checks) whose located steps are real lines of the case's files (prog.mod, or a further
    task's module passed with --add-task)."""
    assert trace is not None, f"{name}: VIOLATED without a trace"
    # A task that waits forever while the others go on (several tasks) is a no_deadlock
    # violation shown as a lasso: the others' loop, repeated forever.
    waits_in_loop = name == "no_deadlock" and bool(trace["cycle"])
    if name in SAFETY and not waits_in_loop:
        # a safety violation ends at the error, which the trace names with the error's step
        assert not trace["cycle"] and trace["closing"] is None and trace["loop_start"] is None
        assert trace["error"]["step"] == trace["prefix"][-1]["index"], name
        assert trace["prefix"][-1]["location"] is not None, f"{name}: the error has no line"
    elif not trace["cycle"]:
        # a property's bad prefix: every run that goes on from its last step violates it
        assert trace["closing"] is None and trace["loop_start"] is None
        assert trace["error"]["bad_prefix"], f"{name}: the trace has an empty cycle " \
                                             "(not a lasso) and is no bad prefix"
        assert trace["error"]["step"] == trace["prefix"][-1]["index"], name
    else:
        assert trace["loop_start"] == trace["cycle"][0]["index"]
        assert trace["error"] is None
    steps = trace["prefix"] + trace["cycle"] + [trace["closing"]]
    located = [step for step in steps if step is not None and step["location"] is not None]
    assert located, f"{name}: no step of the trace names a source line"
    for step in located:
        location = step["location"]
        file = Path(location["file"]).name
        if file.endswith(" (interface)") and (folder / file[:-len(" (interface)")]).exists():
            continue          # an encrypted module's interface, declared from its uses
        assert file == PROGRAM or file in _task_files(folder), f"{name}: step in {file}"
        lines = (folder / file).read_text(encoding="latin-1").splitlines()
        line = location["line"]
        assert 1 <= line <= len(lines), f"{name}: line {line} is not in {file}"
        assert step["source"] == lines[line - 1].strip(), \
            f"{name}: step {step['index']} shows {step['source']!r}, line {line} reads " \
            f"{lines[line - 1].strip()!r}"


def _task_files(folder: Path) -> set[str]:
    """The module files of further tasks named by the case's ``--add-task`` options."""
    words = [word for line in _data_lines(folder / "args") for word in shlex.split(line)]
    return {file for option, value in zip(words, words[1:]) if option == "--add-task"
            for file in value.split(",")}


def assert_verdicts(case: Case, stdout: str) -> None:
    document = json.loads(stdout)
    got = {entry["name"]: entry["verdict"] for entry in document["properties"]}
    assert got == case.verdicts
    for entry in document["properties"]:
        if entry["verdict"] == "VIOLATED":
            assert_real_lasso(entry["name"], entry["trace"], case.folder)
        else:
            assert entry["trace"] is None
        if entry["verdict"] == "UNKNOWN":
            assert entry["reason"], f"{entry['name']}: UNKNOWN without a reason"


def assert_diagnostic(expected: ExpectedError, stdout: str, stderr: str) -> None:
    # bad input prints no verdicts: the JSON report holds only the errors (or nothing,
    # for a usage error found before the format is known)
    if stdout:
        document = json.loads(stdout)
        assert document["properties"] == [], "bad input must not print verdicts"
        assert expected.code in {error["code"] for error in document["errors"]}
    assert f"[{expected.code}]" in stderr, stderr
    assert "Traceback" not in stderr, stderr
    if expected.where is not None:
        pattern = re.escape(expected.where) + r":\d+: error: .*\[" + expected.code + r"\]"
        assert re.search(pattern, stderr), f"expected {expected.where}: ... [{expected.code}]\n" \
                                           f"{stderr}"


@pytest.mark.parametrize("case", all_cases())
def test_check_case(case: Case, monkeypatch) -> None:
    code, stdout, stderr = run_check(case, monkeypatch)
    if case.error is not None:
        assert_diagnostic(case.error, stdout, stderr)
    else:
        assert stdout, f"no report; stderr:\n{stderr}"
        assert_verdicts(case, stdout)
    assert code == case.exit_code, stderr


def test_enough_hand_checked_cases() -> None:
    """The suite keeps its breadth: 40 verdict cases and the bad-input cases."""
    cases = [load_case(folder) for folder in CASES_DIR.iterdir() if folder.is_dir()]
    assert sum(1 for c in cases if c.error is None) >= 40
    assert {c.error.code for c in cases if c.error} >= {
        "RMC001", "RMC214", "RMC401", "RMC402", "RMC403", "RMC405", "RMC502", "RMC503"}
