"""Taint marks in the state: the flows of RMC820 as something ``check`` verifies.

``instrument(program)`` returns the program with a mark beside every datum that may
hold input (a global ``bool`` per data object, parameter and function result, named
``taint_<name>``) and statements that keep the marks as the program runs:

* a source sets the mark of what it writes (``SocketReceive \\Str:=m`` then
  ``taint_m := TRUE``); a function source (ReadNum, AInput ...) or an analog or group
  input read by name makes the expression that reads it marked;
* an assignment copies the mark of its value (``taint_t := taint_a OR taint_b``; into
  a component or element: ``taint_t := taint_t OR ...``); a predefined routine's
  by-reference arguments take the mark of its other arguments; a call passes marks to
  its parameters and back through its by-reference ones; ``RETURN e`` marks the
  function's result; routine data starts unmarked at each call;
* a check clears marks: entering the body of an IF, ELSEIF, WHILE or CASE whose
  condition compares a datum (``<``, ``<=``, ``>``, ``>=``, ``=``, TEST) clears its
  mark; when that body handles the datum (leaves the routine, or assigns the datum a
  new value) the later branches and the ELSE, taken when the comparison failed, clear
  it too (``IF x > 800 RETURN;`` bounds x for what follows; ``IF x > 800 TPWrite
  "too far";`` does not);
* before each sink (the arguments of ``flows.sinks``) ``IF <mark of the argument>
  unchecked_input := N;`` records that unchecked input reached sink N.

The property ``no_unchecked_input: G "unchecked_input = 0"`` then holds exactly when
no run takes unchecked input to a sink: a run where the check fails leaves the mark
set, a run where it holds clears it, and a flow whose check is real is not reported.
Only programs checked with ``--flows`` are instrumented: no other check pays for it.
"""
from __future__ import annotations

import itertools
from dataclasses import dataclass
from typing import Optional

from ... import ast
from ...check.result import VIOLATED
from ...check.trace import build_trace
from ...diagnostics import UNCHECKED_INPUT, Diagnostic, SourceCache
from .arguments import bind_predefined, bind_user
from .context import LintContext, name_of, subexpressions, top_expressions
from .checks import COMPARISONS, compares, handles
from .flows import (SOURCE_FUNCTIONS, SOURCE_OUTPUTS, SOURCE_SIGNAL_TYPES, TaintAnalysis,
                    predefined_data_flow, sink_arguments)

MARKS_FILE = "<flow marks>"
MARKS_MODULE = "RapidmcFlowMarks"
PROPERTY = "no_unchecked_input"
_RELATIONS = COMPARISONS + ("<>",)


@dataclass(frozen=True)
class Sink:
    number: int
    span: ast.Span
    description: str


@dataclass(frozen=True)
class Instrumented:
    program: ast.Program
    sinks: tuple[Sink, ...]
    flag: str                          # the global num the sinks set

    @property
    def property_text(self) -> str:
        return f'{PROPERTY}: G "{self.flag} = 0"'

    def sink(self, number: int) -> Optional[Sink]:
        return next((s for s in self.sinks if s.number == number), None)


def instrument(program: ast.Program) -> Instrumented:
    """The program with taint marks (see the module's docstring)."""
    return _Instrumenter(program).run()


