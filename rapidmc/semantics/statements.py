"""Compiling a routine's statements into a flat instruction list.

Structured statements become branches whose targets are ``Label`` objects,
resolved to instruction indices at the end.  A label placed "here" waits
for the next emitted instruction; at the end of a block, waiting labels
fall through to the block's continuation.  So the end of an IF branch or a
loop body continues directly at the right place: no extra jump steps.
"""
from __future__ import annotations

import functools

from typing import Optional

from .. import ast
from ..diagnostics import (ASSIGN_CONST, BAD_CONTROL, DUPLICATE, TYPE_MISMATCH, UNKNOWN_LABEL,
                           UNKNOWN_NAME, UNKNOWN_ROUTINE, UserError, error)
from ..diagnostics.error_report import UNKNOWN_CODES
from .library import registry
from .expressions import ExpressionCompiler, _check_index as check_index
from .instructions import (Action, Branch, Call, CallPlan, ElementWrite, EndRoutine, EndUndo,
                           ExitProgram, ForInit, ForNext, Instruction, Jump, LateCall,
                           LeavePlan, Raise, Retry, Return, TestDispatch, TryNext)
from .errors import placeholder_reached
from .index_reads import datum_reads, is_whole_index
from .machine import GLOBAL, with_locals
from .scope import (CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE, SYSTEM_VARIABLES, Scope,
                    Symbol)
from .types import NUM, SEMI_VALUE, STRING, ArrayType, RapidType

TARGET_FIELDS = ("next", "start", "after", "target_true", "target_false", "target", "exit",
                 "body", "default")


class Label:
    __slots__ = ("pc", "alias")

    def __init__(self):
        self.pc = -1
        self.alias: Optional[Label] = None

    def resolve(self) -> int:
        label = self
        while label.pc < 0 and label.alias is not None:
            label = label.alias
        return label.pc


