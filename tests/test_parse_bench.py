"""bench/parse.py, whose figures the docs quote, runs and reports every stage and the floor
of the design (each irreducible part measured alone), on a small generated module."""
from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from rapidmc.syntax import accelerated

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

BENCH = Path(__file__).resolve().parent.parent / "bench" / "parse.py"


@pytest.mark.skipif(not accelerated.AVAILABLE, reason="lark_cython not installed")
def test_parse_bench_reports_stages_and_floor():
    output = subprocess.run([sys.executable, str(BENCH), "--stages", "400", "1"],
                            capture_output=True, text=True, check=True, timeout=300).stdout
    figures = dict(re.findall(r"^  (\S.*?)\s+([0-9.]+) ms", output, re.MULTILINE))
    for stage in ("scanning", "LALR loop alone", "AST construction", "whole parse",
                  "regular expression", "token objects", "sum"):
        assert float(figures[stage]) > 0, output
    nodes = next(name for name in figures if name.endswith("AST nodes"))
    assert int(nodes.split()[0].replace(",", "")) > 1000   # every distinct node is rebuilt
    parts = ["regular expression", "token objects", "LALR loop alone", nodes]
    assert float(figures["sum"]) == pytest.approx(sum(float(figures[p]) for p in parts),
                                                  abs=0.5)
