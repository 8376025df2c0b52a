"""How a worker writes the states it sends to their owners, and reads the states it is sent.

Two codecs, one per kind of state table, with one interface (``Partition`` uses it):

* ``VectorCodec``, for a model's packed table (``model.packed``, the whole-controller models
  and the counters): a state travels as the table's own encoding, its frame and data
  vectors of value ids, written by the table itself (``vectors_of``).  Those ids are the
  sender's: each batch carries the values and contexts the sender numbered since its last
  batch to that owner (ids only grow), and the owner keeps, per sender, an array that
  maps the sender's ids to its own.  So a state costs its vectors' bytes on the wire (4
  bytes a value), a whole batch is translated with a few array operations, and the owner
  stores a state with one call into the table (``intern_vectors``): no Python object is
  pickled or built per state, and a state the owner already has is never rebuilt.  The
  share a worker keeps for itself is its table's keys (its step interned their segments
  already), stored by key (``intern_keys``).
  The owner of a state is a hash of its vectors in which every id stands for a
  fingerprint of its value (BLAKE2b of ``canonical.canonical_bytes``), the same in every
  process: equal values, equal fingerprints; so every worker agrees on the owner.
* ``NodeCodec``, for a collapsed table (``check.states``, both engines: a RAPID model
  without a packed table, as one with free inputs or an environment reaction, and every
  RAPID model on the Python engine): a state travels as the node ids of its split parts
  (``parts_of``: each part a tree of nodes interned once, ``check.nodes``), 4 bytes a
  part.  As above, the ids are the sender's: each batch carries the nodes the sender
  numbered since its last batch to that owner, a container as its kind and its children's
  ids, a leaf as its value (children are numbered before their parents, so the owner
  rebuilds and interns them in order), and the owner maps the sender's ids to its own.
  The owner of a state is a hash of its parts' fingerprints; a node's fingerprint is
  computed once, from its children's (a leaf's: BLAKE2b of its canonical bytes), so equal
  trees have equal fingerprints in every process.  A received batch is stored by one call
  into the table (``intern_rows``): no state is pickled, rebuilt or split again.
* ``PickleCodec``, for every other table (models that do not split their states):
  states travel pickled, owned by ``canonical.owner``.

Interface: ``successor_keys(id, state, successors)`` (a key per successor, in the model's
order, from the successor states or from ``successors(state)``; equal keys: equal states,
for the level's deduplication), ``outbox()`` (a batch being written), ``send(outboxes, keys,
fields)`` (a chunk of keys routed to their owners' outboxes, each with a number, its
parent's id; returns each key's owner), ``encode(target, outbox)``, ``store(sender, data)``
(stores the batch's states: their ids, whether each was new and their fields, in order),
``owns(state, index)``.
"""
from __future__ import annotations

import hashlib
import pickle
import struct
from array import array
from itertools import chain, compress
from typing import Hashable, Sequence

from pyrsistent import pvector

from ..nodes import PVECTOR, has_children
from .canonical import canonical_bytes

PROTOCOL = pickle.HIGHEST_PROTOCOL
ID_BITS = 40                       # a link: sender partition << ID_BITS | the parent's id
ID_MASK = (1 << ID_BITS) - 1
_SIZES = struct.Struct("<QQQQ")    # a vector batch's header, frames, data sizes; states
_OWN = struct.Struct("<Q")         # a vector batch a worker keeps for itself: its states
SLICE = 1 << 16                    # states of a received batch translated at a time


def link(partition: int, state_id: int) -> int:
    return partition << ID_BITS | state_id


def unlink(parent: int) -> tuple[int, int]:
    return parent >> ID_BITS, parent & ID_MASK


def codec_for(table, index: int, count: int, by_data: bool = False):
    """The codec for a worker's table: vectors where the table offers them, node ids where
    it collapses states into parts (both need numpy, which Ray brings), else pickles.
    ``by_data``: states owned by their data segment (vectors, ``data_owners_fit``) or their
    global data part (node ids)."""
    try:
        import numpy  # noqa: F401
    except ImportError:
        return PickleCodec(table, count)
    if getattr(table, "vectors_of", None) is not None:
        return VectorCodec(table, index, count, by_data)
    if getattr(table, "collapsed", False):
        return NodeCodec(table, index, count, by_data)
    return PickleCodec(table, count)


