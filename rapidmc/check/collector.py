"""Python's cycle collector during a search: what the search has stored is scanned once.

A search keeps millions of objects for as long as it runs (the state
table's component dicts and lists, the successor cache, the states on the
depth-first path).  The model's step function meanwhile leaves cyclic
garbage behind, so the collector must keep running; but each of its full
collections would walk every object the search holds, and it runs one
whenever a quarter as many objects as survived the last one have survived
since: over a long search, a cost that grows with the square of the
number of states.

So during a search (``frozen_while_searching``) the objects alive at each
budget checkpoint (``freeze_survivors``, ten times a second), once the
garbage among the young ones is collected, are moved out of the
collector's reach with ``gc.freeze``; the collector then sees only what
was allocated since.  Nothing is kept from reference counting:
frozen objects that are dropped are freed as before.  When the search
ends, ``gc.unfreeze`` hands everything back to the oldest generation.
"""
from __future__ import annotations

import contextlib
import gc

_searches = 0       # searches running (one inside another keeps the objects frozen)


@contextlib.contextmanager
def frozen_while_searching():
    global _searches
    _searches += 1
    gc.freeze()
    try:
        yield
    finally:
        _searches -= 1
        if not _searches:
            gc.unfreeze()


def freeze_survivors() -> None:
    """Out of the collector's reach: every object alive now (only during a search).

    The cyclic garbage among the young objects is collected first, so that
    none of it is frozen.  (Not a full collection: that would also stop
    tracking the search's big dicts, whose next insertion would then make
    them young again, to be walked by every young collection.)"""
    if _searches:
        gc.collect(1)
        gc.freeze()
