"""Expressions that can never raise a run-time error, whatever the data they read hold.

The slicing analysis may drop a data object only if no computation that
reads it can fail.  ``Totality`` proves that for a small, common family of
expressions and answers "not total" for everything else:

* literals; reading data of a value type (not an optional parameter, not
  signal data);
* ``NOT``, ``AND``, ``OR``, ``XOR`` of total bools; ``=``/``<>`` of total
  operands; ``<``, ``<=``, ``>``, ``>=`` of total numbers; unary minus;
* ``a + c`` and ``a - c`` with ``c`` a literal of at most 2^20 in size: a
  stored num (float32) or dnum is finite, and adding so little to a finite
  value never rounds to infinity (the gap below the largest float32 is
  2^104), so ERR_NUM_LIMIT cannot happen;
* string ``+`` when the longest possible result fits 80 characters;
* ``NumToStr(a, d)`` with ``a`` a total num and ``d`` a literal 0..6 (at
  most 41 + d characters: 39 digits of the largest float32, sign, point);
* an element ``a{i}`` of array data with literal indices within its declared
  bounds;
* the robot's position, joints, tool or work object of the calling task
  (``CRobT``, ``CJointT``, ``CPos``, ``CTool``, ``CWObj`` with no ``\\TaskName``
  or ``\\TaskRef``; ``\\Tool`` and ``\\WObj`` name data): the model reads them
  from the state and never raises (``semantics.library.position``).

An aggregate ``[e1, ..., en]`` has no type of its own: it is *assignable* to a
record of n components, or an array of n elements, when each ``ei`` is
assignable to its part, a numeric literal within num's range included (9E9,
an axis the robot lacks).
"""
from __future__ import annotations

from typing import Callable, Optional

from ... import ast
from ...semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA
from ...semantics.types import ArrayType, RapidType
from ...semantics.errors import RapidError
from ...semantics.types import RECORD
from ...semantics.values import NUM_MAX_DECIMALS, STRING_MAX, to_num

SMALL_LITERAL = 2 ** 20
LITERAL = "<literal>"             # a small numeric literal: takes the other operand's type
NUMERIC = ("NUM", "DNUM", LITERAL)
NUM_TO_STR_DIGITS = 41
# the readings of the calling task's robot -> the type they return
ROBOT_READINGS = {"CROBT": "ROBTARGET", "CJOINTT": "JOINTTARGET", "CPOS": "POS",
                  "CTOOL": "TOOLDATA", "CWOBJ": "WOBJDATA"}
ROBOT_READING_ARGUMENTS = frozenset({"TOOL", "WOBJ"})

# what a total expression yields: (type key, longest string length)
Info = tuple[str, int]