SAMPLE_STATES = 1000       # states ``data_owners_fit`` looks at (at least)
SEGMENTS_PER_WORKER = 16   # distinct data segments among them it asks for, per worker,
SEGMENTS_PER_STATE = 0.25  # and per state looked at


def data_owners_fit(system, table, count: int) -> bool:
    """Whether the states of a packed model (``table``: a packed table of ``system``) may be
    owned by their data segment alone (``VectorCodec``): a worker then stores only its own
    share of the data segments, and a step that changes no global data stays with its
    worker, but the balance rests on the number of data segments and their sizes.  So this
    looks at the first ``SAMPLE_STATES`` (or ``32 * count``) states in breadth-first order
    and asks for ``SEGMENTS_PER_WORKER * count`` distinct data segments among them and one
    for every four states (most steps change global data: the segments are then many and
    small); else the owner is a hash of the whole state.  (Among their first 1,000
    states, the counters have 392 data segments; bench/tasks.py's socket server 189 (1,093
    in all, which split 44/56 between two workers), two tasks 102, the ROS server 17 (283
    in all: 43/57 to 57/43 by the hash's seed).)  The check's process decides, once, and
    tells every worker."""
    vectors_of = getattr(table, "vectors_of", None)
    if vectors_of is None or count < 2:
        return False
    limit, wanted = max(SAMPLE_STATES, 32 * count), SEGMENTS_PER_WORKER * count
    frontier = list(system.initial_states())
    seen, segments = set(frontier), set()
    expanded = 0
    while expanded < min(len(frontier), limit):     # (the frontier grows meanwhile)
        state = frontier[expanded]
        expanded += 1
        segments.add(vectors_of(state)[1])
        for after in system.successor_states(state):
            if after not in seen:
                seen.add(after)
                frontier.append(after)
    return len(segments) >= max(wanted, SEGMENTS_PER_STATE * expanded)


# odd 64-bit constants of the owner hash (any fixed ones do; these are splitmix64's)
_GOLDEN = 0x9E3779B97F4A7C15
_MIX1, _MIX2 = 0xBF58476D1CE4E5B9, 0x94D049BB133111EB
_MASK64 = (1 << 64) - 1


def fingerprint(value) -> int:
    """A 64-bit fingerprint of a value, the same in every process (canonical bytes)."""
    return int.from_bytes(hashlib.blake2b(canonical_bytes(value), digest_size=8).digest(),
                          "little")


class _Keyed:
    """A successor with its parts' fingerprints (``PartPrints``): hashed by them, equal to
    another successor exactly when the states are equal (the fingerprints only sort out
    the unequal ones cheaply)."""
    __slots__ = ("prints", "state")

    def __init__(self, prints: tuple, state):
        self.prints, self.state = prints, state

    def __eq__(self, other) -> bool:
        return self.prints == other.prints and self.state == other.state

    def __hash__(self) -> int:
        return hash(self.prints)


class PartPrints:
    """The fingerprint (``fingerprint``: of its canonical bytes, the same in every process) of
    each part of a tuple-shaped state, remembered by the part's identity and then by its
    value: a successor hands on most parts of its state unchanged, as the same objects,
    found without hashing them (a 512-element array too); a part a step wrote is often
    equal to one met before (found by value), and only a new value is encoded.  The
    remembered parts are kept alive, so an identity is never another object's; each memory
    is emptied when it grows past ``limit``."""

    def __init__(self, limit: int = 1 << 16):
        self.by_identity: dict = {}     # id(part) -> (part, fingerprint)
        self.by_value: dict = {}        # part -> fingerprint
        self.limit = limit

    def __call__(self, state) -> tuple:
        if not isinstance(state, tuple):
            return (fingerprint(state),)
        by_identity = self.by_identity
        prints = []
        for part in state:
            entry = by_identity.get(id(part))
            if entry is None or entry[0] is not part:
                if len(by_identity) >= self.limit:
                    by_identity.clear()
                entry = by_identity[id(part)] = (part, self._by_value(part))
            prints.append(entry[1])
        return tuple(prints)

    def _by_value(self, part) -> int:
        try:
            found = self.by_value.get(part)
        except TypeError:                   # (an unhashable part: encoded each time)
            return fingerprint(part)
        if found is None:
            if len(self.by_value) >= self.limit:
                self.by_value.clear()
            found = self.by_value[part] = fingerprint(part)
        return found


