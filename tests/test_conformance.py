"""RAPID conformance suite: programs with their expected FlexPendant output.

Every case under ``tests/conformance/<area>/`` is data (see
``tests/conformance/README.md``):

* ``<name>.mod`` — a one-module program, with optional companions of the
  same stem: ``.out`` (exact stdout, required), ``.in`` (stdin),
  ``.args`` (extra ``rapidmc run`` arguments on one line), ``.exit``
  (expected exit code, default 0) and ``.err`` (lines that must each be
  substrings of stderr);
* ``<name>/`` — a folder holding several ``.mod`` files (loaded in sorted
  order) and ``expected.out``, with optional ``input.in``, ``args``,
  ``exit`` and ``err``.

Each case runs ``rapidmc.cli.main(["run", *files, *args])`` in-process
with stdin replaced by the case's input, and its stdout, exit code and
stderr are compared with the expectations.
"""
from __future__ import annotations

import importlib.util
import io
import shlex
import signal
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

CONFORMANCE_ROOT = Path(__file__).parent / "conformance"
MINIMUM_CASES = 200            # both parts of the suite together
MINIMUM_CASES_PER_PART = 110
PART_A_AREAS = ("types", "arrays", "declarations", "expressions", "statements",
                "routines", "errors", "interrupts", "static")    # the language
CASE_TIMEOUT_SECONDS = 10      # a hanging interpreter fails one case, not the suite
STATIC_ERROR_EXIT = 2
SINGLE_FILE_COMPANIONS = (".out", ".in", ".args", ".exit", ".err")
FOLDER_COMPANIONS = ("expected.out", "input.in", "args", "exit", "err")


@dataclass(frozen=True)
class ConformanceCase:
    """One program and what running it must produce."""

    case_id: str                 # path relative to the conformance root
    modules: tuple[Path, ...]
    expected_stdout_file: Path
    expected_stdout: str
    stdin_text: str
    extra_args: tuple[str, ...]
    expected_exit: int
    stderr_fragments: tuple[str, ...]


# ---------------------------------------------------------------------------
# Discovery
# ---------------------------------------------------------------------------


def _read_optional(path: Path, default: str = "") -> str:
    return path.read_text(encoding="latin-1") if path.exists() else default


def _case_from_parts(case_id: str, modules: tuple[Path, ...], out: Path, stdin: Path,
                     args: Path, exit_file: Path, err: Path) -> ConformanceCase:
    exit_text = _read_optional(exit_file, "0").strip()
    fragments = [line.rstrip("\r") for line in _read_optional(err).splitlines()]
    return ConformanceCase(
        case_id=case_id,
        modules=modules,
        expected_stdout_file=out,
        expected_stdout=_read_optional(out),
        stdin_text=_read_optional(stdin),
        extra_args=tuple(shlex.split(_read_optional(args))),
        expected_exit=int(exit_text),
        stderr_fragments=tuple(line for line in fragments if line.strip()),
    )


def _single_file_case(root: Path, module: Path) -> ConformanceCase:
    def companion(suffix: str) -> Path:
        return module.with_suffix(suffix)

    return _case_from_parts(
        module.relative_to(root).as_posix(), (module,),
        companion(".out"), companion(".in"), companion(".args"),
        companion(".exit"), companion(".err"))


def _folder_case(root: Path, folder: Path) -> ConformanceCase:
    return _case_from_parts(
        folder.relative_to(root).as_posix() + "/",
        tuple(sorted(folder.glob("*.mod"))),
        folder / "expected.out", folder / "input.in", folder / "args",
        folder / "exit", folder / "err")


def _is_folder_case(folder: Path) -> bool:
    return (folder / "expected.out").exists()


def discover_cases(root: Path = CONFORMANCE_ROOT) -> list[ConformanceCase]:
    """All cases below root, in sorted path order."""
    cases = []
    for folder in sorted(path for path in root.rglob("*") if path.is_dir()):
        if _is_folder_case(folder):
            cases.append(_folder_case(root, folder))
    for module in sorted(root.rglob("*.mod")):
        if not _is_folder_case(module.parent):
            cases.append(_single_file_case(root, module))
    return sorted(cases, key=lambda case: case.case_id)


CASES = discover_cases()


# ---------------------------------------------------------------------------
# Running a case in-process
# ---------------------------------------------------------------------------


class _CaseTimeout(BaseException):
    """Not an Exception, so the CLI's internal-error guard cannot swallow it."""


def _raise_timeout(signum, frame):
    raise _CaseTimeout()