class Totality:
    """Totality of expressions in one routine (``lookup`` resolves names there)."""

    def __init__(self, lookup: Callable):
        self.lookup = lookup

    def total(self, expr) -> bool:
        return self.info(expr) is not None

    def assignable(self, expr, target_type) -> bool:
        """``expr`` is total and storing it in ``target_type`` needs no conversion that may fail."""
        if isinstance(expr, ast.Aggregate):
            parts = _parts(target_type, len(expr.items))
            return parts is not None and \
                all(self.assignable(item, part) for item, part in zip(expr.items, parts))
        if isinstance(expr, ast.NumLiteral) and _type_key(target_type) in ("NUM", "DNUM"):
            return _in_num_range(expr.value)
        info = self.info(expr)
        if info is None:
            return False
        kind = info[0]
        target = _type_key(target_type)
        if target is None:
            return False
        if kind == target:
            return True
        return target in ("NUM", "DNUM") and kind == LITERAL or (target, kind) == ("DNUM", "NUM")

    def info(self, expr) -> Optional[Info]:
        method = getattr(self, "_" + type(expr).__name__, None)
        return method(expr) if method is not None else None

    # ------------------------------------------------------------ leaves
    def _NumLiteral(self, expr: ast.NumLiteral) -> Optional[Info]:
        return (LITERAL, 0) if abs(expr.value) <= SMALL_LITERAL else None

    def _StringLiteral(self, expr: ast.StringLiteral) -> Optional[Info]:
        return ("STRING", len(expr.value))

    def _BoolLiteral(self, expr: ast.BoolLiteral) -> Optional[Info]:
        return ("BOOL", 0)

    def _NameRef(self, expr: ast.NameRef) -> Optional[Info]:
        symbol = self.lookup(expr.name)
        if symbol is None:
            return None
        key = _type_key(symbol.type)
        if key is None:
            return None
        if symbol.kind == CONSTANT:
            length = len(symbol.value) if isinstance(symbol.value, str) else 0
            return (key, length)
        if symbol.kind not in (GLOBAL_DATA, LOCAL_DATA) or symbol.optional:
            return None
        return (key, STRING_MAX if key == "STRING" else 0)

    def _Index(self, expr: ast.Index) -> Optional[Info]:
        if not isinstance(expr.base, ast.NameRef):
            return None
        symbol = self.lookup(expr.base.name)
        if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA, CONSTANT) or \
                symbol.optional or not isinstance(symbol.type, ArrayType) or \
                len(expr.indices) != symbol.type.rank:
            return None
        for index, size in zip(expr.indices, symbol.type.dims):
            if not isinstance(index, ast.NumLiteral) or size is None or \
                    index.value != int(index.value) or not 1 <= index.value <= size:
                return None
        key = _type_key(symbol.type.element)
        if key is None:
            return None
        return (key, STRING_MAX if key == "STRING" else 0)

    # --------------------------------------------------------- operators
    def _Unary(self, expr: ast.Unary) -> Optional[Info]:
        operand = self.info(expr.operand)
        if operand is None:
            return None
        if expr.op == "NOT":
            return operand if operand[0] == "BOOL" else None
        return operand if operand[0] in NUMERIC else None

    def _Binary(self, expr: ast.Binary) -> Optional[Info]:
        left, right = self.info(expr.left), self.info(expr.right)
        if left is None or right is None:
            return None
        op = expr.op
        if op in ("AND", "OR", "XOR"):
            return ("BOOL", 0) if left[0] == right[0] == "BOOL" else None
        if op in ("=", "<>"):
            return ("BOOL", 0)
        if op in ("<", "<=", ">", ">="):
            return ("BOOL", 0) if left[0] in NUMERIC and right[0] in NUMERIC else None
        if op not in ("+", "-"):
            return None
        if left[0] == right[0] == "STRING" and op == "+":
            length = left[1] + right[1]
            return ("STRING", length) if length <= STRING_MAX else None
        if left[0] in NUMERIC and right[0] == LITERAL:
            return left
        if left[0] == LITERAL and right[0] in NUMERIC:
            return right
        return None

    def _FunctionCall(self, expr: ast.FunctionCall) -> Optional[Info]:
        if expr.name.key in ROBOT_READINGS:
            return self._robot_reading(expr)
        if expr.name.key != "NUMTOSTR" or len(expr.args) != 2:
            return None
        value, decimals = expr.args
        if value.kind != ast.REQUIRED or decimals.kind != ast.REQUIRED:
            return None
        if value.name is not None or decimals.name is not None:
            return None
        number = self.info(value.value)
        digits = decimals.value
        if number is None or number[0] not in ("NUM", LITERAL) or \
                not isinstance(digits, ast.NumLiteral) or digits.value != int(digits.value) or \
                not 0 <= digits.value <= NUM_MAX_DECIMALS:
            return None
        if self.lookup(expr.name) is not None:
            return None                    # a user routine of that name
        return ("STRING", NUM_TO_STR_DIGITS + int(digits.value))


    def _robot_reading(self, expr: ast.FunctionCall) -> Optional[Info]:
        """The calling task's robot read (``ROBOT_READINGS``), its tool and work object
        named by data (the model does not evaluate them), or None."""
        if self.lookup(expr.name) is not None:
            return None                    # a user routine of that name
        for argument in expr.args:
            if argument.kind != ast.OPTIONAL or argument.name is None or \
                    argument.name.key not in ROBOT_READING_ARGUMENTS or \
                    not isinstance(argument.value, ast.NameRef) or \
                    self.lookup(argument.value.name) is not None and \
                    self.info(argument.value) is None:
                return None                # predefined data (wobj0) is not in the scope
        return (ROBOT_READINGS[expr.name.key], 0)


def _parts(target_type, count: int) -> Optional[list]:
    """The types of the ``count`` parts an aggregate fills in ``target_type`` (a record's
    components, a one-dimensional array's elements), or None when it has another shape."""
    if isinstance(target_type, ArrayType):
        if target_type.dims == (count,) and target_type.element.is_value:
            return [target_type.element] * count
        return None
    if isinstance(target_type, RapidType) and target_type.kind == RECORD and \
            len(target_type.components) == count:
        return [component.type for component in target_type.components]
    return None


def _in_num_range(value: float) -> bool:
    try:
        to_num(value)
    except RapidError:
        return False
    return True


def _type_key(rapid_type) -> Optional[str]:
    if isinstance(rapid_type, ArrayType):
        return rapid_type.key if rapid_type.element.is_value else None
    if isinstance(rapid_type, RapidType) and rapid_type.is_value:
        return rapid_type.key
    return None
