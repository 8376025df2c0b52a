"""The grammar (and the HTML report's page) ships inside the wheel: build it, install it in a
fresh venv, parse there.

Slow-ish (10-40 s): it runs pip, whose isolated build fetches setuptools and
wheel from the package index; the venv sees this interpreter's lark, pyrsistent
and networkx through a .pth file.
"""
from __future__ import annotations

import subprocess
import sys
import venv
import zipfile
from pathlib import Path

import lark
import networkx
import pyrsistent
import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
HELLO = ROOT / "case_studies" / "hello" / "hello.mod"


def run(*command, cwd) -> str:
    done = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=180)
    assert done.returncode == 0, done.stdout + done.stderr
    return done.stdout


def test_wheel_contains_grammar_and_parses_in_fresh_venv(tmp_path):
    wheels = tmp_path / "wheels"
    run(sys.executable, "-m", "pip", "wheel", "--no-deps", "-q",
        "-w", str(wheels), str(ROOT), cwd=tmp_path)
    (wheel,) = wheels.glob("rapidmc-*.whl")
    names = zipfile.ZipFile(wheel).namelist()
    assert {f"rapidmc/report/html_page/page.{kind}" for kind in ("html", "css", "js")} <= set(names)
    packages = {str(init.relative_to(ROOT)) for init in (ROOT / "rapidmc").rglob("__init__.py")}
    assert packages <= set(names), f"packages missing from the wheel: {sorted(packages - set(names))}"
    environment = tmp_path / "env"
    # no pip of its own (ensurepip would cost 4 CPU s): this interpreter's pip installs into it
    venv.create(environment, system_site_packages=True, with_pip=False)
    python = str(environment / "bin" / "python")
    # The dependencies come from wherever this interpreter has them (a CI venv or
    # the system), as plain path entries: only the wheel provides rapidmc.
    site = run(python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])",
               cwd=tmp_path).strip()
    dependency_dirs = {str(Path(module.__file__).resolve().parent.parent)
                       for module in (lark, pyrsistent, networkx)}
    (Path(site) / "rapidmc_test_dependencies.pth").write_text("\n".join(sorted(dependency_dirs)))
    run(sys.executable, "-m", "pip", "--python", python, "install", "--no-deps", "--no-index",
        "-q", str(wheel), cwd=tmp_path)
    script = ("import rapidmc, sys; from rapidmc.syntax import parse_file; "
              "print(rapidmc.__file__); m = parse_file(sys.argv[1]); print(m[0].name.text)")
    location, module_name = run(python, "-c", script, str(HELLO), cwd=tmp_path).split()
    assert location.startswith(str(environment))
    assert module_name == "Hello"
