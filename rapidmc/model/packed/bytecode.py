"""The fused steps and atoms as code for the compiled core's step machine (``_packed.c``).

A routine's fused steps (``semantics.fused_step``) are Python source written
per instruction; the same instructions compile here to a small stack code:
one block per pc (the quiet blocks: assignments in ``config.skipped_writes``
left out, as the unlabelled entries do), run by the machine with the
routine's merge kinds exactly as ``FusedRoutine.run`` runs them.  The
expressions are compiled from their Python sources (``Compiled.source``,
read with the ``ast`` module): the vocabulary is small and fixed
(``store[i]``, ``locals_[i]``, ``_read(cx, i)``, constants, aggregates, comparisons,
``bool(a & b)``, ``not``, ``-``, ``+ - *``, ``_to_num`` and the other
arithmetic helpers), and whatever else a source holds (a function call,
string concatenation) compiles to ``UNSUPPORTED``: the machine gives up at
that block and the search asks the Python step, which is the reference.

Waits, barriers, writes of constants (a socket's state), a received message chosen from
its site's domain (CHOOSE_CONST), moves where the robot's position is left out (their
arguments evaluated, array indexes checked: CHECK_INDEX) and writes of elements of
global arrays (SET_ELEMENT) compile too (``Instruction.machine``, ``_task_block``; a
routine with no fused block gets code for them alone): run only as one task's step among several
(TASK_ONLY), a try that does not pass is an idle step (WAIT), as ``Wait.run`` and
``library.tasks._barrier`` leave the task waiting.

Atoms (``model.fused_atoms``) compile the same way, each between
``ATOM_BEGIN`` and ``ATOM_END`` (a RAPID error makes the atom false).

Example::

    code = RoutineCode.compile(program, config, routine_index, value_ids)
    code.block_start[pc]      # where pc's block starts in code.code (-1: none)
"""
from __future__ import annotations

import ast as python_ast
from array import array
from typing import Callable, Optional

from ...semantics.fused_step import NEVER_JOINS, block_targets, routine_fused
from ...semantics.instructions import (
    Action, Branch, CallPlan, CheckedReads, ChosenWrite, ConstantWrite, ElementWrite, ForInit,
    ForNext, Jump, LeavePlan, TestDispatch, Wait)

# opcodes, in the order of _packed.c's enum (from 1)
OPCODES = ("CONST LOAD_STORE LOAD_LOCAL READ READ_DYN ADD SUB MUL DIVIDE TO_NUM TO_DNUM "
           "INT_DIV INT_MOD NEG NOT EQ NE LT LE GT GE AND OR SET_STORE SET_LOCAL SET_TEMP "
           "GET_TEMP GOTO BRANCH GOTO_IF RESET_CHOSEN UNSUPPORTED FOR_DEFAULT_STEP FOR_INIT "
           "FOR_NEXT ATOM_BEGIN ATOM_END END TASK_ONLY JUMP_IF_FALSE REQUIRE POP CHOOSE_BOOL "
           "WAIT SYNC CHOOSE_CONST CHECK_INDEX SET_ELEMENT BUILD_TUPLE CALL LEAVE").split()
OP = {name: number for number, name in enumerate(OPCODES, 1)}
MAX_STACK = 48            # deeper expressions are left to Python (the machine has 64)
MAX_PATH = 16             # element writes with deeper components are Python's (_packed.c)
MAX_ARGUMENTS = 8         # calls with more arguments are Python's (the machine's temps)

_COMPARISONS = {python_ast.Eq: "EQ", python_ast.NotEq: "NE", python_ast.Lt: "LT",
                python_ast.LtE: "LE", python_ast.Gt: "GT", python_ast.GtE: "GE"}
_ARITHMETIC = {python_ast.Add: "ADD", python_ast.Sub: "SUB", python_ast.Mult: "MUL"}
_HELPERS = {"_to_num": ("TO_NUM", 1), "_to_dnum": ("TO_DNUM", 1), "_divide": ("DIVIDE", 2),
            "_int_div": ("INT_DIV", 2), "_int_mod": ("INT_MOD", 2)}
# the stack effect of each opcode that is not a push of one value
_POPS = {"ADD": 1, "SUB": 1, "MUL": 1, "DIVIDE": 1, "INT_DIV": 1, "INT_MOD": 1, "EQ": 1,
         "NE": 1, "LT": 1, "LE": 1, "GT": 1, "GE": 1, "AND": 1, "OR": 1}