def _finish(mixed: int) -> int:
    """splitmix64's finaliser on a 64-bit number (every bit reaches every other)."""
    mixed ^= mixed >> 30
    mixed = mixed * _MIX1 & _MASK64
    mixed ^= mixed >> 27
    mixed = mixed * _MIX2 & _MASK64
    return mixed ^ mixed >> 31


def owner_of_prints(prints: tuple, count: int) -> int:
    """The partition of a state by its parts' fingerprints, position by position."""
    return _finish(_positioned(prints)) % count


def _positioned(prints) -> int:
    """The fingerprints summed, each weighted by its position (so order counts)."""
    mixed = 0
    for position, value in enumerate(prints):
        mixed = (mixed + value * (2 * position + 1) * _MIX1) & _MASK64
    return mixed


class PickleCodec:
    """States pickled by the standard C pickler, owned by ``owner_of_prints``."""

    def __init__(self, table, count: int):
        self.table, self.count = table, count
        self.prints = PartPrints()

    def successor_keys(self, state_id: int, state, successors) -> list:
        """Keys: (the parts' fingerprints, the state)."""
        if callable(successors):
            successors = successors(state)
        prints = self.prints
        return [_Keyed(prints(successor), successor) for successor in successors]

    def new_round(self) -> None:
        """(Nothing to let go between rounds.)"""

    def outbox(self) -> tuple[list, array]:
        return [], array("q")

    def send(self, outboxes, keys: Sequence["_Keyed"], fields: Sequence[int]) -> list[int]:
        count = self.count
        owners = []
        for key, field in zip(keys, fields):
            target = owner_of_prints(key.prints, count)
            outboxes[target][0].append(key.state)
            outboxes[target][1].append(field)
            owners.append(target)
        return owners

    def encode(self, target: int, outbox) -> bytes:
        return pickle.dumps(outbox, protocol=PROTOCOL)

    def store(self, sender: int, data: bytes) -> tuple[list, list, array]:
        states, fields = pickle.loads(data)
        intern = self.table.intern
        stored = [intern(state, True) for state in states]
        return array("q", [i for i, _ in stored]), [new for _, new in stored], fields

    def owns(self, state: Hashable, index: int) -> bool:
        return owner_of_prints(self.prints(state), self.count) == index


