"""One worker of a partitioned search: the states it owns, their parents, its frontier.

A ``Partition`` is a plain class; ``search`` runs it as a Ray actor, one per worker, and
keeps the actors for the next search of the same Ray session (``start`` begins one).  Its
states are those whose canonical hash (``canonical.owner``) names it; it stores them in a
state table of the engine's (``native.state_table``: the model's packed table where it
offers one, else the compiled one where built), each
with the link to the state it was first reached from, which may live in another partition.

A link is one number (``codec.link``): ``sender << ID_BITS | id`` (the sender partition and
the parent's id there), -1 for an initial state; ``Links`` keeps them in a file.

The search runs in breadth-first levels, each in one or more rounds.  A round is one call
of ``step``: ``receive`` stores the states the other partitions sent in the round before
(and the batch this one kept for itself), and ``expand`` steps at most ``ROUND`` states of
the current level (asking the predicate of each first: the first one it marks ends the
search) and sorts their successors into one batch per owner.  A round that ``advance``s
begins the next level with the states stored since the last one began; the leader
(``rounds.Levels``, run by the first partition: ``lead``, ``rounds``) asks for it once every
partition has expanded its whole level, so a state is stored at its depth.
Rounds bound what a worker holds at once: the successors of ``ROUND`` states and their
batches, not a whole level's.  The worker's ``codec`` (``codec.py``) decides the owner of a
state and how states travel: as the packed table's vectors where the model has one (owned
by their data segment where ``codec.data_owners_fit``), else as node ids or pickled.

``eager`` searches (``--eager``) give up the levels to need fewer rounds: in a round a
worker stores its own successors at once and goes on expanding them (``_eager_round``), up
to ``ROUND`` states, and sends only what other partitions own, so a path costs a round
only where it passes to another partition: on 2 workers the whole-controller models
(owners by the whole state: one successor in two stays) need a third to a sixth of the
rounds of their levels, on 16 about four fifths (docs/distributed.md).  Every state is
still stored once and expanded once (the same states, transitions and deadlocks), and the
predicate asked of each before it is stepped; but a state may be stored deeper than its
breadth-first depth, with a longer path to it: a counterexample replays, but may be longer
than one process's, and the depth is not counted.  The leader drives an eager search's
calls (``flow``) without lock-step rounds: each call steps for a bounded CPU time and
answers with its batches, which the leader passes on at once (``flow.Flow``).
"""
from __future__ import annotations

import contextlib
import os
import pickle
import sys
import time
from array import array
from itertools import islice
from typing import Callable, Hashable, Optional, Sequence

from ..collector import freeze_survivors, frozen_while_searching
from ..native import PYTHON, engine_of, state_table
from .codec import codec_for, data_owners_fit, link, unlink  # noqa: F401  (search's links)

CHUNK = 4096            # successors whose owners are computed together (``codec.send``)
ROUND = 1 << 13         # states a worker expands in one round at most (module docstring)
EAGER_SLICE = 1 << 10   # ... of which an eager round expands at once (``_eager_round``)
FREEZE_EVERY = 0.1      # seconds between an eager round's freezes of the survivors
MEMORY_EVERY = 0.05     # seconds between two readings of the memory (``_note_memory``)
NO_PARENT = -1


def encode_batch(batch) -> bytes:
    """A batch of states as bytes, pickled here by the standard C pickler: Ray's own
    serializer (cloudpickle) calls back into Python for every object of every state, which
    cost a worker more CPU time than stepping the states."""
    return pickle.dumps(batch, protocol=pickle.HIGHEST_PROTOCOL)


def decode_batch(data: bytes):
    return pickle.loads(data)


