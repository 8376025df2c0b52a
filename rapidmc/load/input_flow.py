"""Where the value read from a free input goes, followed through the program's data.

``input_domains`` gives a free group or analog input a finite default domain
when every use of its value is one it can place: a comparison with a number,
a TEST against numbers, a wait for a number, or a use with no effect.  Real
programs first store the value and use it later (issue 28, survey of public
backups): a part code copied into a routine's INOUT parameter and used as an
array index after a range check, a PLC's speed percentage scaled into a
``speeddata`` that only moves read.  This module follows such a value:

* **Raw value** (the input's own number).  Besides the comparisons of
  ``compared_numbers``, it may be an index of an array of known size (GI
  only: each element is a class of its own, and so is beyond either end), be
  stored whole into a ``num``/``dnum`` variable or parameter, or be passed to
  one of the program's own routines; the data it was stored into is then
  followed the same way: each of its reads is such a use.  A by-reference
  parameter that holds the value passes it back to the argument of every call.
* **Mixed value** (after ``+ - *`` with other operands).  It may only reach a
  sink: an IN argument of a predefined routine modelled with no effect, an
  argument a move never evaluates (speed, zone), or data whose every read is
  such an argument; or an offset of ``Offs`` whose result is a move's target,
  when nothing reads the robot's position back (no ``CRobT``, ``CPos``,
  ``CJointT``, ``CalcJointT`` ... in the code, no robot atom in a property):
  a camera's pick position sent as group inputs moves the robot, and nothing
  else.

Data followed must be the task's own ``VAR`` data or routine data (a PERS
can be read where the analysis does not look) and must not be read by a
property's atom.  Any other use refuses the default, naming the use.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional, Union

from .. import ast
from ..semantics.library import lookup_function, lookup_procedure
from ..semantics.library.motion import MOVE_ROUTINES, UNEVALUATED_BY_MOVES
from ..semantics.library.position import ROBOT_PARTS
from ..semantics.library.registry import NO_EFFECT, matched_parameters
from ..semantics.scope import CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE, SIGNAL
from ..semantics.types import ArrayType
from ..semantics.values import to_num

# what reads the robot's position, tool or work object back: ROBOT_PARTS (CRobT, CPos,
# CJointT, CTool, CWObj) may, when their value too only shapes moves' targets; CalcJointT
# (it may fail), CalcRobT and GetSysData never may
ROBOT_READERS = frozenset(ROBOT_PARTS) | {"CALCJOINTT", "CALCROBT", "GETSYSDATA"}
# what reads where the robot is (not its tool or work object)
POSITION_READERS = frozenset({"CROBT", "CPOS", "CJOINTT"})
MOVE_TARGETS = frozenset({"TOPOINT", "CIRPOINT", "TOJOINTPOS"})
# data reached by a name computed at run time: a value stored there may be read unseen
BY_NAME = frozenset({"GETDATAVAL", "SETDATAVAL", "SETALLDATAVAL"})
UNEVALUATED = "arguments no model evaluates"    # kinds of sink (Uses.sinks)
TARGETS = "moves' targets"
MAX_INDEXED = 64              # an index of a bigger array: too many classes to branch over
INERT_OPS = ("+", "-", "*")   # operations that cannot fail on a num read (no divisor) ...
NUM_MAX = 3.4028234663852886e38     # ... while results stay within num: the largest num
ROUNDED_AWAY = 2.0 ** 102     # less than half the num spacing at NUM_MAX (2**104): rounds down
GROUP_MAX = 2.0 ** 32 - 1     # the largest value of a group input (32 bits at most)
# offsets of Offs at most this big leave any coordinate's overflow to the other terms: beside
# 2**89 and more, where overflow could begin, they are far below the num spacing
OFFSET_MAX = 2.0 ** 64
NUMERIC = ("NUM", "DNUM")     # types of data a raw value may be stored in and followed
WRITABLE = ("VAR", "IN", "INOUT")   # storage of data followed (not PERS, CONST, FOR)


@dataclass
class Uses:
    """What the uses of one input's value, followed through data, amount to."""

    numbers: set = field(default_factory=set)   # class boundaries of the raw value
    compared: set = field(default_factory=set)  # the numbers among them it is compared with
    refusal: Optional[str] = None               # the first use that allows no default
    through: list = field(default_factory=list)  # names of the data followed, in order
    indexed: list = field(default_factory=list)  # sizes of arrays the value indexes
    sinks: list = field(default_factory=list)   # kinds of sink uses reach ("moves' targets")

    def sunk(self, kind: str) -> bool:
        if kind not in self.sinks:
            self.sinks.append(kind)
        return True


