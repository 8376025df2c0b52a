"""Which error numbers a statement may raise, and which branches of an ERROR handler's
tests of ERRNO such an error can take (issue 28).

The dead-data analysis (``liveness``) analyses a routine's ERROR handler once per
statement an error may come from: RETRY goes back to that statement, TRYNEXT on after it.
A server's handler usually TRYNEXTs only for a few numbers (a lost UDP connection, a
closed socket, a motion error the program booked) and RETRYs after reconnecting for every
other.  When the statement's errors are known, the branches for the other numbers are
not taken, and what TRYNEXT would read after the statement is not live before it.

* ``StatementErrors.errors(node)``: the errors of an assignment ``x := e`` to data named
  directly: none when ``e`` is total (``Totality``), ERR_ARGVALERR for ``NOrient`` of a
  total orient (a zero quaternion), the union over an aggregate's items; None (any error)
  for every other statement.
* ``ErrnoTests``: for the handler's instructions ``IF ERRNO = c`` / ``ERRNO <> c`` and
  ``TEST ERRNO``, the successors an error of known numbers may take.  ``c`` is a literal,
  a predefined ERR_ constant, or a *booked* errnum: VAR data of the program that only
  ``BookErrNo`` writes (the controller books 1..90, never a predefined number 1001 and
  above), whose initial value is below 1001, and which elsewhere is only compared, tested,
  raised or listed in a handler's number list.  Only tests every path from the handler's
  start reaches with ERRNO unchanged are pruned: no instruction before them calls a user
  routine (one that handles an error of its own changes ERRNO).  And only when no
  interrupt can change ERRNO: every TRAP's handler (if any) starts with RAISE (the error
  then stops the program, ``errors_flow``) and no routine a TRAP calls has a handler.
"""
from __future__ import annotations

from typing import Optional

from ... import ast
from ...semantics.errors import ERROR_NUMBERS
from ...semantics.instructions import Action, Branch, Jump, Raise, TestDispatch
from ...semantics.library.program_control import CALLS_BY_NAME
from ...semantics.scope import CONSTANT, GLOBAL_DATA, ROUTINE
from .merging import JUMP_FIELDS
from .totality import Totality, _parts

ANY = None                       # the errors of a statement that may raise anything
PREDEFINED_FIRST = min(ERROR_NUMBERS.values())
BOOKED = "booked"                # a test value that is never a predefined number
UNKNOWN = "unknown"              # a test value that may be any number
# instructions the handler may run before a test of ERRNO without changing it, with the
# predefined actions, when their syntax calls no user routine (``_keeps_errno``)
KEEPS_ERRNO = (Branch, Jump, TestDispatch)


class StatementErrors:
    """The errors of assignments in one routine (``totality`` resolves its names)."""

    def __init__(self, totality: Totality):
        self.totality = totality

    def errors(self, node) -> Optional[frozenset]:
        if not isinstance(node, ast.Assignment) or not isinstance(node.target, ast.NameRef):
            return ANY
        symbol = self.totality.lookup(node.target.name)
        if symbol is None or symbol.by_reference or symbol.optional:
            return ANY
        return self._value_errors(node.value, symbol.type)

    def _value_errors(self, expr, target_type) -> Optional[frozenset]:
        if self.totality.assignable(expr, target_type):
            return frozenset()
        if isinstance(expr, ast.Aggregate):
            parts = _parts(target_type, len(expr.items))
            if parts is None:
                return ANY
            found: set = set()
            for item, part in zip(expr.items, parts):
                errors = self._value_errors(item, part)
                if errors is ANY:
                    return ANY
                found |= errors
            return frozenset(found)
        if isinstance(expr, ast.FunctionCall) and expr.name.key == "NORIENT" and \
                self.totality.lookup(expr.name) is None and \
                getattr(target_type, "key", "") == "ORIENT" and len(expr.args) == 1 and \
                expr.args[0].kind == ast.REQUIRED and expr.args[0].name is None and \
                self.totality.assignable(expr.args[0].value, target_type):
            return frozenset({"ERR_ARGVALERR"})    # a zero quaternion has no orientation
        return ANY


