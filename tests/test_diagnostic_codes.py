"""docs/diagnostics.md lists every registered diagnostic code (the registry is the source)."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

from rapidmc.diagnostics import REGISTRY

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

DOC = Path(__file__).resolve().parent.parent / "docs" / "diagnostics.md"


def test_every_registered_code_is_documented_with_its_summary():
    rows = dict(re.findall(r"^\| (RMC\d{3}) \| [\w-]+ \| (.+) \|$", DOC.read_text(), re.M))
    assert set(rows) == set(REGISTRY)
    for code, entry in REGISTRY.items():
        assert rows[code] == entry.summary, code


def test_codes_sit_in_the_documented_ranges():
    assert all(re.fullmatch(r"RMC[0-8]\d\d", code) for code in REGISTRY)