Place = tuple   # (Symbol, routine index or None): data that holds the value


@dataclass(frozen=True)
class Read:
    """One read of a name: the node, its ancestors, the scope and routine it is in."""

    node: object
    parents: tuple
    scope: object
    routine: object


class InputFlow:
    """Follows input values through the data of ``routines``.

    ``observed_names``: upper-case names of data that properties' atoms read
    (``None``: unknown, so no data is followed)."""

    def __init__(self, routines, observed_names: Optional[frozenset],
                 robot_observed: bool = True, module_data: tuple = ()):
        self.routines = routines
        self.module_data = module_data         # the program's GlobalData, by store slot
        self._fixed: Optional[dict] = None
        self.observed_names = observed_names
        self.robot_observed = robot_observed     # a property's atom reads a robot
        self._reads: Optional[dict] = None
        self._robot_read: Optional[bool] = None
        self._by_name = False           # data is read by a computed name somewhere
        self._late_calls = False        # a routine is called by a computed name somewhere

    # --- the uses of a value --------------------------------------------------------------

    def raw(self, read: Read, uses: Uses, integral: bool, classify, seen: set) -> None:
        """A read whose value is the input's own number.  ``classify(read)``: the numbers
        it is compared with (a set) or how else it is used (a string), as
        ``compared_numbers`` says."""
        if uses.refusal is not None:
            return
        found = classify(read)
        if not isinstance(found, str):
            uses.numbers.update(found)
            uses.compared.update(found)
            return
        node, parents = _unwrapped(read.node, list(read.parents))
        parent = parents[-1] if parents else None
        if isinstance(parent, ast.Index) and any(i is node for i in parent.indices):
            size = self._index_size(parent, node, read.scope)
            if integral and size is not None:
                uses.numbers.update(float(k) for k in range(1, size + 1))
                uses.indexed.append(size)
                return
            uses.refusal = _at(read, "an analog value used as an array index") \
                if not integral else \
                _at(read, f"used as an index of an array of more than {MAX_INDEXED} elements "
                    "or of unknown size")
            return
        if isinstance(parent, ast.Assignment) and parent.value is node:
            place = self._place(parent.target, read)
            if place is not None:
                self._follow(place, uses, integral, classify, seen)
                return
        if isinstance(parent, ast.Argument) and len(parents) >= 2:
            place = self._own_parameter(parents[-2], parent, read)
            if place is not None:
                self._follow(place, uses, integral, classify, seen)
                return
        if self.sink(read, uses, seen, GROUP_MAX if integral else NUM_MAX):
            return
        uses.refusal = _at(read, found)

    def sink(self, read: Read, uses: Uses, seen: set, bound: float) -> bool:
        """Whether the value read at ``read`` (at most ``bound`` in size) reaches nothing
        that can tell values apart: through ``+ - *`` and unary minus only into an
        argument no model evaluates, or into data whose every read is such an argument; or
        into moves' targets only, when nothing reads the robot's position but to move
        again (``robot_unobserved``).  A condition, index, divisor, atom or operation that
        can fail (one that may leave the range of num for some value) is never a sink."""
        node, parents, bound = _inert_result(*_unwrapped(read.node, list(read.parents)),
                                             bound, read.scope, self.fixed_data())
        parent = parents[-1] if parents else None
        if self._shapes_target(node, parents, read.scope, bound):
            return self.robot_unobserved() and uses.sunk(TARGETS)
        if isinstance(parent, ast.Argument) and len(parents) >= 2 and \
                isinstance(parents[-2], ast.ProcedureCall):
            return unevaluated_argument(parents[-2], parent, read.scope) and \
                uses.sunk(UNEVALUATED)
        if isinstance(parent, ast.Assignment) and parent.value is node:
            place = self._place(_base(parent.target), read, any_type=True)
            if place is None:
                return False
            if self._sink_place(place, uses, seen):
                return uses.sunk(UNEVALUATED)
            if self._target_place(place, set()) and self.robot_unobserved():
                if place[0].name not in uses.through:
                    uses.through.append(place[0].name)
                return uses.sunk(TARGETS)
        return False

    # --- moves' targets ----------------------------------------------------------------------

    def _shapes_target(self, node, parents: list, scope, bound: float = NUM_MAX) -> bool:
        """Whether the value of ``node`` (at most ``bound`` in size) only becomes (part of)
        a predefined move's target: its target argument, or an offset of ``Offs`` too small
        to carry a coordinate out of the num range, whose result does."""
        parent = parents[-1] if parents else None
        if not isinstance(parent, ast.Argument) or len(parents) < 2:
            return False
        call = parents[-2]
        if not isinstance(call, (ast.ProcedureCall, ast.FunctionCall)):   # %name% args
            return False
        if scope.lookup(call.name.key) is not None:            # the program's own routine
            return False
        if isinstance(call, ast.FunctionCall) and call.name.key == "OFFS":
            offset = parent is not call.args[0]
            return (bound <= OFFSET_MAX if offset else
                    _small_offsets(call, parents, scope, self.fixed_data())) and \
                self._shapes_target(call, parents[:-2], scope)
        if not isinstance(call, ast.ProcedureCall) or call.name.key not in MOVE_ROUTINES:
            return False
        entry = lookup_procedure(call.name.key)
        for arg, parameter in matched_parameters(call.args, entry.signature.parameters):
            if arg is parent:
                return parameter is not None and parameter.key in MOVE_TARGETS
        return False

    def _target_place(self, place: Place, seen: set) -> bool:
        """Data (a robtarget, a jointtarget, a num) whose every read only shapes moves'
        targets: whole or by components, through ``+ - *``, as a target or an ``Offs``
        argument, or stored into such data (itself included)."""
        symbol, _ = place
        if symbol.by_reference or symbol.storage != "VAR" or \
                isinstance(symbol.type, ArrayType):
            return False
        if place in seen:
            return True
        seen.add(place)
        size = self.fixed_data().get(symbol.slot, NUM_MAX) if symbol.kind == GLOBAL_DATA \
            else NUM_MAX                # module data of a known size (a GI's reading / 10)
        for read in self.reads().get(place, ()):
            node, parents, bound = _through_offs(
                *_inert_result(*_components(read.node, list(read.parents)), size,
                               read.scope, self.fixed_data()), read.scope, self.fixed_data())
            parent = parents[-1] if parents else None
            if self._shapes_target(node, parents, read.scope, bound):
                continue
            if isinstance(parent, ast.Assignment) and parent.value is node:
                into = self._place(_base(parent.target), read, any_type=True)
                if into is not None and self._target_place(into, seen):
                    continue
            return False
        return True

    def robot_unobserved(self) -> bool:
        """Whether no property's atom reads a robot and the code reads a robot's position
        only to move it again (``pos := CRobT(); pos.trans.z := pos.trans.z - 250;
        MoveL pos, ...``): where it went then tells no behaviour apart."""
        if self.robot_observed:
            return False
        if self._robot_read is None:
            self._robot_read = not all(self._reader_only_moves(node, parents, routine)
                                       for routine in self.routines
                                       for node, parents in ast.walk(routine.ast)
                                       if isinstance(node, (ast.FunctionCall, ast.ProcedureCall))
                                       and node.name.key in ROBOT_READERS)
        return not self._robot_read

    def position_reads_kept(self) -> list:
        """The calls of CRobT, CPos and CJointT in the code whose value does more than shape
        moves' targets (a condition, an index, an argument ...): what the program does there
        may depend on where the robot is, and so on where it started."""
        return [node for routine in self.routines for node, parents in ast.walk(routine.ast)
                if isinstance(node, ast.FunctionCall) and node.name.key in POSITION_READERS
                and routine.scope.lookup(node.name.key) is None
                and not self._reader_only_moves(node, parents, routine)]

    def _reader_only_moves(self, call, parents: tuple, routine) -> bool:
        if not isinstance(call, ast.FunctionCall) or call.name.key not in ROBOT_PARTS or \
                routine.scope.lookup(call.name.key) is not None:
            return False
        node, parents, bound = _through_offs(
            *_inert_result(*_components(call, list(parents)), NUM_MAX, routine.scope,
                           self.fixed_data()), routine.scope, self.fixed_data())
        parent = parents[-1] if parents else None
        if self._shapes_target(node, parents, routine.scope, bound):
            return True
        if isinstance(parent, ast.Assignment) and parent.value is node:
            read = Read(node, tuple(parents), routine.scope, routine)
            place = self._place(_base(parent.target), read, any_type=True)
            return place is not None and self._target_place(place, set())
        return False

    # --- data that holds the value --------------------------------------------------------

    def _follow(self, place: Place, uses: Uses, integral: bool, classify, seen: set) -> None:
        if place in seen:
            return
        seen.add(place)
        symbol, _ = place
        if symbol.name not in uses.through:
            uses.through.append(symbol.name)
        for read in self.reads().get(place, ()):
            self.raw(read, uses, integral, classify, seen)
            if uses.refusal is not None:
                return
        for argument_place in self._bound_arguments(place, uses):
            self._follow(argument_place, uses, integral, classify, seen)

    def _sink_place(self, place: Place, uses: Uses, seen: set) -> bool:
        """Data whose every read is whole an argument no model evaluates."""
        symbol, _ = place
        if symbol.by_reference or symbol.storage not in ("VAR",):
            return False
        key = ("sink",) + place
        if key in seen:
            return True
        seen.add(key)
        for read in self.reads().get(place, ()):
            parent = read.parents[-1] if read.parents else None
            if not (isinstance(parent, ast.Argument) and len(read.parents) >= 2 and
                    isinstance(read.parents[-2], ast.ProcedureCall) and
                    unevaluated_argument(read.parents[-2], parent, read.scope)):
                return False
        if symbol.name not in uses.through:
            uses.through.append(symbol.name)
        return True

    def _place(self, target, read: Read, any_type: bool = False) -> Optional[Place]:
        """The data ``target`` (a name) denotes, when the analysis may follow it."""
        if not isinstance(target, ast.NameRef):
            return None
        self.reads()
        if self._by_name:
            return None
        symbol = read.scope.lookup(target.name.key)
        if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA):
            return None
        if symbol.storage not in WRITABLE or isinstance(symbol.type, ArrayType):
            return None
        if not any_type and getattr(symbol.type, "key", "") not in NUMERIC:
            return None
        if self.observed_names is None or symbol.name.upper() in self.observed_names:
            return None
        return (symbol, read.routine.index if symbol.kind == LOCAL_DATA else None)

    def _unfollowed(self, target, read: Read) -> str:
        """Why the data ``target`` names is not followed."""
        symbol = read.scope.lookup(target.name.key) if isinstance(target, ast.NameRef) else None
        if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA):
            return "not data of the task"
        if self.observed_names is None or symbol.name.upper() in self.observed_names:
            return "data a property's atom reads"
        if symbol.storage not in WRITABLE:
            return f"{symbol.storage} data, which another task may read"
        return "not a num"

    def _own_parameter(self, call, argument: ast.Argument, read: Read) -> Optional[Place]:
        """The parameter of the program's own routine that ``argument`` is bound to."""
        if not isinstance(call, (ast.ProcedureCall, ast.FunctionCall)):
            return None
        routine = self._own_routine(call, read.scope)
        if routine is None:
            return None
        for arg, parameter in matched_parameters(call.args, routine.parameters):
            if arg is argument and parameter is not None:
                if parameter.by_reference and not isinstance(argument.value, ast.NameRef):
                    return None
                if getattr(parameter.type, "key", "") not in NUMERIC:
                    return None
                symbol = routine.scope.lookup(parameter.key)
                if symbol is None or symbol.kind != LOCAL_DATA:
                    return None
                if self.observed_names is None:
                    return None
                return (symbol, routine.index)
        return None

    def _bound_arguments(self, place: Place, uses: Uses) -> list:
        """For a by-reference parameter: the data every call passes for it (a value stored
        into the parameter is stored there)."""
        symbol, routine_index = place
        if not (symbol.kind == LOCAL_DATA and symbol.storage in ("VAR", "INOUT")
                and symbol.by_reference) or routine_index is None:
            return []
        if self._late_calls:            # a call by a computed name may pass any data
            uses.refusal = f"'{symbol.name}' is a by-reference parameter, and a routine is " \
                "called by a name computed at run time (%...%), which may pass any data"
            return []
        places = []
        for read in self._calls_of(routine_index):
            call = read.node
            routine = self._routine(routine_index)
            for arg, parameter in matched_parameters(call.args, routine.parameters):
                if parameter is None or parameter.key != symbol.name.upper():
                    continue
                bound = self._place(arg.value, read)
                if bound is None:
                    uses.refusal = _at(Read(arg.value or call, read.parents, read.scope,
                                            read.routine),
                                       f"passed for {routine.name}'s {parameter.mode} parameter "
                                       f"{parameter.name}, which holds an input's value, and "
                                       f"is {self._unfollowed(arg.value, read)}")
                    return []
                places.append(bound)
        return places

    # --- indexes of the program -----------------------------------------------------------

    def reads(self) -> dict:
        """Place -> its reads, over every routine (assignment targets are writes)."""
        if self._reads is None:
            self._reads = {}
            self._calls = {}
            for routine in self.routines:
                for node, parents in ast.walk(routine.ast):
                    if isinstance(node, ast.LateBindingCall):
                        self._late_calls = True
                    if isinstance(node, ast.ProcedureCall) and node.name.key in BY_NAME:
                        self._by_name = True
                    if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                        callee = self._own_routine(node, routine.scope)
                        if callee is not None:
                            self._calls.setdefault(callee.index, []).append(
                                Read(node, parents, routine.scope, routine))
                    if not isinstance(node, ast.NameRef) or _written(node, parents):
                        continue
                    symbol = routine.scope.lookup(node.name.key)
                    if symbol is None or symbol.kind not in (GLOBAL_DATA, LOCAL_DATA):
                        continue
                    place = (symbol, routine.index if symbol.kind == LOCAL_DATA else None)
                    self._reads.setdefault(place, []).append(
                        Read(node, parents, routine.scope, routine))
        return self._reads

    def fixed_data(self) -> dict:
        """Store slot -> a bound of the size, for each module ``VAR num`` whose value is
        known to stay small: no routine may write it (``_may_write``), so it holds its
        initial value all along, or every write is a whole assignment ``x := e`` whose
        ``e`` has a size bound (``_magnitude``) from what is already known here (a group
        input's reading, a constant, other such data; ``x`` itself never, so a write that
        grows it keeps it unknown), and the bound is the largest of them and the initial
        value.  Nothing is known when a routine writes data by name (``SetDataVal``).
        Routines of another namespace (an environment) resolve names to data of their
        own."""
        if self._fixed is None:
            self.reads()
            writes: dict = {}                   # slot -> [(value, scope, parents)] or None
            for routine in self.routines:
                for node, parents in ast.walk(routine.ast):
                    if isinstance(node, ast.NameRef) and \
                            _may_write(node, parents, routine.scope):
                        symbol = routine.scope.lookup(node.name.key)
                        if symbol is None or symbol.kind != GLOBAL_DATA:
                            continue
                        parent = parents[-1] if parents else None
                        whole = isinstance(parent, ast.Assignment) and parent.target is node
                        if whole and writes.get(symbol.slot, []) is not None:
                            writes.setdefault(symbol.slot, []).append(
                                (parent.value, routine.scope, tuple(parents)))
                        else:
                            writes[symbol.slot] = None      # a part, a reference: unknown
            self._fixed = {} if self._by_name else _bounded_data(self.module_data, writes)
        return self._fixed

    def _calls_of(self, routine_index: int) -> list:
        self.reads()
        return self._calls.get(routine_index, [])

    def _routine(self, index: int):
        return next(r for r in self.routines if r.index == index)

    def _own_routine(self, call, scope):
        symbol = scope.lookup(call.name.key)
        if symbol is None or symbol.kind != ROUTINE:
            return None
        return next((r for r in self.routines if r.index == symbol.slot), None)

    @staticmethod
    def _index_size(index: ast.Index, node, scope) -> Optional[int]:
        if not isinstance(index.base, ast.NameRef):
            return None
        symbol = scope.lookup(index.base.name.key)
        kind = getattr(symbol, "type", None)
        if not isinstance(kind, ArrayType):
            return None
        position = next(k for k, i in enumerate(index.indices) if i is node)
        size = kind.dims[position] if position < len(kind.dims) else None
        return size if size is not None and size <= MAX_INDEXED else None


