"""The outcomes issue 19 changed (TPReadFK's labelled keys and breaks, ReadCfgData's known
instances) give the same verdicts under the default reductions as without them."""
from __future__ import annotations

import contextlib
import io
import json
import os
from pathlib import Path

import pytest

from rapidmc.cli import main

CHECK = Path(__file__).resolve().parent / "check"
CASES = sorted(p.name for p in CHECK.iterdir()
               if p.is_dir() and p.name.startswith(("tp_read_fk_", "cfg_", "defect_")))


def verdicts(folder: Path, *extra: str) -> dict:
    args = ["prog.mod"] + (["--ltl", "props.ltl"] if (folder / "props.ltl").exists() else [])
    _, out = _check(folder, *args, *extra)
    return {p["name"]: p["verdict"] for p in json.loads(out)["properties"]}


def _check(folder: Path, *argv: str):
    out = io.StringIO()
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(io.StringIO()):
            code = main(["check", *argv, "--quiet", "--format", "json"])
    finally:
        os.chdir(cwd)
    return code, out.getvalue()


@pytest.mark.parametrize("name", CASES)
def test_reductions_keep_the_verdicts(name):
    folder = CHECK / name
    assert verdicts(folder) == verdicts(folder, "--no-reduce")