class Unsupported(Exception):
    """Internal: this source needs the Python step."""


class ExpressionCode:
    """Compiles Python sources of ``Compiled`` expressions to machine code."""

    def __init__(self, value_id: Callable[[object], int], names: dict, store_length: int,
                 locals_allowed: bool = True):
        self.value_id = value_id
        self.names = names
        self.store_length = store_length
        self.locals_allowed = locals_allowed

    def compile(self, source: str) -> list[int]:
        """The code that pushes the value of ``source`` (Unsupported: not covered)."""
        try:
            tree = python_ast.parse(source, mode="eval")
        except SyntaxError:
            raise Unsupported(source) from None
        code: list[int] = []
        depth = self._emit(tree.body, code, 0)
        if depth > MAX_STACK:
            raise Unsupported("too deep")
        return code

    def _emit(self, node, code: list[int], depth: int) -> int:
        """Append the code of ``node``; the deepest stack it needs (``depth`` below it)."""
        kind = type(node)
        if kind is python_ast.Constant:
            return self._constant(node.value, code, depth)
        if kind is python_ast.Name:
            if node.id not in self.names:
                raise Unsupported(node.id)
            return self._constant(self.names[node.id], code, depth)
        if kind is python_ast.Subscript:
            where, slot = self._slot(node)
            if where == "store":
                if not 0 <= slot < self.store_length:
                    raise Unsupported("store slot")
                code += [OP["LOAD_STORE"], slot]
            else:
                code += [OP["LOAD_LOCAL"], slot]
            return depth + 1
        if kind is python_ast.Compare:
            if len(node.ops) != 1 or type(node.ops[0]) not in _COMPARISONS:
                raise Unsupported("comparison")
            return self._operands([node.left, node.comparators[0]], code, depth,
                                  _COMPARISONS[type(node.ops[0])])
        if kind is python_ast.UnaryOp:
            if type(node.op) is python_ast.Not:
                name = "NOT"
            elif type(node.op) is python_ast.USub:
                name = "NEG"
            else:
                raise Unsupported("unary")
            deepest = self._emit(node.operand, code, depth)
            code.append(OP[name])
            return deepest
        if kind is python_ast.BinOp:
            if type(node.op) not in _ARITHMETIC:
                raise Unsupported("operator")
            return self._operands([node.left, node.right], code, depth,
                                  _ARITHMETIC[type(node.op)])
        if kind is python_ast.Call:
            return self._call(node, code, depth)
        if kind is python_ast.Tuple:            # an aggregate: its items in order
            deepest = depth + 1
            for position, item in enumerate(node.elts):
                deepest = max(deepest, self._emit(item, code, depth + position))
            code += [OP["BUILD_TUPLE"], len(node.elts)]
            return deepest
        raise Unsupported(type(node).__name__)

    def _constant(self, value, code: list[int], depth: int) -> int:
        try:
            hash(value)
        except TypeError:
            raise Unsupported("unhashable constant") from None
        code += [OP["CONST"], self.value_id(value)]
        return depth + 1

    def _slot(self, node) -> tuple[str, int]:
        base, index = node.value, node.slice
        if type(base) is not python_ast.Name or base.id not in ("store", "locals_") or \
                type(index) is not python_ast.Constant or type(index.value) is not int:
            raise Unsupported("subscript")
        if base.id == "locals_" and not self.locals_allowed:
            raise Unsupported("local data in an atom")
        return base.id, index.value

    def _operands(self, operands: list, code: list[int], depth: int, name: str) -> int:
        deepest = depth
        for position, operand in enumerate(operands):
            deepest = max(deepest, self._emit(operand, code, depth + position))
        code.append(OP[name])
        return deepest

    def _call(self, node, code: list[int], depth: int) -> int:
        function = node.func
        if type(function) is not python_ast.Name or node.keywords:
            raise Unsupported("call")
        arguments = node.args
        if function.id == "_read" and len(arguments) == 2 and \
                type(arguments[0]) is python_ast.Name and arguments[0].id == "cx":
            index = arguments[1]
            if type(index) is python_ast.Constant and type(index.value) is int:
                code += [OP["READ"], index.value]
                return depth + 1
            deepest = self._emit(index, code, depth)
            code.append(OP["READ_DYN"])
            return deepest
        if function.id == "bool" and len(arguments) == 1 and \
                type(arguments[0]) is python_ast.BinOp and \
                type(arguments[0].op) in (python_ast.BitAnd, python_ast.BitOr):
            inner = arguments[0]
            return self._operands([inner.left, inner.right], code, depth,
                                  "AND" if type(inner.op) is python_ast.BitAnd else "OR")
        helper = _HELPERS.get(function.id)
        if helper is None or len(arguments) != helper[1]:
            raise Unsupported(function.id)
        return self._operands(arguments, code, depth, helper[0])


