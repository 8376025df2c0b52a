"""One worker of a distributed LTL search: its share of model × automaton, and its edges.

A product state is (model state, automaton state), as in ``check.product``; it belongs to
the partition that owns its model state (``canonical.owner``), so one model state's product
states live together and its valuation is computed once per sender.  A partition keeps:

* ``table``: its model states (the engine's state table), and ``keys``: product id ->
  ``model id * width + automaton state`` (``index``: the reverse);
* ``parent``: the link (``partition.link``) to the product state each was first reached
  from, breadth-first: the lasso's prefix;
* ``edge_start`` / ``edges``: every product state's successors as links, kept after the
  reachability search so that the OWCTY rounds (``owcty``) never step the model again.

A sender does not know the id an owner gives a successor, so ``receive`` answers each
sender with the ids of the states it sent, in the order sent, and ``expand`` (called next)
writes them into the edges it left open (``_open``).

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

import time
from array import array
from typing import Optional

from ..native import engine_of, state_table
from ..product import Product
from .canonical import owner
from .partition import NO_PARENT, decode_batch, encode_batch, link, unlink

REACH, ELIMINATE, REGIONS = "reach", "eliminate", "regions"
UNSEEN = -1             # REGIONS: not reached yet


class ProductPartition:
    """The product states of one partition (see the module docstring)."""

    def __init__(self):
        self.table = None
        self.alive: Optional[bytearray] = None  # the OWCTY set (None: every state)

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
        self.keys, self.index_of = array("q"), {}
        self.parent = array("q")
        self.edge_start, self.edges = array("q", [0]), array("q")
        self._open: list = []                  # per owner: positions in ``edges`` to fill
        self.transitions = 0
        self.sent = 0
        self.cpu_started = time.process_time()

    # --- the reachability search ---------------------------------------------------

    def receive(self, senders, *batches) -> tuple:
        """Store the new product states of the batches (``senders[i]`` sent ``batches[i]``:
        model states, automaton states, parents' ids there).  Returns one array per
        partition (the ids of what it sent, in order), then (product states stored, new)."""
        table, keys, index_of, parent = self.table, self.keys, self.index_of, self.parent
        width = self.product.width
        before = len(keys)
        answers = [array("q") for _ in range(self.count)]
        for sender, batch in zip(senders, batches):
            states, automaton_states, parents = decode_batch(batch)
            ids = answers[sender] if sender >= 0 else array("q")
            for state, q, parent_id in zip(states, automaton_states, parents):
                model_id, _ = table.intern(state, True)
                key = model_id * width + q
                product_id = index_of.get(key)
                if product_id is None:
                    product_id = index_of[key] = len(keys)
                    keys.append(key)
                    parent.append(NO_PARENT if sender < 0 else link(sender, parent_id))
                ids.append(product_id)
        return (*answers, (len(keys), len(keys) - before))

    def expand(self, *answers) -> tuple:
        """Fill the edges the last level left open with the owners' ``answers``, then step
        the product states stored since: one batch per owner, then (transitions so far)."""
        self._close(answers)
        width, count = self.product.width, self.count
        table, keys, valuation, moves = self.table, self.keys, self.valuation, self._moves
        edges, edge_start = self.edges, self.edge_start
        outgoing = [([], array("B"), array("q")) for _ in range(count)]
        opened = [array("q") for _ in range(count)]
        successors_of = getattr(self.system, "successor_states", None) or self._targets
        for product_id in range(len(edge_start) - 1, len(keys)):
            model_id, q = divmod(keys[product_id], width)
            state = table[model_id]
            successors = list(dict.fromkeys(successors_of(state))) or [state]   # (stutter)
            for successor in successors:
                target = owner(successor, count) if count > 1 else 0
                states, automaton_states, parents = outgoing[target]
                for q_next in moves(q, valuation(successor)):
                    states.append(successor)
                    automaton_states.append(q_next)
                    parents.append(product_id)
                    opened[target].append(len(edges))
                    edges.append(-1)
            edge_start.append(len(edges))
        self._open = opened
        self.transitions = len(edges)
        self.sent += sum(len(batch[0]) for target, batch in enumerate(outgoing)
                         if target != self.index)
        return (*map(encode_batch, outgoing), self.transitions)

    def _close(self, answers) -> None:
        edges = self.edges
        for target, (positions, ids) in enumerate(zip(self._open, answers)):
            for position, product_id in zip(positions, ids):
                edges[position] = link(target, product_id)
        self._open = []

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
                "bytes": table.memory_bytes() + sum(len(a) * a.itemsize for a in arrays),
                "engine": engine_of(table),
                "cpu_seconds": time.process_time() - self.cpu_started,
                "max_rss_kb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss}

    def clear(self) -> None:
        self.__dict__.clear()
        self.__init__()


def _job(model, property_name: str) -> tuple:
    """(system, automaton of the property's negation, valuation) of a prepared model."""
    for prop, buchi, valuation in model.jobs:
        if prop.name == property_name:
            return model.system, buchi, valuation
    raise KeyError(f"no property {property_name!r} in the rebuilt model")