class VectorCodec:
    """States as a packed table's vectors (module docstring)."""

    lazy_states = True          # ``successor_keys`` takes a state id without its state

    def __init__(self, table, index: int, count: int, by_data: bool = False):
        import numpy
        self.np = numpy
        self.table, self.index, self.count = table, index, count
        self.data_length = table.store_length
        self.by_data = by_data and self.data_length > 0
        self.value_print = numpy.zeros(0, numpy.uint64)      # by value id: fingerprint
        self.context_print = numpy.zeros(0, numpy.uint64)    # by context id: fingerprint
        self.sent_values = [0] * count       # per owner: values handed over (ids below it)
        self.sent_contexts = [0] * count
        self.value_map: dict = {}            # per sender: its value id -> this table's
        self.context_map: dict = {}
        self._vectors = table.vectors_of
        self._intern_parts = table.intern_parts
        self._segments_batch, self._intern_batch = table.segments_batch, table.intern_batch
        self._machine = table.step                 # (None: the state is Python's to step)
        # owned by data segment (``_owners_of``), the data segments of successors this
        # worker's steps make go to a spare table, emptied each round (``new_round``), and
        # move into the table only for the successors it owns (``intern_keys``): a worker
        # then holds only its own share of the data segments, not all of them
        table.spare_data(self.by_data)

    # ---------------------------------------------------------------- sending
    # A successor's key is its interned segments, ``frame id << 32 | data id`` in this table
    # (equal states, equal segments): the step machine gives them without building the
    # state (``step``), and a state Python stepped is written to its vectors once.
    def successor_keys(self, state_id: int, state, successors) -> list[int]:
        """(``state`` may be None: the table rebuilds it if Python must step it.)"""
        if callable(successors):
            found = self._machine(state_id)
            if found is not None:
                return [frame << 32 | data for frame, data in found]
            successors = successors(self.table[state_id] if state is None else state)
        vectors, intern = self._vectors, self._intern_parts
        keys = []
        for successor in successors:
            frame, data = intern(*vectors(successor))
            keys.append(frame << 32 | data)
        return keys

    def prepare(self, state: Hashable) -> tuple[bytes, bytes]:
        """The state's vectors (for ``owners``)."""
        return self._vectors(state)

    def send(self, outboxes, keys: Sequence[int], fields: Sequence[int]) -> list[int]:
        """The chunk's successors, written to their owners' outboxes with their ``fields``
        (a parent's id): their segments read out of the table together
        (``segments_batch``), their owners computed together, and each owner's share
        written again in one call.  Returns each successor's owner."""
        np = self.np
        return self._route(outboxes, np.array(keys, np.uint64),
                           np.array(fields, np.int64)).tolist()

    def send_expanded(self, outboxes, keys: bytes, parents: bytes,
                      chunk: int = 4096) -> list[int]:
        """``send`` of what the table's ``expand_keys`` gave (keys and parents as bytes of
        uint64 and int64), ``chunk`` successors at a time (the arrays a chunk's owners are
        computed with are several times its vectors' size); returns how many went to each
        owner."""
        np = self.np
        keys, parents = np.frombuffer(keys, np.uint64), np.frombuffer(parents, np.int64)
        sent = np.zeros(self.count, np.int64)
        for first in range(0, len(keys), chunk):
            owners = self._route(outboxes, keys[first:first + chunk],
                                 parents[first:first + chunk])
            sent += np.bincount(owners.astype(np.int64), minlength=self.count)
        return sent.tolist()

    def _route(self, outboxes, keys, parents):
        """``send``'s work on arrays: the owner of each key (``key_owners``); the segments of
        the keys other workers own read out of the table for them."""
        np = self.np
        owners = self.key_owners(keys)
        for target in range(self.count):
            mine = owners == target
            number = int(np.count_nonzero(mine))
            if not number:
                continue
            some = (keys, parents) if number == len(keys) else (keys[mine], parents[mine])
            if target == self.index:          # (this table's own keys: ``encode``)
                outboxes[target].append((some[0].tobytes(), some[1].tobytes()))
            else:
                outboxes[target].append((*self._segments_batch(some[0].tobytes()),
                                         some[1].tobytes()))
        return owners

    def key_owners(self, keys):
        """The owners of states given by their keys in this table (a uint64 array): what
        ``_owners_of`` says of their vectors, in one call into the compiled core
        (``owners``)."""
        self._fingerprint_new()
        owners = self.table.owners(keys.tobytes(), self.value_print, self.context_print,
                                   self.count, self.by_data)
        return self.np.frombuffer(owners, self.np.uint32)

    def owners(self, items: Sequence[tuple[bytes, bytes]]) -> list[int]:
        """The owner of each state given by its vectors (``prepare``)."""
        np = self.np
        frames = np.frombuffer(b"".join(frame for frame, _ in items), np.uint32)
        lengths = np.fromiter((len(frame) >> 2 for frame, _ in items), np.uint32, len(items))
        data = np.frombuffer(b"".join(data for _, data in items), np.uint32)
        return self._owners_of(frames, data, lengths).tolist()

    def _owners_of(self, frames, data, lengths):
        """The owners of states (their frame vectors end to end, their data vectors end to
        end, the frames' lengths): a hash over the fingerprints of each one's context,
        program counter and values, position by position; ``by_data``: of the values of its
        data segment alone, so that all states of a data segment have one owner, which
        alone stores that segment, and a step that changes no global data (a jump, a test,
        a wait) leads to a state of the same worker."""
        np = self.np
        self._fingerprint_new()
        data_mixed = self._data_mixed(data, len(lengths)) if self.data_length else None
        if self.by_data:
            return _finish_all(np, data_mixed) % np.uint64(self.count)
        lengths = lengths.astype(np.int64)
        starts = np.cumsum(lengths) - lengths
        with np.errstate(over="ignore"):
            prints = np.take(self.value_print, frames, mode="clip")
            prints[starts] = self.context_print[frames[starts]]
            prints[starts + 1] = frames[starts + 1].astype(np.uint64) * np.uint64(_GOLDEN)
            positions = np.arange(len(frames), dtype=np.uint64) - \
                np.repeat(starts, lengths).astype(np.uint64)
            mixed = np.add.reduceat(prints * (positions * np.uint64(2) + np.uint64(1))
                                    * np.uint64(_MIX1), starts)
            if data_mixed is not None:
                mixed ^= data_mixed
        return _finish_all(np, mixed) % np.uint64(self.count)

    def _data_mixed(self, data, count: int):
        """Per state, a hash of its data vector's fingerprints, position by position."""
        np = self.np
        return _rows_mixed(np, self.value_print[data].reshape(count, self.data_length), _MIX2)

    def _fingerprint_new(self) -> None:
        """Fingerprints of the values and contexts the table numbered since the last call."""
        np, table = self.np, self.table
        known = len(self.value_print)
        values = table.exported_values(known)
        if values:
            self.value_print = np.concatenate(
                (self.value_print, np.fromiter(map(fingerprint, values), np.uint64, len(values))))
        known = len(self.context_print)
        if table.context_count() > known:
            contexts = [context for context, _ in table.exported_contexts(known)]
            self.context_print = np.concatenate(
                (self.context_print, np.fromiter(map(fingerprint, contexts), np.uint64,
                                                 len(contexts))))

    def new_round(self) -> None:
        """Forget the spare data segments of the round before (``__init__``): its batches
        are written and its own successors stored."""
        if self.by_data:
            self.table.clear_spare()

    def outbox(self) -> list:
        """A batch being written: chunks of (frame vectors, data vectors, the frames'
        lengths in ids, the parents' ids), as ``send`` wrote them."""
        return []

    def encode(self, target: int, outbox) -> bytes:
        """A batch for ``target``: the values and contexts numbered since the last batch to
        it, then the outbox's chunks, each part joined.  The batch for this worker itself
        is its table's keys of the states and their parents: their segments are in the
        table already (the step interned them), so they are stored by key
        (``intern_keys``), not read out and hashed again."""
        table = self.table
        if target == self.index:
            keys = b"".join(chunk[0] for chunk in outbox)
            return b"".join([_OWN.pack(len(keys) >> 3), keys] + [chunk[1] for chunk in outbox])
        values = table.exported_values(self.sent_values[target])
        self.sent_values[target] += len(values)
        contexts = table.exported_contexts(self.sent_contexts[target])
        self.sent_contexts[target] += len(contexts)
        header = pickle.dumps((values, contexts), protocol=PROTOCOL)
        parts = [b"".join(chunk[part] for chunk in outbox) for part in range(4)]
        frames, data, lengths, parents = parts
        return b"".join((_SIZES.pack(len(header), len(frames), len(data), len(lengths) >> 2),
                         header, frames, data, lengths, parents))

    # -------------------------------------------------------------- receiving
    def store(self, sender: int, blob: bytes) -> tuple:
        """The batch's states stored (``intern_batch``), read in place (views of ``blob``)
        and translated a slice at a time, so a large batch is not copied whole: (their ids,
        whether each was new, their fields), arrays in the batch's order."""
        np, table = self.np, self.table
        if sender == self.index:                       # (its own keys: ``encode``)
            count, = _OWN.unpack_from(blob)
            keys, parents = _pieces(blob, _OWN.size, (8 * count, 8 * count))
            ids, news = table.intern_keys(keys)
            return (np.frombuffer(ids, np.int64), np.frombuffer(news, np.bool_),
                    np.frombuffer(parents, np.int64))
        header_size, frames_size, data_size, count = _SIZES.unpack_from(blob)
        header, frames, data, lengths, parents = _pieces(
            blob, _SIZES.size, (header_size, frames_size, data_size, 4 * count, 8 * count))
        values, contexts = pickle.loads(header)
        frames, data, lengths = (np.frombuffer(piece, np.uint32)
                                 for piece in (frames, data, lengths))
        parents = np.frombuffer(parents, np.int64)
        value_map, context_map = self._maps(sender, values, contexts)
        ends = np.cumsum(lengths, dtype=np.int64)
        width = self.data_length
        intern = self._intern_batch
        ids, news = [], []
        for first in range(0, count, SLICE):
            last = min(first + SLICE, count)
            begin = int(ends[first - 1]) if first else 0
            some_frames = frames[begin:int(ends[last - 1])]
            some_data = data[first * width:last * width]
            some_lengths = lengths[first:last]
            # its ids -> this table's ids
            starts = ends[first:last] - some_lengths - begin
            mapped = np.take(value_map, some_frames, mode="clip") if len(value_map) \
                else some_frames.copy()
            mapped[starts] = context_map[some_frames[starts]]
            mapped[starts + 1] = some_frames[starts + 1]
            some_frames = mapped
            some_data = value_map[some_data] if len(some_data) else some_data
            some_ids, some_new = intern(some_frames, some_data, some_lengths)
            ids.append(np.frombuffer(some_ids, np.int64))
            news.append(np.frombuffer(some_new, np.bool_))
        if not ids:
            return np.zeros(0, np.int64), np.zeros(0, np.bool_), parents
        return np.concatenate(ids), np.concatenate(news), parents

    def _maps(self, sender: int, values, contexts) -> tuple:
        """The arrays from ``sender``'s value and context ids to this table's, extended by
        the values and contexts it handed over with this batch."""
        np, table = self.np, self.table
        value_map = self.value_map.get(sender, np.zeros(0, np.uint32))
        if values:
            value_map = np.concatenate(
                (value_map, np.frombuffer(table.value_ids(values), np.uint32)))
        context_map = self.context_map.get(sender, np.zeros(0, np.uint32))
        if contexts:
            context_map = np.concatenate(
                (context_map, np.array([table.import_context(context, flags)
                                        for context, flags in contexts], np.uint32)))
        self.value_map[sender], self.context_map[sender] = value_map, context_map
        return value_map, context_map

    def owns(self, state: Hashable, index: int) -> bool:
        return self.owners([self.prepare(state)])[0] == index