class RoutineCode:
    """One routine's blocks as machine code, with the tables the machine steers by."""

    def __init__(self, kinds: bytes, first_visible: bytes, block_start: array, code: array):
        self.kinds = kinds
        self.first_visible = first_visible
        self.block_start = block_start
        self.code = code

    def as_tuple(self) -> tuple:
        """What ``PackedTable.set_program`` takes per routine."""
        return (bytes(self.kinds), bytes(self.first_visible), self.block_start.tobytes(),
                self.code.tobytes())

    @classmethod
    def compile(cls, program, config, routine: int, value_id: Callable[[object], int],
                store_length: int, initial_store=None) -> Optional["RoutineCode"]:
        """The routine's code, or None when its steps are not fused (``fused_step``).
        ``initial_store``: the first state's global data (a barrier's task list is
        compiled for its value there: ``_sync_block``)."""
        fused = routine_fused(program, config, routine)
        instructions = program.routines[routine].code
        if fused is not None:
            starts, kinds, first_visible = fused.starts, fused.kinds, fused.first_visible
        elif any(getattr(instruction, "machine", None) is not None
                 for instruction in instructions):
            # (no fused block, but steps of one task among several: each its own step)
            starts = bytes(len(instructions))
            kinds, first_visible = bytes([NEVER_JOINS]) * len(instructions), \
                bytes([1]) * len(instructions)
        else:
            return None
        skipped = config.skipped_writes
        block_start = array("i", [-1]) * len(starts)
        code = array("i")
        for pc, instruction in enumerate(instructions):
            waits = getattr(instruction, "machine", None) is not None
            if not starts[pc] and not waits:
                continue
            expressions = ExpressionCode(value_id, {}, store_length)
            try:
                if waits:
                    block = _task_block(instruction, expressions, initial_store, config,
                                        program)
                else:
                    block = _block(instruction, expressions, skipped)
            except Unsupported:
                block = [OP["UNSUPPORTED"]]
            if block is None:
                continue
            block_start[pc] = len(code)
            code.extend(block)
        return cls(kinds, first_visible, block_start, code)


def _block(instruction, expressions: ExpressionCode, skipped: frozenset) -> Optional[list[int]]:
    """The code of ``instruction``'s block, as ``fused_step._block`` writes its source."""
    kind = type(instruction)
    fusion = instruction.fusion
    code: list[int] = [OP["RESET_CHOSEN"]] if instruction.reads_io else []
    if kind is Jump:
        code += [OP["GOTO"], instruction.target]
    elif kind is Branch and fusion is not None and fusion.is_constant:
        code += [OP["GOTO"], block_targets(instruction)[0]]
    elif kind is Branch and fusion is not None:
        code += _source(expressions, fusion)
        code += [OP["BRANCH"], instruction.target_true, instruction.target_false]
    elif kind is Action and fusion is not None:
        where, slot, value = fusion
        if instruction.span not in skipped:
            code += _source(expressions, value)
            code += [OP["SET_STORE" if where == "store" else "SET_LOCAL"], slot]
        code += [OP["GOTO"], instruction.next]
    elif kind is ForInit and fusion is not None:
        for temp, bound in enumerate(fusion):
            code += _source(expressions, bound) + [OP["SET_TEMP"], temp]
        if len(fusion) != 3:
            code += [OP["FOR_DEFAULT_STEP"], OP["SET_TEMP"], 2]
        code += [OP["FOR_INIT"], instruction.slot, instruction.next, instruction.exit]
    elif kind is ForNext:
        code += [OP["FOR_NEXT"], instruction.slot, instruction.body, instruction.exit]
    elif kind is TestDispatch and fusion is not None:
        subject, case_values = fusion
        code += _source(expressions, subject) + [OP["SET_TEMP"], 0]
        for values_, (_, target) in zip(case_values, instruction.cases):
            for value in values_:
                code += _source(expressions, value)
                code += [OP["GET_TEMP"], 0, OP["EQ"], OP["GOTO_IF"], target]
        code += [OP["GOTO"], instruction.default]
    else:
        return None
    return code


