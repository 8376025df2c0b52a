"""bench/survey_sockets.py, whose figures docs/realworld-survey.md quotes: a socket program of
a corpus gets its row, and the lines column counts every place of a warning given once per
cause (a place is a flat location, as the warning's own)."""
from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CASE = ROOT / "tests" / "dead_code" / "routine_called_from_dead_code_only"


def test_a_socket_programs_row_counts_the_lines_of_every_place(tmp_path):
    corpus = tmp_path / "corpus"
    (corpus / "someone+server").mkdir(parents=True)
    shutil.copy(CASE / "prog.mod", corpus / "someone+server" / "prog.mod")
    rows_file = tmp_path / "rows.json"
    subprocess.run([sys.executable, str(ROOT / "bench" / "survey_sockets.py"), str(corpus),
                    "--json", str(rows_file)], check=True, capture_output=True, timeout=300)
    (row,) = json.loads(rows_file.read_text())
    assert row["name"] == "someone+server/prog.mod" and row["outcome"] == "verdicts"
    # (the case's warnings: lines 25-26 with the places 28-31 and 32-34; routine Report, 35-37)
    assert row["unreached"] == 2 and row["any_input"] == 1
    assert row["places"] == 2 + 1                # (a warning without places counts one)
    assert row["lines"] == (2 + 4 + 3) + 3
