"""``require_tool``: a missing outside tool skips the tests that need it, or fails them in CI.

It is called at module level (tests/test_ltl_spot.py, tests/test_engine_spot.py) and inside
tests (tests/test_ltl_spin.py); both must skip cleanly, not error at collection.
"""
from __future__ import annotations

import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

TESTS = Path(__file__).resolve().parent
MODULE_LEVEL = """
    from tool_requirements import require_tool
    require_tool(False, "RAPIDMC_REQUIRE_GADGET", "no gadget here")

    def test_needs_the_gadget():
        pass
"""
IN_A_TEST = """
    from tool_requirements import require_tool

    def test_needs_the_gadget():
        require_tool(False, "RAPIDMC_REQUIRE_GADGET", "no gadget here")
"""


def run_pytest(tmp_path: Path, source: str, required: bool) -> subprocess.CompletedProcess:
    (tmp_path / "test_gadget.py").write_text(textwrap.dedent(source))
    environment = {"PYTHONPATH": str(TESTS), "PATH": "/usr/bin:/bin"}
    if required:
        environment["RAPIDMC_REQUIRE_GADGET"] = "1"
    return subprocess.run([sys.executable, "-m", "pytest", "-q", "-rs", "-p", "no:cacheprovider",
                           str(tmp_path / "test_gadget.py")], cwd=tmp_path, env=environment,
                          capture_output=True, text=True)


@pytest.mark.parametrize("source", [MODULE_LEVEL, IN_A_TEST], ids=["module", "test"])
def test_missing_tool_skips(tmp_path, source):
    outcome = run_pytest(tmp_path, source, required=False)
    assert outcome.returncode in (0, 5), outcome.stdout    # 5: a skipped module collects nothing
    assert "1 skipped" in outcome.stdout and "no gadget here" in outcome.stdout


@pytest.mark.parametrize("source", [MODULE_LEVEL, IN_A_TEST], ids=["module", "test"])
def test_missing_tool_fails_when_required(tmp_path, source):
    outcome = run_pytest(tmp_path, source, required=True)
    assert outcome.returncode != 0
    assert "no gadget here, but RAPIDMC_REQUIRE_GADGET=1" in outcome.stdout