# Waits and barriers are steps of one task among several (``staged_step``): a try that
# finds the condition false or a partner missing leaves the state as it is (WAIT: an
# idle step, which the machine keeps or drops as ``idle_steps_dropped`` does).  Their
# blocks begin with TASK_ONLY: a program of one task steps them in Python (its general
# step may merge runs there).
def _task_block(instruction, expressions: ExpressionCode, initial_store, config,
                program) -> list[int]:
    """The code of an instruction the machine runs only as one task's step among several
    (``Instruction.machine``)."""
    plan = instruction.machine
    if type(instruction) is Wait:
        return _wait_block(instruction, expressions)
    if isinstance(plan, ConstantWrite):
        return _constant_write_block(instruction, expressions.value_id, config)
    if isinstance(plan, ChosenWrite):
        return _chosen_write_block(instruction, expressions.value_id, config)
    if isinstance(plan, CheckedReads):
        return _checked_reads_block(instruction, expressions, config)
    if isinstance(plan, ElementWrite):
        return _element_write_block(instruction, expressions)
    if isinstance(plan, CallPlan):
        return _call_block(plan, expressions, program)
    if isinstance(plan, LeavePlan):
        return [OP["TASK_ONLY"], OP["LEAVE"]]
    return _sync_block(instruction, expressions.value_id, initial_store)


def _constant_write_block(instruction, value_id: Callable[[object], int], config) -> list[int]:
    """A ``ConstantWrite``: its slot checked against the values it requires (another:
    REQUIRE gives the step to Python), then set."""
    plan = instruction.machine
    if plan.choice_option and getattr(config, plan.choice_option, True):
        raise Unsupported("a failure may be chosen")
    if len(plan.required) > 1:
        raise Unsupported("several values required")
    code = [OP["TASK_ONLY"]]
    for value in plan.required:
        code += [OP["LOAD_STORE"], plan.slot, OP["CONST"], value_id(value), OP["EQ"],
                 OP["REQUIRE"]]
    if plan.writes:
        code += [OP["CONST"], value_id(plan.value), OP["SET_STORE"], plan.slot]
    return code + [OP["GOTO"], instruction.next]


def _chosen_write_block(instruction, value_id: Callable[[object], int], config) -> list[int]:
    """A ``ChosenWrite``: its guard checked (another value: REQUIRE gives the step to
    Python), then one of the domain's values chosen (CHOOSE_CONST, a choice of as many
    as the domain has, in its order) and set."""
    plan = instruction.machine
    domain = plan.domain(config)
    if not domain:
        raise Unsupported("a failure may be chosen")
    return [OP["TASK_ONLY"], OP["LOAD_STORE"], plan.guard, OP["CONST"],
            value_id(plan.required), OP["EQ"], OP["REQUIRE"],
            OP["CHOOSE_CONST"], len(domain), *(value_id(value) for value in domain),
            OP["SET_STORE"], plan.slot, OP["GOTO"], instruction.next]


def _checked_reads_block(instruction, expressions: ExpressionCode, config) -> list[int]:
    """A ``CheckedReads`` where its option is on: each value computed and dropped, each
    element's index checked against its array (CHECK_INDEX: a raise is Python's), then
    on."""
    plan = instruction.machine
    if not getattr(config, plan.option, False):
        raise Unsupported(f"{plan.option} is off")
    code = [OP["TASK_ONLY"]]
    for compiled in plan.sources:
        code += _source(expressions, compiled) + [OP["POP"]]
    for slot, index in plan.elements:
        code += _source(expressions, index) + [OP["CHECK_INDEX"], slot]
    return code + [OP["GOTO"], instruction.next]


def _element_write_block(instruction, expressions: ExpressionCode) -> list[int]:
    """An ``ElementWrite`` (as ``assign_element`` runs it: the index first, then the
    value): SET_ELEMENT makes the array with that element, or with that component of it
    (the path's offsets; an index out of range is Python's).  Written even where the data
    is sliced (the projection resets it): the index may raise."""
    plan = instruction.machine
    if len(plan.path) >= MAX_PATH:
        raise Unsupported("a deep component")
    return [OP["TASK_ONLY"], *_source(expressions, plan.index),
            *_source(expressions, plan.value), OP["SET_ELEMENT"], plan.slot,
            len(plan.path), *plan.path, OP["GOTO"], instruction.next]


