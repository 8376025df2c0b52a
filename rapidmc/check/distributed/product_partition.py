"""One worker of a distributed LTL search: its share of model × automaton, and its edges.

A product state is (model state, automaton state), as in ``check.product``; it belongs to
the partition that owns its model state, so one model state's product states live together.
Model states travel and are owned as in the reachability search (``codec``: the packed
table's vectors where the model has one, else pickles): a sender sends each successor of a
product state once, with the automaton state it leaves (in the parent's field), and the
owner takes the automaton's moves on the successor's valuation (computed once per model
state it stores).  A partition keeps:

* ``table``: its model states (the engine's state table; a successor every move of the
  automaton refuses is stored there too, in no product state), ``letters``: each one's
  valuation, and ``keys``: product id -> ``model id * width + automaton state``
  (``index_of``: the reverse);
* ``parent``: the link (``partition.link``) to the product state each was first reached
  from, breadth-first: the lasso's prefix;
* ``edge_start`` / ``edges``: every product state's successors as links, kept after the
  reachability search so that the OWCTY rounds (``owcty``) never step the model again.

A sender does not know the ids an owner gives a successor's product states, nor how many
there are, so ``receive`` answers each sender with, for each successor it sent (in the order
sent), their number and ids, and ``expand`` (called next) writes them as the edges of the
states it stepped last (``_close``).

As in the reachability search, what the search keeps is out of the cycle collector's reach
while it runs (``check.collector``).

After the reachability search, ``propagate`` runs one level of one of three spreads over
the stored edges; each takes the ids other partitions sent (``incoming``), then sends on
along the edges of the states it queued:

* ``REACH``: the states reachable from the accepting ones still in the set, counting for
  each how many edges from them enter it;
* ``ELIMINATE``: states no edge of the set enters leave it, and take their edges' counts
  with them;
* ``REGIONS``: breadth-first through the set from all its accepting states at once; each
  state joins the region of the first accepting state that reaches it (with its parent
  there), and each accepting state keeps the first edge of the set that enters it, and
  from which region (``owcty`` closes the lasso's cycle with these).
"""
from __future__ import annotations

import contextlib
import time
from array import array
from typing import Callable, Optional

from ..collector import freeze_survivors, frozen_while_searching
from ..native import engine_of, state_table
from ..product import Product
from .codec import codec_for
from .partition import CHUNK, NO_PARENT, SystemSource, decode_batch, encode_batch, link, unlink

REACH, ELIMINATE, REGIONS = "reach", "eliminate", "regions"
UNSEEN = -1             # REGIONS: not reached yet


