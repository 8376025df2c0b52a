"""One outcome per configuration read and run (issue 28).

A controller's configuration does not change while its program runs: an
instance and attribute ReadCfgData finds once, it finds at every later read,
and one it does not find it never finds.  Where rapidmc does not know the
configuration (``configuration.NOT_KNOWN``), the first read of an instance and
attribute chooses found or ERR_CFG_NOTFND; the state remembers that choice,
and every later read of the same instance and attribute, from any task, gives
the same outcome without choosing again.

The memory is one hidden global (``Linker.controller_data``), created only for
a program with a ReadCfgData call: a sorted tuple of ``(key, found)`` pairs, so
that two runs that made the same choices in another order reach the same
state.  No RAPID name reaches it, so reports do not show it and no reduction
resets it (its type is not a value type).
"""
from __future__ import annotations

from typing import Optional

from ..types import NON_VALUE, RapidType
from .configuration import split_path

# the memory's type: not a value type, so reports leave it out and no reduction slices it
OUTCOMES = RapidType("<CFGOUTCOMES>", "configuration outcomes", NON_VALUE)
MEMORY_NAME = "<ReadCfgData outcomes>"


def memory_slot(linker, span) -> int:
    """The global slot of the outcomes chosen so far (created at the first call compiled)."""
    return linker.controller_data(MEMORY_NAME, OUTCOMES, (), span)


def read_key(path: str, attribute: str) -> tuple:
    """What a read names, as the look-up compares it: the domain and type in upper case,
    the instance as written, the attribute in lower case (another form of path as
    written, without surrounding blanks)."""
    return (split_path(path) or path.strip(), attribute.strip().lower())


def remembered(outcomes: tuple, key: tuple) -> Optional[bool]:
    """Whether the read ``key`` found its instance when first chosen (None: not read yet)."""
    for known, found in outcomes:
        if known == key:
            return found
    return None


def remember(outcomes: tuple, key: tuple, found: bool) -> tuple:
    """``outcomes`` with the choice for ``key`` added, in sorted order."""
    return tuple(sorted(outcomes + ((key, found),), key=_order))


def _order(item: tuple) -> tuple:
    (path, attribute), _ = item
    return (repr(path), attribute)
