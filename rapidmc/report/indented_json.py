"""``json.dumps(value, indent=N, ensure_ascii=False)``, the same text, written faster.

With an indent the standard library leaves its C encoder and formats through nested Python
generators; a report with a long counterexample spent a noticeable share of ``check
--format json`` there.  This writer keeps that output to the character (tests/
test_indented_json.py compares the two on generated documents and on every report kind): it
tests the types in the encoder's order, writes strings with the encoder's own C string
escaper, numbers with ``int.__repr__`` and ``float.__repr__`` (``NaN`` and ``Infinity`` as
the encoder allows them), keys as the encoder converts them, and empty containers as ``[]``
and ``{}``.  A value the encoder cannot take raises ``TypeError`` as it does.
"""
from __future__ import annotations

import json.encoder

_string = json.encoder.encode_basestring          # the C escaper when it is built
_INFINITY = float("inf")


def dumps(value, indent: int) -> str:
    """The text ``json.dumps(value, indent=indent, ensure_ascii=False)`` gives."""
    chunks: list[str] = []
    _write(value, chunks.append, "\n", " " * indent)
    return "".join(chunks)


def _number(value: float) -> str:
    if value != value:
        return "NaN"
    if value == _INFINITY:
        return "Infinity"
    if value == -_INFINITY:
        return "-Infinity"
    return float.__repr__(value)


def _scalar(value):
    """The text of a value that is no container, or None for a container."""
    if isinstance(value, str):
        return _string(value)
    if value is None:
        return "null"
    if value is True:
        return "true"
    if value is False:
        return "false"
    if isinstance(value, int):
        return int.__repr__(value)
    if isinstance(value, float):
        return _number(value)
    if isinstance(value, (list, tuple, dict)):
        return None
    raise TypeError(f"Object of type {value.__class__.__name__} is not JSON serializable")


def _key(key) -> str:
    if isinstance(key, str):
        return _string(key)
    if isinstance(key, float):
        return _string(_number(key))
    if key is True:
        return '"true"'
    if key is False:
        return '"false"'
    if key is None:
        return '"null"'
    if isinstance(key, int):
        return _string(int.__repr__(key))
    raise TypeError(f"keys must be str, int, float, bool or None, not {key.__class__.__name__}")


def _write(value, emit, newline: str, step: str) -> None:
    """Emit ``value``'s text; ``newline`` starts a line at the value's own depth."""
    text = _scalar(value)
    if text is not None:
        emit(text)
        return
    inner = newline + step
    if isinstance(value, dict):
        if not value:
            emit("{}")
            return
        emit("{")
        separator = inner
        for key, item in value.items():
            emit(separator)
            emit(_key(key))
            emit(": ")
            _write(item, emit, inner, step)
            separator = "," + inner
        emit(newline)
        emit("}")
        return
    if not value:
        emit("[]")
        return
    emit("[")
    separator = inner
    for item in value:
        emit(separator)
        _write(item, emit, inner, step)
        separator = "," + inner
    emit(newline)
    emit("]")