class _Instrumenter:
    def __init__(self, program: ast.Program):
        self.program = program
        self.context = LintContext(program)
        self.analysis = TaintAnalysis(self.context, sanitise=False)
        self.taken = {n for n in _all_names(program)}
        self.marks: dict[object, str] = {}           # declaration id / ("return", F) -> mark
        self.declarations: list[ast.DataDeclaration] = []
        self.sinks: list[Sink] = []
        self._cleared_keys: dict[int, str] = {}       # id of a clearing statement -> datum
        self.flag = self._fresh("unchecked_input")
        self.span = ast.Span(MARKS_FILE, 1, 1)

    # ------------------------------------------------------------ names
    def _fresh(self, wanted: str) -> str:
        base = wanted[:28]
        name, number = base, 1
        while name.upper() in self.taken:
            number += 1
            name = f"{base}_{number}"
        self.taken.add(name.upper())
        return name

    def _mark_of_key(self, key, text: str) -> str:
        if key not in self.marks:
            self.marks[key] = self._fresh(f"taint_{text}")
        return self.marks[key]

    def mark(self, name: ast.Name, routine, module) -> Optional[str]:
        """The mark of the datum ``name`` refers to, when it may ever hold input."""
        declaration = self.context.declaration(name.key, routine, module)
        key = id(declaration) if declaration is not None else ("?", name.key)
        if key not in self.analysis.tainted:
            return None
        return self._mark_of_key(key, name.text)

    def return_mark(self, function_key: str) -> Optional[str]:
        if function_key not in self.analysis.returns:
            return None
        routine = self.context.routines[function_key][0]
        return self._mark_of_key(("return", function_key), f"{routine.name.text}_result")

    # ------------------------------------------------------------ the run
    def run(self) -> Instrumented:
        modules = tuple(self._module(module) for module in self.program.modules)
        data = [_bool_declaration(name, self.span) for name in self.marks.values()]
        data.append(ast.DataDeclaration("VAR", ast.GLOBAL, ast.TypeRef(
            ast.Name.of("num", self.span), self.span), ast.Name.of(self.flag, self.span), (),
            ast.NumLiteral(0, "0", self.span), self.span))
        marks_module = ast.Module(ast.Name.of(MARKS_MODULE, self.span), (), (), tuple(data), (),
                                  self.span)
        SourceCache.remember(MARKS_FILE, "")
        return Instrumented(ast.Program(modules + (marks_module,)), tuple(self.sinks),
                            self.flag)

    def _module(self, module: ast.Module) -> ast.Module:
        routines = tuple(self._routine(routine, module) for routine in module.routines)
        return _replace(module, routines=routines)

    def _routine(self, routine: ast.Routine, module: ast.Module) -> ast.Routine:
        entry = []
        for decl in routine.data:
            mark = self.mark(decl.name, routine, module)
            if mark is not None:
                entry.append(_assign(mark, _false(routine.span), routine.span))
        body = tuple(entry) + self._body(routine.body, routine, module)
        error = routine.error
        if error is not None:
            error = _replace(error, body=self._body(error.body, routine, module))
        return _replace(routine, body=body, error=error)

    def _body(self, body, routine, module) -> tuple:
        result = []
        for statement in body:
            before, after = self._effects(statement, routine, module)
            result.extend(before)
            result.append(self._nested(statement, routine, module, after))
            if type(statement) not in (ast.If, ast.CompactIf):     # (they run it in each branch)
                result.extend(after)
        return tuple(result)

    # ------------------------------------------------------------ nested bodies
    def _nested(self, statement, routine, module, after):
        kind = type(statement)
        if kind is ast.If:
            return self._if(statement.branches, statement.else_body, statement.span, routine,
                            module, after)
        if kind is ast.CompactIf:
            return self._if((ast.IfBranch(statement.condition, (statement.statement,),
                                          statement.span),), None, statement.span, routine,
                            module, after, compact=True)
        if kind is ast.While:
            return _replace(statement, body=self._guarded(statement.body, statement.condition,
                                                          routine, module, after))
        if kind is ast.For:
            return _replace(statement, body=self._body(statement.body, routine, module))
        if kind is ast.Test:
            cleared = self._clears(statement, routine, module, statement.span)
            cases = tuple(_replace(c, body=tuple(cleared) + self._body(c.body, routine, module))
                          for c in statement.cases)
            default = statement.default
            if default is not None:
                default = self._body(default, routine, module)
            return _replace(statement, cases=cases, default=default)
        return statement

    def _if(self, branches, else_body, span, routine, module, after, compact=False):
        """An IF: a branch whose condition compares a datum clears its mark; when that
        branch handles the datum (leaves, or assigns it), the later branches and the ELSE,
        reached when the comparison failed, clear it too."""
        new_branches, handled = [], []
        for branch in branches:
            body = tuple(handled) + self._guarded(branch.body, branch.condition, routine,
                                                  module, after)
            new_branches.append(_replace(branch, body=body))
            handled += [clear for clear in self._clears(branch.condition, routine, module, span)
                        if handles(branch.body, self._compared_key(clear))]
        if else_body is not None:
            else_body = tuple(after) + tuple(handled) + self._body(else_body, routine, module)
        elif handled or after:
            else_body = tuple(after) + tuple(handled)
        if compact and else_body is None and len(new_branches[0].body) == 1:
            return ast.CompactIf(new_branches[0].condition, new_branches[0].body[0], span)
        return ast.If(tuple(new_branches), else_body, span)

    def _compared_key(self, clear) -> str:
        return self._cleared_keys.get(id(clear), "")

    def _guarded(self, body, condition, routine, module, after) -> tuple:
        """A body entered when ``condition`` held: the marks it compares are cleared."""
        cleared = self._clears(condition, routine, module, condition.span)
        return tuple(after) + tuple(cleared) + self._body(body, routine, module)

    def _clears(self, condition, routine, module, span) -> list:
        names = {}
        subject = condition.subject if type(condition) is ast.Test else condition
        for expression in subexpressions(subject):
            if type(expression) is ast.NameRef:
                names.setdefault(expression.name.key, expression.name)
        result = []
        for key, name in names.items():
            mark = self.mark(name, routine, module)
            if mark is not None and compares(condition, key):
                clear = _assign(mark, _false(span), span)
                self._cleared_keys[id(clear)] = key
                result.append(clear)
        return result

    # ------------------------------------------------------------ effects of one statement
    def _effects(self, statement, routine, module) -> tuple[list, list]:
        """(statements to run before, statements to run after) ``statement``."""
        before, after = [], []
        span = statement.span
        kind = type(statement)
        for top in top_expressions(statement):
            for expression in subexpressions(top):
                if type(expression) is ast.FunctionCall:
                    self._call_effects(expression, False, routine, module, span, before, after)
        if kind is ast.Assignment:
            name = name_of(statement.target)
            mark = name and self.mark(name, routine, module)
            if mark:
                value = self.taint(statement.value, routine, module, span)
                if type(statement.target) is not ast.NameRef:
                    value = _or(_ref(mark, span), value, span)
                after.append(_assign(mark, value, span))
        elif kind is ast.ProcedureCall:
            self._call_effects(statement, True, routine, module, span, before, after)
            self._sink(statement, routine, module, before)
        elif kind is ast.LateBindingCall:
            self._sink_check(statement.name_expr, "the routine name of a late-bound call",
                             routine, module, span, before)
        elif kind is ast.Return and statement.value is not None and routine.kind == ast.FUNC:
            mark = self.return_mark(routine.name.key)
            if mark:
                before.append(_assign(mark, self.taint(statement.value, routine, module, span),
                                      span))
        return before, after

    def _call_effects(self, call, procedure, routine, module, span, before, after) -> None:
        key = call.name.key
        if procedure and key in SOURCE_OUTPUTS:
            bound = bind_predefined(call)
            for parameter in SOURCE_OUTPUTS[key][1]:
                argument = bound.get(parameter)
                name = name_of(argument.value) if argument and argument.value else None
                mark = name and self.mark(name, routine, module)
                if mark:
                    after.append(_assign(mark, ast.BoolLiteral(True, span), span))
            return
        user = self.context.routines.get(key)
        if user is not None:
            self._user_call(call, user[0], routine, module, span, before, after)
            return
        inputs, outputs = predefined_data_flow(call, procedure)
        if not inputs or not outputs:
            return
        value = _any(self.taint(e, routine, module, span) for e in inputs)
        if type(value) is ast.BoolLiteral and not value.value:
            return
        for output in outputs:
            name = name_of(output)
            mark = name and self.mark(name, routine, module)
            if mark:
                before.append(_assign(mark, _or(_ref(mark, span), value, span), span))

    def _user_call(self, call, callee, routine, module, span, before, after) -> None:
        bound = bind_user(call, callee)
        for parameter in callee.parameters:
            argument = bound.get(parameter.name.key)
            if argument is None or argument.value is None:
                continue
            key = id(parameter)
            if key not in self.analysis.tainted:
                continue
            mark = self._mark_of_key(key, parameter.name.text)
            before.append(_assign(mark, self.taint(argument.value, routine, module, span), span))
            if parameter.mode != ast.IN:
                name = name_of(argument.value)
                target = name and self.mark(name, routine, module)
                if target:
                    value = _ref(mark, span)
                    if type(argument.value) is not ast.NameRef:
                        value = _or(_ref(target, span), value, span)
                    after.append(_assign(target, value, span))

    def _sink(self, call, routine, module, before) -> None:
        for expression, what in sink_arguments(call):
            self._sink_check(expression, f"the {what} of {call.name.text}", routine, module,
                             call.span, before)

    def _sink_check(self, expression, description, routine, module, span, before) -> None:
        value = self.taint(expression, routine, module, span)
        if type(value) is ast.BoolLiteral and not value.value:
            return
        number = len(self.sinks) + 1
        self.sinks.append(Sink(number, expression.span, description))
        before.append(ast.CompactIf(value, _assign(self.flag, ast.NumLiteral(
            number, str(number), span), span), _generated(span)))

    # ------------------------------------------------------------ the mark of a value
    def taint(self, expression, routine, module, span):
        """A bool expression: does ``expression``'s value hold unchecked input now?"""
        parts, seen = [], set()
        pending = [expression]
        while pending:
            current = pending.pop()
            kind = type(current)
            if kind is ast.NameRef:
                part = self._name_part(current.name, routine, module, span)
                if part is not None and part not in seen:
                    seen.add(part)
                    parts.append(part)
            elif kind is ast.FunctionCall:
                if current.name.key in SOURCE_FUNCTIONS:
                    return ast.BoolLiteral(True, span)
                mark = self.return_mark(current.name.key)
                if mark is not None and mark not in seen:
                    seen.add(mark)
                    parts.append(mark)
                if self.context.routines.get(current.name.key) is None:
                    pending.extend(a.value for a in current.args if a.value is not None)
            elif kind is ast.Binary:
                if current.op not in _RELATIONS:
                    pending.extend((current.right, current.left))
            elif kind is ast.Unary:
                if current.op != "NOT":
                    pending.append(current.operand)
            elif kind is ast.Component or kind is ast.Index:
                pending.append(current.base)
            elif kind is ast.Aggregate:
                pending.extend(current.items)
        if any(part is True for part in parts):
            return ast.BoolLiteral(True, span)
        return _any(_ref(part, span) for part in parts)

    def _name_part(self, name, routine, module, span):
        declaration = self.context.declaration(name.key, routine, module)
        if isinstance(declaration, ast.DataDeclaration) and \
                declaration.type.name.key in SOURCE_SIGNAL_TYPES:
            return True
        return self.mark(name, routine, module)


