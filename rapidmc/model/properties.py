"""Properties to check: property files, formulas, and atomic propositions over RAPID states.

A property file holds one ``NAME: FORMULA`` (or a bare ``FORMULA``) per line (``#`` starts a
comment); formulas use Spot's LTL syntax, or are specification patterns such as
``response(P, S) after(Q)`` (``ltl.patterns``), which stand for their LTL translation.  Atoms are RAPID boolean
expressions over the program's global data, evaluated in each state:

* ``"c_in = 0 AND s1 = 1"`` — a quoted RAPID expression;
* ``flag_1`` — a bare identifier: a bool data object, or a signal (by its
  physical name such as ``C_IN``, or by the signal data bound to it) whose
  value is 1;
* ``"main.flag_1"`` — routine data (or a value parameter) of the innermost
  active call of a routine; false while the routine is not active;
* location and robot atoms, as functions usable in quoted atoms:
  ``InRoutine("Grip")`` (the innermost active routine), ``AtLine(42)`` or
  ``AtLine("prog.mod", 42)`` (the statement about to execute),
  ``AtLabel("retry_point")``, ``AtTarget(c1)`` (the TCP is at robtarget or
  pos ``c1``, within 0.5 mm), ``Ended()`` (the program has ended),
  ``Failed()`` (it stopped on an uncaught error);
* on a controller of several tasks, names and places qualified with a task:
  ``T_ROB2.slot``, ``T_ROB2.main.flag``, ``InRoutine(T_ROB2, "MoveToSlot")``,
  ``Waiting(T_ROB1)`` ... (``task_atoms``).

An atom whose evaluation raises a RAPID error (e.g. signal data not yet
bound with AliasIO) is false in that state.
"""
from __future__ import annotations

import functools
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Optional

from .. import ast
from ..diagnostics import (ATOM, DUPLICATE_PROPERTY, FILE_NOT_FOUND, PROPERTY_FILE,
                          UNKNOWN_NAME, Diagnostic, SourceCache, UserError, error)
from .fused_atoms import fused_valuation
from .task_atoms import (ROBOT_ATOMS, ControllerTasks, Task, task_stack, tasks_read,
                         unqualified_nodes)
from ..ltl import Formula, parse_formula, to_text
from ..ltl.patterns import is_pattern, parse_pattern, pattern_formula
from ..semantics.errors import RapidError
from ..semantics.expressions import Compiled, ExpressionCompiler, constant
from ..semantics.machine import Machine
from ..semantics.program import Program
from ..semantics.robots import task_robot
from ..semantics.scope import (CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE, SIGNAL, Scope,
                              Symbol)
from ..semantics.instructions import Wait
from ..semantics.library.tasks import SyncWait
from ..semantics.state import ENDED, FAILED, RUNNING, STOPPED, State
from ..semantics.library.position import ROBOT_PARTS
from ..semantics.library.registry import lookup_function
from ..semantics.types import BOOL, NUM, POS, PREDEFINED_TYPES, ROBTARGET, STRING, RapidType

_PROPERTY_LINE = re.compile(r"^\s*([A-Za-z_][A-Za-z0-9_.-]*)\s*:(?!=)\s*(.*?)\s*$")
AT_TARGET_TOLERANCE = 0.5      # mm


@dataclass(frozen=True)
class Property:
    name: str
    text: str                  # the formula as written (a pattern's: its LTL translation)
    formula: Formula
    file: str
    line: int
    pattern: Optional[str] = None   # a specification pattern as written (ltl.patterns)


def read_property_file(path: str) -> list[Property]:
    """The properties in a property file."""
    file = Path(path)
    if not file.exists():
        raise error(FILE_NOT_FOUND, f"property file '{path}' does not exist")
    if file.is_dir():
        raise error(FILE_NOT_FOUND, f"'{path}' is a directory, not a property file")
    text = file.read_bytes().decode("latin-1")
    SourceCache.remember(path, text)
    properties = []
    for number, line in enumerate(text.splitlines(), start=1):
        stripped = _strip_comment(line)
        if not stripped.strip():
            continue
        properties.append(parse_property(stripped, path, number))
    if not properties:
        raise error(PROPERTY_FILE, f"property file '{path}' holds no property "
                    "(write one 'NAME: FORMULA' per line)")
    return properties