class Links:
    """Each stored state's link to its parent (the sender partition and the parent's id
    there, ``link``), by state id, as one number ``1 + parent id * partitions + sender``
    (0: an initial state), kept in a file, not in memory.  A link is written once, when
    its state is stored, and read back only to rebuild a counterexample (``step_back``,
    a few reads a step), so a worker's memory holds just the last ``WRITE_EVERY`` links
    not yet written; the file (8 bytes a link, in the worker's temporary directory,
    ``tempfile``: removed when the search's links go) holds the rest.  In memory they
    cost 4 bytes a state, a fifth of a worker's compact table (``_packed.c``'s
    ``compact``): counters N=10 on 2 workers, 21 MB of each worker's peak (docs/distributed.md).
    (``link``'s own form, the sender in the high bits, would not fit in fewer bytes.)"""

    WRITE_EVERY = 1 << 16          # links gathered in memory before they go to the file

    def __init__(self, count: int):
        self.count = count
        self.items = array("Q")    # the links not written yet, from id ``written`` on
        self.written = 0
        self.file = None           # (made at the first write)

    def initial(self) -> None:
        self.items.append(0)
        self._write()

    def extend(self, sender: int, stored: tuple) -> None:
        """The links of the states a codec's ``store`` found new (``stored``: their ids,
        whether each was new, their fields: the parents' ids at ``sender``)."""
        _, new, fields = stored
        count, first = self.count, sender + 1
        if hasattr(fields, "dtype"):              # (numpy arrays: the codecs' own)
            numbers = fields[new].astype("uint64") * count + first
            self.items.frombytes(numbers.astype("uint64").tobytes())
        else:
            self.items.extend(field * count + first for field, fresh in zip(fields, new)
                              if fresh)
        self._write()

    def _write(self, always: bool = False) -> None:
        """The links gathered in memory appended to the file (``always``: however few)."""
        if len(self.items) < self.WRITE_EVERY and not (always and self.items):
            return
        if self.file is None:
            import tempfile
            self.file = tempfile.TemporaryFile(prefix="rapidmc-links-")
        self.file.seek(0, os.SEEK_END)
        self.file.write(self.items.tobytes())
        self.file.flush()
        self.written += len(self.items)
        self.items = array("Q")

    def __getitem__(self, state_id: int) -> int:
        if state_id >= self.written:
            number = self.items[state_id - self.written]
        else:
            number = int.from_bytes(os.pread(self.file.fileno(), 8, 8 * state_id),
                                    sys.byteorder)
        if not number:
            return NO_PARENT
        parent, sender = divmod(number - 1, self.count)
        return link(sender, parent)

    def __len__(self) -> int:
        return self.written + len(self.items)

    def memory_bytes(self) -> int:
        return len(self.items) * self.items.itemsize

    def file_bytes(self) -> int:
        return 8 * self.written

    def close(self) -> None:
        if self.file is not None:
            self.file.close()
            self.file = None


class SystemSource:
    """The model a worker searches: the system itself (pickled with it), or a ``recipe``
    that builds it in the worker's process (``built_once``)."""

    def __init__(self, system=None, recipe: Optional[Callable] = None):
        self.system, self.recipe = system, recipe

    def build(self):
        return self.system if self.recipe is None else built_once(self.recipe)


_BUILT: dict = {}       # a recipe's key -> what it built in this process
KEEP_BUILT = 4


def built_once(recipe: Callable):
    """``recipe()``, built once per process for equal recipes (equal pickled bytes): the
    searches of one check, safety and LTL, share the model their worker built."""
    import hashlib
    from ray import cloudpickle
    key = hashlib.blake2b(cloudpickle.dumps(recipe), digest_size=16).hexdigest()
    if key not in _BUILT:
        if len(_BUILT) >= KEEP_BUILT:
            _BUILT.clear()
        _BUILT[key] = recipe()
    return _BUILT[key]


