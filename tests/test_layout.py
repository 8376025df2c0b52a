"""The package layout: stages in a fixed order, imports pointing down it, each package explained.

A module may import its own stage and the stages listed before it, never one listed after it
(docs/architecture.md, "Where new code goes").  The few imports that point up are listed in
``UPWARD`` with the reason each is there; a new one fails this test until it is justified there
or moved.
"""
from __future__ import annotations

import ast
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

PACKAGE = Path(__file__).resolve().parent.parent / "rapidmc"

# Lowest first.  A stage is a package (folder) or a module loose at the package root.
STAGES = [
    ("__init__", "ast", "diagnostics"),    # the vocabulary every stage shares
    ("syntax",),                           # source text -> AST
    ("semantics",),                        # link, states, steps, the predefined library
    ("ltl",),                              # formulas, Büchi automata
    ("check",),                            # the generic search engine (no RAPID)
    ("load",),                             # files, backups, input domains, stubs
    ("model",),                            # the program as a transition system, properties
    ("findings",),                         # coverage, vacuity, fixed readings
    ("report",),                           # text, JSON, SARIF, JUnit, HTML, graphs
    ("api",),                              # one check, stage by stage
    ("commands", "cli"),                   # the command line
    ("__main__",),
]
LEVEL = {stage: level for level, names in enumerate(STAGES) for stage in names}

# (importing module, imported module): why it may point up.
UPWARD = {
    ("rapidmc.syntax.call_statement", "rapidmc.semantics.library"):
        "a syntax error's message says that a predefined function was called as a procedure; "
        "the registry of predefined routines is the one place that knows their kinds",
}

MAX_LOOSE_MODULES = 8


def modules() -> list[tuple[str, Path]]:
    found = []
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        found.append((".".join(parts), path))
    return found


def stage_of(module: str) -> str:
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "__init__"


def imported(module: str, path: Path) -> list[str]:
    """Every rapidmc module ``path`` imports, at any depth (lazy imports count too)."""
    package = module.split(".") if path.name == "__init__.py" else module.split(".")[:-1]
    names = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names += [alias.name for alias in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = package[:len(package) - node.level + 1] if node.level else []
            target = ".".join(base + ([node.module] if node.module else []))
            names.append(target)
            if not node.module or target == "rapidmc":     # from . import x: x may be a module
                names += [f"{target}.{alias.name}" for alias in node.names]
    return [name for name in names if name == "rapidmc" or name.startswith("rapidmc.")]


def upward_imports() -> list[tuple[str, str]]:
    found = []
    for module, path in modules():
        here = LEVEL[stage_of(module)]
        for target in imported(module, path):
            stage = stage_of(target)
            if stage in LEVEL and LEVEL[stage] > here \
                    and not any(module == a and target.startswith(b) for a, b in UPWARD):
                found.append((module, target))
    return found


def test_every_stage_is_listed():
    stages = {path.stem if path.is_file() else path.name
              for path in PACKAGE.iterdir()
              if (path.suffix == ".py" or (path / "__init__.py").exists())}
    assert stages == set(LEVEL), "a stage of rapidmc/ is missing from STAGES (or gone)"


def test_imports_point_down_the_stages():
    assert upward_imports() == []


def test_the_check_finds_an_upward_import(tmp_path, monkeypatch):
    """The rule is live: a semantics module importing the model stage is reported."""
    fake = tmp_path / "rapidmc"
    (fake / "semantics").mkdir(parents=True)
    (fake / "semantics" / "__init__.py").write_text("")
    (fake / "semantics" / "bad.py").write_text("from ..model import properties\n")
    monkeypatch.setattr(sys.modules[__name__], "PACKAGE", fake)
    assert upward_imports() == [("rapidmc.semantics.bad", "rapidmc.model")]


def test_few_modules_loose_at_the_root():
    loose = sorted(path.name for path in PACKAGE.glob("*.py"))
    assert len(loose) <= MAX_LOOSE_MODULES, loose


@pytest.mark.parametrize("init", sorted(PACKAGE.rglob("__init__.py")),
                         ids=lambda path: str(path.parent.relative_to(PACKAGE.parent)))
def test_every_package_opens_with_a_docstring(init):
    docstring = ast.get_docstring(ast.parse(init.read_text(encoding="utf-8")))
    assert docstring and len(docstring) > 40, f"{init} needs a docstring saying what it owns"


def test_the_architecture_page_names_every_package():
    page = (PACKAGE.parent / "docs" / "architecture.md").read_text(encoding="utf-8")
    for init in sorted(PACKAGE.rglob("__init__.py")):
        folder = init.parent
        if folder == PACKAGE:
            continue
        name = folder.name + "/"
        assert name in page, f"docs/architecture.md does not name the package {name}"