def _strip_comment(line: str) -> str:
    """The line without a ``#`` comment (a ``#`` inside a quoted atom is kept)."""
    quoted = False
    for i, ch in enumerate(line):
        if ch == '"':
            quoted = not quoted
        elif ch == "#" and not quoted:
            return line[:i]
    return line


def parse_property(text: str, file: str = "<formula>", line: int = 1) -> Property:
    """``NAME: FORMULA`` or a bare ``FORMULA`` (from a property file line or a --formula option).

    A formula without a name is named by its own text, as written (spaces
    between words kept as one), so reports still say which property is which.
    """
    match = _PROPERTY_LINE.match(text)
    if match and not match.group(2):
        raise error(PROPERTY_FILE, f"property '{match.group(1)}' has no formula after its colon",
                    ast.Span(file, line, 1, line, len(text) + 1))
    if match:
        name, formula_text = match.group(1), match.group(2)
        column = match.start(2) + 1
    else:
        formula_text = text.strip()
        name = " ".join(formula_text.split())
        column = len(text) - len(text.lstrip()) + 1
    if is_pattern(formula_text):
        formula = pattern_formula(parse_pattern(formula_text, file, line, column))
        return Property(name, to_text(formula), formula, file, line, pattern=formula_text)
    formula = parse_formula(formula_text, file=file, line=line, column=column)
    return Property(name, formula_text, formula, file, line)


def check_unique(properties: list[Property]) -> None:
    seen: dict[str, Property] = {}
    for prop in properties:
        first = seen.get(prop.name.upper())
        if first is not None:
            raise error(DUPLICATE_PROPERTY, f"property '{prop.name}' is defined twice (first at "
                        f"{first.file}:{first.line})", ast.Span(prop.file, prop.line, 1))
        seen[prop.name.upper()] = prop


# ---------------------------------------------------------------------------
# Atoms
# ---------------------------------------------------------------------------

_WRAPPER_HEAD = "MODULE RapidmcAtom\nPROC RapidmcAtom()\nrapidmc_atom_value :=\n"
_WRAPPER_TAIL = "\n;\nENDPROC\nENDMODULE\n"
_WRAPPER_LINE = 4


def parse_atom_expression(text: str, where: ast.Span) -> ast.Expr:
    """Parse the RAPID expression of an atom; diagnostics point into the property."""
    try:
        return _atom_expression(text)
    except UserError as exc:
        raise UserError([_relocate(d, where) for d in exc.diagnostics]) from None


# A process that checks again (the API's callers, the tests) parses the same atoms again;
# the expression (frozen nodes, spans in "<atom>") is a function of the text alone.
@functools.lru_cache(maxsize=4096)
def _atom_expression(text: str) -> ast.Expr:
    from ..syntax import parse_text
    modules = parse_text(_WRAPPER_HEAD + text + _WRAPPER_TAIL, "<atom>")
    return modules[0].routines[0].body[0].value


def _relocate(diagnostic: Diagnostic, where: ast.Span) -> Diagnostic:
    span = diagnostic.span
    if span is not None and span.line == _WRAPPER_LINE:
        span = ast.Span(where.file, where.line, where.column + span.column - 1)
    else:
        span = where
    return Diagnostic(ATOM, f"in atom: {diagnostic.message}", span)


_OPERATORS_THEN_NAME = re.compile(r"([FGX]+)([A-Za-z_][A-Za-z0-9_]*)")