class Partition:
    """The states of one partition (see the module docstring)."""

    def __init__(self):
        self.table = None
        self._frozen: Optional[contextlib.ExitStack] = None

    def start(self, index: int, count: int, source: "SystemSource", predicate: str,
              deadlock_is_target: bool, watch: Optional[str] = None,
              by_data: bool = False, eager: bool = False) -> None:
        """Begin a search (an actor serves the searches of one check one after another);
        ``by_data``: states are owned by their data segment (a packed model's,
        ``codec.data_owners_fit``) or their global data part (``codec.NodeCodec``); ``eager``: rounds without levels (module docstring)."""
        self.index, self.count, self.eager = index, count, eager
        system = source.build()
        self.system = system
        self.predicate = getattr(system, predicate)
        self.deadlock_is_target = deadlock_is_target
        # a method (state, successor states) -> bool to ask of every expanded state
        self.watch = getattr(system, watch) if watch is not None else None
        self.watched = False                   # whether it ever said True
        self.table = state_table(system, packed=True)
        compact = getattr(self.table, "compact", None)
        if compact is not None:               # (a packed table: ``_packed.c``'s ``compact``)
            compact()
        self.codec = codec_for(self.table, index, count, by_data)
        # the batch for itself stays here: the Python engine's table stores it from its keys
        # (``NodeCodec.encode``; the compiled tables take rows in one call)
        self.codec.own_keys = engine_of(self.table) == PYTHON
        self.parent = Links(count)
        self.expanded = 0                      # states before this id have been expanded
        self.trimmed = 0                       # ... when the C heap was last trimmed
        self.level_end = 0                     # the current level: ids below this one
        self.own = None                        # the batch the last round kept for this one
        self.transitions = 0
        self.deadlocks = 0
        self.sent = 0                          # successors sent to other partitions
        # what the search keeps is out of the cycle collector's reach, as in one process
        # (``collector``: else its collections walk the model's caches again and again,
        # which doubled a worker's CPU time on the two-task model)
        self.finish()
        self._frozen = contextlib.ExitStack()
        self._frozen.enter_context(frozen_while_searching())
        self.cpu_started = time.process_time()  # (figures: CPU seconds of this search)
        self.step_seconds = 0.0                # ... of which in ``step`` (the rest: Ray's)
        self.step_thread = 0.0                 # ... of that, the calling thread's own (the
        #                                        rest: Ray's threads meanwhile)
        self.step_wall = 0.0                   # wall seconds in ``step`` (the rest: waits)
        self.wall_started = self.frozen_at = time.monotonic()
        self.calls = 0                         # calls of ``step`` or ``flow`` served
        self.spans: list = []                  # ... each one's wall-clock start and end
        self.per_state = 0.0                   # CPU seconds an expanded state took, lately
        self.sent_bytes = 0                    # bytes of the batches to other partitions
        self.start_rss_kb = _peak_rss_kb()      # the process's peak before this search
        self.peak_private_kb = 0               # (``_note_memory``)
        self.peak_shared_kb = 0                # ... of the object store's pages mapped here
        self.memory_noted = 0.0

    def receive(self, senders: Sequence[int], *batches) -> int:
        """Store the new states of the batches (``senders[i]`` sent ``batches[i]``, written
        by the codec: states and their parents' ids there; sender -1: the initial states,
        sent to every partition, of which each keeps those it owns; an eager round's list
        of batches, one after another), and of the batch the last round kept here, in
        partition order.  Returns the states stored."""
        table, parent = self.table, self.parent
        arrived = list(zip(senders, batches))
        if self.own is not None:
            arrived.append((self.index, self.own))
            arrived.sort(key=lambda pair: pair[0])
            self.own = None
        for sender, batch in arrived:
            if sender < 0:
                for state in decode_batch(batch)[0]:
                    if self.count == 1 or self.codec.owns(state, self.index):
                        if table.intern(state, True)[1]:
                            parent.initial()
                continue
            for one in batch if isinstance(batch, list) else (batch,):
                parent.extend(sender, self.codec.store(sender, one))
        return len(table)

    def step(self, advance: bool, senders: Sequence[int], *batches) -> tuple:
        """One round (module docstring): ``receive``, then (``advance``) begin the next
        level, then ``expand``.  Returns a batch per partition (this one's own is kept here
        and an empty one returned in its place), then (states stored, the level's states
        when it began in this round else 0, the first state the predicate marks or -1,
        transitions, deadlocks, the first deadlocked state when those are targets or -1,
        whether ``watch`` said True, the level's states still to expand here).  Nothing is
        sent once a target was found."""
        return self._timed(self._step, advance, senders, batches)

    def flow(self, seconds: float, senders: Sequence[int], *batches) -> tuple:
        """A call of an eager search driven without lock-step (``flow.Flow``): ``receive``,
        then ``_eager_round`` for at most ``seconds`` of CPU.  Its figures are ``step``'s,
        then how many batches it wrote for each partition (none where it sent nothing)."""
        return self._timed(self._flow, seconds, senders, batches, freeze=False)

    def _flow(self, seconds: float, senders: Sequence[int], batches) -> tuple:
        self.receive(senders, *batches)
        return self._eager_round(0, seconds)

    def _timed(self, method, *args, freeze: bool = True) -> tuple:
        """``method(*args)``, its CPU and wall seconds counted; then the survivors frozen
        (``freeze``: after every call; else at most every ``FREEZE_EVERY`` seconds, as the
        leader's own slices of a ``flow`` are a few milliseconds each)."""
        started, began, at = time.process_time(), time.monotonic(), time.time()
        thread_started = time.thread_time()
        self.calls += 1
        try:
            return method(*args)
        finally:
            self.spans.append((at, time.time()))
            if freeze or began > self.frozen_at + FREEZE_EVERY:
                freeze_survivors()
                self.frozen_at = time.monotonic()
            if self.expanded - self.trimmed >= ROUND:
                self.trimmed = self.expanded
                _heap_trimmed()
            self.step_seconds += time.process_time() - started
            self.step_thread += time.thread_time() - thread_started
            self.step_wall += time.monotonic() - began
            self._note_memory()

    def _note_memory(self, always: bool = False) -> None:
        """The largest memory of this process not shared with Ray's object store, and the
        largest share of the store's pages it mapped (which the one-process search has
        none of: ``cluster.LOCAL_SYSTEM_CONFIG`` keeps a local cluster's batches out of
        the store), after a round at most every ``MEMORY_EVERY`` seconds and at the end
        (Linux: /proc).  (Reading /proc after every round cost a narrow level's round a
        tenth of a millisecond.)"""
        now = time.monotonic()
        if not always and now - self.memory_noted < MEMORY_EVERY:
            return
        self.memory_noted = now
        try:
            with open("/proc/self/status", "rb") as status:
                text = status.read()
            private = _status_kb(text, b"RssAnon:") + _status_kb(text, b"RssFile:")
            shared = _status_kb(text, b"RssShmem:")
        except (OSError, ValueError):
            return
        self.peak_private_kb = max(self.peak_private_kb, private)
        self.peak_shared_kb = max(self.peak_shared_kb, shared)

    def _step(self, advance: bool, senders: Sequence[int], batches) -> tuple:
        stored = self.receive(senders, *batches)
        new = 0
        if advance:
            new = stored - self.level_end
            self.level_end = stored
        if self.eager:
            return self._eager_round(new)
        *outgoing, figures = self.expand()
        self.own = outgoing[self.index]
        outgoing[self.index] = b""
        return (*outgoing, (stored, new, *figures, self.level_end - self.expanded))

    def _eager_round(self, new: int, seconds: Optional[float] = None) -> tuple:
        """``_step``'s round of an ``eager`` search: the states stored and not yet expanded,
        ``EAGER_SLICE`` at a time, each slice's own successors stored at once (so the next
        slice expands them), until none is left or the round expanded ``ROUND`` states or
        (``seconds``) spent that much CPU, its slices then sized to about that by the CPU a
        state took lately (what survives out of the cycle collector's reach
        every ``FREEZE_EVERY`` seconds: a round of the interrupts model, stepped in Python,
        cost a third more without); for each other partition the list of the slices'
        batches (of those that sent it states).  The same figures as ``_step``'s, the
        level being every state stored, then the number of batches for each partition and
        the CPU seconds a state took lately."""
        table, index, last = self.table, self.index, self.expanded + ROUND
        sending: list = [[] for _ in range(self.count)]
        frozen = time.monotonic()
        began = time.thread_time()
        while True:
            size = EAGER_SLICE
            if seconds is not None and self.per_state > 0:
                size = max(16, min(EAGER_SLICE, int(seconds / self.per_state)))
            first, sliced = self.expanded, time.thread_time()
            self.level_end = min(len(table), last, self.expanded + size)
            *outgoing, figures = self.expand()
            if self.expanded > first:
                self.per_state = (time.thread_time() - sliced) / (self.expanded - first)
            for target, batch in enumerate(outgoing):
                if target != index and batch is not None:
                    sending[target].append(batch)
            if figures[0] >= 0 or figures[3] >= 0:            # (the search ends here)
                break
            self.own = outgoing[index]
            self.receive(())
            if self.expanded == len(table) or self.expanded >= last or \
                    (seconds is not None and time.thread_time() - began > seconds):
                break
            if time.monotonic() > frozen + FREEZE_EVERY:   # (as one process's search does)
                freeze_survivors()
                frozen = time.monotonic()
        self.level_end = len(table)
        sending[index] = b""
        return (*sending, (len(table), new, *figures, self.level_end - self.expanded,
                           [len(batches) for batches in sending], self.per_state))

    def _nothing(self) -> list:
        return [self.codec.encode(target, self.codec.outbox()) for target in range(self.count)]

    def expand(self) -> tuple:
        """Step the next ``ROUND`` states of the level: one batch per partition, then the
        round's figures (the first of those states the predicate marks or -1; transitions,
        deadlocks, the first deadlocked state when those are targets or -1, and whether
        ``watch`` said True).  Once the predicate marks a state the level is dropped (the
        search ends there, with the figures of the levels before)."""
        table, count, index, codec = self.table, self.count, self.index, self.codec
        codec.new_round()
        successors_of = getattr(self.system, "successor_states", None)
        if successors_of is None:
            successors_of = self._targets
        watch = self.watch
        keys_of = codec.successor_keys
        predicate = self.predicate
        # a packed table answers the run-time error predicate from a state's context, and
        # its step machine steps most states from their ids: a state is rebuilt as a
        # Python object only where something needs it
        failed_at = getattr(table, "failed_at", None) \
            if predicate == getattr(self.system, "failed", None) else None
        lazy = failed_at is not None and watch is None and getattr(codec, "lazy_states", False)
        outboxes = [codec.outbox() for _ in range(count)]
        end = min(self.level_end, self.expanded + ROUND)
        if failed_at is not None and getattr(table, "expand_keys", None) is not None:
            return self._expand_keys(end, outboxes)
        send = codec.send
        # a successor reached again in this level is sent once (its first parent, as its
        # owner would keep): storing a state costs its owner more than encoding it here.
        # ``firsts`` keeps each successor's first parent in the order they were reached;
        # the successors from ``flushed`` on are not routed yet
        firsts: dict = {}
        flushed = 0
        sent = [0] * count
        transitions = deadlocks = 0
        deadlock_target = -1
        watched = self.watched

        def flush(flushed: int) -> int:
            pending = list(islice(firsts.items(), flushed, None))
            owners = send(outboxes, [key for key, _ in pending],
                          [parent for _, parent in pending])
            for target in range(count):
                sent[target] += owners.count(target)
            return len(firsts)

        for state_id in range(self.expanded, end):
            state = None if lazy else table[state_id]
            if failed_at(state_id) if lazy else predicate(state):
                self.expanded = self.level_end
                return [*self._nothing(), (state_id, self.transitions, self.deadlocks, -1,
                                           self.watched)]
            if watch is None:
                keys = keys_of(state_id, state, successors_of)
            else:                              # (it wants the successor states)
                successors = successors_of(state)
                if not watched and watch(state, successors):
                    watched = True
                keys = keys_of(state_id, state, successors)
            transitions += len(keys)
            if not keys:
                deadlocks += 1
                if self.deadlock_is_target and deadlock_target < 0:
                    deadlock_target = state_id
            for key in keys:
                if key not in firsts:
                    firsts[key] = state_id
            if len(firsts) - flushed >= CHUNK:
                flushed = flush(flushed)
        if len(firsts) > flushed:
            flush(flushed)
        self.watched = watched
        return self._expanded(end, outboxes, sent, transitions, deadlocks, deadlock_target)

    def _expand_keys(self, end: int, outboxes: list) -> tuple:
        """``expand`` of a packed table whose predicate is its run-time error: the round's
        steps, the predicate, the watch (asked only where the program may be stuck, as one
        process's loop asks it) and the level's deduplication in one call into the compiled
        core (``expand_keys``), its successors routed in one call of the codec: no Python
        call per state but for the states Python steps."""
        table, watch = self.table, self.watch
        asked = None
        if watch is not None and not self.watched:
            def asked(state_id: int, frames: list, data: list) -> bool:
                return watch(*table.stepped(state_id, frames, data))
        keys, parents, transitions, deadlocks, deadlocked, failed, watched = \
            table.expand_keys(self.expanded, end, True, asked)
        self.watched = self.watched or watched
        if failed >= 0:
            self.expanded = self.level_end
            return [*self._nothing(), (failed, self.transitions, self.deadlocks, -1,
                                       self.watched)]
        sent = self.codec.send_expanded(outboxes, keys, parents, CHUNK)
        target = deadlocked if self.deadlock_is_target else -1
        return self._expanded(end, outboxes, sent, transitions, deadlocks, target)

    def _expanded(self, end: int, outboxes: list, sent: list, transitions: int,
                  deadlocks: int, deadlock_target: int) -> tuple:
        """The round's batches and figures, once its states up to ``end`` are stepped."""
        codec, index = self.codec, self.index
        self.expanded = end
        self.transitions += transitions
        self.deadlocks += deadlocks
        self.sent += sum(sent) - sent[index]
        # (an eager search sends no batch without states: the codecs hand what a batch
        # would have carried over with the next one)
        outgoing = [None if self.eager and target != index and not sent[target] else
                    codec.encode(target, outboxes[target]) for target in range(self.count)]
        self.sent_bytes += sum(len(batch) for target, batch in enumerate(outgoing)
                               if target != index and batch is not None)
        return [*outgoing,
                (-1, self.transitions, self.deadlocks, deadlock_target, self.watched)]

    def _targets(self, state) -> list:
        return [successor for _, successor in self.system.successors(state)]

    def lead(self, peers: Sequence, initial: bytes, max_states, per_level: bool) -> None:
        """Drive the search's rounds from here (``rounds`` module docstring): this is the
        first partition, ``peers`` the others (actors, or ``_Here`` in one process)."""
        from .flow import Flow, local_ready, ray_ready
        from .rounds import Levels, local_values, ray_values
        here = {0} | {index for index, peer in enumerate(peers, 1) if isinstance(peer, _Here)}
        alone = len(here) == self.count
        get = local_values if alone else ray_values
        parts = [_Here(self), *peers]
        if self.eager:
            self.levels = Flow(parts, here, get, local_ready if alone else ray_ready,
                               max_states, per_level)
        else:
            self.levels = Levels(parts, here, get, max_states, per_level)
        self.levels.begin(initial)

    def rounds(self, seconds: float) -> dict:
        """The leader's rounds for about ``seconds`` (``rounds.Levels.run``)."""
        return self.levels.run(seconds)

    def settle(self) -> None:
        """The leader's calls still in flight ended (before the figures are read)."""
        levels = getattr(self, "levels", None)
        if levels is not None and hasattr(levels, "drain"):
            levels.drain()

    def step_back(self, state_id: int) -> tuple[Hashable, int]:
        """The state with this id and the link to its parent (``NO_PARENT`` for an initial one)."""
        return self.table[state_id], self.parent[state_id]

    def finish(self) -> None:
        """Hand the search's objects back to the cycle collector."""
        if self._frozen is not None:
            self._frozen.close()
            self._frozen = None

    def clear(self) -> None:
        """Let the search's states go (the system stays, for the check's next search)."""
        self.finish()
        if getattr(self, "parent", None) is not None:
            self.parent.close()
        self.__dict__.clear()
        self.__init__()

    def figures(self) -> dict:
        """What this partition holds: states, bytes, engine, and the process's peak memory."""
        self._note_memory(always=True)
        table = self.table
        return {"states": len(table), "transitions": self.transitions, "sent": self.sent,
                "bytes": table.memory_bytes() + self.parent.memory_bytes(),
                "link_file_bytes": self.parent.file_bytes(),
                "engine": engine_of(table),
                "cpu_seconds": time.process_time() - self.cpu_started,
                "step_seconds": self.step_seconds, "step_thread": self.step_thread,
                "sent_bytes": self.sent_bytes,
                "step_wall": self.step_wall, "calls": self.calls, "spans": self.spans,
                "wall_seconds": time.monotonic() - self.wall_started,
                "start_rss_kb": self.start_rss_kb, "peak_private_kb": self.peak_private_kb,
                "peak_shared_kb": self.peak_shared_kb,
                "max_rss_kb": _peak_rss_kb(), "pid": os.getpid(),
                "rounds": self.levels.rounds + 1 if getattr(self, "levels", None) else 0}


