"""Data that only shapes where moves go, when the check leaves the robot's position out.

Where nothing but moves reads the robot's position (``model.robot_tracking``), a
move evaluates its arguments and leaves the robot where it is: the value of its
target (``ToPoint``, ``CirPoint``, ``ToJointPos``) changes no state.  Real programs
keep data that feeds nothing else: a stack height that grows by a disc per
place (``NShaft1Z4 := NShaft1Z4 - NDH``, then ``MoveL Offs(Shaft1,0,0,NShaft1Z4)``),
a layer offset ``h := h + 20`` passed to ``Place(Offs(Target_30,0,0,h))``.  Each
cycle leaves a new value (float32 sums do not come back to the same bits), so the
check never ends although the program repeats after a few states.

``MoveShaping`` is the cone of influence of ``relevance`` with three readings
relaxed; the data it no longer finds relevant *shape moves only*:

* a move's target whose expression is arithmetic (``ShapingTotality``: data, literals,
  sums, differences and unary minus of numbers, products by a constant number (a literal
  or a CONST: a layer's height ``nActLayer*nBoxSizeZ``), ``Offs`` of such) is not
  observed, where the robot is not tracked;
* a call of a user procedure whose arguments are all positional passes each such
  argument to an ``IN`` parameter as an assignment would (``param := argument``),
  instead of making its data relevant;
* an assignment ``x := e`` with ``e`` arithmetic passes influence on, as a total one does.

What remains between this reading and the exact one is whether that arithmetic leaves
num's range (ERR_NUM_LIMIT: ``x := x + x`` forever, or adding a value near the largest
num): the reduction assumes it does not, and the verdicts say so under ``assumes:`` (``findings.assumptions``), naming the
data.  Everything else of ``relevance`` holds: a condition, an index, a divisor, any
other call, an atom that reads the data keeps it, and so does a product fed back into
its own factor (``x := x * 2``: it leaves the range within about 128 cycles, so the
assumption would not hold).  ``--track-robot`` keeps it too.
"""
from __future__ import annotations

from typing import Optional

from ... import ast
from ...semantics.library import registry
from ...semantics.library.arguments import argument_expression
from ...semantics.library.motion import MOVE_ROUTINES
from ...semantics.scope import CONSTANT, ROUTINE
from .relevance import _Analysis
from .totality import LITERAL, NUMERIC, SMALL_LITERAL, Info, Totality

# the arguments of a move that say where it goes
TARGETS = ("CIRPOINT", "TOPOINT", "TOJOINTPOS")
_ARITHMETIC = frozenset({"+", "-"})


class ShapingTotality(Totality):
    """``Totality`` with sums and differences of numbers and ``Offs`` of a robtarget by
    numbers, and their products by a constant number, taken as total: they never fail but
    for leaving num's range, which the reduction of move-shaping data assumes they do not
    (``MoveShaping.run`` keeps a product fed back into its factor; other products and
    quotients are not total: a quotient may divide by zero)."""

    def _Binary(self, expr: ast.Binary) -> Optional[Info]:
        found = super()._Binary(expr)
        if found is not None:
            return found
        if expr.op == "*":
            return self._scaled(expr)
        if expr.op not in _ARITHMETIC:
            return None
        left, right = self.info(expr.left), self.info(expr.right)
        if left is None or right is None or left[0] not in NUMERIC or right[0] not in NUMERIC:
            return None
        if left[0] == LITERAL:
            return right
        return left if right[0] in (LITERAL, left[0]) else None

    def _scaled(self, expr: ast.Binary) -> Optional[Info]:
        """``a * c`` or ``c * a`` with ``c`` a constant number (a literal or a CONST): a
        fixed multiple of arithmetic (a layer's height, ``nActLayer*nBoxSizeZ``)."""
        for factor, constant in ((expr.left, expr.right), (expr.right, expr.left)):
            if self.constant(constant):
                info = self.info(factor)
                if info is not None and info[0] in NUMERIC:
                    return info
        return None

    def constant(self, expr) -> bool:
        if isinstance(expr, ast.NumLiteral):
            return self.info(expr) is not None
        if isinstance(expr, ast.NameRef):
            symbol = self.lookup(expr.name)
            return symbol is not None and symbol.kind == CONSTANT and \
                isinstance(symbol.value, (int, float)) and not isinstance(symbol.value, bool) \
                and abs(symbol.value) <= SMALL_LITERAL
        return False

    def _FunctionCall(self, expr: ast.FunctionCall) -> Optional[Info]:
        if expr.name.key != "OFFS" or self.lookup(expr.name) is not None:
            return super()._FunctionCall(expr)
        if len(expr.args) != 4 or any(argument.kind != ast.REQUIRED or argument.name is not None
                                      for argument in expr.args):
            return None
        point, *offsets = (self.info(argument.value) for argument in expr.args)
        if point is None or point[0] != "ROBTARGET" or \
                any(offset is None or offset[0] not in ("NUM", LITERAL) for offset in offsets):
            return None
        return ("ROBTARGET", 0)