def operators_spelled_out(word: str, is_known: Callable[[str], bool]) -> Optional[str]:
    """``GFa`` -> ``G F a``: a word that starts with unary operator letters, spaced.

    Among the ways to split off the operator letters (``GFlag``: ``G Flag``
    or ``G F lag``) the one leaving a known name is preferred, else the
    longest run of operators.  None when the word does not start that way.

    >>> operators_spelled_out("XXb", lambda name: False)
    'X X b'
    >>> operators_spelled_out("GFlag", lambda name: name == "FLAG")
    'G Flag'
    """
    match = _OPERATORS_THEN_NAME.fullmatch(word)
    if match is None:
        return None
    run = match.group(1)
    splits = [(word[:k], word[k:]) for k in range(len(run), 0, -1)]
    operators, name = next(((ops, rest) for ops, rest in splits if is_known(rest.upper())),
                           splits[0])
    return " ".join([*operators, name])


class AtomCompiler:
    """Compiles atoms to ``fn(machine) -> bool`` over a program's global state."""

    def __init__(self, program: Program):
        self.program = program
        self.linker = program.scopes
        self.linker.options["infer_signals"] = False    # atoms name only known signals
        self.tasks = ControllerTasks(program)
        scope = self.tasks.unqualified_scope()
        # physical signal names (C_IN, S_1) take precedence over program data names
        for signal in program.signals:
            scope.names[signal.key] = Symbol(SIGNAL, signal.name, NUM, slot=signal.index,
                                             storage="SIGNAL")
        self.scope = scope
        self.observed: set[int] = set()       # physical signals the atoms read
        self.observes_signal_data = False     # an atom reads signal data (binding unknown)
        # upper-case names of program data the atoms read; None once an atom calls one of
        # the program's own functions (which may read any data)
        self.observed_data: Optional[set] = set()
        self.observes_robot = False           # an atom reads a robot's position (CRobT ...)
        self.expressions: list = []           # the atoms compiled, as expressions
        # what the program's inputs are to a check against these atoms (api._input_facts),
        # by what the atoms read: computed once for the many configs of coverage probes
        self.input_facts: dict = {}

    def _note_signals(self, expr: ast.Expr) -> None:
        for symbol in self.symbols(expr):
            if isinstance(symbol, ast.FunctionCall):
                own = self.scope.lookup(symbol.name.key)
                if own is not None and own.kind == ROUTINE:
                    self.observed_data = None
                    self.observes_robot = True     # the program's function may read it
                elif symbol.name.key in ROBOT_ATOMS:
                    self.observes_robot = True
                continue
            if not isinstance(symbol, Symbol):
                continue
            if symbol.kind == SIGNAL:
                self.observed.add(symbol.slot)
            elif getattr(symbol.type, "kind", "") == "semi-value":
                self.observes_signal_data = True
            elif symbol.kind in (GLOBAL_DATA, LOCAL_DATA) and self.observed_data is not None:
                self.observed_data.add(symbol.name.upper())

    def symbols(self, expr: ast.Expr):
        """What each name in ``expr`` denotes (None: not a data name of the program), the
        task-qualified ``T_ROB2.slot`` included; other nodes are yielded as they are."""
        for node in unqualified_nodes(expr, self.tasks):
            if isinstance(node, ast.NameRef):
                yield self.scope.lookup(node.name.key)
            else:
                yield node
        for node in _task_qualified(expr, self.tasks):
            yield self.tasks.scope(self.tasks.named(node.base)).lookup(node.name.key)

    def compile(self, atom: str, where: ast.Span) -> Callable:
        return self._compile_atom(atom, where)[0]

    def _compile_atom(self, atom: str, where: ast.Span) -> tuple[Callable, bool, Optional[tuple]]:
        """The atom's ``fn(machine) -> bool``, whether it reads only global data and
        signals (``reads_data_only``), and for such an atom whose expression has a source
        (``Compiled.source``) its truth as (Python source, names), else None."""
        expr = parse_atom_expression(atom, where)
        self.tasks.check_unambiguous(expr, where, atom)
        self._note_signals(expr)
        self.expressions.append(expr)
        try:
            compiled = self._compile(expr)
        except UserError as exc:
            notes = self._operator_notes(atom, where, exc.diagnostics)
            raise UserError([Diagnostic(ATOM, f"atom \"{atom}\": {d.message}", where,
                                        notes=tuple(d.notes) + notes)
                             for d in exc.diagnostics]) from None
        fn = compiled.fn
        source = compiled.source
        if compiled.type is NUM and isinstance(expr, ast.NameRef):
            number = fn
            fn = lambda m: number(m) == 1  # noqa: E731  (a signal or num named bare: = 1)
            source = None if source is None else f"({source}) == 1"
        elif compiled.type is not BOOL:
            raise error(ATOM, f"atom \"{atom}\" is {compiled.type or 'of unknown type'}, not bool "
                        "(write a comparison, e.g. \"x = 1\")", where)

        def safe(m):
            try:
                return bool(fn(m))
            except RapidError:
                return False
        data_only = reads_data_only(self.symbols(expr))
        fused = (source, compiled.names or {}) if data_only and source is not None and \
            "locals_" not in source else None
        return safe, data_only, fused

    def tasks_read(self, atom: str) -> tuple[str, ...]:
        """The tasks whose own data or places ``atom`` reads (``task_atoms.tasks_read``; the
        atom compiles: ``compile`` has seen it)."""
        return tasks_read(parse_atom_expression(atom, ast.Span("<atom>", 1, 1)), self.tasks)

    def _operator_notes(self, atom: str, where: ast.Span, diagnostics) -> tuple[str, ...]:
        """For an unknown bare name like ``GFa``: Spot's reading, spaced (``G F a``)."""
        line = SourceCache.line(where.file, where.line) or ""
        written_bare = line[where.column - 1:where.column - 1 + len(atom)] == atom
        if not written_bare or not any(d.code is UNKNOWN_NAME for d in diagnostics):
            return ()
        spaced = operators_spelled_out(atom, lambda name: self.scope.lookup(name) is not None)
        if spaced is None:
            return ()
        return (f"rapidmc reads the word {atom} as one name, while Spot reads it as operators "
                f"applied to a name; for the operators write '{spaced}' (with spaces)",)

    def _compile(self, expr: ast.Expr) -> Compiled:
        return _AtomExpressions(self).value(expr)

    def valuation(self, atoms: tuple[str, ...], spans: dict,
                  memo: bool = True) -> Callable[[State], int]:
        """``fn(state) -> int``: bit i set when atom i holds (``fn.atom_count``: how many
        atoms; see ``_valuation``)."""
        valuation = self._valuation(atoms, spans, memo)
        valuation.atom_count = len(atoms)
        return valuation

    def _valuation(self, atoms: tuple[str, ...], spans: dict,
                   memo: bool = True) -> Callable[[State], int]:
        """``fn(state) -> int``: bit i set when atom i holds.

        The atoms that read only global data and signals (most do) and have a
        source are evaluated by one generated function (``fused_atoms``), in
        every state: that costs less than remembering their bits.  The other
        atoms that read only global data and signals are evaluated once per
        distinct (global data, signals) pair and remembered (``memo``; up to
        ``VALUATION_MEMO_SIZE`` pairs): states that differ only in their
        program counter share the bits.  The rest are evaluated in every state.
        """
        compiled = [self._compile_atom(atom, spans.get(atom, ast.Span("<formula>", 1, 1)))
                    for atom in atoms]
        program = self.program
        if not memo:
            return _evaluator(program, [(1 << i, fn) for i, (fn, _, _) in enumerate(compiled)])
        fused = [(1 << i, *source) for i, (_, _, source) in enumerate(compiled)
                 if source is not None]
        on_data = [(1 << i, fn) for i, (fn, data, source) in enumerate(compiled)
                   if data and source is None]
        elsewhere = [(1 << i, fn) for i, (fn, data, _) in enumerate(compiled) if not data]
        others = _remembered(_evaluator(program, on_data)) if on_data else None
        if elsewhere:
            rest = _evaluator(program, elsewhere)
            others = rest if others is None else _either(others, rest)
        if not fused:
            return others or (lambda state: 0)
        return fused_valuation(fused, others)