def _status_kb(text: bytes, field: bytes) -> int:
    """A field of /proc/self/status in kB (ValueError where it is missing)."""
    at = text.index(field) + len(field)
    return int(text[at:text.index(b"\n", at)].split()[0])


def _free_heap():
    """The C library's ``malloc_trim(0)`` where it has one (glibc), else a call that does
    nothing."""
    import ctypes
    import ctypes.util
    try:
        return ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6").malloc_trim
    except (OSError, AttributeError):
        return lambda _pad: 0


_MALLOC_TRIM = None


def _heap_trimmed() -> None:
    """Hand the C heap's free pages back to the system, after calls that stepped a round's
    worth of states (``Partition._timed``).  A worker's threads share one heap
    (``search.WORKER_ENVIRONMENT``), where a round's batches, numpy's arrays and Ray's
    buffers come and go beside the table's growing arrays; the pages they leave free stay
    in the worker's RSS until trimmed: at counters N=10, 10-19 MB of each worker's peak
    (docs/distributed.md).  About 0.5 ms a trim; narrow levels, whose rounds step a few
    hundred states, trim once in dozens of rounds."""
    global _MALLOC_TRIM
    if _MALLOC_TRIM is None:
        _MALLOC_TRIM = _free_heap()
    _MALLOC_TRIM(0)


