"""The Ray actor of a distributed check: one process per partition, for all its searches.

A check runs its built-in searches (``partition.Partition``) and then its LTL properties
(``product_partition.ProductPartition``) on the same workers: a ``Worker`` holds one of
each and forwards ``call(part, method, ...)`` to it, so the check starts its worker
processes once (a process start costs a second or more), and a worker builds the model
once for all of them (``SystemSource`` keys).
"""
from __future__ import annotations

from .partition import Partition
from .product_partition import ProductPartition

SAFETY, CYCLES = "safety", "cycles"


class Worker:
    def __init__(self):
        self.parts = {SAFETY: Partition(), CYCLES: ProductPartition()}

    def call(self, part: str, method: str, *args):
        return getattr(self.parts[part], method)(*args)


def call(actor, part: str, method: str, *args, returns: int = 1):
    """``method`` of the worker's ``part``, asked remotely: ``returns`` object refs."""
    return actor.call.options(num_returns=returns).remote(part, method, *args)