def run_case(case: ConformanceCase, capsys, monkeypatch) -> tuple[int, str, str]:
    """Run the case's program; returns (exit code, stdout, stderr)."""
    from rapidmc import cli

    monkeypatch.setattr(sys, "stdin", io.StringIO(case.stdin_text))
    argv = ["run", *(str(path) for path in case.modules), *case.extra_args]
    previous = signal.signal(signal.SIGALRM, _raise_timeout)
    signal.alarm(CASE_TIMEOUT_SECONDS)
    try:
        exit_code = cli.main(argv)
    except _CaseTimeout:
        pytest.fail(f"rapidmc run did not finish within {CASE_TIMEOUT_SECONDS} s")
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, previous)
    captured = capsys.readouterr()
    return exit_code, captured.out, captured.err


def _run_command_exists() -> bool:
    return importlib.util.find_spec("rapidmc.commands.run") is not None


requires_run = pytest.mark.skipif(
    not _run_command_exists(), reason="`rapidmc run` (rapidmc.commands.run) is not written yet")


@requires_run
@pytest.mark.parametrize("case", CASES, ids=[case.case_id for case in CASES])
def test_program_behaves_as_documented(case: ConformanceCase, capsys, monkeypatch):
    exit_code, stdout, stderr = run_case(case, capsys, monkeypatch)
    assert stdout == case.expected_stdout, f"stdout differs; stderr was:\n{stderr}"
    assert exit_code == case.expected_exit, f"exit code {exit_code}; stderr was:\n{stderr}"
    for fragment in case.stderr_fragments:
        assert fragment in stderr, f"{fragment!r} missing from stderr:\n{stderr}"


# ---------------------------------------------------------------------------
# The suite's own shape
# ---------------------------------------------------------------------------


def test_suite_has_at_least_200_cases():
    assert len(CASES) >= MINIMUM_CASES, (
        f"{len(CASES)} conformance cases found, the suite needs {MINIMUM_CASES}")


def test_language_part_has_at_least_110_cases():
    language_cases = [case for case in CASES if case.case_id.split("/")[0] in PART_A_AREAS]
    assert len(language_cases) >= MINIMUM_CASES_PER_PART


def _companions_without_program(root: Path) -> list[str]:
    orphans = []
    for suffix in SINGLE_FILE_COMPANIONS:
        for path in root.rglob("*" + suffix):
            if _is_folder_case(path.parent) or path.name in FOLDER_COMPANIONS:
                continue
            if not path.with_suffix(".mod").exists():
                orphans.append(path.relative_to(root).as_posix())
    return sorted(orphans)


def test_every_companion_file_belongs_to_a_program():
    assert _companions_without_program(CONFORMANCE_ROOT) == []


def _case_format_problems(case: ConformanceCase) -> list[str]:
    problems = []
    if not case.expected_stdout_file.exists():
        problems.append("no expected stdout file")
    if not case.modules:
        problems.append("no .mod file")
    if case.expected_exit not in (0, 1, STATIC_ERROR_EXIT):
        problems.append(f"exit code {case.expected_exit} is not 0, 1 or 2")
    if case.expected_exit == STATIC_ERROR_EXIT and case.expected_stdout:
        problems.append("a static error runs nothing, so its stdout must be empty")
    if case.expected_exit != 0 and not case.stderr_fragments:
        problems.append("an error case must name what stderr shows")
    return problems


@pytest.mark.parametrize("case", CASES, ids=[case.case_id for case in CASES])
def test_case_files_are_well_formed(case: ConformanceCase):
    assert _case_format_problems(case) == []


SAMPLE_TREE = {
    "area/single.mod": "MODULE m\nENDMODULE\n",
    "area/single.out": "hi\n",
    "area/single.exit": "1\n",
    "area/single.err": "ERR_DIVZERO\n\n",
    "area/single.args": "--io di1=1 --entry start\n",
    "area/multi/b.mod": "MODULE b\nENDMODULE\n",
    "area/multi/a.mod": "MODULE a\nENDMODULE\n",
    "area/multi/expected.out": "x\n",
    "area/multi/input.in": "3\n",
}


def test_discovery_reads_both_case_layouts(tmp_path):
    for relative, text in SAMPLE_TREE.items():
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
    cases = discover_cases(tmp_path)
    assert [case.case_id for case in cases] == ["area/multi/", "area/single.mod"]
    multi, single = cases
    assert [path.name for path in multi.modules] == ["a.mod", "b.mod"]
    assert (multi.expected_stdout, multi.stdin_text, multi.expected_exit) == ("x\n", "3\n", 0)
    assert single.extra_args == ("--io", "di1=1", "--entry", "start")
    assert (single.expected_exit, single.stderr_fragments) == (1, ("ERR_DIVZERO",))
