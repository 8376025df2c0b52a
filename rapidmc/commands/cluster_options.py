"""``--workers N``, ``--ray ADDRESS``, ``--swarm N``: run the built-in checks' searches on Ray.

``--workers N`` starts a local Ray cluster of N CPUs and splits the states among N workers;
``--ray ADDRESS`` (``auto``: the cluster ``ray start`` runs here) joins a cluster and uses
one worker per CPU it has; ``--swarm N`` runs N randomized bitstate searches instead, on the
local machine or, with ``--ray``, on the cluster.  ``--eager`` (with ``--workers`` or
``--ray``) lets each worker follow its own successors within a round instead of going in
breadth-first levels: fewer rounds, the same verdicts and counts, but a counterexample may
be longer than one process's.  docs/distributed.md says what each
guarantees.  Without Ray installed each is the RAY_UNAVAILABLE diagnostic (exit 2).
"""
from __future__ import annotations

import argparse
from typing import Optional

from ..check.distributed import Cluster, require_ray
from ..diagnostics import USAGE, error


def add_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--workers", type=int, default=None, metavar="N",
                       help="search on a local Ray cluster of N workers, the states split "
                            "among them by hash (pip install 'rapidmc[ray]'); same verdicts "
                            "and counts as one process")
    parser.add_argument("--ray", default=None, metavar="ADDRESS",
                        help="search on the Ray cluster at ADDRESS ('auto': the one 'ray "
                             "start' runs on this machine), one worker per CPU")
    group.add_argument("--swarm", type=int, default=None, metavar="N",
                       help="N independent randomized bitstate searches (SPIN's swarm) for a "
                            "bug hunt: the first violation stops them; never HOLDS")
    parser.add_argument("--eager", action="store_true",
                        help="with --workers or --ray: each worker follows its own successors "
                             "within a round instead of going in breadth-first levels (fewer "
                             "rounds; same verdicts and counts, counterexamples may be longer)")


def cluster_from_arguments(args: argparse.Namespace) -> Optional[Cluster]:
    """The cluster the options ask for (None: search in this process); checks Ray is there."""
    workers, address, swarm = (getattr(args, name, None) for name in ("workers", "ray", "swarm"))
    eager = getattr(args, "eager", False)
    if workers is None and address is None and swarm is None:
        if eager:
            raise error(USAGE, "--eager is a way of searching on workers: give --workers N "
                        "or --ray ADDRESS with it")
        return None
    if eager and swarm is not None:
        raise error(USAGE, "--eager is a way of the partitioned search; --swarm runs "
                    "independent searches: give one of them")
    if workers is not None and address is not None:
        raise error(USAGE, "--workers starts a local cluster and --ray joins one: give one of them")
    for option, number in (("--workers", workers), ("--swarm", swarm)):
        if number is not None and number < 1:
            raise error(USAGE, f"{option} expects a number of workers of at least 1, got {number}")
    cluster = Cluster(workers=workers, address=address, swarm=swarm or 0, eager=eager)
    if getattr(args, "compact", False) or getattr(args, "bitstate", None) and not swarm:
        raise error(USAGE, f"{cluster.option} stores every state; it does not combine with "
                    "--compact or --bitstate (--swarm takes --bitstate as each search's size)")
    require_ray(cluster.option)
    return cluster
