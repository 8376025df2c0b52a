"""How states travel between the workers of a partitioned search (``distributed/codec.py``),
without Ray: partitions driven in this process (``partition.search_here``).

Where the model has a packed table, a state travels as the table's vectors; where it has
none (free inputs, or the Python engine), as the node ids of its parts.  Either way the ids
are the sender's own: the owner must map them to its ids (values and contexts, or nodes,
handed over incrementally) and every process must agree on a state's owner however its
table numbered them.  The search over every codec (packed vectors and node ids on the
native engine, node ids on the Python engine) must count exactly what one process counts,
and find the violation at the depth one process finds it.
"""
from __future__ import annotations

import gc
from array import array
from dataclasses import replace
from pathlib import Path

import pytest

from rapidmc import api
from rapidmc.check import check_property, find_reachable, native
from rapidmc.check.distributed.codec import NodeCodec, VectorCodec, codec_for, \
    data_owners_fit
from rapidmc.check.distributed.partition import Links, link, search_here, unlink
from rapidmc.check.distributed.product_partition import product_here
from rapidmc.check.result import HOLDS, VIOLATED

pytest.importorskip("numpy")

ROOT = Path(__file__).resolve().parent.parent
CHECK = ROOT / "tests" / "check"
# (name, files, environment, further tasks), all with a packed table: a socket server,
# two tasks, an error raised in a routine with an error handler
MODELS = {
    "socket server": ([CHECK / "socket_field_count" / "prog.mod"], [], []),
    "two tasks": ([CHECK / "tasks_test_and_set" / "prog.mod"], [],
                  [str(CHECK / "tasks_test_and_set" / "other.mod")]),
    "run-time error": ([CHECK / "vm_error_handlers" / "prog.mod"], [], []),
    # free inputs raise an interrupt: no packed table
    "interrupts": ([ROOT / "tests" / "distributed" / "interrupt_counts.mod"], [], []),
}


def codec_expected(name: str, engine: str) -> type:
    """Packed vectors on the native engine where the model has a packed table, else the
    parts' node ids."""
    return VectorCodec if engine == "native" and name != "interrupts" else NodeCodec


def system_of(name: str, **overrides):
    return model_of(name, **overrides).system


def model_of(name: str, formulas=(), **overrides):
    """The prepared model of ``MODELS[name]``, with the check options ``overrides``."""
    files, env, tasks = MODELS[name]
    program = api.load_program([str(f) for f in files], [str(f) for f in env], add_tasks=tasks)
    options = replace(api.CheckOptions(), **overrides)
    options = replace(options, reductions=replace(options.reductions, partial_order=False))
    properties = [api.property_from_text(formula) for formula in formulas]
    return api.prepare(program, properties, options)


def breadth_first(system, limit: int) -> list:
    seen, frontier = [], list(system.initial_states())
    known = set(frontier)
    while frontier and len(seen) < limit:
        state = frontier.pop(0)
        seen.append(state)
        for after in system.successor_states(state):
            if after not in known:
                known.add(after)
                frontier.append(after)
    return seen


def packed(system):
    table = system.packed_table() if native.available() else None
    if table is None:
        pytest.skip("the native core is not built here: no packed table")
    return table


def test_every_table_names_the_same_owner_whatever_its_numbering():
    """Two tables that met the values in opposite orders give states different vectors,
    and still the same owner; the owners split the states between both partitions."""
    system = system_of("socket server")
    states = breadth_first(system, 400)
    first, second = packed(system), packed(system)
    codecs = [VectorCodec(first, 0, 2), VectorCodec(second, 1, 2)]
    for state in states:
        first.intern(state, True)
    for state in reversed(states):
        second.intern(state, True)
    prepared = [[codec.prepare(state) for state in states] for codec in codecs]
    assert any(a != b for a, b in zip(*prepared))              # numbered differently
    owners = [codec.owners(rows) for codec, rows in zip(codecs, prepared)]
    assert owners[0] == owners[1]
    assert 0.3 < sum(owners[0]) / len(states) < 0.7
    assert all(codec.owns(state, owner) for codec in codecs
               for state, owner in zip(states, owners[0]))