def _pieces(blob: bytes, at: int, sizes) -> list:
    """The pieces of a batch of these ``sizes``, one after another from ``at``: views of
    ``blob``, not copies."""
    view, pieces = memoryview(blob), []
    for size in sizes:
        pieces.append(view[at:at + size])
        at += size
    return pieces


def _rows_mixed(np, prints, mix: int):
    """Per row of a 2-D uint64 array of fingerprints, their sum weighted by position."""
    weights = (np.arange(prints.shape[1], dtype=np.uint64) * np.uint64(2) + np.uint64(1)) * \
        np.uint64(mix)
    with np.errstate(over="ignore"):
        return (prints * weights).sum(axis=1, dtype=np.uint64)


def _finish_all(np, mixed):
    """``_finish`` of each number of a uint64 array (in place; the array)."""
    with np.errstate(over="ignore"):
        mixed ^= mixed >> np.uint64(30)
        mixed *= np.uint64(_MIX1)
        mixed ^= mixed >> np.uint64(27)
        mixed *= np.uint64(_MIX2)
        mixed ^= mixed >> np.uint64(31)
    return mixed


_PLAIN, _VECTOR = 0, 1     # a container node's kind in a batch: a tuple, a persistent vector
DATA_PART = 1              # a RAPID state's global data among its split parts (``states``)
_NODE_SIZES = struct.Struct("<QQQQ")   # a node batch's header, rows sizes; width; states


