"""The coverage of ABB's RAPID reference (docs/reference-names.txt) is computed from the
registry, so the figure in docs/predefined.md can be reproduced (issue 8, item 1)."""
from __future__ import annotations

import pytest

from rapidmc.semantics.library import reference_coverage as library_coverage

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def test_the_reference_has_the_four_sections_and_no_name_twice():
    sections = library_coverage.read_reference()
    assert list(sections) == list(library_coverage.KNOWN)
    for name, names in sections.items():
        keys = [n.upper() for n in names]
        assert len(keys) == len(set(keys)), name


def test_a_name_counts_as_covered_only_in_the_registry_of_its_kind(tmp_path):
    reference = tmp_path / "names.txt"
    reference.write_text("# comment\n[instructions]\nMoveL\nAbs\n[functions]\nAbs\nMoveL\n"
                         "[data types]\nrobtarget\nv100\n[data objects]\nv100\nrobtarget\n")
    sections = library_coverage.coverage(reference)
    assert [(s.name, s.covered, s.missing) for s in sections] == [
        ("instructions", 1, ("Abs",)), ("functions", 1, ("MoveL",)),
        ("data types", 1, ("v100",)), ("data objects", 1, ("robtarget",))]
    assert "instructions: 1 of 2\n  missing: Abs" in library_coverage.report(sections)


def test_a_name_before_any_section_is_refused(tmp_path):
    reference = tmp_path / "names.txt"
    reference.write_text("MoveL\n")
    with pytest.raises(ValueError, match="before the first"):
        library_coverage.read_reference(reference)


def test_routines_known_by_name_only_are_counted_apart(tmp_path):
    reference = tmp_path / "names.txt"
    reference.write_text("[instructions]\nMoveL\nRaiseToUser\nIndCnvInit\n[functions]\nAbs\n")
    sections = library_coverage.coverage(reference)
    assert [(s.covered, s.name_only) for s in sections] == [
        (3, ("RaiseToUser", "IndCnvInit")), (1, ())]
    assert "by name only, signature (...): 2" in library_coverage.report(sections)