class ErrnoTests:
    """The feasible successors of a routine's handler tests of ERRNO (module docstring)."""

    def __init__(self, program, routine, nodes: dict, booked: Optional["BookedErrnums"] = None):
        self.routine = routine
        self.nodes = nodes
        self.booked = (booked or BookedErrnums(program)).slots()
        self.prunable = _stable_tests(program, routine, nodes)

    def targets(self, pc: int, errors: Optional[frozenset]) -> Optional[list]:
        """The successors of handler instruction ``pc`` an error of ``errors`` may take,
        or None when all may be taken."""
        if errors is ANY or not errors or pc not in self.prunable:
            return None
        numbers = {ERROR_NUMBERS[name] for name in errors}
        instruction, node = self.routine.code[pc], self.nodes.get(self.routine.code[pc].span)
        if isinstance(instruction, Branch) and isinstance(node, (ast.IfBranch, ast.While)):
            return self._branch(instruction, node.condition, numbers)
        if isinstance(instruction, TestDispatch) and isinstance(node, ast.Test) and \
                self._is_errno(node.subject) and len(node.cases) == len(instruction.cases):
            return self._test(instruction, node, numbers)
        return None

    def _branch(self, instruction: Branch, condition, numbers: set) -> Optional[list]:
        if not isinstance(condition, ast.Binary) or condition.op not in ("=", "<>"):
            return None
        for errno, other in ((condition.left, condition.right),
                             (condition.right, condition.left)):
            if self._is_errno(errno):
                value = self._value(other)
                equal = {self._may_equal(value, n) for n in numbers}
                if True in equal and False in equal or value == UNKNOWN:
                    return None
                holds = (True in equal) == (condition.op == "=")
                return [instruction.target_true if holds else instruction.target_false]
        return None

    def _test(self, instruction: TestDispatch, node: ast.Test, numbers: set) -> list:
        targets = set()
        for number in numbers:
            matched = False
            for case, (_, target) in zip(node.cases, instruction.cases):
                answers = {self._may_equal(self._value(value), number) for value in case.values}
                if answers & {True, UNKNOWN}:
                    targets.add(target)
                if True in answers:          # this case takes it: later ones never do
                    matched = True
                    break
            if not matched:
                targets.add(instruction.default)
        return sorted(targets)

    def _is_errno(self, expr) -> bool:
        return isinstance(expr, ast.NameRef) and expr.name.key == "ERRNO" and \
            self.routine.scope.lookup("ERRNO") is None

    def _value(self, expr):
        """A test value: its number, BOOKED or UNKNOWN."""
        if isinstance(expr, ast.NumLiteral):
            return expr.value
        if isinstance(expr, ast.NameRef):
            symbol = self.routine.scope.lookup(expr.name.key)
            if symbol is not None and symbol.kind == CONSTANT and \
                    isinstance(symbol.value, (int, float)) and not isinstance(symbol.value, bool):
                return symbol.value
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.slot in self.booked:
                return BOOKED
        return UNKNOWN

    @staticmethod
    def _may_equal(value, number: int):
        """True, False, or UNKNOWN when ``value`` may or may not be ``number``."""
        if value == UNKNOWN:
            return UNKNOWN
        if value == BOOKED:
            return False
        return value == number


class BookedErrnums:
    """``_booked_errnums`` of one program, walked once when first asked: an analysis of
    every routine (``liveness``) asks it for each routine with an ERROR handler."""

    def __init__(self, program):
        self.program = program
        self._slots: Optional[set] = None

    def slots(self) -> set:
        if self._slots is None:
            self._slots = _booked_errnums(self.program)
        return self._slots


def _booked_errnums(program) -> set:
    """Global slots of VAR data only BookErrNo writes (module docstring)."""
    candidates = {data.key: data for data in program.globals
                  if data.storage == "VAR" and getattr(data.type, "key", "") == "NUM"
                  and isinstance(data.initial, (int, float)) and data.initial < PREDEFINED_FIRST}
    booked = {key for key in candidates}
    for routine in program.routines:
        if routine.ast is None or getattr(routine, "scope", None) is None:
            continue
        for node, parents in ast.walk(routine.ast):
            if not isinstance(node, ast.NameRef) or node.name.key not in booked:
                continue
            symbol = routine.scope.lookup(node.name.key)
            if symbol is None or symbol.kind != GLOBAL_DATA or \
                    symbol.slot != candidates[node.name.key].slot:
                continue
            if not _compared_or_booked(node, parents):
                booked.discard(node.name.key)
    return {candidates[key].slot for key in booked}