def test_vectors_sent_to_another_table_are_stored_as_the_same_states():
    """Batches in the sender's ids, values and contexts handed over as they appear: the
    receiver stores exactly the states sent, with their parents, once.  The share the
    sender keeps for itself travels as its table's keys and is stored by key."""
    system = system_of("two tasks")
    states = breadth_first(system, 300)
    sender_table, receiver_table = packed(system), packed(system)
    # three partitions: the sender is the third, the receiver stores the other two shares
    sender, receiver = VectorCodec(sender_table, 2, 3), VectorCodec(receiver_table, 1, 3)
    for state in states[100:]:              # the receiver numbered other states first
        receiver_table.intern(state, True)
    stored, kept = [], set()
    for batch in (states[:150], states[150:], states[:150]):       # the last: all known
        outboxes = [sender.outbox() for _ in range(3)]
        keys = [(lambda frame, data: frame << 32 | data)(*sender_table.intern_parts(
            *sender.prepare(state))) for state in batch]
        owners = sender.send(outboxes, keys, range(len(batch)))
        assert owners == sender.owners([sender.prepare(state) for state in batch])
        own = sender.encode(2, outboxes[2])
        ids, new, fields = sender.store(2, own)
        assert [sender_table[i] for i in ids.tolist()] == [batch[f] for f in fields.tolist()]
        assert len(own) == 8 + 16 * len(ids)    # (keys and parents only)
        kept.update(sender_table[i] for i in ids.tolist())
        before = len(receiver_table)
        for target in (0, 1):         # (each owner's share, written for the receiver)
            ids, new, fields = receiver.store(2, sender.encode(1, outboxes[target]))
            assert [receiver_table[i] for i in ids.tolist()] == \
                [batch[field] for field in fields.tolist()]
            again = Links(3)
            again.extend(2, receiver.store(2, sender.encode(1, outboxes[target])))
            assert not len(again)               # (stored already: nothing new again)
            made = Links(3)
            made.extend(2, (ids, new, fields))
            links = [made[i] for i in range(len(made))]
            assert links == [link(2, field) for field, fresh in zip(fields.tolist(), new)
                             if fresh]
            assert all(unlink(each)[0] == 2 for each in links)
            stored += [(receiver_table[state_id], batch[unlink(each)[1]]) for state_id, each
                       in zip(range(before, len(receiver_table)), links)]
            before = len(receiver_table)
    assert all(got == sent_state for got, sent_state in stored)
    received = {receiver_table[i] for i in range(len(receiver_table))}
    assert kept and received | kept == set(states)
    assert len(receiver_table) == len(received) == len(set(states[100:]) | (set(states) - kept))
    assert sender_table.context_count() >= 2    # several contexts went across


def test_node_codec_tables_name_the_same_owner_whatever_their_numbering():
    """Two collapsed tables that met the nodes in opposite orders give states different
    node ids, and still the same owner, both partitions owning some."""
    with native.engine_used("python"):
        system = system_of("interrupts")
        states = breadth_first(system, 400)
        tables = [native.state_table(system), native.state_table(type(system)(
            system.program, system.config))]        # (two models: two node tables)
        codecs = [NodeCodec(table, index, 2) for index, table in enumerate(tables)]
        for state in states:
            tables[0].intern(state, True)
        for state in reversed(states):
            tables[1].intern(state, True)
        parts = [[table.parts_of(state) for state in states] for table in tables]
        assert any(a != b for a, b in zip(*parts))                # numbered differently
        owners = [[int(codec.owns(state, 1)) for state in states] for codec in codecs]
    assert owners[0] == owners[1]
    assert 0.3 < sum(owners[0]) / len(states) < 0.7