class ProductPartition:
    """The product states of one partition (see the module docstring)."""

    def __init__(self):
        self.table = None
        self.alive: Optional[bytearray] = None  # the OWCTY set (None: every state)
        self._frozen: Optional[contextlib.ExitStack] = None

    def start(self, index: int, count: int, source, property_name: str, expected) -> None:
        """Begin the search of one property (``source.build()`` gives the prepared model;
        ``expected``: the automaton the driver translated, which this one must equal, as
        the lasso names its states)."""
        model = source.build()
        self.system, buchi, self.valuation = _job(model, property_name)
        if buchi != expected:
            raise RuntimeError(f"internal error: the worker's automaton for {property_name} "
                               "differs from the driver's")
        self.product = Product(None, buchi)
        self.index, self.count = index, count
        self.table = state_table(self.system, packed=True)
        self.codec = codec_for(self.table, index, count)
        self.letters: list[int] = []           # model id -> its valuation (any width)
        self.keys, self.index_of = array("q"), {}
        self.parent = array("q")
        self.edge_start, self.edges = array("q", [0]), array("q")
        self.expanded = 0                      # product states before this id are stepped
        self._sent_to = array("i")             # the last level's successors: their owners
        self.transitions = 0
        self.sent = 0                          # successors sent to other partitions
        self.sent_bytes = 0                    # ... their batches' bytes
        self.finish()                          # (see the module docstring)
        self._frozen = contextlib.ExitStack()
        self._frozen.enter_context(frozen_while_searching())
        self.cpu_started = time.process_time()

    # --- the reachability search ---------------------------------------------------

    def receive(self, senders, *batches) -> tuple:
        """Store the product states of the batches (``senders[i]`` sent ``batches[i]``; sender
        -1: the initial states, pickled with their automaton states and sent to every
        partition, of which each keeps those it owns).  Returns one answer per partition
        (for each successor it sent, in order: how many product states it gave, and their
        ids), then (product states stored, new)."""
        try:
            return self._receive(senders, batches)
        finally:
            freeze_survivors()

    def _receive(self, senders, batches) -> tuple:
        keys, index_of, parent, width = self.keys, self.index_of, self.parent, self.product.width
        before = len(keys)
        answers = [(array("q"), array("q")) for _ in range(self.count)]
        for sender, batch in zip(senders, batches):
            if sender < 0:
                states, automaton_states, _ = decode_batch(batch)
                for state, q in zip(states, automaton_states):
                    if self.count == 1 or self.codec.owns(state, self.index):
                        model_id, _ = self.table.intern(state, True)
                        self._letter(model_id)
                        key = model_id * width + q
                        if key not in index_of:
                            index_of[key] = len(keys)
                            keys.append(key)
                            parent.append(NO_PARENT)
                continue
            counts, ids = answers[sender]
            moves, letters = self._moves, self.letters
            stored_ids, _, stored_fields = self.codec.store(sender, batch)
            for model_id, field in zip(stored_ids.tolist(), stored_fields.tolist()):
                parent_id, q = divmod(field, width)
                letter = letters[model_id] if model_id < len(letters) else \
                    self._letter(model_id)
                targets = moves(q, letter)
                counts.append(len(targets))
                for q_next in targets:
                    key = model_id * width + q_next
                    product_id = index_of.get(key)
                    if product_id is None:
                        product_id = index_of[key] = len(keys)
                        keys.append(key)
                        parent.append(link(sender, parent_id))
                    ids.append(product_id)
        return (*answers, (len(keys), len(keys) - before))

    def _letter(self, model_id: int) -> int:
        """The valuation of a model state, noted when it is first stored (ids are dense)."""
        letters = self.letters
        while len(letters) <= model_id:
            letters.append(self.valuation(self.table[len(letters)]))
        return letters[model_id]

    def expand(self, *answers) -> tuple:
        """Write the edges of the states stepped last from the owners' ``answers``, then step
        the product states stored since: one batch per owner, then (transitions so far:
        the edges written)."""
        try:
            self._close(answers)
            return self._expand()
        finally:
            freeze_survivors()

    def _expand(self) -> tuple:
        width, count, codec = self.product.width, self.count, self.codec
        table, keys = self.table, self.keys
        successors_of = getattr(self.system, "successor_states", None) or self._targets
        keys_of = codec.successor_keys
        outboxes = [codec.outbox() for _ in range(count)]
        send = codec.send
        sent_to, fanout = array("i"), array("q")
        pending, fields = [], []

        def flush():
            sent_to.extend(send(outboxes, pending, fields))
            pending.clear()
            fields.clear()

        end = len(keys)
        for product_id in range(self.expanded, end):
            model_id, q = divmod(keys[product_id], width)
            state = table[model_id]
            successors = list(dict.fromkeys(keys_of(model_id, state, successors_of))) or \
                keys_of(model_id, state, [state])                      # (stutter)
            fanout.append(len(successors))
            field = product_id * width + q
            pending.extend(successors)
            fields.extend([field] * len(successors))
            if len(pending) >= CHUNK:
                flush()
        if pending:
            flush()
        self.expanded = end
        self._sent_to, self._fanout = sent_to, fanout
        self.sent += sum(1 for target in sent_to if target != self.index)
        outgoing = [codec.encode(target, outboxes[target]) for target in range(count)]
        self.sent_bytes += sum(len(batch) for target, batch in enumerate(outgoing)
                               if target != self.index)
        return (*outgoing, self.transitions)

    def _close(self, answers) -> None:
        """The edges of the states ``_expand`` stepped last: for each, for each successor it
        sent, the product states the owner answered (``receive``)."""
        if not self._sent_to:
            return
        edges, edge_start = self.edges, self.edge_start
        counts = [iter(answer[0]) for answer in answers]
        ids = [iter(answer[1]) for answer in answers]
        targets = iter(self._sent_to)
        for successors in self._fanout:
            for _ in range(successors):
                target = next(targets)
                taken = ids[target]
                for _ in range(next(counts[target])):
                    edges.append(link(target, next(taken)))
            edge_start.append(len(edges))
        self._sent_to = array("i")
        self.transitions = len(edges)

    def _moves(self, q: int, valuation: int):
        product = self.product
        if product.tables is not None:
            return product.tables[q][valuation & product.read]
        return product.moves(q, valuation)

    def _targets(self, state) -> list:
        return [successor for _, successor in self.system.successors(state)]

    # --- OWCTY over the stored edges ---------------------------------------------------

    def reset(self) -> int:
        """Begin a REACH spread: queue the accepting states of the set; their number."""
        size = len(self.keys)
        if self.alive is None:
            self.alive = bytearray(b"\x01") * size
        self.reached = bytearray(size)
        self.entering = array("q", bytes(8 * size))    # edges from the set into each state
        accepting, width = self.product.accepting, self.product.width
        self.queue = [i for i, key in enumerate(self.keys)
                      if self.alive[i] and accepting[key % width]]
        for i in self.queue:
            self.reached[i] = 1
        return len(self.queue)

    def restrict(self) -> int:
        """Keep only the states the REACH spread reached, and queue for an ELIMINATE spread
        those no edge of the set enters; returns the size of the set left."""
        alive, reached, entering = self.alive, self.reached, self.entering
        queue = []
        for i in range(len(alive)):
            if alive[i] and not (reached[i] and entering[i]):
                alive[i] = 0
                if reached[i]:
                    queue.append(i)
        self.queue = queue
        return self.size()

    def size(self) -> int:
        """How many states of this partition are in the set."""
        return len(self.keys) if self.alive is None else sum(self.alive)

    def begin_regions(self) -> int:
        """Begin a REGIONS spread: every accepting state of the set is the source of its
        region; returns their number."""
        size, alive = len(self.keys), self.alive
        accepting, width = self.product.accepting, self.product.width
        self.region = array("q", [UNSEEN]) * size           # link of the region's source
        self.region_parent = array("q", [NO_PARENT]) * size
        self.entry: dict = {}        # source id -> (region entered from, link of the state)
        self.queue = []
        for i, key in enumerate(self.keys):
            if alive[i] and accepting[key % width]:
                self.region[i] = link(self.index, i)
                self.queue.append(i)
        return len(self.queue)

    def propagate(self, mode: str, *incoming) -> tuple:
        """One level of a spread (module docstring): take ``incoming`` (one batch per
        sender: the ids its edges enter here; for REGIONS also the links of the states they
        leave and their regions), then send along the edges of the queued states.  Returns
        one batch per owner, then the number of states queued this level."""
        alive = self.alive
        if mode == REACH:
            entering, reached, queue = self.entering, self.reached, self.queue
            for ids, _ in incoming:
                for i in ids:
                    if alive[i]:
                        entering[i] += 1
                        if not reached[i]:
                            reached[i] = 1
                            queue.append(i)
        elif mode == ELIMINATE:
            entering, queue = self.entering, self.queue
            for ids, _ in incoming:
                for i in ids:
                    if alive[i]:
                        entering[i] -= 1
                        if entering[i] == 0:
                            alive[i] = 0
                            queue.append(i)
        else:
            region, parents, entry, queue = self.region, self.region_parent, self.entry, \
                self.queue
            index = self.index
            for ids, links, regions in incoming:
                for i, parent, source in zip(ids, links, regions):
                    if not alive[i]:
                        continue
                    if region[i] == UNSEEN:
                        region[i], parents[i] = source, parent
                        queue.append(i)
                    elif region[i] == link(index, i) and i not in entry:
                        entry[i] = (source, parent)
        return self._send(mode)

    def _send(self, mode: str) -> tuple:
        queue, self.queue = self.queue, []
        edges, edge_start, count = self.edges, self.edge_start, self.count
        if mode != REGIONS:
            outgoing = [array("q") for _ in range(count)]
            for i in queue:
                for position in range(edge_start[i], edge_start[i + 1]):
                    target, target_id = unlink(edges[position])
                    outgoing[target].append(target_id)
            return (*[(ids, ()) for ids in outgoing], len(queue))
        outgoing = [(array("q"), array("q"), array("q")) for _ in range(count)]
        region = self.region
        for i in queue:
            here, source = link(self.index, i), region[i]
            for position in range(edge_start[i], edge_start[i + 1]):
                target, target_id = unlink(edges[position])
                ids, parents, regions = outgoing[target]
                ids.append(target_id)
                parents.append(here)
                regions.append(source)
        return (*outgoing, len(queue))

    # --- paths and figures -------------------------------------------------------------

    def entries(self) -> list[tuple[int, int, int]]:
        """After a REGIONS spread: (link of an accepting state of the set, the region the
        first edge into it came from, link of that edge's state), for each of them."""
        index = self.index
        return [(link(index, i), source, parent) for i, (source, parent) in self.entry.items()]

    def step_back(self, product_id: int) -> tuple:
        """(model state, automaton state, link to the breadth-first parent)."""
        model_id, q = divmod(self.keys[product_id], self.product.width)
        return self.table[model_id], q, self.parent[product_id]

    def region_back(self, product_id: int) -> int:
        """The link to the state the REGIONS spread reached ``product_id`` from
        (``NO_PARENT``: the source of its region)."""
        return self.region_parent[product_id]

    def figures(self) -> dict:
        import resource
        table = self.table
        arrays = (self.keys, self.parent, self.edge_start, self.edges)
        return {"states": len(self.keys), "model_states": len(table),
                "transitions": len(self.edges), "sent": self.sent,
                "sent_bytes": self.sent_bytes,
                "bytes": table.memory_bytes() + sum(len(a) * a.itemsize for a in arrays),
                "engine": engine_of(table), "codec": type(self.codec).__name__,
                "cpu_seconds": time.process_time() - self.cpu_started,
                "max_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}

    def finish(self) -> None:
        """Hand the search's objects back to the cycle collector."""
        if self._frozen is not None:
            self._frozen.close()
            self._frozen = None

    def clear(self) -> None:
        self.finish()
        self.__dict__.clear()
        self.__init__()


def initial_batch(system, product: Product, valuation) -> bytes:
    """The initial product states, for every partition (each keeps those it owns)."""
    states, automaton_states = [], []
    initial = product.initial_automaton_state
    for state in system.initial_states():
        for q in dict.fromkeys(product.targets(initial, valuation(state))):
            states.append(state)
            automaton_states.append(q)
    return encode_batch((states, automaton_states, []))


def product_here(model, property_name: str, count: int,
                 on_level: Optional[Callable[[], None]] = None) -> list[ProductPartition]:
    """The breadth-first search of the product with ``count`` partitions driven in this
    process, level by level as ``owcty`` drives the actors (no Ray): for tests, which
    ``on_level()`` lets look in between.  Returns the partitions, their collector handed
    back (``finish``)."""
    _, buchi, valuation = _job(model, property_name)
    parts = [ProductPartition() for _ in range(count)]
    for index, part in enumerate(parts):
        part.start(index, count, SystemSource(model), property_name, buchi)
    batch = initial_batch(model.system, Product(None, buchi), valuation)
    received = [part.receive([-1], batch) for part in parts]
    senders = list(range(count))
    try:
        while True:
            if on_level is not None:
                on_level()
            expanded = [part.expand(*[answer[index] for answer in received])
                        for index, part in enumerate(parts)]
            if not sum(answer[count][1] for answer in received):
                return parts
            received = [part.receive(senders, *[batches[target] for batches in expanded])
                        for target, part in enumerate(parts)]
    finally:
        for part in parts:
            part.finish()


def _job(model, property_name: str) -> tuple:
    """(system, automaton of the property's negation, valuation) of a prepared model."""
    for prop, buchi, valuation in model.jobs:
        if prop.name == property_name:
            return model.system, buchi, valuation
    raise KeyError(f"no property {property_name!r} in the rebuilt model")