def _compared_or_booked(node, parents: tuple) -> bool:
    parent = parents[-1] if parents else None
    if isinstance(parent, ast.Argument):
        call = parents[-2] if len(parents) > 1 else None
        return isinstance(call, ast.ProcedureCall) and call.name.key == "BOOKERRNO"
    if isinstance(parent, ast.Binary):
        return parent.op in ("=", "<>")
    if isinstance(parent, ast.TestCase):
        return node in parent.values
    if isinstance(parent, ast.Test):
        return parent.subject is node
    if isinstance(parent, ast.Raise):
        return True
    if isinstance(parent, ast.ErrorHandler):
        return parent.numbers is not None and node in parent.numbers
    return False


def _stable_tests(program, routine, nodes: dict) -> set:
    """The handler pcs every path from the handler's start reaches with ERRNO unchanged
    (none when an interrupt may change it)."""
    start = routine.handler_pc
    if start < 0 or not _traps_keep_errno(program, routine):
        return set()
    end = routine.undo_pc if routine.undo_pc > start else len(routine.code)
    successors = {pc: _handler_successors(routine.code[pc], start, end)
                  for pc in range(start, end)}
    reached = _closure([start], successors)
    changing = [target for pc in reached if not _keeps_errno(routine, pc, nodes)
                for target in successors[pc]]
    return reached - _closure(changing, successors)


def _closure(first: list, successors: dict) -> set:
    seen, todo = set(first), list(first)
    while todo:
        for target in successors[todo.pop()]:
            if target not in seen:
                seen.add(target)
                todo.append(target)
    return seen


def _keeps_errno(routine, pc: int, nodes: dict) -> bool:
    instruction = routine.code[pc]
    if isinstance(instruction, KEEPS_ERRNO):
        return not _calls_user_routine(nodes.get(instruction.span), routine)
    return type(instruction) is Action and \
        not _calls_user_routine(nodes.get(instruction.span), routine)


def _handler_successors(instruction, start: int, end: int) -> list:
    targets = [getattr(instruction, field, None) for field in JUMP_FIELDS]
    if isinstance(instruction, TestDispatch):
        targets += [target for _, target in instruction.cases]
    return [t for t in targets if isinstance(t, int) and start <= t < end]


def _calls_user_routine(node, routine) -> bool:
    if node is None:
        return True
    for inner, _ in ast.walk(node):
        if isinstance(inner, ast.LateBindingCall):
            return True
        if isinstance(inner, (ast.ProcedureCall, ast.FunctionCall)):
            symbol = routine.scope.lookup(inner.name.key)
            if symbol is not None:
                return True
            if inner.name.key in CALLS_BY_NAME:
                return True
    return False


def _traps_keep_errno(program, analysed) -> bool:
    """No interrupt can change ERRNO while ``analysed``'s handler runs: every TRAP's
    handler starts with RAISE (the error stops the program), and no routine a TRAP calls
    has a handler or is ``analysed``, nor calls a routine by a name computed at run time."""
    todo = [routine for routine in program.routines if routine.kind == "TRAP"]
    for trap in todo:
        if trap.handler_pc >= 0 and not isinstance(trap.code[trap.handler_pc], Raise):
            return False
    seen = {routine.index for routine in todo}
    while todo:
        routine = todo.pop()
        if routine is analysed or routine.ast is None or \
                routine.kind != "TRAP" and routine.handler_pc >= 0:
            return False
        for node, _ in ast.walk(routine.ast):
            if isinstance(node, ast.LateBindingCall) or \
                    isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) and \
                    node.name.key in CALLS_BY_NAME:
                return False
            if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
                symbol = routine.scope.lookup(node.name.key)
                if symbol is not None and symbol.kind == ROUTINE and symbol.slot not in seen:
                    seen.add(symbol.slot)
                    todo.append(program.routines[symbol.slot])
    return True