@pytest.mark.parametrize("engine", ["native", "python"])
def test_node_ids_sent_to_another_table_are_stored_as_the_same_states(engine):
    """Batches in the sender's node ids, its new nodes handed over as they appear (also in
    a batch without states): the receiver stores exactly the states sent, once."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        # (its edges stored: served in their own step, the model has fewer than 300 states)
        system = system_of("interrupts", edge_inputs=False)
        states = breadth_first(system, 300)
        assert len(states) == 300
        other = type(system)(system.program, system.config)
        sender_table, receiver_table = native.state_table(system), native.state_table(other)
        sender, receiver = NodeCodec(sender_table, 0, 2), NodeCodec(receiver_table, 1, 2)
        for state in states[100:]:          # the receiver numbered other states first
            receiver_table.intern(state, True)
        for batch in (states[:150], None, states[150:], states[:150]):  # the last: all known
            outboxes = [sender.outbox(), sender.outbox()]
            if batch is None:       # nodes alone: those of states the receiver is sent next
                sender.successor_keys(0, None, states[150:])
                batch = []
            else:
                sender.send(outboxes, sender.successor_keys(0, None, batch), range(len(batch)))
            for target in (0, 1):           # (each owner's share, written for the receiver)
                ids, new, fields = receiver.store(0, sender.encode(1, outboxes[target]))
                assert [receiver_table[i] for i in ids.tolist()] == \
                    [batch[field] for field in fields.tolist()]
    assert {receiver_table[i] for i in range(len(receiver_table))} == set(states)
    assert len(receiver_table) == len(states)


@pytest.mark.parametrize("numpy_arrays", [True, False])
def test_parent_links_are_read_back_from_their_file_as_written(numpy_arrays, monkeypatch):
    """A partition's parent links go to a file every ``WRITE_EVERY`` links: each one is
    read back as ``link`` wrote it (initial: -1), from the file or from those still in
    memory, past 32 bits too; memory holds only those not written yet."""
    import numpy
    monkeypatch.setattr(Links, "WRITE_EVERY", 4)
    links = Links(3)
    links.initial()
    wanted = [-1]
    for sender, fields in ((2, [0, 5, 7]), (1, [(1 << 32) // 3 - 1]), (0, [1 << 33, 4]),
                           (2, [9, 10])):
        new = [True] * len(fields)
        new[-1] = len(fields) == 1          # (the last one: not new, unless alone)
        stored = (None, numpy.array(new), numpy.array(fields, numpy.int64)) if numpy_arrays \
            else (None, new, fields)
        links.extend(sender, stored)
        wanted += [link(sender, field) for field, fresh in zip(fields, new) if fresh]
        assert [links[i] for i in range(len(links))] == wanted
    assert len(links) == len(wanted) == 6 and links.file_bytes() == 8 * 4
    assert links.memory_bytes() == 8 * 2
    links.close()


@pytest.mark.parametrize("name", ["socket server", "two tasks", "run-time error"])
def test_a_round_expanded_in_the_compiled_core_is_every_successor_once(name):
    """``expand_keys`` (a worker's round over a packed table): each distinct successor of
    the states in id order once, with the first state that reached it, as stepping each
    state (``step``, else Python's ``python_successors``) gives them; the counts of
    transitions and deadlocks; the first state where the program failed stops the round."""
    system = system_of(name)
    table = packed(system)
    for state in breadth_first(system, 200):
        table.intern(state, True)
    first, last = 20, len(table)
    keys, parents, transitions, deadlocks, deadlocked, failed, watched = \
        table.expand_keys(first, last, True, None)
    failed_ids = [i for i in range(first, last) if table.failed_at(i)]
    end = failed_ids[0] if failed_ids else last
    assert failed == (failed_ids[0] if failed_ids else -1) and not watched
    expected, parent_ids, seen, steps = [], [], set(), 0
    for state_id in range(first, end):
        found = table.step(state_id)
        if found is None:
            found = table.python_successors(state_id)
        steps += len(found)
        for frame, data in found:
            if (frame, data) not in seen:
                seen.add((frame, data))
                expected.append(frame << 32 | data)
                parent_ids.append(state_id)
    assert array("Q", keys).tolist() == expected and array("q", parents).tolist() == parent_ids
    if failed < 0:
        assert transitions == steps
        assert deadlocked == next((i for i in range(first, end) if not table.step(i) and
                                   not table.python_successors(i)), -1)
    if name == "run-time error":
        assert failed >= 0          # (the model's error is within the first 200 states)


def test_a_sparing_table_keeps_new_data_segments_apart_until_a_state_needs_them():
    """``spare_data``: the data segments a step makes go to the spare table (ids with bit
    30), read as any other (``segments_batch``); storing a state by its key moves its data
    segment into the table (``intern_keys``); ``clear_spare`` forgets the rest, and the
    stored states still read the same."""
    if not native.available():
        pytest.skip("the native core is not built here")
    system = system_of("socket server")
    plain, sparing = packed(system), packed(system)
    for state in breadth_first(system, 50):
        plain.intern(state, True)
        sparing.intern(state, True)
    sparing.spare_data(True)
    data_before = sparing.counts()["data"]
    plain_keys, *_ = plain.expand_keys(0, 50, False, None)
    spare_keys, *_ = sparing.expand_keys(0, 50, False, None)
    plain_keys, spare_keys = array("Q", plain_keys), array("Q", spare_keys)
    spare = [key for key in spare_keys if key & (1 << 30)]
    assert spare and sparing.counts()["data"] == data_before
    assert sparing.segments_batch(spare_keys.tobytes()) == \
        plain.segments_batch(plain_keys.tobytes())
    kept = array("Q", spare[:3])
    ids, news = sparing.intern_keys(kept.tobytes())
    assert sparing.counts()["data"] == data_before + len({key & 0xFFFFFFFF for key in kept})
    stored = array("q", ids).tolist()
    states = [sparing[state_id] for state_id in stored]
    sparing.clear_spare()
    assert [sparing[state_id] for state_id in stored] == states
    assert all(state in set(breadth_first(system, 400)) for state in states)


@pytest.mark.parametrize("by_data", [False, True])
@pytest.mark.parametrize("name", ["socket server", "two tasks"])
def test_the_compiled_owner_of_a_key_is_the_owner_of_its_vectors(name, by_data):
    """``key_owners`` (the compiled core's ``owners``, which routes successors by key) names
    the owner ``_owners_of`` names from the same states' vectors (which decides the initial
    states', ``owns``), for three workers, by whole state and by data segment."""
    if not native.available():
        pytest.skip("the native core is not built here")
    np = pytest.importorskip("numpy")
    system = system_of(name)
    table = packed(system)
    for state in breadth_first(system, 300):
        table.intern(state, True)
    codec = VectorCodec(table, 0, 3, by_data)
    keys = np.frombuffer(table.expand_keys(0, len(table), False, None)[0], np.uint64)
    frames, data, lengths = (np.frombuffer(part, np.uint32)
                             for part in table.segments_batch(keys.tobytes()))
    by_vectors = codec._owners_of(frames, data, lengths)
    by_keys = codec.key_owners(keys)
    assert len(keys) > 100 and by_keys.tolist() == by_vectors.tolist()
    if not by_data or name == "socket server":     # (two tasks: two data segments)
        assert len(set(by_keys.tolist())) > 1


@pytest.mark.parametrize("name, by_data", [("socket server", True), ("two tasks", False)])
def test_a_data_segment_has_one_owner_where_the_model_has_enough_of_them(name, by_data):
    """Owners by data segment (``data_owners_fit``: enough distinct segments among the
    first states): the partitions hold the one process's data segments between them, each
    once, and count its states; a model of two data segments keeps owners by whole state."""
    if not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used("native"):          # (packed tables: also under RAPIDMC_ENGINE)
        system = system_of(name)
        assert data_owners_fit(system, packed(system), 2) is by_data
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, _ = search_here(system, 2)
    assert all(part.codec.by_data is by_data for part in parts)
    assert sum(len(part.table) for part in parts) == one.stats.product_states
    if by_data:
        whole = packed(system)
        for state in breadth_first(system, one.stats.product_states):
            whole.intern(state, True)
        assert sum(part.table.counts()["data"] for part in parts) == whole.counts()["data"]


def test_the_compiled_round_asks_the_watch_where_the_program_may_be_stuck():
    """``expand_keys``' watch: asked (with the state's id and its successors' parts) until
    it says True once, and its answer returned."""
    system = system_of("two tasks")
    table = packed(system)
    for state in breadth_first(system, 200):
        table.intern(state, True)
    asked = []

    def watch(state_id, frames, data):
        state, targets = table.stepped(state_id, frames, data)
        assert state == table[state_id] and len(targets) == len(frames)
        asked.append(state_id)
        return len(asked) == 2
    *_, watched = table.expand_keys(0, len(table), False, watch)
    assert watched and len(asked) == 2
    *_, watched = table.expand_keys(0, len(table), False, lambda *_: False)
    assert not watched


@pytest.mark.parametrize("engine", ["native", "python"])
@pytest.mark.parametrize("name", ["socket server", "two tasks", "interrupts"])
def test_partitions_count_what_one_process_counts(name, engine):
    """Every codec: the same states, transitions, deadlocks and depth as one process."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        system = system_of(name)
        one = find_reachable(system, system.failed, max_states=None)
        parts, levels, target = search_here(system, 2)
        codec = type(parts[0].codec)
        assert codec is codec_expected(name, engine)
        assert codec_for(parts[0].table, 0, 2).__class__ is codec
    assert one.verdict == HOLDS and target is None
    assert sum(len(part.table) for part in parts) == one.stats.product_states
    assert sum(part.transitions for part in parts) == one.stats.transitions
    assert sum(part.deadlocks for part in parts) == one.stats.deadlocks
    assert levels - 1 == one.stats.max_depth       # (the last level stores nothing)
    assert all(len(part.table) for part in parts)


@pytest.mark.parametrize("engine", ["native", "python"])
def test_partitions_find_the_error_at_its_depth(engine):
    """The first state the predicate marks is found in the level of its depth: its parent
    links, across partitions, are as long as one process's counterexample."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        system = system_of("run-time error")
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2)
    assert one.verdict == VIOLATED and target is not None
    path = _path_to(parts, target)
    assert len(path) == len(one.prefix)
    assert system.failed(path[0]) and path[-1] in system.initial_states()


def test_the_error_path_is_rebuilt_from_links_read_back_from_their_files(monkeypatch):
    """The parent links of a real search, written to their files every few links
    (``Links.WRITE_EVERY``), give the path one process finds."""
    monkeypatch.setattr(Links, "WRITE_EVERY", 3)
    system = system_of("run-time error")
    one = find_reachable(system, system.failed, max_states=None)
    parts, _, target = search_here(system, 2)
    assert all(part.parent.file_bytes() > 0 for part in parts)
    path = _path_to(parts, target)
    assert len(path) == len(one.prefix)
    assert system.failed(path[0]) and path[-1] in system.initial_states()
    assert all(after in system.successor_states(before)
               for after, before in zip(path, path[1:]))


def _path_to(parts, target) -> list:
    """The states from the target back to an initial state, by parent links."""
    partition, state_id = target
    path, states = [], sum(len(part.table) for part in parts)
    while True:
        state, parent = parts[partition].step_back(state_id)
        path.append(state)
        assert len(path) <= states, "the links go round in a cycle"
        if parent < 0:
            return path
        partition, state_id = unlink(parent)


@pytest.mark.parametrize("engine", ["native", "python"])
@pytest.mark.parametrize("name", ["socket server", "two tasks", "interrupts"])
def test_eager_partitions_count_what_one_process_counts(name, engine):
    """Eager rounds (``--eager``: each partition follows its own successors within a
    round) store and expand every state once: the same states, transitions and deadlocks
    as one process, in fewer rounds than its levels."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        system = system_of(name)
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2, eager=True)
        rounds = parts[0].levels.rounds
    assert one.verdict == HOLDS and target is None
    assert sum(len(part.table) for part in parts) == one.stats.product_states
    assert sum(part.transitions for part in parts) == one.stats.transitions
    assert sum(part.deadlocks for part in parts) == one.stats.deadlocks
    assert all(len(part.table) for part in parts)
    assert rounds < one.stats.max_depth


@pytest.mark.parametrize("eager", [False, True])
@pytest.mark.parametrize("name", ["socket server", "two tasks", "interrupts"])
def test_node_ids_owned_by_their_global_data_count_what_one_process_counts(name, eager):
    """Owners by the global data part (``NodeCodec``'s ``by_data``): the same states,
    transitions and deadlocks as one process, and each global data value is stored by one
    partition only (its states all live there)."""
    with native.engine_used("python"):          # (collapsed tables: node ids)
        system = system_of(name)
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2, eager=eager, by_data=True)
        assert all(type(part.codec) is NodeCodec and part.codec.by_data for part in parts)
        data = [{part.table[state_id][1] for state_id in range(len(part.table))}
                for part in parts]
    assert one.verdict == HOLDS and target is None
    assert sum(len(part.table) for part in parts) == one.stats.product_states
    assert sum(part.transitions for part in parts) == one.stats.transitions
    assert sum(part.deadlocks for part in parts) == one.stats.deadlocks
    assert all(data) and not data[0] & data[1]


@pytest.mark.parametrize("eager", [False, True])
def test_node_ids_owned_by_their_global_data_find_the_error_on_a_real_path(eager):
    """Owned by their global data, the partitions find the error too, on a path of the
    model's steps (as long as one process's where the search goes in levels)."""
    with native.engine_used("python"):
        system = system_of("run-time error")
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2, eager=eager, by_data=True)
        assert one.verdict == VIOLATED and target is not None
        path = _path_to(parts, target)[::-1]
        assert path[0] in system.initial_states() and system.failed(path[-1])
        for before, after in zip(path, path[1:]):
            assert after in [successor for _, successor in system.successors(before)]
    assert len(path) == len(one.prefix) if not eager else len(path) >= len(one.prefix)


@pytest.mark.parametrize("engine", ["native", "python"])
def test_eager_partitions_find_the_error_on_a_real_path(engine):
    """An eager search finds the error too; its path, across partitions, is a path of the
    model's steps from an initial state (it may be longer than one process's)."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        system = system_of("run-time error")
        one = find_reachable(system, system.failed, max_states=None)
        parts, _, target = search_here(system, 2, eager=True)
        assert one.verdict == VIOLATED and target is not None
        path = _path_to(parts, target)[::-1]
        assert path[0] in system.initial_states() and system.failed(path[-1])
        assert not any(system.failed(state) for state in path[:-1])
        for before, after in zip(path, path[1:]):
            assert after in [successor for _, successor in system.successors(before)]
    assert len(path) >= len(one.prefix)


# properties that hold, so that one process too searches the whole product
LTL = {"two tasks": 'exclusive: G "inside <= 1"', "socket server": 'sane: G "done >= -1"',
       "interrupts": 'counted: G "nParts < 3"'}


@pytest.mark.parametrize("engine", ["native", "python"])
@pytest.mark.parametrize("name", ["socket server", "two tasks", "interrupts"])
def test_ltl_partitions_count_what_one_process_counts(name, engine):
    """The LTL workers' product search travels by the same codecs (vectors for a packed
    model, else node ids: no pickles) and stores the same product states and transitions as one process;
    while it runs its objects are out of the cycle collector's reach, and handed back."""
    if engine == "native" and not native.available():
        pytest.skip("the native core is not built here")
    with native.engine_used(engine):
        model = model_of(name, [LTL[name]])
        prop, buchi, valuation = model.jobs[0]
        one = check_property(model.system, buchi, valuation, max_states=None)
        frozen = []
        parts = product_here(model, prop.name, 2, on_level=lambda: frozen.append(
            gc.get_freeze_count()))
    assert {type(part.codec) for part in parts} == {codec_expected(name, engine)}
    assert one.verdict == HOLDS
    assert sum(len(part.keys) for part in parts) == one.stats.product_states
    assert sum(len(part.edges) for part in parts) == one.stats.transitions
    assert all(len(part.keys) for part in parts)
    assert frozen and min(frozen) > 0 and gc.get_freeze_count() == 0


def test_partition_reads_its_memory():
    """A partition's figures carry its peak memory, read from /proc (Linux), and the CPU
    its calls spent: the thread that stepped them at most the whole process's."""
    if not Path("/proc/self/status").exists():
        pytest.skip("no /proc here")
    parts, _, _ = search_here(system_of("two tasks"), 2)
    for part in parts:
        figures = part.figures()
        assert figures["peak_private_kb"] > 1024, figures
        assert 0 < figures["step_thread"] <= figures["step_seconds"] + 0.01, figures
