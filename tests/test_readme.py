"""The README starts with two commands that must stay true; CI runs the second one."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent


def readme_commands() -> list[str]:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    return re.findall(r"```\n(.*?)\n```", text, flags=re.S)[:2]


def test_readme_starts_with_the_two_commands():
    main_job, tests = readme_commands()
    assert "pip install -e ." in main_job and "rapidmc check" in main_job
    assert "pytest" in tests


def test_ci_runs_the_readme_test_command():
    _, tests = readme_commands()
    ci_lines = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    assert tests in ci_lines


def test_the_main_job_files_exist():
    main_job, _ = readme_commands()
    check = main_job.split("rapidmc check", 1)[1].split()
    files = [word for word in check if not word.startswith("--")]
    assert files and all((ROOT / f).exists() for f in files), files