def _remembered(evaluate: Callable[[State], int]) -> Callable[[State], int]:
    """``evaluate`` (of atoms reading only global data and signals) remembered per
    (global data, signals) pair, up to ``VALUATION_MEMO_SIZE`` pairs."""
    remembered: dict = {}

    def valuation(state: State) -> int:
        key = (state.store, state.io)
        bits = remembered.get(key)
        if bits is None:
            if len(remembered) >= VALUATION_MEMO_SIZE:
                remembered.clear()
            bits = remembered[key] = evaluate(state)
        return bits
    return valuation


def _either(first: Callable[[State], int], second: Callable[[State], int]):
    return lambda state: first(state) | second(state)


VALUATION_MEMO_SIZE = 1 << 14


def _evaluator(program: Program, atoms: list[tuple[int, Callable]]) -> Callable[[State], int]:
    """``fn(state) -> int``: the bits of ``atoms`` (bit, fn(machine)) that hold in ``state``."""
    def evaluate(state: State) -> int:
        m = Machine(program, state, None)
        bits = 0
        for bit, fn in atoms:
            if fn(m):
                bits |= bit
        return bits
    return evaluate


# expression nodes whose value depends on nothing but their operands
_DATA_NODES = (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral, ast.Index, ast.Component,
               ast.Unary, ast.Binary, ast.Aggregate)
