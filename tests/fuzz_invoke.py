"""Run the ``rapidmc`` command in-process and judge its output (fuzzing support, no tests here).

A run is acceptable when its exit code is documented (0, 1, 2 or 3), stderr holds no
Python traceback and no internal error, and each diagnostic on stderr opens with the
documented first line ``FILE:LINE:COL: error: MESSAGE [RMCnnn]`` (or ``rapidmc: ...``
when it has no position).  Lines that follow a diagnostic (the source line, the caret,
notes) and the check command's progress lines are allowed.
"""
from __future__ import annotations

import re
import tempfile
from dataclasses import dataclass
from pathlib import Path

import pytest

from cli_capture import run_cli

class ScratchFolder:
    """A temporary folder for the files a test module writes (``folder / name``).  The module
    assigns ``fixture()`` to a name: it makes the folder before the module's tests and removes
    it after them, so no run leaves folders behind in /tmp."""

    def __init__(self, prefix: str) -> None:
        self.prefix = prefix
        self.path: Path | None = None

    def __truediv__(self, name: str) -> Path:
        assert self.path is not None, "the module's scratch folder fixture is not set up"
        return self.path / name

    def fixture(self):
        @pytest.fixture(autouse=True, scope="module")
        def scratch_folder():
            with tempfile.TemporaryDirectory(prefix=self.prefix) as folder:
                self.path = Path(folder)
                yield
                self.path = None
        return scratch_folder


DOCUMENTED_EXIT_CODES = (0, 1, 2, 3)
DIAGNOSTIC_HEAD = re.compile(r"^(\S+:\d+:\d+|rapidmc): (error|warning): .* \[RMC\d{3}\]$")
#: the start of a line that claims to be a diagnostic (and so must have the full shape)
LOOKS_LIKE_DIAGNOSTIC = re.compile(r"^(\S+:\d+:\d+|rapidmc|\S+): (error|warning|internal)")
TRACEBACK_MARKS = ("Traceback (most recent call last)", "internal error")


@dataclass(frozen=True)
class Outcome:
    """What one in-process command gave."""

    argv: tuple[str, ...]
    exit_code: int
    stdout: str
    stderr: str

    def problems(self) -> list[str]:
        """Why this outcome breaks the standards (empty when it does not)."""
        found = []
        if self.exit_code not in DOCUMENTED_EXIT_CODES:
            found.append(f"exit code {self.exit_code}")
        found.extend(f"traceback/internal error in stderr: {mark!r}"
                     for mark in TRACEBACK_MARKS if mark in self.stderr)
        found.extend(f"malformed diagnostic line: {line!r}" for line in self.stderr.split("\n")
                     if LOOKS_LIKE_DIAGNOSTIC.match(line) and not DIAGNOSTIC_HEAD.match(line))
        if self.exit_code == 2 and not any(DIAGNOSTIC_HEAD.match(line)
                                           for line in self.stderr.split("\n")):
            found.append("exit code 2 without a diagnostic")
        return found

    def describe(self) -> str:
        return (f"rapidmc {' '.join(self.argv)} -> exit {self.exit_code}\n"
                f"problems: {self.problems()}\n--- stderr ---\n{self.stderr[-3000:]}")


def invoke(argv: list[str], stdin_text: str = "") -> Outcome:
    """Run ``rapidmc ARGV`` in this process with the given standard input."""
    return Outcome(tuple(argv), *run_cli(argv, stdin=stdin_text))


def assert_acceptable(outcome: Outcome) -> None:
    assert not outcome.problems(), outcome.describe()