class NodeCodec:
    """States of a collapsed table as their parts' node ids (module docstring).

    ``by_data``: a state's owner is a hash of its global data part's fingerprint alone
    (``DATA_PART``), as ``VectorCodec``'s owners by data segment: a step that writes no
    global data (a jump, a test, a wait, a step of locals) leads to a state of the same
    worker, so fewer successors travel and an eager worker follows more of its paths
    itself; the balance rests on the number of distinct global data values.  Any owner
    that every process computes alike keeps the search exact: each state is still stored
    by exactly one worker."""

    def __init__(self, table, index: int, count: int, by_data: bool = False):
        import numpy
        self.np = numpy
        self.table, self.index, self.count = table, index, count
        self.by_data = by_data
        self.nodes = table.nodes
        self.parts_of = table.parts_of
        self.prints = numpy.zeros(0, numpy.uint64)     # by node id: fingerprint
        self.print_list: list = []            # the same as Python ints (``_fingerprint_new``)
        self.sent_nodes = [0] * count         # per owner: nodes handed over (ids below it)
        self.node_map: dict = {}              # per sender: its node id -> this table's (list)
        self.node_array: dict = {}            # ... the same as a numpy array
        # whether the batch for itself stays in this process (``Partition``'s rounds keep
        # it): then it is the keys themselves, not bytes (``encode``)
        self.own_keys = False

    # ---------------------------------------------------------------- sending
    def successor_keys(self, state_id: int, state, successors) -> list[tuple]:
        """Keys: the successors' parts' node ids (equal states, equal keys)."""
        if callable(successors):
            successors = successors(state)
        parts_of = self.parts_of
        return [parts_of(successor) for successor in successors]

    def new_round(self) -> None:
        """(Nothing to let go between rounds.)"""

    def outbox(self) -> list:
        """A batch being written: chunks of (the states' rows of node ids, their parents)."""
        return []

    def send(self, outboxes, keys: Sequence[tuple], fields: Sequence[int]) -> list[int]:
        """The chunk's successors, each owner's share written to its outbox with their
        ``fields``; returns each successor's owner."""
        np = self.np
        if not keys:
            return []
        width = len(keys[0])
        # (a flat pass over the keys' ids: a third faster than ``np.array`` of the tuples)
        rows = np.fromiter(chain.from_iterable(keys), np.uint32, len(keys) * width) \
            .reshape(len(keys), width)
        parents = np.array(fields, np.int64)
        owners = self._owners_of(rows)
        for target in range(self.count):
            mine = owners == target
            number = int(np.count_nonzero(mine))
            if not number:
                continue
            if target == self.index and self.own_keys:     # (the keys themselves)
                outboxes[target].append(
                    (keys, parents) if number == len(keys) else
                    (list(compress(keys, mine.tolist())), parents[mine]))
            elif number == len(keys):
                outboxes[target].append((rows, parents))
            else:
                outboxes[target].append((rows[mine], parents[mine]))
        return owners.tolist()

    def _owners_of(self, rows):
        """The owners of states given by rows of node ids: a hash of their parts'
        fingerprints, position by position."""
        np = self.np
        self._fingerprint_new()
        if self.by_data:               # (the global data's part alone: ``NodeCodec``)
            mixed = self.prints[rows[:, DATA_PART]]
            return _finish_all(np, mixed) % np.uint64(self.count)
        mixed = _rows_mixed(np, self.prints[rows], _MIX1)
        return _finish_all(np, mixed) % np.uint64(self.count)

    def _fingerprint_new(self) -> None:
        """The fingerprints of the nodes numbered since the last call: a leaf's, of its
        canonical bytes; a container's, of its children's by position (children come
        first), so equal trees have equal fingerprints whatever a process numbered them."""
        nodes, np = self.nodes, self.np
        known, total = len(self.prints), len(nodes)
        if total == known:
            return
        value, ids = nodes.value, nodes.ids
        prints = self.print_list
        for node_id in range(known, total):
            node = value(node_id)
            if has_children(node):
                children = ids(node)
                prints.append(_finish(_positioned([prints[child] for child in children]) ^
                                      len(children)))
            else:
                prints.append(fingerprint(node))
        self.prints = np.concatenate((self.prints, np.array(prints[known:], np.uint64)))

    def encode(self, target: int, outbox):
        """A batch for ``target``: the nodes numbered since the last batch to it, then the
        states' rows of node ids and their parents.  The batch a worker keeps for itself,
        where it never leaves the process (``own_keys``), is the keys as
        ``successor_keys`` made them (tuples of this table's node ids) and their parents,
        stored without a round trip through bytes (``store``)."""
        if target == self.index and self.own_keys:
            return (list(chain.from_iterable(keys for keys, _ in outbox)),
                    b"".join(parents.tobytes() for _, parents in outbox))
        kinds, payloads = [], []
        if target != self.index:
            total = len(self.nodes)
            kinds, payloads = self._export(self.sent_nodes[target], total)
            self.sent_nodes[target] = total
        header = pickle.dumps((kinds, payloads), protocol=PROTOCOL)
        width = outbox[0][0].shape[1] if outbox else 0
        rows = b"".join(chunk[0].tobytes() for chunk in outbox)
        parents = b"".join(chunk[1].tobytes() for chunk in outbox)
        return b"".join((_NODE_SIZES.pack(len(header), len(rows), width, len(parents) >> 3),
                         header, rows, parents))

    def _export(self, first: int, last: int) -> tuple[list, list]:
        """Nodes ``first`` .. ``last`` - 1: each one's kind (None for a leaf) and its
        children's ids (a leaf: its value)."""
        value, ids = self.nodes.value, self.nodes.ids
        kinds, payloads = [], []
        for node_id in range(first, last):
            node = value(node_id)
            if has_children(node):
                kind = type(node)
                kinds.append(_PLAIN if kind is tuple else _VECTOR if kind is PVECTOR else kind)
                payloads.append(ids(node))
            else:
                kinds.append(None)
                payloads.append(node)
        return kinds, payloads

    # -------------------------------------------------------------- receiving
    def store(self, sender: int, blob: bytes) -> tuple:
        """The batch's states stored (``intern_rows``): (their ids, whether each was new,
        their fields), arrays in the batch's order."""
        np = self.np
        if sender == self.index and self.own_keys:        # (its own keys: ``encode``)
            keys, parents = blob
            intern = self.table.intern_parts
            ids, news = array("q"), bytearray()
            for key in keys:
                state_id, new = intern(key)
                ids.append(state_id)
                news.append(new)
            return (np.frombuffer(ids, np.int64), np.frombuffer(bytes(news), np.bool_),
                    np.frombuffer(parents, np.int64))
        header_size, rows_size, width, count = _NODE_SIZES.unpack_from(blob)
        header, rows, parents = _pieces(blob, _NODE_SIZES.size,
                                        (header_size, rows_size, 8 * count))
        kinds, payloads = pickle.loads(header)
        rows = np.frombuffer(rows, np.uint32)
        parents = np.frombuffer(parents, np.int64)
        if sender != self.index:          # its ids -> this table's (its nodes, even alone)
            rows = self._import(sender, kinds, payloads)[rows]
        if not count:
            return np.zeros(0, np.int64), np.zeros(0, np.bool_), parents
        ids, news = self.table.intern_rows(rows.tobytes(), width)
        return np.frombuffer(ids, np.int64), np.frombuffer(news, np.bool_), parents

    def _import(self, sender: int, kinds: list, payloads: list):
        """The array from ``sender``'s node ids to this table's, extended by the nodes it
        handed over with this batch (each rebuilt from this table's canonical children, and
        interned)."""
        nodes = self.nodes
        node, values = nodes.node, nodes.values
        mapping = self.node_map.setdefault(sender, [])
        for kind, payload in zip(kinds, payloads):
            if kind is None:
                mapping.append(node(payload))
                continue
            children = values([mapping[child] for child in payload])
            if kind is _VECTOR:
                made = pvector(children)
            elif kind is _PLAIN:
                made = children
            else:
                made = tuple.__new__(kind, children)
            mapping.append(node(made))
        known = self.node_array.get(sender, self.np.zeros(0, self.np.uint32))
        if len(known) < len(mapping):
            known = self.node_array[sender] = self.np.concatenate(
                (known, self.np.array(mapping[len(known):], self.np.uint32)))
        return known

    def owns(self, state: Hashable, index: int) -> bool:
        return int(self._owners_of(self.np.array([self.parts_of(state)], self.np.uint32))[0]) \
            == index