# ---------------------------------------------------------------- small builders

def _replace(node, **changes):
    from dataclasses import replace
    return replace(node, **changes)


def _ref(name: str, span) -> ast.NameRef:
    return ast.NameRef(ast.Name.of(name, span), span)


def _assign(name: str, value, span) -> ast.Assignment:
    span = _generated(span)
    return ast.Assignment(_ref(name, span), value, span)


_GENERATED = itertools.count(1)


def _generated(span: ast.Span) -> ast.Span:
    """A span of its own for a statement the marks add at ``span``'s place: the reductions
    know statements by span (``model.reduction.merging.nodes_by_span``), so no two may
    share one.  It starts where ``span`` starts (traces and coverage name the statement
    it belongs to) and ends on no line (``end_line`` 0: no real span does)."""
    return ast.Span(span.file, span.line, span.column, 0, next(_GENERATED))


def _false(span) -> ast.BoolLiteral:
    return ast.BoolLiteral(False, span)


def _or(left, right, span):
    if type(right) is ast.BoolLiteral:
        return right if right.value else left
    return ast.Binary("OR", left, right, span)


def _any(expressions):
    result = None
    for expression in expressions:
        result = expression if result is None else _or(result, expression, expression.span)
    return result if result is not None else ast.BoolLiteral(False, ast.NO_SPAN)


