"""Where a distributed search runs: a local Ray cluster of N workers, or one to join.

``Cluster(workers=N)`` starts Ray on this machine with N CPUs (``--workers N``);
``Cluster(address=...)`` joins a running cluster (``--ray ADDRESS``, ``auto`` for the one
``ray start`` set up here).  Either way ``session()`` is a context in which Ray is up, and
it leaves a Ray it started itself shut down afterwards (a Ray already running in the
process, as in the tests, is used as it is and left running).

Ray is an optional extra (``pip install 'rapidmc[ray]'``); without it, ``require_ray``
raises the diagnostic that names the extra.

Joining an address waits at most ``CONNECT_SECONDS`` for an answer: Ray itself retries an
address where no cluster answers for minutes (a name that does not resolve: more than two),
about half a minute an attempt, so before Ray is asked, ``_answers`` checks that a gRPC
server (as Ray's cluster head and its client server are) answers there: it accepts a
connection and replies to HTTP/2's opening with its settings.  A refused connection is asked
again within that time (a head that ``ray start`` is still bringing up).  Else:
RAY_UNREACHABLE.
"""
from __future__ import annotations

import contextlib
import logging
import os
import socket
import threading
import time
from dataclasses import dataclass
from typing import Optional

from ...diagnostics import EXIT_WORKER_LOST, RAY_START, RAY_UNAVAILABLE, RAY_UNREACHABLE, error

EXTRA_HINT = "install it with: pip install 'rapidmc[ray]'"
START_HINT = "start one with: ray start --head --port=6379"
CONNECT_SECONDS = 20      # how long --ray ADDRESS may take to answer

# A local cluster passes objects of up to 16 MiB inline, in the gRPC message of the call
# that returns or takes them, instead of through the shared object store (Ray's default:
# above 100 KiB).  A round's batches are mostly above 100 KiB on big models (counters
# N=10: 0.4 MB on average); through the store each one cost the raylet CPU (its creation,
# sealing and release: 2.4 s of CPU at counters N=10) and left the store's pages a worker
# read mapped in its memory (about 28 MB per worker there).  (A joined cluster keeps its
# own settings: the same ones as ``RAY_`` variables of ``ray start``, docs/distributed.md.)
LOCAL_SYSTEM_CONFIG = {"max_direct_call_object_size": 16 << 20,
                       "task_rpc_inlined_bytes_limit": 64 << 20}


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
    eager: bool = False               # --eager: rounds without breadth-first levels

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
            self._join(ray, options)
        else:
            cpus = self.workers if self.workers is not None else \
                min(self.swarm, os.cpu_count() or 1)
            self._start(ray, cpus, options)
        try:
            yield ray
        finally:
            from .search import drop_actors     # (their handles die with this session)
            drop_actors(ray)
            ray.shutdown()

    def _start(self, ray, cpus: int, options: dict) -> None:
        """``ray.init`` of a local cluster, or RAY_START (exit 5, as a lost worker: the
        search could not run, no verdict).  Ray's processes may fail to come up on a
        loaded or small machine ("The current node timed out during startup")."""
        try:
            ray.init(num_cpus=cpus, _system_config=LOCAL_SYSTEM_CONFIG, **options)
        except Exception as exc:     # whatever Ray raises here is its processes' failure
            with contextlib.suppress(Exception):
                ray.shutdown()
            lines = str(exc).strip().splitlines()
            raise error(RAY_START, f"{self.option}: the local Ray cluster did not start",
                        None, (lines[0] if lines else type(exc).__name__)[:300],
                        "no verdict: run again when the machine is less loaded, or "
                        "without " + self.option, exit_code=EXIT_WORKER_LOST) from None

    def _join(self, ray, options: dict) -> None:
        """``ray.init`` at ``address``, or RAY_UNREACHABLE (``_answers``: at once where no
        gRPC server answers within ``CONNECT_SECONDS``)."""
        def unreachable(why: str):
            return error(RAY_UNREACHABLE, f"--ray {self.address}: no Ray cluster to join there",
                         None, why[:300], START_HINT)

        why = _answers(self.address, CONNECT_SECONDS)
        if why is not None:
            raise unreachable(why)
        try:
            ray.init(address=self.address, **options)
        except (ConnectionError, RuntimeError, ValueError, TimeoutError) as exc:
            first = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
            raise unreachable(first) from None


# what an HTTP/2 client sends first (RFC 9113, 3.4): the preface, then its (empty) settings
HTTP2_OPENING = b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n" + bytes((0, 0, 0, 4, 0, 0, 0, 0, 0))
SETTINGS_FRAME = 4          # a frame's type, the fourth byte of its 9-byte header


def _answers(address: str, seconds: float) -> Optional[str]:
    """None if a gRPC server at ``address`` (``[ray://]host:port``; ``auto`` and other forms
    are Ray's to read) answers HTTP/2's opening within ``seconds``, else why not.  (In a
    thread of its own, as the name's resolution has no timeout.)"""
    host, _, port = address.split("://", 1)[-1].rpartition(":")
    if not host or not port.isdigit():
        return None
    found: list = []
    silent = f"{host}:{port}: no answer within {seconds:g} s"

    deadline = time.monotonic() + seconds

    def ask():
        try:
            # a head that ``ray start`` is still bringing up refuses at first: ask again
            while True:
                try:
                    peer = socket.create_connection((host.strip("[]"), int(port)),
                                                    timeout=seconds)
                    break
                except ConnectionRefusedError:
                    if time.monotonic() + 0.5 > deadline:
                        raise
                    time.sleep(0.5)
            with peer:
                peer.sendall(HTTP2_OPENING)
                header = b""
                while len(header) < 9:
                    more = peer.recv(9 - len(header))
                    if not more:
                        break
                    header += more
        except TimeoutError:
            found.append(silent)
            return
        except OSError as exc:
            found.append(f"{host}:{port}: {exc.strerror or exc or type(exc).__name__}")
            return
        found.append(None if len(header) == 9 and header[3] == SETTINGS_FRAME else
                     f"{host}:{port} answers, but not as a Ray cluster does (gRPC)")

    attempt = threading.Thread(target=ask, daemon=True)
    attempt.start()
    attempt.join(seconds)
    return found[0] if found else silent