def _bounded_data(module_data, writes: dict) -> dict:
    """Store slot -> size bound of the module ``VAR num`` data ``writes`` (slot -> the
    whole assignments to it, or None when it is written otherwise) lets be bounded: data
    never written has its initial value's size; data every write of which has a bound
    below the largest num from the bounds found so far gets the largest of them and its
    initial value's, round after round until no more is found.  Each bound holds in
    every state: the initial value meets it, and each write stores a value within it,
    computed from data whose bounds were proven before (never from its own)."""
    candidates = {data.slot: abs(float(data.initial)) for data in module_data
                  if data.storage == "VAR" and getattr(data.type, "key", "") in NUMERIC and
                  type(data.initial) in (int, float) and writes.get(data.slot, []) is not None}
    sizes = {slot: size for slot, size in candidates.items() if slot not in writes}
    found = True
    while found:
        found = False
        for slot, initial in candidates.items():
            if slot in sizes:
                continue
            bound = max([initial] + [_magnitude(value, scope, parents, sizes)
                                     for value, scope, parents in writes[slot]])
            if bound < NUM_MAX:
                sizes[slot] = bound
                found = True
    return sizes


def unevaluated_argument(call: ast.ProcedureCall, argument: ast.Argument, scope) -> bool:
    """Whether ``argument`` is one a predefined routine never evaluates: an IN argument of
    a routine modelled with no effect, or how fast or how close a move goes."""
    if scope.lookup(call.name.key) is not None:        # the program's own routine
        return False
    entry = lookup_procedure(call.name.key)
    if entry is None:
        return False
    unevaluated = entry.modelled == NO_EFFECT
    for arg, parameter in matched_parameters(call.args, entry.signature.parameters):
        if arg is argument:
            if parameter is None or parameter.mode.upper() != "IN":
                return False
            return unevaluated or (call.name.key in MOVE_ROUTINES and
                                   parameter.key in UNEVALUATED_BY_MOVES)
    return False


