"""Searches on many processes and machines, with Ray (``pip install 'rapidmc[ray]'``).

* ``search.partitioned_reachable``: the breadth-first reachability search of the built-in
  checks, with the states split among workers by canonical hash (``canonical``), one Ray
  actor per partition (``partition``): the same verdicts and counts as one process.
* ``swarm.swarm_reachable``: many independent randomized bitstate searches as Ray tasks;
  the first violation stops them; never HOLDS.
* ``cluster.Cluster``: where they run (``--workers N``, ``--ray ADDRESS``, ``--swarm N``).

Nothing here imports Ray at import time: without the extra, asking for a cluster is the
``RAY_UNAVAILABLE`` diagnostic (``cluster.require_ray``).
"""
from .canonical import canonical_bytes, owner
from .cluster import Cluster, require_ray

__all__ = ["Cluster", "canonical_bytes", "owner", "require_ray"]
