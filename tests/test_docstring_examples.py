"""The examples in the docstrings of the issue-8 modules run and give what they show."""
from __future__ import annotations

import doctest
import importlib

import pytest

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

MODULES = ["rapidmc.diagnostics.error_report", "rapidmc.syntax.recovery", "rapidmc.syntax.call_statement",
           "rapidmc.load.stubs",
           "rapidmc.load.stubs.passes", "rapidmc.load.stubs.records", "rapidmc.semantics.library.documentation", "rapidmc.semantics.library.registry",
           "rapidmc.check.trace", "rapidmc.model.value_text", "rapidmc.report.trace_text", "rapidmc.report.line_width", "rapidmc.diagnostics",
           "rapidmc.findings.editor", "rapidmc.findings.declarations", "rapidmc.report.hover",
           "rapidmc.report.lsp_diagnostics"]


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    result = doctest.testmod(importlib.import_module(name))
    assert result.failed == 0 and result.attempted > 0
