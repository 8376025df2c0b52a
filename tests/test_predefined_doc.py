"""docs/predefined.md is generated from the library's registry and kept in step (issue 8, C)."""
from __future__ import annotations

import pytest

from rapidmc.semantics.library import documentation as library_doc
from rapidmc.semantics.library import TOPICS, all_entries, parse_signature
from rapidmc.semantics.library.registry import MODELLED_AS

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py


def test_committed_page_equals_the_generated_one():
    assert library_doc.DOC.read_text(encoding="utf-8") == library_doc.document(), \
        "docs/predefined.md is out of date: run python -m rapidmc.semantics.library.documentation"


def test_every_shown_signature_parses_back_to_the_registered_one():
    for entry in all_entries():
        assert parse_signature(library_doc.signature_text(entry.signature)) == entry.signature


def test_every_routine_has_a_topic_module_and_says_how_it_is_modelled():
    for entry in all_entries():
        assert entry.topic in TOPICS, entry.signature.name
        assert entry.modelled in MODELLED_AS, entry.signature.name
        assert (entry.impl is None) == (entry.factory is not None), entry.signature.name


def test_check_mode_reports_a_stale_page(tmp_path, monkeypatch):
    stale = tmp_path / "predefined.md"
    stale.write_text("old\n")
    monkeypatch.setattr(library_doc, "DOC", stale)
    assert library_doc.main(["--check"]) == 1
    assert library_doc.main([]) == 0 and library_doc.main(["--check"]) == 0