class MoveShaping(_Analysis):
    """The relevant data when moves' targets are not observed (module docstring)."""

    totality_type = ShapingTotality

    def __init__(self, program):
        super().__init__(program)
        # (key assigned, keys its value reads) of each assignment of a product
        self.products: list[tuple] = []

    def run(self) -> bool:
        """``_Analysis.run``, then a product whose value flows back into its own factors
        (``x := x * 2``, through other data too) keeps them: it grows geometrically and
        leaves num's range within about 128 cycles, which the assumption would hide."""
        if not super().run():
            return False
        for target, keys in self.products:
            if target in self.sources(keys):
                self.relevant.update(keys)
        return True

    def _note_products(self, target, value) -> None:
        if target is not None and any(isinstance(node, ast.Binary) and node.op == "*"
                                      for node, _ in ast.walk(value)):
            self.products.append((target, set(self.keys_read(value))))

    def assignment(self, statement: ast.Assignment) -> None:
        super().assignment(statement)
        if isinstance(statement.target, ast.NameRef):
            self._note_products(self.key(statement.target.name), statement.value)

    def statement(self, statement) -> bool:
        if type(statement).__name__ == "ProcedureCall" and \
                isinstance(statement.name, ast.Name):
            symbol = self.routine.scope.lookup(statement.name.key)
            if symbol is None and statement.name.key in MOVE_ROUTINES:
                self.move(statement)
                return True
            if symbol is not None and symbol.kind == ROUTINE:
                self.user_call(statement, self.program.routines[symbol.slot])
                return True
        return super().statement(statement)

    def move(self, call: ast.ProcedureCall) -> None:
        """A move: its arithmetic targets are not observed, every other argument is."""
        entry = registry.lookup_procedure(call.name.key)
        required = [parameter.key.upper() for parameter in entry.signature.parameters
                    if not parameter.optional] if entry is not None else []
        unobserved = set()
        for key in TARGETS:
            position = required.index(key) if key in required else -1
            expression = argument_expression(call, key, position)
            if expression is not None and self.totality.info(expression) is not None:
                unobserved.add(id(expression))
        for argument in call.args:
            if id(argument.value) not in unobserved:
                self.seed(argument)

    def user_call(self, call: ast.ProcedureCall, callee) -> None:
        """A user procedure: an arithmetic argument of an IN parameter is assigned to it."""
        parameters = callee.parameters
        plain = len(call.args) == len(parameters) and all(
            argument.kind == ast.REQUIRED and argument.name is None for argument in call.args)
        if not plain:
            self.seed(call)
            return
        for argument, parameter in zip(call.args, parameters):
            if parameter.by_reference or parameter.optional or \
                    not self.totality.assignable(argument.value, parameter.type):
                self.seed(argument)
            else:
                key = ("L", callee.index, parameter.slot)
                self.flows.setdefault(key, set()).update(self.keys_read(argument.value))
                self._note_products(key, argument.value)