_DATA_SYMBOLS = (GLOBAL_DATA, CONSTANT, SIGNAL)


def reads_data_only(symbols) -> bool:
    """Whether an atom reads nothing of a state but its global data and signals, given
    what its names denote (``AtomCompiler.symbols``).

    Conservative: any function call (location and robot atoms, user functions),
    routine data, ERRNO/INTNO or a name not found makes it False."""
    for node in symbols:
        if node is None:
            return False
        if isinstance(node, Symbol):
            if node.kind not in _DATA_SYMBOLS:
                return False
        elif not isinstance(node, _DATA_NODES):
            return False
    return True


def _task_qualified(expr: ast.Expr, tasks: ControllerTasks):
    """The ``TASK.name`` nodes of ``expr`` (in ``TASK.routine.name``: ``TASK.routine``,
    which names a routine, not data: routine data reads a call stack)."""
    from ..semantics.configured_signals import _walk_expression
    for node in _walk_expression(expr):
        if isinstance(node, ast.Component) and tasks.named(node.base) is not None:
            yield node


class _AtomExpressions(ExpressionCompiler):
    """RAPID expressions plus the location and robot atom functions."""

    def __init__(self, atoms: AtomCompiler, scope: Optional[Scope] = None):
        super().__init__(atoms.linker, scope or atoms.scope, hoist=None)
        self.atoms = atoms

    def _FunctionCall(self, expr: ast.FunctionCall, expected) -> Compiled:
        factory = LOCATION_ATOMS.get(expr.name.key)
        if factory is not None:
            return factory(self.atoms, expr)
        if expr.name.key in ROBOT_PARTS:
            compiled = _robot_function(self.atoms, expr)
            if compiled is not None:
                return compiled
        return super()._FunctionCall(expr, expected)

    def _Component(self, expr: ast.Component, expected) -> Compiled:
        """``routine.data``: routine data of the innermost active call of that routine;
        ``TASK.data`` and ``TASK.routine.data``: the same in task TASK's names."""
        base = expr.base
        task = self.atoms.tasks.named(base)
        if task is not None:
            inner = _AtomExpressions(self.atoms, self._task_scope(task, expr.name))
            return inner.value(ast.NameRef(expr.name, expr.span), expected)
        if isinstance(base, ast.Component):
            task = self.atoms.tasks.named(base.base)
            if task is not None:
                inner = _AtomExpressions(self.atoms, self._task_scope(task, base.name))
                return inner._Component(ast.Component(ast.NameRef(base.name, base.span),
                                                      expr.name, expr.span), expected)
        if isinstance(base, ast.NameRef):
            symbol = self.scope.lookup(base.name.key)
            if symbol is not None and symbol.kind == ROUTINE:
                return _routine_data(self.atoms, symbol.slot, expr)
        return super()._Component(expr, expected)


    def _task_scope(self, task: Task, name: ast.Name) -> Scope:
        """The names of ``task``, which must declare ``name`` (else: who does)."""
        tasks = self.atoms.tasks
        if tasks.scope(task).names.get(name.key) is None:
            owners = [other.qualifier for other, _ in tasks.declarations(name.key)]
            notes = (f"declared by {', '.join(owners)}",) if owners else ()
            raise error(UNKNOWN_NAME, f"task {task.qualifier} declares no '{name.text}'",
                        name.span, *notes)
        return tasks.scope(task)