def _inert_result(node, parents: list, bound: float, scope, fixed: dict) -> tuple:
    """The outermost expression ``node``'s value (at most ``bound`` in size) goes into
    through operations that cannot fail on it, and a bound of that expression's size:
    unary minus, ``+ - *`` and division by a number literal other than 0, each while its
    result stays within the range of num for every operand of the sizes known (an analog
    input may hold the largest num: ``AInput(ai) * 10`` raises ERR_NUM_LIMIT)."""
    while parents:
        parent = parents[-1]
        if isinstance(parent, ast.Unary) and parent.op == "-":
            node = parents.pop()
            continue
        if not isinstance(parent, ast.Binary) or parent.op not in INERT_OPS + ("/",):
            break
        other = parent.right if parent.left is node else parent.left
        size = _magnitude(other, scope, tuple(parents), fixed)
        if parent.op == "/":
            if parent.left is not node or not isinstance(other, ast.NumLiteral) or \
                    not 0 < size < math.inf:
                break
            result = bound / size
        elif parent.op == "*":
            result = bound * size if bound and size else 0.0
        else:
            result = bound + size
            if result < NUM_MAX + ROUNDED_AWAY:     # a sum this close rounds to the largest num
                result = min(result, NUM_MAX)
        if not result <= NUM_MAX:
            break
        bound = result
        node = parents.pop()
    return node, parents, bound


