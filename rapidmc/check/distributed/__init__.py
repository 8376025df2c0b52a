"""Searches on many processes and machines, with Ray (``pip install 'rapidmc[ray]'``).

* ``search.partitioned_reachable``: the breadth-first reachability search of the built-in
  checks, with the states split among workers by canonical hash (``canonical``), one Ray
  actor per partition (``partition``), its rounds driven by the first worker
  (``rounds``): the same verdicts and counts as one process.
* ``owcty.partitioned_accepting_cycle``: an LTL property's search for an accepting cycle
  of model × automaton, partitioned the same way (``product_partition``), by OWCTY: the
  same verdicts and product state counts as one process, and a lasso that replays.
* ``worker.Worker``: the actor that runs both kinds of partition for a check.
* ``swarm.swarm_reachable``: many independent randomized bitstate searches as Ray tasks;
  the first violation stops them; never HOLDS.
* ``cluster.Cluster``: where they run (``--workers N``, ``--ray ADDRESS``, ``--swarm N``).

Nothing here imports Ray at import time: without the extra, asking for a cluster is the
``RAY_UNAVAILABLE`` diagnostic (``cluster.require_ray``).
"""
from .canonical import canonical_bytes, owner
from .cluster import Cluster, require_ray

__all__ = ["Cluster", "canonical_bytes", "owner", "require_ray"]
