"""A distributed worker's compact packed table (``_packed.c``'s ``compact``): state keys in
4 bytes and data segments' items in 1 or 2 bytes while they fit, widened when one does not.

Differential: the same states interned into a compact table and a plain one get the same
ids and read back as the same states, in every width the tables pass through (a model with
more than 256 distinct values and more than 256 frames widens both), whether the table was
made compact before its first state or after some; and the compact table holds them in
fewer bytes.
"""
from __future__ import annotations

from array import array
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import native
from rapidmc.check.distributed.partition import search_here
from test_distributed_codec import breadth_first as every_state_breadth_first, packed

ROOT = Path(__file__).resolve().parent.parent
PROGRAMS = {
    "wide values": ROOT / "tests" / "distributed" / "wide_values.mod",
    "socket server": ROOT / "tests" / "check" / "socket_field_count" / "prog.mod",
}


def system_of(name: str):
    from dataclasses import replace
    options = api.CheckOptions()
    options = replace(options, reductions=replace(options.reductions, partial_order=False))
    return api.prepare(api.load_program([str(PROGRAMS[name])]), [], options).system


def breadth_first(system) -> list:
    return every_state_breadth_first(system, 1 << 20)


@pytest.mark.parametrize("compact_after", [0, 100])
@pytest.mark.parametrize("name", ["wide values", "socket server"])
def test_a_compact_table_stores_the_states_a_plain_one_stores(name, compact_after):
    system = system_of(name)
    states = breadth_first(system)
    plain, compact = packed(system), packed(system)
    for number, state in enumerate(states):
        if number == compact_after:
            compact.compact()
        assert compact.intern(state, True) == plain.intern(state, True)
        assert compact.intern(state, False) == (number, False)
    assert len(compact) == len(plain) == len(states)
    assert [compact[i] for i in range(len(states))] == states
    assert [compact.key(i) for i in range(len(states))] == \
        [plain.key(i) for i in range(len(states))]
    assert compact.native_bytes() < plain.native_bytes()
    if name == "wide values":
        assert plain.counts()["frames"] > 256 and plain.counts()["values"] > 256


def test_a_compact_table_expands_a_round_as_a_plain_one():
    """``expand_keys`` and ``segments_batch`` (a worker's round) read a compact table's
    narrow data segments as a plain table's."""
    system = system_of("wide values")
    plain, compact = packed(system), packed(system)
    compact.compact()
    for state in breadth_first(system):
        plain.intern(state, True)
        compact.intern(state, True)
    found = [table.expand_keys(0, len(table), True, None) for table in (plain, compact)]
    assert found[0] == found[1]
    keys = array("Q", found[0][0]).tobytes()
    assert plain.segments_batch(keys) == compact.segments_batch(keys)


def test_workers_with_compact_tables_count_what_one_process_counts():
    """Two partitions (each with a compact table, as a worker has) store exactly one
    process's states of the model that widens both the keys and the data segments."""
    from rapidmc.check import find_reachable
    if not native.available():
        pytest.skip("the native core is not built here: no packed table")
    with native.engine_used("native"):
        system = system_of("wide values")
        packed(system)
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2)
    assert target is None
    assert sum(len(part.table) for part in parts) == one.stats.product_states
    assert all(part.table.native_bytes() > 0 for part in parts)