def _through_offs(node, parents: list, bound: float, scope, fixed: dict) -> tuple:
    """The outermost ``Offs`` call that ``node``'s value (at most ``bound`` in size) goes
    into, as its point shifted by offsets, or as an offset, small enough (``OFFSET_MAX``)
    to carry no coordinate out of the num range, then through operations ``_inert_result``
    lets through; ``node`` itself when it is no argument of the predefined ``Offs``.  Offs only
    shifts the point, so its result is data as inert as its arguments."""
    while len(parents) >= 2 and isinstance(parents[-1], ast.Argument) and \
            isinstance(parents[-2], ast.FunctionCall) and parents[-2].name.key == "OFFS" and \
            scope.lookup("OFFS") is None:
        call = parents[-2]
        if not (_small_offsets(call, parents, scope, fixed) if parents[-1] is call.args[0]
                else bound <= OFFSET_MAX):
            break
        node, parents, bound = _inert_result(*_components(call, parents[:-2]), NUM_MAX, scope,
                                             fixed)
    return node, parents, bound


def _small_offsets(call: ast.FunctionCall, parents, scope, fixed: dict) -> bool:
    """Whether each offset of an ``Offs`` call (below ``parents``) is at most ``OFFSET_MAX``
    in size: a point read back and shifted turn by turn by a bigger one may leave the range
    of num (ERR_NUM_LIMIT), where the robot left at its start never would."""
    inner = tuple(parents) + (call,)
    return all(_magnitude(argument.value, scope, inner, fixed) <= OFFSET_MAX
               for argument in call.args[1:])


