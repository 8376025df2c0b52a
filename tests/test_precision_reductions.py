"""The outcomes issue 19 changed (TPReadFK's labelled keys and breaks, ReadCfgData's known
instances) give the same verdicts under the default reductions as without them."""
from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.test_assumptions import check_in_folder

CHECK = Path(__file__).resolve().parent / "check"
CASES = sorted(p.name for p in CHECK.iterdir()
               if p.is_dir() and p.name.startswith(("tp_read_fk_", "cfg_", "defect_")))


def verdicts(folder: Path, *extra: str) -> dict:
    args = ["prog.mod"] + (["--ltl", "props.ltl"] if (folder / "props.ltl").exists() else [])
    _, out = check_in_folder(folder, *args, "--format", "json", *extra)
    return {p["name"]: p["verdict"] for p in json.loads(out)["properties"]}


@pytest.mark.parametrize("name", CASES)
def test_reductions_keep_the_verdicts(name):
    folder = CHECK / name
    assert verdicts(folder) == verdicts(folder, "--no-reduce")
