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


def test_a_message_too_long_for_its_line_keeps_the_code_on_the_head_line_and_loses_nothing():
    # an unreached-code warning joining many causes once made a head line of 330
    # characters, which the report wrapped before its code: tools read no code then
    import re as _re
    from rapidmc.ast import Span
    from rapidmc.diagnostics import HEAD_WIDTH, NEVER_REACHED, Diagnostic, render
    causes = "; ".join(f"with the assumed input values tried (sig{n}_3 at line {n})"
                       for n in range(12))
    message = f"lines 10-13 of FieldOf are never reached {causes}"
    shown = render(Diagnostic(NEVER_REACHED, message, Span("m.sys", 10, 7), severity="warning"), source=False)
    lines = shown.split("\n")
    assert all(len(line) <= HEAD_WIDTH for line in lines)
    assert _re.fullmatch(r"m\.sys:10:7: warning: lines 10-13 .* \.\.\. \[RMC701\]", lines[0])
    assert len(lines) > 1 and all(line.startswith("    ... ") for line in lines[1:])
    # the message, read back from its pieces, is the whole message
    pieces = [lines[0][len("m.sys:10:7: warning: "):-len(" ... [RMC701]")]] + \
        [line[len("    ... "):] for line in lines[1:]]
    assert " ".join(pieces).split() == message.split()
    short = render(Diagnostic(NEVER_REACHED, "line 4 is never reached", Span("m.sys", 4, 1),
                              severity="warning"),
                   source=False)
    assert short == "m.sys:4:1: warning: line 4 is never reached [RMC701]"
