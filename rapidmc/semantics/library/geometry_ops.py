"""RAPID operators on pos and orient: which function implements ``a op b``.

``pos + pos``, ``pos - pos``, ``num * pos``, ``pos * num`` (scaling),
``pos / num`` (scaling by the inverse), ``pos * pos`` (cross product) and
``orient * orient`` (rotation composition).

``pos / num`` is not in the operator table of ABB's RAPID overview (``/`` is
listed for num / num), but program modules of controller backups use it
(``pCenter := (p1 + p2) / 2``), so controllers load and run it (issue 19):
each component is divided, and a zero divisor raises ERR_DIVZERO as num / num
does.  Types are compared by their canonical key, so any type
object with ``.key`` ("POS", "ORIENT", "NUM", "DNUM") works.
"""
from __future__ import annotations

from typing import Callable, Optional

from ..values import divide
from .vector_math import as_pos, orient_multiply, pos_add, pos_cross, pos_scale, pos_sub

_SCALARS = ("NUM", "DNUM")


def _key(rapid_type: object) -> Optional[str]:
    return getattr(rapid_type, "key", None)


def _scale_right(vector, factor):
    return pos_scale(factor, vector)


def _divide(vector, divisor):
    return as_pos(tuple(divide(component, divisor) for component in vector))


# (operator, left key, right key) -> (function, result key)
_OPERATORS: dict[tuple[str, str, str], tuple[Callable, str]] = {
    ("+", "POS", "POS"): (pos_add, "POS"),
    ("-", "POS", "POS"): (pos_sub, "POS"),
    ("*", "POS", "POS"): (pos_cross, "POS"),
    ("*", "ORIENT", "ORIENT"): (orient_multiply, "ORIENT"),
}
for _scalar in _SCALARS:
    _OPERATORS[("*", _scalar, "POS")] = (pos_scale, "POS")
    _OPERATORS[("*", "POS", _scalar)] = (_scale_right, "POS")
    _OPERATORS[("/", "POS", _scalar)] = (_divide, "POS")


def operator_for(op: str, left_type: object, right_type: object):
    """``(fn, result_type)`` for ``left op right``, or ``(None, None)``."""
    from .. import types
    found = _OPERATORS.get((op, _key(left_type), _key(right_type)))
    if found is None:
        return None, None
    fn, result_key = found
    return fn, types.POS if result_key == "POS" else types.ORIENT
