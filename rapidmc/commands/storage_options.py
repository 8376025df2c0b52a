"""``--compact``, ``--bitstate SIZE``, ``--engine``: how a check stores and searches states.

By default every state is stored (exact).  ``--compact`` keeps 64-bit
fingerprints, ``--bitstate SIZE`` two bits per state in SIZE bytes
(``rapidmc.check.hashed``); neither ever reports HOLDS.  ``--engine
native|python`` chooses the compiled search core or the pure Python engine
(``rapidmc.check.native``; the default: native when it is built).
"""
from __future__ import annotations

import argparse
import re
from typing import Optional

from ..check import native
from ..check.hashed import BITSTATE, COMPACT
from ..diagnostics import NATIVE_ENGINE, USAGE, error
from ..diagnostics.quoting import quoted

UNITS = {"": 1, "B": 1, "K": 1 << 10, "KB": 1 << 10, "M": 1 << 20, "MB": 1 << 20,
         "G": 1 << 30, "GB": 1 << 30}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--compact", action="store_true",
                       help="remember visited states by 64-bit fingerprints, not whole: less "
                            "memory; a search without violation says UNKNOWN (probably holds) "
                            "with the odds that a collision hid a state")
    group.add_argument("--bitstate", metavar="SIZE", default=None,
                       help="remember visited states as bits in SIZE bytes (e.g. 256MB; "
                            "SPIN's supertrace): any state space, partial coverage; never HOLDS")
    parser.add_argument("--engine", choices=native.ENGINES, default=None,
                        help="search with the compiled core (native) or the pure Python "
                             f"engine (default: native when it is built; now "
                             f"{native.engine()})")


def select_engine(args: argparse.Namespace) -> None:
    """Search with the engine ``--engine`` names (none: the process's default)."""
    name = getattr(args, "engine", None)
    if name is None:
        return
    if name == native.NATIVE and not native.available():
        raise error(NATIVE_ENGINE, "--engine native: the compiled search core is not built in "
                    "this installation (reinstall with a C compiler, or use --engine python)")
    native.use_engine(name)


def storage_from_arguments(args: argparse.Namespace) -> Optional[tuple]:
    if getattr(args, "compact", False):
        return (COMPACT,)
    size = getattr(args, "bitstate", None)
    if size is None:
        return None
    return (BITSTATE, parse_size(size))


def parse_size(text: str) -> int:
    """``64MB`` -> 67108864; a usage error for anything else."""
    match = re.fullmatch(r"\s*(\d+)\s*([KMG]?B?)\s*", text.upper())
    if match is None or int(match.group(1)) <= 0:
        raise error(USAGE, f"--bitstate expects a size such as 64MB or 1GB, got {quoted(text)}")
    return int(match.group(1)) * UNITS[match.group(2)]