def _magnitude(expr, scope, parents: tuple = (), fixed: Optional[dict] = None) -> float:
    """A bound of the size of ``expr``'s value (math.inf: unknown): a number literal or
    CONST num, an input's reading, a function's fixed reading, a FOR variable
    (``_loop_size``), routine data nothing writes (``_initial_size``), module data of a
    known size (``fixed``: its store slot -> its size, ``InputFlow.fixed_data``), any num data,
    and ``+ - *``, unary minus and division by a number literal of such.  ``parents``: the
    ancestors of ``expr`` in its routine, outermost (the routine) first."""
    fixed = {} if fixed is None else fixed
    inner = parents + (expr,)
    if isinstance(expr, ast.Unary) and expr.op in ("-", "+"):
        return _magnitude(expr.operand, scope, inner, fixed)
    if isinstance(expr, ast.NumLiteral):
        try:
            return abs(to_num(expr.value))
        except Exception:
            return math.inf
    if isinstance(expr, ast.Binary) and expr.op in INERT_OPS:
        left, right = (_magnitude(expr.left, scope, inner, fixed),
                       _magnitude(expr.right, scope, inner, fixed))
        if expr.op == "*":
            return left * right if left and right else 0.0
        return left + right
    if isinstance(expr, ast.Binary) and expr.op == "/" and isinstance(expr.right, ast.NumLiteral):
        divisor = _magnitude(expr.right, scope, inner, fixed)
        return _magnitude(expr.left, scope, inner, fixed) / divisor \
            if 0 < divisor < math.inf else math.inf
    if isinstance(expr, ast.NameRef):
        loop = _enclosing_loop(expr, parents)
        if loop is not None:
            return _loop_size(*loop, scope, fixed)
        symbol = scope.lookup(expr.name.key)
        if symbol is not None and symbol.kind == CONSTANT and type(symbol.value) is float:
            return abs(symbol.value)
        initial = _initial_size(symbol, parents, scope)
        if initial is not None:
            return initial
        if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.slot in fixed:
            return fixed[symbol.slot]
    if isinstance(expr, (ast.NameRef, ast.Component, ast.Index)):
        found = _data_type(expr, scope)
        kind = getattr(found, "signal_kind", None) or getattr(found, "key", "")
        return {"GI": GROUP_MAX, "AI": NUM_MAX, "NUM": NUM_MAX}.get(kind, math.inf)
    if isinstance(expr, ast.FunctionCall) and scope.lookup(expr.name.key) is None:
        if expr.name.key in ("GINPUT", "AINPUT"):
            return GROUP_MAX if expr.name.key == "GINPUT" else NUM_MAX
        entry = lookup_function(expr.name.key)
        reading = getattr(getattr(entry, "factory", None), "reading", None)
        if type(reading) is float:
            return abs(reading)
    return math.inf


