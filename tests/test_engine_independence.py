"""The ``engine_independent`` mark: the probe of tests/conftest.py fails a marked test that
consults the search engine, and ``.ci/run`` leaves only marked modules out of its
Python-engine run.

The probe is run on a small suite of its own (a fresh pytest process in a temporary folder
with a copy of the conftest): a marked test that searches fails and names the functions it
called, a marked test that only parses passes, and an unmarked search passes.  The probe sees
one process only, so a marked module that starts processes must say here why their engine does
not follow the run's.
"""
from __future__ import annotations

import ast
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
TESTS = ROOT / "tests"

pytestmark = pytest.mark.engine_independent

# modules with marked tests that start processes, and why those processes' engine is not the
# run's (a module that marks single tests is held to it as one that marks them all)
STARTED_PROCESSES = {
    "test_pre_commit.py": "pre-commit installs its own rapidmc without the core "
                          "(RAPIDMC_NO_NATIVE=1): its hooks search on the Python engine in "
                          "both runs",
    "test_engine_independence.py": "its pytest process runs the probe on toy tests, the same "
                                   "in both runs",
    "test_parse_wheel.py": "builds a wheel from the sources (the core too, whatever the run's "
                           "engine) and parses with it",
    "test_parse_bench.py": "runs the parser's benchmark, which never searches",
    "test_tool_requirements.py": "runs pytest on toy tests of the tool requirements",
    "test_distributed_canonical.py": "steps a model in processes with other hash seeds, with "
                                     "no state table or search",
    "test_lsp.py": "the language server parses and lints; it does not import rapidmc.check",
}

SEARCHING = '''
import pytest
from rapidmc.check import find_reachable

class Line:
    def initial_states(self):
        return (0,)
    def successors(self, state):
        return (("step", state + 1),) if state < 3 else ()

{mark}
def test_search():
    assert find_reachable(Line(), lambda state: state == 3).verdict == "VIOLATED"
'''

PARSING = '''
import pytest
from rapidmc.syntax import parse_text

pytestmark = pytest.mark.engine_independent

def test_parse():
    assert parse_text("MODULE M\\nENDMODULE\\n", "m.mod") is not None
'''


def run_probe_suite(tmp_path: Path) -> subprocess.CompletedProcess:
    shutil.copy(TESTS / "conftest.py", tmp_path / "conftest.py")
    (tmp_path / "test_marked_search.py").write_text(
        SEARCHING.format(mark="@pytest.mark.engine_independent"))
    (tmp_path / "test_unmarked_search.py").write_text(SEARCHING.format(mark=""))
    (tmp_path / "test_marked_parse.py").write_text(PARSING)
    return subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider",
                           "-p", "no:xdist", "-rf", str(tmp_path)],
                          cwd=tmp_path, capture_output=True, text=True, timeout=300)


def test_probe_fails_a_marked_test_that_searches_and_passes_the_others(tmp_path):
    done = run_probe_suite(tmp_path)
    output = done.stdout + done.stderr
    assert done.returncode == 1, output
    assert "1 failed, 2 passed" in output, output
    assert re.search(r"FAILED test_marked_search.py::test_search", output), output
    assert "is marked engine_independent but consults the search engine" in output, output
    assert "state_table" in output, output


def marked_modules() -> list[Path]:
    """The modules that mark all their tests (``pytestmark``) or some of them (a decorator,
    or ``pytest.mark.engine_independent(test)`` as test_fuzz does)."""
    return [path for path in sorted(TESTS.glob("test_*.py"))
            if any(isinstance(node, ast.Attribute) and node.attr == "engine_independent"
                   and isinstance(node.value, ast.Attribute) and node.value.attr == "mark"
                   for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))))]


def test_modules_that_mark_single_tests_are_among_the_marked_modules():
    names = {path.name for path in marked_modules()}
    assert {"test_fuzz.py", "test_staged_step.py", "test_ltl_spin.py"} <= names, names


def test_marked_modules_that_start_processes_say_why_their_engine_is_not_the_runs():
    starting = [path.name for path in marked_modules()
                if re.search(r"\bsubprocess\b|\bPopen\b|multiprocessing",
                             path.read_text(encoding="utf-8"))]
    assert starting, "expected some marked modules to start processes"
    unexplained = [name for name in starting if name not in STARTED_PROCESSES]
    assert not unexplained, unexplained
    stale = [name for name in STARTED_PROCESSES if name not in starting]
    assert not stale, stale


def test_ci_leaves_only_marked_modules_out_of_the_python_engine_run():
    lines = (ROOT / ".ci" / "run").read_text(encoding="utf-8").splitlines()
    python_runs = [line for line in lines if line.startswith("RAPIDMC_ENGINE=python")]
    assert len(python_runs) == 1, python_runs
    assert '-m "not engine_independent"' in python_runs[0]
    readme_command = re.findall(r"```\n(.*?)\n```",
                                (ROOT / "README.md").read_text(encoding="utf-8"), re.S)[1]
    assert "-m" not in readme_command.split("pytest", 1)[1].split()