def _bool_declaration(name: str, span) -> ast.DataDeclaration:
    return ast.DataDeclaration("VAR", ast.GLOBAL, ast.TypeRef(ast.Name.of("bool", span), span),
                               ast.Name.of(name, span), (), ast.BoolLiteral(False, span), span)


def _all_names(program: ast.Program):
    for module in program.modules:
        yield module.name.key
        for decl in module.data:
            yield decl.name.key
        for routine in module.routines:
            yield routine.name.key
            for decl in routine.data:
                yield decl.name.key
            for parameter in routine.parameters:
                yield parameter.name.key


# --- what a counterexample of the flow property shows ----------------------------------


def flow_sinks(program, results, describer) -> list[Diagnostic]:
    """For a violated ``no_unchecked_input``: a warning (RMC820) at the sink its
    counterexample takes unchecked input to."""
    marks = program.options.get("flow_marks")
    if marks is None:
        return []
    found = []
    for checked in results:
        if checked.name != PROPERTY or checked.result.verdict != VIOLATED:
            continue
        trace = build_trace(checked.result, describer)
        for step in (*trace.prefix, *trace.cycle):
            for change in step.changes:
                sink = marks.sink(_number(change.new)) if change.name == marks.flag else None
                if sink is not None:
                    found.append(Diagnostic(
                        UNCHECKED_INPUT, f"unchecked input reaches {sink.description} "
                        f"(step {step.index} of the counterexample of {PROPERTY})",
                        sink.span, severity="warning"))
                    return found
    return found


def _number(text) -> int:
    try:
        return int(float(text))
    except (TypeError, ValueError):
        return 0
