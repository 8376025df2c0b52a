"""The pre-commit hooks of .pre-commit-hooks.yaml, run by the real ``pre-commit`` tool.

A sample git repository is made in a temporary folder; ``pre-commit try-repo`` runs the lint
hook on its staged modules, and a ``.pre-commit-config.yaml`` that names the hooks (with the
check hook's ``args``) guards a real ``git commit``.  The hooks repository is a snapshot of this
work tree (tracked and new files) committed once, so that pre-commit installs its environment
once for the session, shared by the pytest-xdist workers; the native core is not built there
(RAPIDMC_NO_NATIVE) to keep that install short, as the hooks work the same on the Python
engine.
"""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from filelock import FileLock

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "tests" / "ci"
PRE_COMMIT = [sys.executable, "-m", "pre_commit"]

pytestmark = [pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed"),
              pytest.mark.engine_independent]      # the hooks' rapidmc has no core: see below


def git(*arguments: str, cwd: Path) -> str:
    done = subprocess.run(["git", *arguments], cwd=cwd, capture_output=True, text=True,
                          check=True, env=_git_environment())
    return done.stdout


def _git_environment() -> dict:
    environment = {k: v for k, v in os.environ.items() if not k.startswith("GIT_")}
    environment.update(GIT_AUTHOR_NAME="t", GIT_AUTHOR_EMAIL="t@example.com",
                       GIT_COMMITTER_NAME="t", GIT_COMMITTER_EMAIL="t@example.com",
                       GIT_CONFIG_GLOBAL=os.devnull, GIT_CONFIG_NOSYSTEM="1")
    return environment


@pytest.fixture(scope="session")
def shared_folder(tmp_path_factory) -> Path:
    """A folder all pytest-xdist workers of this session share (the parent of their
    temporary folders; without xdist the session's own), so that the hooks' environment is
    built once per session, not once per worker."""
    base = tmp_path_factory.getbasetemp()
    folder = (base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base) / "pre-commit-shared"
    folder.mkdir(exist_ok=True)
    return folder


@pytest.fixture(scope="session")
def hooks_repository(shared_folder) -> tuple[Path, str]:
    """This work tree's files as one commit of a fresh repository: (its path, the commit).
    The first worker makes it; the others wait for the lock and reuse it."""
    snapshot = shared_folder / "hooks"
    with FileLock(str(shared_folder / "hooks.lock")):
        if not (snapshot / ".git").is_dir():
            _snapshot_work_tree(snapshot)
        return snapshot, git("rev-parse", "HEAD", cwd=snapshot).strip()


