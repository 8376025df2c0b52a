"""Name resolution: what an identifier means at a given place.

RAPID's scopes, innermost first: FOR loop variables, routine parameters and
data, the module's own items (LOCAL or not), the task's global items (the
non-LOCAL items of every module of the same namespace), then the system
(predefined data and routines).  Environment modules form a namespace of
their own, like a second task.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional

from .types import AnyType

# symbol kinds
GLOBAL_DATA = "global"
LOCAL_DATA = "local"
CONSTANT = "constant"
SIGNAL = "signal"
ROUTINE = "routine"

# the system variables every task has (the step keeps them: State.errno, State.intno), never
# a configured signal or stub data, whatever the code compares them with
SYSTEM_VARIABLES = frozenset({"ERRNO", "INTNO"})


@dataclass(frozen=True)
class Symbol:
    """What a name denotes.

    * GLOBAL_DATA: ``slot`` in the store, ``storage`` VAR/PERS.
    * LOCAL_DATA: ``slot`` in the frame; ``storage`` VAR, CONST, FOR, or a
      parameter mode (IN, VAR, INOUT, PERS); ``optional`` for optional params.
    * CONSTANT: ``value`` known at link time (CONST data, predefined data).
    * SIGNAL: a configured physical signal, ``slot`` is its io index.
    * ROUTINE: ``slot`` is the routine index.
    """

    kind: str
    name: str
    type: Optional[AnyType]
    slot: int = -1
    storage: str = ""
    value: Any = None
    optional: bool = False
    by_reference: bool = False
    span: Any = None


class Scope:
    """A chain of name tables; lookups walk outwards."""

    __slots__ = ("names", "parent")

    def __init__(self, parent: Optional["Scope"] = None):
        self.names: dict[str, Symbol] = {}
        self.parent = parent

    def lookup(self, key: str) -> Optional[Symbol]:
        scope = self
        while scope is not None:
            symbol = scope.names.get(key)
            if symbol is not None:
                return symbol
            scope = scope.parent
        return None

    def declare(self, key: str, symbol: Symbol) -> Optional[Symbol]:
        """Add ``symbol``; returns the symbol already declared here under ``key``, if any."""
        existing = self.names.get(key)
        if existing is None:
            self.names[key] = symbol
        return existing

    def child(self) -> "Scope":
        return Scope(self)