def _peak_rss_kb() -> int:
    import resource
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss


def search_here(system, count: int, predicate: str = "failed", eager: bool = False,
                by_data: Optional[bool] = None) -> tuple[list, int, tuple]:
    """The partitioned search with ``count`` partitions driven in this process by the
    cluster's driver (``search._Rounds``), without Ray: for tests and bench/distributed.py
    (``by_data`` as ``search.partitioned_reachable``'s).  Returns (the partitions, levels,
    the first (partition, state id) the predicate marks or None)."""
    from .search import _Rounds
    from ..budget import SearchBudget
    if by_data is None:
        by_data = data_owners_fit(system, state_table(system, packed=True), count)
    parts = [Partition() for _ in range(count)]
    for index, part in enumerate(parts):
        part.start(index, count, SystemSource(system), predicate, False, None, by_data, eager)
    try:
        rounds = _Rounds(_HERE, [_Here(part) for part in parts], system, SearchBudget(None),
                         None, eager)
        result, _, _ = rounds.run()
    finally:
        for part in parts:
            part.finish()
    return parts, result.stats.max_depth + 1, rounds.target


class _Here:
    """A partition called as ``worker.call`` calls an actor, in this process."""

    def __init__(self, part: Partition):
        self.part = part
        self.call = self

    def options(self, num_returns: int = 1) -> "_Here":
        return self

    def remote(self, _kind: str, method: str, *args):
        return getattr(self.part, method)(*args)


class _HERE:
    """``ray.get`` for ``_Here``: the answers are there already."""

    @staticmethod
    def get(answers):
        return answers