# --- location and robot atoms ------------------------------------------------

def _task_and_args(atoms: AtomCompiler, expr: ast.FunctionCall) -> tuple[Task, list]:
    """The task a location atom names first (else the main task: on a controller of
    several tasks, ``check_unambiguous`` has asked for one) and its other arguments."""
    args = expr.args
    task = atoms.tasks.named(args[0].value) if args else None
    if task is None:
        return atoms.tasks.tasks[0], _string_args(expr, args)
    return task, _string_args(expr, args[1:])


def _string_args(expr: ast.FunctionCall, args) -> list:
    out = []
    for arg in args:
        if arg.kind != ast.REQUIRED or arg.value is None:
            raise error(ATOM, f"{expr.name.text} takes plain arguments", expr.span)
        value = arg.value
        if isinstance(value, (ast.StringLiteral, ast.NumLiteral)):
            out.append(value.value)
        elif isinstance(value, ast.NameRef):
            out.append(value.name.text)
        else:
            raise error(ATOM, f"{expr.name.text} takes names, strings or numbers", arg.span)
    return out


def _current(m: Machine, task: int = 0):
    """The innermost routine of task ``task`` and its next instruction (None: ended)."""
    frames = task_stack(m, task)
    if not frames:
        return None
    frame = frames[-1]
    routine = m.program.routines[frame.routine]
    return routine, routine.code[frame.pc]


def _in_task(atoms: AtomCompiler, task: Task):
    """The routines of ``task`` (on a controller of one task: every routine)."""
    routines = atoms.program.routines
    if not atoms.tasks.several:
        return routines
    return [r for r in routines if r.namespace == task.namespace]


def _in_routine(atoms: AtomCompiler, expr) -> Compiled:
    task, args = _task_and_args(atoms, expr)
    if len(args) != 1:
        raise error(ATOM, "InRoutine takes one routine name (after a task)", expr.span)
    key = str(args[0]).upper()
    if not any(r.key == key for r in _in_task(atoms, task)):
        owner = f"task {task.name} has" if atoms.tasks.several else "there is"
        raise error(ATOM, f"InRoutine: {owner} no routine named '{args[0]}'", expr.span)
    number = task.number

    def in_routine(m):
        here = _current(m, number)
        return here is not None and here[0].key == key
    return Compiled(in_routine, BOOL)


def _at_line(atoms: AtomCompiler, expr) -> Compiled:
    task, args = _task_and_args(atoms, expr)
    number = task.number
    if len(args) == 1:
        file, line = None, args[0]
    elif len(args) == 2:
        file, line = str(args[0]), args[1]
    else:
        raise error(ATOM, "AtLine takes a line number, optionally after a file name", expr.span)

    def at_line(m):
        here = _current(m, number)
        if here is None or here[1].span is None:
            return False
        span = here[1].span
        return span.line == line and (file is None or Path(span.file).name == Path(file).name
                                      or span.file == file)
    return Compiled(at_line, BOOL)