class RoutineCompiler:
    """Compiles one routine (body, ERROR and UNDO handlers) into ``routine.code``."""

    def __init__(self, linker, routine, scope: Scope):
        self.linker = linker
        self.routine = routine
        self.scope = scope
        self.code: list[Instruction] = []
        self.waiting: list[Label] = []
        self.labels: dict[str, Label] = {}
        self.gotos: list[tuple[Jump, ast.Goto]] = []
        self.section = "body"
        self.statement_start: Optional[Label] = None
        self.statement_after: Optional[Label] = None
        self.statement_reads_io = False
        self.statement_signals: Optional[set] = set()    # (None: any signal)
        self.statement_chooses = False
        self.statement_code: list[Instruction] = []

    # --------------------------------------------------------------- emission
    def emit(self, instruction: Instruction, next_label: Optional[Label] = None) -> Instruction:
        """Append ``instruction``; labels waiting for a position resolve to it."""
        for label in self.waiting:
            label.pc = len(self.code)
        self.waiting.clear()
        instruction.start = self.statement_start
        instruction.after = self.statement_after
        self.code.append(instruction)
        self.statement_code.append(instruction)
        if next_label is None:
            next_label = Label()
            self.waiting.append(next_label)
        instruction.next = next_label
        return instruction

    def here(self) -> Label:
        label = Label()
        self.waiting.append(label)
        return label

    def end_block(self, follow: Label) -> None:
        for label in self.waiting:
            if label is not follow:
                label.alias = follow
        self.waiting.clear()

    # ------------------------------------------------------------- compiling
    def compile(self, decl: ast.Routine) -> None:
        end = Label()
        self.block(decl.body, end)
        self.place(end)
        end_routine = EndRoutine(decl.end_span, decl.kind == "FUNC", decl.name.text)
        self.emit_end(end_routine)
        if decl.kind == "PROC":
            end_routine.machine = LeavePlan(self.routine.index)
        if decl.error is not None:
            self.section = "error"
            self.routine.handler_pc = len(self.code)
            handler_end = Label()
            self.block(decl.error.body, handler_end)
            self.place(handler_end)
            self.emit_end(EndRoutine(decl.error.span, decl.kind == "FUNC", decl.name.text))
        if decl.undo is not None:
            self.section = "undo"
            self.routine.undo_pc = len(self.code)
            undo_end = Label()
            self.block(decl.undo, undo_end)
            self.place(undo_end)
            self.emit_end(EndUndo(decl.end_span))
        for jump, goto in self.gotos:
            label = self.labels.get(goto.label.key)
            if label is None:
                self.linker.report(error(UNKNOWN_LABEL, f"GOTO to unknown label "
                                             f"'{goto.label.text}'", goto.span))
                continue
            jump.target = label
        self.resolve()
        self.routine.code = self.code

    def place(self, label: Label) -> None:
        self.waiting.append(label)

    def emit_end(self, instruction: Instruction) -> None:
        self.statement_start = self.here()
        self.statement_after = None
        self.emit(instruction, next_label=Label())

    def resolve(self) -> None:
        for instruction in self.code:
            for field in TARGET_FIELDS:
                value = getattr(instruction, field, None)
                if isinstance(value, Label):
                    setattr(instruction, field, value.resolve())
            if isinstance(instruction, TestDispatch):
                instruction.cases = [(fns, t.resolve() if isinstance(t, Label) else t)
                                     for fns, t in instruction.cases]

    def block(self, statements, follow: Label) -> None:
        for statement in statements:
            after = Label()
            try:
                self.statement(statement, after)
            except UserError as failure:      # report it with the others; check the rest
                self.report(failure, statement)
            self.waiting.append(after)
        self.end_block(follow)

    def report(self, failure: UserError, statement) -> None:
        """Record a statement's error; an unknown name also brings the statement's other
        unknown names (the compiler stopped at the first)."""
        self.linker.report(failure, statement)
        self.nested_blocks(statement)
        first = failure.diagnostics[0]
        if first.code not in UNKNOWN_CODES:
            return
        for name, use in ast.names_used(statement):
            if name.key != first.subject and not self.knows(name, use):
                what = "name" if use == "data" else use
                code = UNKNOWN_NAME if use == "data" else UNKNOWN_ROUTINE
                self.linker.report(error(code, f"unknown {what} '{name.text}'", name.span,
                                         subject=name.key))

    def nested_blocks(self, statement) -> None:
        """A compound statement that failed in its own part (an IF condition, a TEST
        subject): its nested statements are checked all the same, for their errors.
        (FOR is left out: its loop variable is declared by the statement itself.)"""
        blocks = []
        if isinstance(statement, ast.If):
            blocks = [branch.body for branch in statement.branches] + [statement.else_body or ()]
        elif isinstance(statement, ast.While):
            blocks = [statement.body]
        elif isinstance(statement, ast.Test):
            blocks = [case.body for case in statement.cases] + [statement.default or ()]
        elif isinstance(statement, ast.CompactIf):
            blocks = [(statement.statement,)]
        for body in blocks:
            self.block(body, Label())

    def knows(self, name: ast.Name, use: str) -> bool:
        """Whether ``name`` means something here (data, a routine, predefined)."""
        if self.scope.lookup(name.key) is not None or name.key in SYSTEM_VARIABLES:
            return True
        if use == "data":
            return self.linker.system_symbol(name) is not None
        lookup = registry.lookup_function if use == "function" else registry.lookup_procedure
        return lookup(name.key) is not None

    def statement(self, statement, follow: Label) -> None:
        saved = (self.statement_start, self.statement_after, self.statement_reads_io,
                 self.statement_chooses, self.statement_code, self.statement_signals)
        self.statement_start = self.here()
        self.statement_after = follow
        self.statement_reads_io = False
        self.statement_signals = set()
        self.statement_chooses = False
        self.statement_code = []
        try:
            getattr(self, "_" + type(statement).__name__)(statement, follow)
            if self.statement_reads_io:
                signals = self.statement_signals
                signals = None if signals is None else frozenset(signals)
                for instruction in self.statement_code:
                    instruction.reads_io = True
                    instruction.signals_read = signals
            if self.statement_chooses:
                for instruction in self.statement_code:
                    # (a jump evaluates nothing: the merged run goes on through it)
                    instruction.chooses = type(instruction) not in (Jump, ForNext)
        finally:
            (self.statement_start, self.statement_after, self.statement_reads_io,
             self.statement_chooses, self.statement_code, self.statement_signals) = saved

    def _note_io_read(self, index: Optional[int] = None) -> None:
        """The statement reads signal ``index`` (None: a signal not known here)."""
        self.statement_reads_io = True
        if index is None:
            self.statement_signals = None
        elif self.statement_signals is not None:
            self.statement_signals.add(index)

    def _note_choice(self) -> None:
        self.statement_chooses = True

    def expressions(self, scope: Optional[Scope] = None) -> ExpressionCompiler:
        compiler = ExpressionCompiler(self.linker, scope or self.scope, hoist=self.hoist,
                                      routine=self.routine)
        compiler.io_reader = self._note_io_read
        compiler.choice_noter = self._note_choice
        return compiler

    def hoist(self, call: ast.FunctionCall, callee, for_wait: bool = False) -> int:
        """Emit the call of a user FUNC before the statement; return the result slot.
        ``for_wait``: the call evaluates a WaitUntil or polling condition, so the function
        reads data other parties write as the condition would (``called_from_wait``)."""
        binders = self.linker.bind_user_call(self.expressions(), callee, call.args, call.span)
        slot = self.routine.new_temporary()
        instruction = self.emit(Call(call.span, callee, binders, slot))
        instruction.for_wait = for_wait
        return slot

    # ------------------------------------------------------- simple statements
    def _index_length(self, key: str, value: ast.Expr) -> Optional[int]:
        """The shortest length of the arrays the routine's local ``key`` indexes, when every
        read of it in the routine is a whole index of an array named directly whose length
        is known (``i := step{1}; x := table{i}``) and the data ``value`` reads is read for
        nothing else there (``index_reads``), else None: a read of outside data assigned to
        it then takes only those indexes (``ExpressionCompiler.index_lengths``)."""
        if not self.expressions().outside_read_only_as_index(value):
            return None
        lengths: list = []
        for read, parent in datum_reads(self.routine.ast, key):
            if isinstance(parent, ast.Assignment) and parent.target is read:
                continue
            base = parent.base if is_whole_index(read, parent) else None
            symbol = self.scope.lookup(base.name.key) if isinstance(base, ast.NameRef) \
                else None
            array = getattr(symbol, "type", None)
            position = next((k for k, index in enumerate(parent.indices) if index is read),
                            None) if base is not None else None
            if not isinstance(array, ArrayType) or position >= len(array.dims) or \
                    array.dims[position] is None:
                return None
            lengths.append(array.dims[position])
        return min(lengths) if lengths else None

    def _Assignment(self, statement: ast.Assignment, follow: Label) -> None:
        compiler = self.expressions()
        target = statement.target
        root_expr = target
        while isinstance(root_expr, (ast.Index, ast.Component)):
            root_expr = root_expr.base
        if isinstance(root_expr, ast.NameRef):
            root_symbol = self.scope.lookup(root_expr.name.key) or \
                self.linker.system_symbol(root_expr.name)
            if root_symbol is not None and root_symbol.kind == CONSTANT:
                raise error(ASSIGN_CONST, f"cannot assign to constant '{root_expr.name.text}'",
                            target.span)
            if root_symbol is None and root_expr.name.key in SYSTEM_VARIABLES:
                raise error(ASSIGN_CONST, f"{root_expr.name.text} is read-only (set by the "
                            "system)", target.span)
        if isinstance(root_expr, ast.Placeholder):     # <VAR> := value
            self.emit(self._placeholder_assignment(compiler, statement, root_expr.kind))
            return
        ref_fn, target_type, symbol = compiler.reference(target, "assigned")
        root = symbol
        if root.kind == CONSTANT or root.storage in ("CONST",):
            raise error(ASSIGN_CONST, f"cannot assign to constant '{root.name}'", target.span)
        if root.storage == "FOR":
            raise error(ASSIGN_CONST, f"the FOR loop variable '{root.name}' is read-only",
                        target.span)
        if isinstance(target_type, RapidType) and target_type.kind == SEMI_VALUE:
            raise error(TYPE_MISMATCH, f"a signal cannot be assigned with ':='; use "
                        f"SetDO/Set/Reset (or AliasIO to bind it)", statement.span)
        if isinstance(target, ast.NameRef) and root.kind == LOCAL_DATA and \
                not root.by_reference:
            length = self._index_length(target.name.key, statement.value)
            if length is not None:       # a local that only indexes: an outside read's indexes
                compiler.index_lengths[id(statement.value)] = length
        value = compiler.value(statement.value, target_type)
        value_fn = value.fn
        fusion = element = None
        if isinstance(target, ast.NameRef) and root.kind == GLOBAL_DATA:
            slot = root.slot

            def assign_global(m):
                value = value_fn(m)          # first: a function may change the store
                m.store = m.store.set(slot, value)
            fn = assign_global
            fusion = ("store", slot, value)
        elif isinstance(target, ast.NameRef) and root.kind == LOCAL_DATA and not root.by_reference:
            slot = root.slot

            def assign_local(m):
                value = value_fn(m)          # first: a function may change the frame
                m.frames[-1] = with_locals(m.frames[-1], slot, value)
            fn = assign_local
            fusion = ("local", slot, value)
        elif (isinstance(target, ast.Index) and len(target.indices) == 1 and
              isinstance(target.base, ast.NameRef) and root.kind == GLOBAL_DATA):
            slot = root.slot
            index = compiler.value(target.indices[0], NUM)
            index_fn = index.fn
            span = target.span
            if index.source is not None and value.source is not None:
                element = ElementWrite(slot, index, value)

            def assign_element(m):
                array = m.store[slot]
                i = check_index(array, index_fn(m), span)
                value = value_fn(m)
                m.store = m.store.set(slot, array[:i] + (value,) + array[i + 1:])
            fn = assign_element
        else:
            element = self._component_write(compiler, target, root, value)

            def assign(m):
                ref = ref_fn(m)
                m.write_ref(ref, value_fn(m))
            fn = assign
        action = self.emit(Action(statement.span, fn))
        if fusion is not None and value.source is not None:
            action.fusion = fusion
        action.machine = element

    @staticmethod
    def _component_write(compiler: ExpressionCompiler, target, root, value) -> Optional[ElementWrite]:
        """The machine's plan of a write of a record component of a global array's element
        (``targets{i}.trans.x := v``: the index evaluated and checked first, then the value,
        as ``reference`` and ``assign`` run it), None for another target."""
        names = []
        while isinstance(target, ast.Component):
            names.append(target.name)
            target = target.base
        if not names or root.kind != GLOBAL_DATA or not isinstance(target, ast.Index) or \
                len(target.indices) != 1 or not isinstance(target.base, ast.NameRef) or \
                not isinstance(root.type, ArrayType) or len(root.type.dims) != 1:
            return None
        record, path = root.type.element, []
        for name in reversed(names):
            offset, record = compiler.component_offset(record, name)
            path.append(offset)
        index = compiler.value(target.indices[0], NUM)
        if index.source is None or value.source is None:
            return None
        return ElementWrite(root.slot, index, value, tuple(path))

    def _ProcedureCall(self, statement: ast.ProcedureCall, follow: Label) -> None:
        compiler = self.expressions()
        symbol = self.scope.lookup(statement.name.key)
        if symbol is not None and symbol.kind == ROUTINE:
            callee = self.linker.routine_by_index(symbol.slot)
            if callee.kind != "PROC":
                what = "function (call it in an expression)" if callee.kind == "FUNC" else \
                    "trap routine (traps run on interrupts: use CONNECT)"
                raise error(TYPE_MISMATCH, f"'{statement.name.text}' is a {what}, not a "
                            "procedure", statement.span)
            sources: list = []
            binders = self.linker.bind_user_call(compiler, callee, statement.args, statement.span,
                                                 sources)
            call = self.emit(Call(statement.span, callee, binders))
            if all(param.mode == "IN" and not param.optional and not param.is_switch and
                   compiled is not None for param, compiled in zip(callee.parameters, sources)) \
                    and len(sources) == len(callee.parameters):
                call.machine = CallPlan(callee.index, tuple(sources))
            return
        if symbol is not None:
            raise error(TYPE_MISMATCH, f"'{statement.name.text}' is data, not a procedure",
                        statement.span)
        instruction = self.linker.calls.predefined_procedure(compiler, statement, self)
        self.emit(instruction)

    def _LateBindingCall(self, statement: ast.LateBindingCall, follow: Label) -> None:
        compiler = self.expressions()
        name = compiler.value(statement.name_expr, STRING)
        candidates = {}
        for callee in self.linker.procedures_visible(self.routine):
            try:
                binders = self.linker.bind_user_call(compiler, callee, statement.args,
                                                     statement.span)
            except Exception:
                binders = None
            candidates[callee.key] = (callee, binders)
        self.emit(LateCall(statement.span, name.fn, candidates))

    def _Goto(self, statement: ast.Goto, follow: Label) -> None:
        jump = Jump(statement.span)
        self.gotos.append((jump, statement))
        self.emit(jump)

    def _Label(self, statement: ast.Label, follow: Label) -> None:
        if statement.name.key in self.labels:
            raise error(DUPLICATE, f"label '{statement.name.text}' is declared twice",
                        statement.span)
        label = self.here()
        self.labels[statement.name.key] = label

    def _Return(self, statement: ast.Return, follow: Label) -> None:
        if self.section == "undo":
            raise error(BAD_CONTROL, "RETURN is not allowed in an UNDO handler", statement.span)
        value_fn = None
        if self.routine.kind == "FUNC":
            if statement.value is None:
                raise error(BAD_CONTROL, f"RETURN in function {self.routine.name} needs a value",
                            statement.span)
            value_fn = self.expressions().value(statement.value, self.routine.return_type).fn
        elif statement.value is not None:
            raise error(BAD_CONTROL, f"RETURN in {self.routine.kind} {self.routine.name} "
                        "cannot have a value", statement.span)
        returns = self.emit(Return(statement.span, value_fn))
        if self.routine.kind == "PROC" and self.section == "body":
            returns.machine = LeavePlan(self.routine.index)

    def _Raise(self, statement: ast.Raise, follow: Label) -> None:
        value_fn = None
        if statement.value is not None:
            value_fn = self.expressions().value(statement.value, NUM).fn
        elif self.section != "error":
            raise error(BAD_CONTROL, "RAISE without an error number is only allowed in an "
                        "ERROR handler", statement.span)
        self.emit(Raise(statement.span, value_fn))

    def _Exit(self, statement: ast.Exit, follow: Label) -> None:
        self.emit(ExitProgram(statement.span))

    def _Retry(self, statement: ast.Retry, follow: Label) -> None:
        self._handler_only(statement, "RETRY")
        self.emit(Retry(statement.span))

    def _TryNext(self, statement: ast.TryNext, follow: Label) -> None:
        self._handler_only(statement, "TRYNEXT")
        self.emit(TryNext(statement.span))

    def _handler_only(self, statement, word: str) -> None:
        if self.section != "error":
            raise error(BAD_CONTROL, f"{word} is only allowed in an ERROR handler",
                        statement.span)

    def _Connect(self, statement: ast.Connect, follow: Label) -> None:
        self.emit(self.linker.calls.connect(self.expressions(), statement))

    @staticmethod
    def _placeholder_assignment(compiler, statement: ast.Assignment, kind: str) -> Action:
        """``<VAR> := value``: the value is computed, then the placeholder raises ERR_EXECPHR."""
        value_fn = compiler.value(statement.value).fn

        def assign_placeholder(m):
            value_fn(m)
            placeholder_reached(kind)
        return Action(statement.span, assign_placeholder)

    def _PlaceholderStatement(self, statement, follow: Label) -> None:
        kind = statement.kind
        self.emit(Action(statement.span, lambda m: placeholder_reached(kind)))

    # --------------------------------------------------- compound statements
    def _If(self, statement: ast.If, follow: Label) -> None:
        # an ELSE that jumps back makes every condition decide whether the loop goes round
        # again (IF ready THEN ... ELSE WaitTime 0.1; GOTO wait; ENDIF)
        else_polls = self._jumps_back(statement.else_body[-1]
                                      if statement.else_body else None)
        for branch in statement.branches:
            otherwise = Label()
            self.branch(branch.condition, branch.span, otherwise, polls=else_polls or
                        self._jumps_back(branch.body[-1] if branch.body else None)
                        or self._polls_client(branch.span))
            self.block(branch.body, follow)
            self.place(otherwise)
        if statement.else_body is not None:
            self.block(statement.else_body, follow)
        else:
            self.end_block(follow)

    def _CompactIf(self, statement: ast.CompactIf, follow: Label) -> None:
        self.branch(statement.condition, statement.span, follow,
                    polls=self._jumps_back(statement.statement)
                    or self._polls_client(statement.span))
        self.statement(statement.statement, follow)
        self.end_block(follow)

    def _While(self, statement: ast.While, follow: Label) -> None:
        head = self.here()
        self.branch(statement.condition, statement.span, follow, polls=True)
        self.block(statement.body, head)

    def _polls_client(self, span) -> bool:
        """Whether an IF in a loop polls data a client is only assumed to write, since no
        loaded write gives the value it awaits (``load.awaited_from_outside``: a handshake
        flag another party sets and this task clears)."""
        where = (span.file, span.line, span.column)
        return any(where in data.polled_at for data in self.linker.outside_data.values())

    def _jumps_back(self, statement) -> bool:
        """Whether ``statement`` is a GOTO to a label placed before it (a polling loop)."""
        return isinstance(statement, ast.Goto) and statement.label.key in self.labels

    def branch(self, condition_expr, span, otherwise: Label, polls: bool = False) -> None:
        """Emit a condition test; what is emitted next runs when it holds.  ``polls``: the
        condition decides whether a loop goes round again (a WHILE, an IF that jumps back),
        so it reads data another party writes as a WaitUntil condition does (issue 28)."""
        compiler = self.expressions()
        compiler.in_wait = polls
        if polls:
            compiler.hoist = functools.partial(self.hoist, for_wait=True)
        condition = compiler.condition(condition_expr)
        test = self.emit(Branch(span, condition.fn, condition_expr))
        if condition.source is not None:
            test.fusion = condition
        body = Label()
        test.target_true = body
        test.target_false = otherwise
        self.place(body)

    def _For(self, statement: ast.For, follow: Label) -> None:
        compiler = self.expressions()
        start = compiler.value(statement.start, NUM)
        stop = compiler.value(statement.stop, NUM)
        step = compiler.value(statement.step, NUM) if statement.step is not None else None
        slot = self.routine.new_temporary(3, statement.variable.text)
        first_pc = len(self.code)
        init = self.emit(ForInit(statement.span, slot, start.fn, stop.fn,
                                 step.fn if step else None))
        bounds = (start, stop) if step is None else (start, stop, step)
        if all(bound.source is not None for bound in bounds):
            init.fusion = bounds
        body_scope = self.scope.child()
        body_scope.declare(statement.variable.key, Symbol(LOCAL_DATA, statement.variable.text,
                                                          NUM, slot=slot, storage="FOR"))
        saved = self.scope
        self.scope = body_scope
        body = Label()
        step_label = Label()
        init.next = body
        init.exit = follow
        self.place(body)
        self.block(statement.body, step_label)
        self.scope = saved
        self.place(step_label)
        next_instruction = ForNext(statement.span, slot)
        self.emit(next_instruction, next_label=follow)
        next_instruction.body = body
        next_instruction.exit = follow
        self.routine.loop_counters.append((slot, first_pc, len(self.code) - 1))
        self.end_block(follow)

    def _Test(self, statement: ast.Test, follow: Label) -> None:
        compiler = self.expressions()
        subject = compiler.value(statement.subject)
        # CASE values first: a user function call in them is emitted before the dispatch
        case_values = [[self.expressions().value(v, subject.type) for v in case.values]
                       for case in statement.cases]
        dispatch = self.emit(TestDispatch(statement.span, subject.fn))
        if all(c.source is not None for c in [subject, *(c for cs in case_values for c in cs)]):
            dispatch.fusion = (subject, case_values)
        bodies = []
        for case, values in zip(statement.cases, case_values):
            label = Label()
            dispatch.cases.append(([value.fn for value in values], label))
            bodies.append((label, case.body))
        default = Label()
        dispatch.default = default if statement.default is not None else follow
        for label, body in bodies:
            self.place(label)
            self.block(body, follow)
        if statement.default is not None:
            self.place(default)
            self.block(statement.default, follow)
        else:
            self.end_block(follow)
