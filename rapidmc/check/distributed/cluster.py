"""Where a distributed search runs: a local Ray cluster of N workers, or one to join.

``Cluster(workers=N)`` starts Ray on this machine with N CPUs (``--workers N``);
``Cluster(address=...)`` joins a running cluster (``--ray ADDRESS``, ``auto`` for the one
``ray start`` set up here).  Either way ``session()`` is a context in which Ray is up, and
it leaves a Ray it started itself shut down afterwards (a Ray already running in the
process, as in the tests, is used as it is and left running).

Ray is an optional extra (``pip install 'rapidmc[ray]'``); without it, ``require_ray``
raises the diagnostic that names the extra.
"""
from __future__ import annotations

import contextlib
import logging
import os
from dataclasses import dataclass
from typing import Optional

from ...diagnostics import RAY_UNAVAILABLE, RAY_UNREACHABLE, error

EXTRA_HINT = "install it with: pip install 'rapidmc[ray]'"


def require_ray(option: str):
    """The ``ray`` module, or the diagnostic saying how to get it."""
    try:
        import ray
    except ImportError:
        raise error(RAY_UNAVAILABLE, f"{option} needs Ray, which is not installed",
                    None, EXTRA_HINT) from None
    return ray


@dataclass(frozen=True)
class Cluster:
    """How to reach Ray, and how many searches to run side by side."""

    workers: Optional[int] = None     # --workers N: a local cluster of N CPUs
    address: Optional[str] = None     # --ray ADDRESS | auto: join that cluster
    swarm: int = 0                    # --swarm N: N randomized searches, not a partition

    @property
    def option(self) -> str:
        if self.swarm:
            return "--swarm"
        return "--workers" if self.address is None else "--ray"

    def partitions(self, ray) -> int:
        """How many partitions: the workers asked for, or the joined cluster's CPUs."""
        if self.workers is not None:
            return self.workers
        return max(1, int(ray.cluster_resources().get("CPU", 1)))

    @contextlib.contextmanager
    def session(self):
        """Ray, up for the length of the block (see the module docstring)."""
        ray = require_ray(self.option)
        if ray.is_initialized():
            yield ray
            return
        options = dict(include_dashboard=False, logging_level=logging.ERROR,
                       log_to_driver=False, configure_logging=True)
        if self.address is not None:
            try:
                ray.init(address=self.address, **options)
            except (ConnectionError, RuntimeError, ValueError) as exc:
                first = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
                raise error(RAY_UNREACHABLE, f"--ray {self.address}: no Ray cluster to join "
                            "there", None, first[:300],
                            "start one with: ray start --head --port=6379") from None
        else:
            cpus = self.workers if self.workers is not None else \
                min(self.swarm, os.cpu_count() or 1)
            ray.init(num_cpus=cpus, **options)
        try:
            yield ray
        finally:
            from .search import drop_actors     # (their handles die with this session)
            drop_actors(ray)
            ray.shutdown()
