"""Code after a jump, or a procedure named by a string, is "never reached under any input"
only where no input reaches it.

Data-driven on tests/dead_code/ (its README gives the layout): each case's coverage
warnings (RMC701) are compared, line and message, with its ``expected`` file; a warning
given once per cause (``findings/unreached_causes.py``) adds its other places
(``25 + 28-30 + 32-34: ...``), so that no line it reports is lost.  A RETURN
whose value raises an error in a routine with an ERROR handler lets TRYNEXT run the
statement after it, so that statement rests on the inputs tried; a RETURN of a name
cannot raise, and what follows it stays dead under any input.
"""
from __future__ import annotations

import json
import shlex
from pathlib import Path

import pytest

from test_assumptions import check_in_folder

CASES = Path(__file__).resolve().parent / "dead_code"
CASE_NAMES = sorted(p.name for p in CASES.iterdir() if p.is_dir())


def coverage_lines(folder: Path) -> list[str]:
    _, out = check_in_folder(folder, *shlex.split((folder / "args").read_text()),
                             "--format", "json")
    return [" + ".join([str(w["location"]["line"])] + [_lines(one) for one in w["lines"][1:]])
            + f": {w['message']}" for w in json.loads(out)["warnings"] if w["code"] == "RMC701"]


def _lines(place: dict) -> str:
    """A place of a warning given once per cause: ``28`` or ``28-30``."""
    first, last = place["line"], place["end_line"]
    return f"{first}-{last}" if last > first else f"{first}"


@pytest.mark.parametrize("name", CASE_NAMES)
def test_coverage_says_under_any_input_only_for_dead_code(name):
    folder = CASES / name
    wanted = [line for line in (folder / "expected").read_text().splitlines()
              if line.strip() and not line.startswith("#")]
    assert coverage_lines(folder) == wanted