def _enclosing_loop(name: ast.NameRef, parents: tuple) -> Optional[tuple]:
    """The innermost FOR whose body ``name`` is in and whose variable it names, with the
    FOR's own ancestors; None when ``name`` is no FOR variable there.  A name in a FOR's
    FROM, TO or STEP is not its variable."""
    chain = tuple(parents) + (name,)
    for position in range(len(chain) - 2, -1, -1):
        loop = chain[position]
        if isinstance(loop, ast.For) and loop.variable.key == name.name.key and \
                any(statement is chain[position + 1] for statement in loop.body):
            return loop, chain[:position]
    return None


def _loop_size(loop: ast.For, parents: tuple, scope, fixed: dict) -> float:
    """A bound of a FOR variable's size in its body: FROM, TO and STEP are evaluated once
    on entry, and the body runs only with the variable between FROM and TO (ForInit,
    ForNext), so the larger of their sizes; STEP only chooses which values between."""
    inner = parents + (loop,)
    return max(_magnitude(loop.start, scope, inner, fixed),
               _magnitude(loop.stop, scope, inner, fixed))


def _initial_size(symbol, parents: tuple, scope) -> Optional[float]:
    """The size of the initial value of routine data ``symbol`` (a ``VAR num`` of the routine
    ``parents`` begins with) when nothing in that routine may write it: no assignment to it,
    no ``CONNECT`` to it, and no argument of it but for an IN parameter of a predefined
    routine.  Routine data lives in its routine's frame: no other routine names it, and
    ``SetDataVal`` reaches only global data.  None: unknown."""
    if symbol is None or symbol.kind != LOCAL_DATA or symbol.storage != "VAR" or \
            symbol.by_reference or getattr(symbol.type, "key", "") not in NUMERIC or \
            not parents or not isinstance(parents[0], ast.Routine):
        return None
    routine = parents[0]
    declaration = next((d for d in routine.data if d.name.key == symbol.name.upper()), None)
    if declaration is None or declaration.dims:
        return None
    for node, ancestors in ast.walk(routine):
        if isinstance(node, ast.NameRef) and node.name.key == declaration.name.key and \
                _may_write(node, ancestors, scope):
            return None
    if declaration.init is None:
        return 0.0
    return _magnitude(declaration.init, scope, (routine,))