def _call_block(plan: CallPlan, expressions: ExpressionCode, program) -> list[int]:
    """A ``CallPlan``: the arguments computed in order, then CALL pushes the callee's frame
    (its initial locals' ids, then per argument its parameter's slot and whether a num is
    rounded to single precision); the machine asks Python once for each context it
    enters (``PackedStateTable.called_context``)."""
    callee = program.routines[plan.routine]
    if len(plan.arguments) > MAX_ARGUMENTS:
        raise Unsupported("many arguments")
    code = [OP["TASK_ONLY"]]
    for compiled in plan.arguments:
        code += _source(expressions, compiled)
    # (a parameter's slot: -1, the argument's value goes there; its initial value, which
    # may be the marker of an absent argument, is no value of the table)
    slots = {param.slot for param in callee.parameters}
    initial = []
    for slot, value in enumerate(callee.initial_locals):
        if slot in slots:
            initial.append(-1)
            continue
        try:
            hash(value)
        except TypeError:
            raise Unsupported("unhashable local") from None
        initial.append(expressions.value_id(value))
    code += [OP["CALL"], plan.routine, len(initial), *initial, len(plan.arguments)]
    for param in callee.parameters:
        code += [param.slot, int(getattr(param.type, "key", "") == "NUM")]
    return code


def _wait_block(instruction, expressions: ExpressionCode) -> list[int]:
    """``Wait.run``: the condition; where it holds the \\TimeFlag cleared and on; else,
    with \\MaxTime, its value computed, then the choice whether the wait times out
    (the flag set and on; without a flag ERR_WAIT_MAXTIME, which Python raises); else
    the task waits."""
    condition, limit, flag = instruction.machine
    code = [OP["TASK_ONLY"]] + ([OP["RESET_CHOSEN"]] if instruction.reads_io else [])
    code += _source(expressions, condition)
    ends = ([OP["CONST"], expressions.value_id(False), OP["SET_STORE"], flag]
            if flag is not None else []) + [OP["GOTO"], instruction.next]
    code += [OP["JUMP_IF_FALSE"], len(ends)] + ends
    if limit is not None:
        code += _source(expressions, limit) + [OP["POP"]]
        times_out = [OP["CONST"], expressions.value_id(True), OP["SET_STORE"], flag,
                     OP["GOTO"], instruction.next] if flag is not None else [OP["UNSUPPORTED"]]
        code += [OP["CHOOSE_BOOL"], OP["JUMP_IF_FALSE"], len(times_out)] + times_out
    return code + [OP["WAIT"]]


def _sync_block(instruction, value_id: Callable[[object], int], initial_store) -> list[int]:
    """A barrier (``library.tasks._barrier`` without \\TimeOut): its partners are
    those of the task list's first value, guarded by that value (another value: Python);
    SYNC then reads the syncidents' generations as ``wait`` does."""
    plan = instruction.machine
    code = [OP["TASK_ONLY"]]
    if plan.task_list is not None:
        if initial_store is None or not 0 <= plan.task_list < len(initial_store):
            raise Unsupported("task list")
        value = initial_store[plan.task_list]
        try:
            partners = plan.partners(value)
        except Exception:           # (a RapidError: Python raises it where it steps)
            raise Unsupported("task list") from None
        code += [OP["LOAD_STORE"], plan.task_list, OP["CONST"], value_id(value), OP["EQ"],
                 OP["REQUIRE"]]
    else:
        partners = plan.partners(None)
    slots = [plan.slots.get(number, -1) for number in partners]
    return code + [OP["SYNC"], plan.own, int(plan.unshared), instruction.next,
                   len(slots)] + slots


def _source(expressions: ExpressionCode, compiled) -> list[int]:
    if compiled.source is None:
        raise Unsupported("no source")
    expressions.names = compiled.names or {}
    return expressions.compile(compiled.source)


def atom_code(atoms: list[tuple[int, str, dict]], value_id: Callable[[object], int],
              store_length: int) -> Optional[array]:
    """The machine code of a fused valuation's atoms ((bit, source, names) each: see
    ``model.fused_atoms``), or None when one of them is not covered."""
    code = array("i")
    for bit, source, names in atoms:
        if bit <= 0 or bit & (bit - 1) or bit >= 1 << 63:
            return None
        try:
            body = ExpressionCode(value_id, names, store_length, locals_allowed=False) \
                .compile(source)
        except Unsupported:
            return None
        begin = len(code)
        code.extend([OP["ATOM_BEGIN"], 0])
        code.extend(body)
        code.extend([OP["ATOM_END"], bit.bit_length() - 1])
        code[begin + 1] = len(code)            # where the next atom starts
    code.append(OP["END"])
    return code