def _at_label(atoms: AtomCompiler, expr) -> Compiled:
    task, args = _task_and_args(atoms, expr)
    if len(args) != 1:
        raise error(ATOM, "AtLabel takes one label name (after a task)", expr.span)
    key = str(args[0]).upper()
    number = task.number
    places = set()
    for routine in _in_task(atoms, task):
        for statement in _labels(routine.ast.body if routine.ast else ()):
            if statement.name.key == key:
                places.add((routine.index, statement.span.line))
    if not places:
        raise error(ATOM, f"AtLabel: no label named '{args[0]}'", expr.span)
    lines = {}
    for routine_index, line in places:
        code = atoms.program.routines[routine_index].code
        following = [i for i, ins in enumerate(code) if ins.span is not None and
                     ins.span.line > line]
        if following:
            lines[routine_index] = min(following, key=lambda i: code[i].span.line)

    def at_label(m):
        frames = task_stack(m, number)
        if not frames:
            return False
        frame = frames[-1]
        return lines.get(frame.routine) == frame.pc
    return Compiled(at_label, BOOL)


def _labels(statements):
    for statement in statements:
        if isinstance(statement, ast.Label):
            yield statement
        for child in ("body", "else_body", "default"):
            inner = getattr(statement, child, None)
            if isinstance(inner, tuple):
                yield from _labels(inner)
        for branch in getattr(statement, "branches", ()) or getattr(statement, "cases", ()):
            yield from _labels(branch.body)


def _robot_task(atoms: AtomCompiler, expr: ast.FunctionCall) -> tuple[Optional[Task], Callable,
                                                                      tuple]:
    """The task a robot atom names first (None: the controller's one robot, which
    ``check_unambiguous`` has made sure of), ``fn(machine)`` reading its robot, and the
    atom's other arguments.  A task named must move a robot."""
    args = expr.args
    if not atoms.tasks.names_task(expr):
        return None, lambda m: m.robot, args
    task = atoms.tasks.named(args[0].value)
    if task.number not in atoms.program.motion_tasks:
        motion = ", ".join(other.name for other in atoms.tasks.motion)
        raise error(ATOM, f"{expr.name.text}: task {task.name} moves no robot", expr.span,
                    f"the motion tasks: {motion}" if motion else
                    "no task of this controller moves a robot")
    if not atoms.program.robot_per_task:
        return task, lambda m: m.robot, args[1:]
    number = task.number
    return task, lambda m: m.robot[number], args[1:]


def _at_target(atoms: AtomCompiler, expr) -> Compiled:
    """``AtTarget(p10)``; ``AtTarget(T_ROB2, p10)``: T_ROB2's robot is at T_ROB2's ``p10``."""
    task, robot, args = _robot_task(atoms, expr)
    if len(args) != 1 or args[0].value is None:
        raise error(ATOM, "AtTarget takes one robtarget or pos (after a task)", expr.span)
    compiler = ExpressionCompiler(atoms.linker, atoms.scope if task is None else
                                  atoms.tasks.scope(task))
    target = compiler.value(args[0].value)
    fn = target.fn
    if target.type is ROBTARGET:
        position = lambda m: fn(m)[0]  # noqa: E731
    elif target.type is POS:
        position = fn
    else:
        raise error(ATOM, "AtTarget takes a robtarget or a pos", args[0].span)

    def at_target(m):
        x, y, z = robot(m)[0][0]
        px, py, pz = position(m)
        return (x - px) ** 2 + (y - py) ** 2 + (z - pz) ** 2 <= AT_TARGET_TOLERANCE ** 2
    return Compiled(at_target, BOOL)


def _robot_function(atoms: AtomCompiler, expr) -> Optional[Compiled]:
    """``CPos(T_ROB2)``, ``CRobT(T_ROB2)`` ...: that task's robot, as the function reads
    the robot of the task that calls it; None without a task (the library's function)."""
    if not atoms.tasks.names_task(expr):
        return None
    _, robot, args = _robot_task(atoms, expr)
    if args:
        raise error(ATOM, f"{expr.name.text} in an atom takes a task only", expr.span)
    part, component = ROBOT_PARTS[expr.name.key]
    rapid_type = PREDEFINED_TYPES[lookup_function(expr.name.key).signature.return_type.upper()]
    if component is None:
        return Compiled(lambda m: robot(m)[part], rapid_type)
    return Compiled(lambda m: robot(m)[part][component], rapid_type)