def _may_write(node: ast.NameRef, parents: tuple, scope) -> bool:
    """Whether ``node`` (or the data it is the base of) may be written where it stands: an
    assignment's or CONNECT's target, or an argument of anything but an IN parameter of a
    predefined routine (the program's own routines are not looked into)."""
    child = node
    for position in range(len(parents) - 1, -1, -1):
        parent = parents[position]
        if isinstance(parent, (ast.Component, ast.Index)) and parent.base is child:
            child = parent
            continue
        if isinstance(parent, (ast.Assignment, ast.Connect)):
            return parent.target is child
        if not isinstance(parent, ast.Argument):
            return False
        call = parents[position - 1] if position else None
        if not isinstance(call, (ast.ProcedureCall, ast.FunctionCall)) or \
                scope.lookup(call.name.key) is not None:
            return True
        entry = lookup_procedure(call.name.key) if isinstance(call, ast.ProcedureCall) \
            else lookup_function(call.name.key)
        if entry is None:
            return True
        return not any(arg is parent and parameter is not None and not parameter.by_reference
                       for arg, parameter in matched_parameters(call.args,
                                                                entry.signature.parameters))
    return False


def _data_type(expr, scope):
    """The type of the data ``expr`` names (``pos.trans.z``: num), or None."""
    if isinstance(expr, ast.NameRef):
        symbol = scope.lookup(expr.name.key)
        return getattr(symbol, "type", None) if symbol is not None and \
            symbol.kind in (GLOBAL_DATA, LOCAL_DATA, CONSTANT, SIGNAL) else None
    if isinstance(expr, ast.Index):
        found = _data_type(expr.base, scope)
        return found.element if isinstance(found, ArrayType) and \
            len(expr.indices) == found.rank else None
    if isinstance(expr, ast.Component):
        found = _data_type(expr.base, scope)
        components = getattr(found, "components", ())
        return next((c.type for c in components if c.key == expr.name.key), None)
    return None


def _components(node, parents: list) -> tuple:
    """``pos.trans.z`` for a read of ``pos`` there: a part of the same data."""
    while parents and isinstance(parents[-1], ast.Component) and parents[-1].base is node:
        node = parents.pop()
    return node, parents


def _unwrapped(node, parents: list) -> tuple:
    """``GInput(s)`` / ``AInput(s)`` for a read of ``s`` inside one: the value is the same."""
    if len(parents) >= 2 and isinstance(parents[-1], ast.Argument) and \
            isinstance(parents[-2], ast.FunctionCall) and \
            parents[-2].name.key in ("GINPUT", "AINPUT") and parents[-2].args[0] is parents[-1]:
        return parents[-2], parents[:-2]
    return node, parents


def _base(target):
    """The data a target of an assignment writes into (``speed`` of ``speed.v_tcp``)."""
    while isinstance(target, (ast.Component, ast.Index)):
        target = target.base
    return target


def _written(node: ast.NameRef, parents: tuple) -> bool:
    """Whether ``node`` is (the base of) an assignment's target: a write, not a read."""
    child = node
    for parent in reversed(parents):
        if isinstance(parent, ast.Assignment):
            return parent.target is child
        if isinstance(parent, (ast.Component, ast.Index)) and parent.base is child:
            child = parent
            continue
        return False
    return False


def _at(read: Read, what: str) -> str:
    node = read.node
    name = node.name.text if isinstance(node, ast.NameRef) else "the value"
    span = getattr(node, "span", None)
    where = f"{span.file}:{span.line}:{span.column}" if span is not None else "an unknown place"
    return f"'{name}' at {where} is {what}"


Found = Union[set, str]