def _snapshot_work_tree(snapshot: Path) -> None:
    listed = subprocess.run(["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                            cwd=ROOT, capture_output=True, check=True).stdout.decode()
    for name in filter(None, listed.split("\0")):
        source = ROOT / name
        if source.is_file():
            (snapshot / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, snapshot / name)
    git("init", "-q", cwd=snapshot)
    git("add", "-A", cwd=snapshot)
    git("commit", "-q", "-m", "snapshot", cwd=snapshot)


@pytest.fixture(scope="session")
def pre_commit_home(shared_folder) -> Path:
    """One pre-commit store for the session: pre-commit locks it while it installs the hooks'
    environment, so workers that start together wait for one install instead of each making
    its own."""
    home = shared_folder / "pre-commit-home"
    home.mkdir(exist_ok=True)
    return home


@pytest.fixture
def sample(tmp_path) -> Path:
    """An empty git repository with the property file committed."""
    git("init", "-q", cwd=tmp_path)
    shutil.copy(SAMPLES / "cell.ltl", tmp_path / "cell.ltl")
    git("add", "cell.ltl", cwd=tmp_path)
    git("commit", "-q", "-m", "properties", cwd=tmp_path)
    return tmp_path


def _pre_commit_environment(home: Path) -> dict:
    """pre-commit's environment: the store ``home``, and a short install of the hooks'
    environment: no native core, no isolated build environment for pip (the hooks'
    virtualenv gets setuptools, which builds rapidmc there, instead of a fresh one fetched from
    the index for each install), and no byte-compiling of what pip installs (the hooks import
    a few of those modules, compiled when imported; about 1 CPU s of each install's 9).
    (pip reads ``PIP_NO_...=0`` as the ``--no-...`` option given.)"""
    environment = _git_environment()
    environment.update(PRE_COMMIT_HOME=str(home), RAPIDMC_NO_NATIVE="1", PRE_COMMIT_COLOR="never",
                       PIP_NO_BUILD_ISOLATION="0", PIP_NO_COMPILE="0",
                       VIRTUALENV_SETUPTOOLS="bundle")
    return environment


def pre_commit(arguments: list[str], repository: Path, home: Path) -> subprocess.CompletedProcess:
    environment = _pre_commit_environment(home)
    return subprocess.run([*PRE_COMMIT, *arguments], cwd=repository, capture_output=True,
                          text=True, env=environment, timeout=900)


def stage(sample: Path, which: str) -> None:
    shutil.copy(SAMPLES / which / "cell.mod", sample / "cell.mod")
    git("add", "cell.mod", cwd=sample)


@pytest.mark.parametrize("which, refused", [("violating", True), ("clean", False)])
def test_try_repo_lint_hook_refuses_a_violating_module_and_passes_a_clean_one(
        hooks_repository, pre_commit_home, sample, which, refused):
    repository, commit = hooks_repository
    stage(sample, which)
    done = pre_commit(["try-repo", str(repository), "rapidmc-lint", "--ref", commit],
                      sample, pre_commit_home)
    output = done.stdout + done.stderr
    assert (done.returncode != 0) is refused, output
    assert ("RMC808" in output) is refused, output
    assert ("Failed" if refused else "Passed") in output


def write_config(sample: Path, repository: Path, commit: str) -> None:
    (sample / ".pre-commit-config.yaml").write_text(
        "repos:\n"
        f"-   repo: {repository}\n"
        f"    rev: {commit}\n"
        "    hooks:\n"
        "    -   id: rapidmc-lint\n"
        "    -   id: rapidmc-check\n"
        "        args: [cell.mod, --ltl, cell.ltl, --max-states, '10000']\n")


def test_installed_hooks_refuse_a_commit_whose_program_violates_a_property(
        hooks_repository, pre_commit_home, sample):
    repository, commit = hooks_repository
    write_config(sample, repository, commit)
    installed = pre_commit(["install"], sample, pre_commit_home)
    assert installed.returncode == 0, installed.stdout + installed.stderr
    git("add", ".pre-commit-config.yaml", cwd=sample)
    stage(sample, "clean")
    git("commit", "-q", "-m", "clean cell", cwd=sample)

    before = git("rev-parse", "HEAD", cwd=sample)
    stage(sample, "violating")
    environment = _pre_commit_environment(pre_commit_home)
    refused = subprocess.run(["git", "commit", "-m", "violating cell"], cwd=sample,
                             capture_output=True, text=True, env=environment, timeout=900)
    output = refused.stdout + refused.stderr
    assert refused.returncode != 0, output
    assert "at_most_three: VIOLATED" in output and "RMC808" in output
    assert git("rev-parse", "HEAD", cwd=sample) == before


def test_check_hook_runs_on_a_property_file_change_with_its_args(
        hooks_repository, pre_commit_home, sample):
    repository, commit = hooks_repository
    write_config(sample, repository, commit)
    git("add", ".pre-commit-config.yaml", cwd=sample)
    stage(sample, "clean")
    done = pre_commit(["run", "rapidmc-check", "--all-files", "--verbose"], sample,
                      pre_commit_home)
    output = done.stdout + done.stderr
    assert done.returncode == 0, output
    assert "at_most_three: HOLDS" in output
