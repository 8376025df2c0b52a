"""The missing names of several tasks, as the task being walked sees them (issue 28).

A whole backup's tasks each load the modules of an option the backup does not hold
(PickMaster's ``pm_projectinfo``, its routines and constants). The stubs infer each such
name once, from the uses of every task that misses it, so that every task declares it
alike: a PERS of a stub type that two tasks share must have one type in both, and a
constant or routine they both use the same value and parameters.

``TaskViews`` holds the one ``Missing`` per name. While task N is walked it shows every
name some task misses, except a name task N declares itself and has not missed: that
task's own declaration stands, and another task's stub of the same name is not its
concern. With a single task nothing is hidden.

Example::

    >>> views = TaskViews(2)
    >>> views["NCOUNT"] = "stub of nCount"
    >>> class Declares: data, routines, records, aliases = {"NCOUNT": 1}, {}, {}, {}
    >>> views.show(1, Declares())
    >>> "NCOUNT" in views, views.of_any_task("NCOUNT")
    (False, 'stub of nCount')
"""
from __future__ import annotations

from collections.abc import MutableMapping


class TaskViews(MutableMapping):
    """``key -> Missing`` of every task, seen from the task shown (``show``)."""

    def __init__(self, count: int):
        self.count = count
        self.every: dict = {}
        self.current = 0
        self.declared: frozenset = frozenset()

    def show(self, number: int, names) -> None:
        """Show task ``number``, whose declarations are ``names`` (names.Declarations)."""
        self.current = number
        self.declared = frozenset() if self.count == 1 else frozenset(
            [*names.data, *names.routines, *names.records, *names.aliases])

    def _visible(self, key: str, missing) -> bool:
        return key not in self.declared or self.current in getattr(missing, "tasks", ())

    def __getitem__(self, key: str):
        missing = self.every[key]
        if not self._visible(key, missing):
            raise KeyError(key)
        return missing

    def __setitem__(self, key: str, missing) -> None:
        self.every[key] = missing

    def __delitem__(self, key: str) -> None:
        del self.every[key]

    def __iter__(self):
        return (key for key, missing in list(self.every.items()) if self._visible(key, missing))

    def __len__(self) -> int:
        return sum(1 for _ in self)

    def of_any_task(self, key: str):
        """The missing name ``key``, also when the task shown declares it, or None."""
        return self.every.get(key)

    def taken(self, key: str) -> bool:
        """Whether some task misses a name ``key`` (a new stub type must not take it)."""
        return key in self.every
