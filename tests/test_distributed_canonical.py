"""The partition of a distributed search: canonical state bytes and their owner.

Workers must agree on the owner of every state, whatever their hash seeds and however a
state was built, or a state would be stored twice (wrong counts) or never expanded.  These
tests need no Ray.
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from pyrsistent import pmap, pvector

from rapidmc import api
from rapidmc.check.distributed.canonical import canonical_bytes, owner

pytestmark = pytest.mark.engine_independent      # no search: see tests/conftest.py

ROOT = Path(__file__).resolve().parent.parent
SORTER = [str(ROOT / "case_studies" / "sorter" / "sorter_b.mod")]
PLANT = [str(ROOT / "case_studies" / "sorter" / "plant.mod")]


def test_equal_values_encode_alike_whatever_their_history():
    assert canonical_bytes(frozenset(["a", "b", "c"])) == canonical_bytes(frozenset(["c", "b", "a"]))
    assert canonical_bytes({"x": 1, "y": 2}) == canonical_bytes({"y": 2, "x": 1})
    assert canonical_bytes(pmap({"x": 1}).set("y", 2)) == canonical_bytes(pmap({"y": 2, "x": 1}))
    assert canonical_bytes((True, 2, 3.0)) == canonical_bytes((1, 2.0, 3))   # equal in Python
    assert canonical_bytes(pvector([1, 2])) == canonical_bytes((1, 2))
    assert canonical_bytes((1.5, "a")) != canonical_bytes((1.25, "a"))
    assert canonical_bytes(("ab", "c")) != canonical_bytes(("a", "bc"))   # prefix-free
    with pytest.raises(TypeError, match="object"):
        canonical_bytes((object(),))


def _owners_in_a_fresh_process(seed: str) -> list[int]:
    code = (
        "import json, sys\n"
        "from rapidmc import api\n"
        "from rapidmc.check.distributed.canonical import owner\n"
        f"m = api.prepare(api.load_program({SORTER!r}, env={PLANT!r}), [])\n"
        "s = m.system; seen = []; frontier = list(s.initial_states())\n"
        "while frontier and len(seen) < 150:\n"
        "    state = frontier.pop(0); seen.append(state)\n"
        "    frontier.extend(after for _, after in s.successors(state))\n"
        "print(json.dumps([owner(state, 7) for state in seen]))\n")
    env = dict(os.environ, PYTHONHASHSEED=seed)
    run = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                         text=True, check=True)
    return json.loads(run.stdout)


def test_processes_with_other_hash_seeds_agree_on_every_owner():
    first, second = _owners_in_a_fresh_process("1"), _owners_in_a_fresh_process("12345")
    assert first == second and len(set(first)) > 3      # the same owners, spread out