def _routine_data(atoms: AtomCompiler, routine_index: int, expr: ast.Component) -> Compiled:
    routine = atoms.program.routines[routine_index]
    symbol = routine.scope.lookup(expr.name.key) if routine.scope is not None else None
    if symbol is None or symbol.kind != LOCAL_DATA or symbol.by_reference:
        raise error(ATOM, f"routine {routine.name} has no routine data or value parameter "
                    f"'{expr.name.text}'", expr.span)
    slot = symbol.slot
    name = f"{routine.name}.{expr.name.text}"
    task = atoms.tasks.task_of_namespace(routine.namespace) if atoms.tasks.several else None
    number = task.number if task is not None else 0

    def read(m):
        for frame in reversed(task_stack(m, number)):
            if frame.routine == routine_index:
                return frame.locals[slot]
        raise RapidError("ERR_REFUNKDAT", f"{name}: {routine.name} is not active")
    return Compiled(read, symbol.type)


def _status(status: int):
    """``Ended()`` ... of the whole controller; ``Ended(T_LOG)`` ... of one task."""
    def factory(atoms: AtomCompiler, expr) -> Compiled:
        task, args = _task_and_args(atoms, expr)
        if args:
            raise error(ATOM, f"{expr.name.text} takes no arguments but a task", expr.span)
        if len(expr.args) == 1:
            return Compiled(_task_status(atoms, task, status), BOOL)
        return Compiled(lambda m: m.status == status, BOOL)
    return factory


def _task_status(atoms: AtomCompiler, task: Task, status: int):
    """Task ``task`` has ended (its stack is empty: the others may run on), has stopped
    with the controller, or raised the uncaught error that stopped every task."""
    number = task.number
    if status == ENDED:
        return lambda m: m.status == ENDED or (m.status != FAILED and not task_stack(m, number))
    if status == STOPPED:
        return lambda m: m.status == STOPPED and bool(task_stack(m, number))
    namespace = task.namespace
    routines = atoms.program.routines

    def failed_here(m):
        fault = m.fault
        return m.status == FAILED and fault is not None and \
            routines[fault.instruction[0]].namespace == namespace
    return failed_here


def _waiting(atoms: AtomCompiler, expr) -> Compiled:
    """``Waiting(T_ROB1)`` (``Waiting()`` in a program of one task): the task's next
    instruction is a wait (WaitUntil, WaitDI,
    WaitDO ..., a WaitSyncTask or SyncMoveOn/Off barrier) that cannot go on now."""
    task, args = _task_and_args(atoms, expr)
    if args:
        raise error(ATOM, "Waiting takes a task (or nothing, for a program of one task)",
                    expr.span)
    number = task.number

    def waiting(m):
        here = _current(m, number)
        if here is None or m.status != RUNNING:
            return False
        instruction = here[1]
        if isinstance(instruction, SyncWait):
            return bool(instruction.missing(m.store, number))
        if isinstance(instruction, Wait):
            return not instruction.condition(_task_view(m, number))
        return False
    return Compiled(waiting, BOOL)


def _task_view(m: Machine, number: int) -> Machine:
    """A machine whose running stack and robot are task ``number``'s (what that task's
    code reads)."""
    if number == 0 and not m.program.robot_per_task:
        return m
    view = Machine(m.program, m.to_state(), None)
    view.frames = list(task_stack(m, number))
    view.robot = task_robot(m.program, m.robot, number)
    return view


LOCATION_ATOMS = {
    "INROUTINE": _in_routine,
    "ATLINE": _at_line,
    "ATLABEL": _at_label,
    "ATTARGET": _at_target,
    "ENDED": _status(ENDED),
    "FAILED": _status(FAILED),
    "WAITING": _waiting,
    "STOPPED": _status(STOPPED),
}
