"""``--compact`` and ``--bitstate SIZE``: how a check remembers visited states.

By default every state is stored (exact).  ``--compact`` keeps 64-bit
fingerprints, ``--bitstate SIZE`` two bits per state in SIZE bytes
(``rapidmc.check.hashed``); neither ever reports HOLDS.
"""
from __future__ import annotations

import argparse
import re
from typing import Optional

from ..check.hashed import BITSTATE, COMPACT
from ..diagnostics import USAGE, error
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
