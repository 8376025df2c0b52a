"""Values in a counterexample as RAPID writes them, with their parts named.

``value_text(value, rapid_type)`` gives the RAPID literal of a value
(``[932.4,1557.5,2189.5]``, ``TRUE``, ``"done"``); an array or a record
comes as a ``Composite`` whose parts are named as RAPID names them
(``{8}``, ``{2,3}``, ``.trans``), so that a trace shows the one element an
assignment changed.  Data of a non-value type (``rawbytes``, ``syncident``,
``clock``) has no literal: it shows as its type in angle brackets, as RAPID
writes a placeholder (``<rawbytes>``; a rawbytes that holds bytes also says how
many).  Nothing here falls back to Python's own spelling of a value.

    >>> from rapidmc.semantics.types import POS
    >>> text = value_text((1.0, 2.5, 3.0), POS)
    >>> text, text.parts[1]
    ('[1,2.5,3]', ('.y', '2.5'))
"""
from __future__ import annotations

from typing import Any

from ..check.trace import Composite
from ..semantics.types import DNUM, NON_VALUE, RECORD, SEMI_VALUE, ArrayType
from ..semantics.library.sockets import (SOCKET_BOUND, SOCKET_CLOSED, SOCKET_CONNECTED,
                                         SOCKET_CREATED, SOCKET_LISTENING)
from ..semantics.values import format_value

OPAQUE_KINDS = (NON_VALUE, SEMI_VALUE)


def value_text(value: Any, rapid_type: Any) -> str:
    """The RAPID literal of ``value`` of static type ``rapid_type`` (None: not known)."""
    if isinstance(rapid_type, ArrayType):
        return _array(value, rapid_type)
    kind = getattr(rapid_type, "kind", None)
    if kind in OPAQUE_KINDS:
        return placeholder(value, rapid_type.name)
    if kind == RECORD and isinstance(value, tuple) and \
            len(value) == len(rapid_type.components):
        parts = tuple((f".{component.name}", value_text(part, component.type))
                      for component, part in zip(rapid_type.components, value))
        return _composite(parts)
    return untyped_text(value, "dnum" if rapid_type is DNUM else "num")


def untyped_text(value: Any, kind: str = "num") -> str:
    """A value whose type is not known (routine data): by what it holds."""
    if isinstance(value, (bool, str, int, float)):
        return format_value(value, kind)
    if isinstance(value, tuple):
        parts = tuple((f"{{{index}}}", untyped_text(part, kind))
                      for index, part in enumerate(value, start=1))
        return _composite(parts)
    return placeholder(value, "rawbytes" if isinstance(value, bytes) else "no value")


def placeholder(value: Any, type_name: str) -> str:
    """``<rawbytes>``, ``<rawbytes: 4 bytes>``, ``<syncident>``: data without a literal; a
    socket or an I/O device with its state (``<socketdev: connected>``)."""
    describe = DESCRIBED_TYPES.get(type_name.upper())
    if describe is not None:
        return f"<{type_name}: {describe(value)}>"
    if isinstance(value, bytes) and value:
        return f"<{type_name}: {len(value)} byte{'s' if len(value) != 1 else ''}>"
    return f"<{type_name}>"


# a socket's status as SocketGetStatus names it (SOCKET_CONNECTED: connected)
SOCKET_STATES = {SOCKET_CREATED: "created", SOCKET_CONNECTED: "connected",
                 SOCKET_BOUND: "bound", SOCKET_LISTENING: "listening", SOCKET_CLOSED: "closed"}


def _socket_state(value: Any) -> str:
    """``connected``; a socket never created (or closed and gone) is ``closed``."""
    if isinstance(value, tuple) and value:
        state = SOCKET_STATES.get(value[0], "closed")
        waiting = value[1] if len(value) > 1 else b""
        return f"{state}, {len(waiting)} bytes unread" if waiting else state
    return "closed"


def _device_state(value: Any) -> str:
    """``open "HOME:/log.txt" (write)`` or ``closed``."""
    if isinstance(value, tuple) and len(value) >= 2:
        return f"open {format_value(str(value[0]))} ({value[1]})"
    return "closed"


DESCRIBED_TYPES = {"SOCKETDEV": _socket_state, "IODEV": _device_state}


def _array(value: Any, array_type: ArrayType) -> str:
    """An array's literal; its parts are its elements, ``{i}`` (``{i,j}`` for rank 2 ...)."""
    if not isinstance(value, tuple):
        return untyped_text(value)
    parts: list[tuple[str, str]] = []
    text = _elements(value, array_type.element, array_type.rank, (), parts)
    return Composite(text, tuple(parts))


def _elements(value: tuple, element: Any, rank: int, index: tuple, parts: list) -> str:
    texts = []
    for number, item in enumerate(value, start=1):
        where = index + (number,)
        if rank > 1 and isinstance(item, tuple):
            texts.append(_elements(item, element, rank - 1, where, parts))
            continue
        item_text = value_text(item, element)
        parts.append(("{" + ",".join(map(str, where)) + "}", item_text))
        texts.append(item_text)
    return "[" + ",".join(texts) + "]"


def _composite(parts: tuple[tuple[str, str], ...]) -> Composite:
    return Composite("[" + ",".join(text for _, text in parts) + "]", parts)
