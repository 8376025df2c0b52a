"""Which search engine runs: the compiled core (``_native``) or the pure Python reference.

The compiled core is an optional C extension (``_native.c``, built by ``pip install``
when a C compiler is at hand; see setup.py).  It takes over the hot paths of the search
— the state table's interning (``NativeStateTable``) and the emptiness loop
(``emptiness``) — and leaves every decision to the same Python code, so both engines
give the same ids, verdicts, counterexamples and counts (tests/test_native_engine.py);
only the memory accounting (``bytes_per_state``) differs.

The engine is chosen once per process: ``RAPIDMC_ENGINE=native|python`` in the
environment, else native when the extension is built; ``use_engine`` (the ``check``
command's ``--engine``) changes it, ``engine_used`` for a block (tests).

Example::

    from rapidmc.check import native
    native.engine()             # "native" when the extension is built, else "python"
    with native.engine_used("python"):
        ...                     # searches here run the Python reference
"""
from __future__ import annotations

import os
from contextlib import contextmanager
from typing import Iterator

from .nodes import NodeTable
from .states import StateTable

try:
    from . import _native
except ImportError:          # not built: the Python engine is the only one
    _native = None

NATIVE = "native"
PYTHON = "python"
ENGINES = (NATIVE, PYTHON)
ENVIRONMENT_VARIABLE = "RAPIDMC_ENGINE"


def available() -> bool:
    """Whether the compiled core is built in this installation."""
    return _native is not None


def _default() -> str:
    chosen = os.environ.get(ENVIRONMENT_VARIABLE, "").strip().lower()
    if chosen == PYTHON or not available():
        return PYTHON
    return NATIVE


_engine = _default()


def engine() -> str:
    """The engine searches use now: ``"native"`` or ``"python"``."""
    return _engine


def use_engine(name: str) -> None:
    """Search with ``name`` from now on (ValueError: unknown, or native and not built)."""
    global _engine
    if name not in ENGINES:
        raise ValueError(f"unknown search engine {name!r} (use {' or '.join(ENGINES)})")
    if name == NATIVE and not available():
        raise ValueError("the native search engine is not built in this installation")
    _engine = name


@contextmanager
def engine_used(name: str) -> Iterator[None]:
    """Search with ``name`` within the block, then with the engine chosen before."""
    before = _engine
    use_engine(name)
    try:
        yield
    finally:
        use_engine(before)


@contextmanager
def engine_kept() -> Iterator[None]:
    """Whatever the block chooses (``use_engine``), the engine chosen before afterwards."""
    global _engine
    before = _engine
    try:
        yield
    finally:
        _engine = before


def description() -> str:
    """For ``--version``: the engine in use and whether the compiled core is built."""
    built = "built" if available() else "not built"
    return f"search engine {_engine} (native core {built})"


def native_search() -> bool:
    """Whether searches run their native loops now."""
    return _engine == NATIVE


def state_table(system, packed: bool = False) -> StateTable:
    """A new state table for ``system``'s states, native when the engine is and the model
    splits its states (a model without ``split_state`` keeps them whole in a dict, which
    the native table would not improve).  ``packed``: the model's packed table when it
    offers one (``packed_table()``: states as vectors its step machine runs on, for the
    breadth-first search)."""
    if _engine != NATIVE:
        return StateTable(system)
    offer = getattr(system, "packed_table", None) if packed else None
    table = offer() if offer is not None else None
    if table is not None:
        return table
    if getattr(system, "split_state", None) is not None:
        return NativeStateTable(system)
    return StateTable(system)


def part_hashes(limit: int):
    """``_native.PartHashes(limit)`` (model/state_keys.py's remembered hashes in C) when
    the core is built, else None.  Whatever the engine: it computes the very numbers the
    Python code does, so no outcome depends on whether it is used."""
    return _native.PartHashes(limit) if _native is not None else None


def engine_of(table: StateTable) -> str:
    """The engine a search with this state table runs on."""
    native = NativeStateTable is not None and isinstance(table, NativeStateTable) or \
        _native is not None and isinstance(getattr(table, "machine_table", lambda: None)(),
                                            _native.PackedTable)
    return NATIVE if native else PYTHON


if _native is not None:
    class NativeNodeTable(_native.NodeTable):
        """``nodes.NodeTable`` with its ``node``, ``ids`` and ``values`` in C (``_nodes.c``):
        the same nodes, found by address and hash-consed without Python calls."""

        splitter = NodeTable.splitter
        joiner = NodeTable.joiner

    class NativeStateTable(_native.Table, StateTable):
        """A collapsed ``StateTable`` whose ``intern``, ``[id]`` and ``len`` run natively
        (``_native.Table``), its components' nodes interned in C (``NativeNodeTable``); new
        components and tails are stored by the Python methods."""

        node_table = NativeNodeTable

        def memory_bytes(self) -> int:
            return self.native_bytes() + self.component_bytes()
else:
    NativeNodeTable = NativeStateTable = None
