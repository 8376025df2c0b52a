"""What the lint rules look at: the program's declarations and every statement and
expression, found in one walk over the syntax tree.

Lint works on ``rapidmc.ast`` alone, not on the linked program: a program that does
not link (a module missing, a name unknown) is still linted, and a rule never waits
for a search.  Names are looked up as RAPID scopes them: a routine's parameters and
data, then its module's data, then the global data of every module.
"""
from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Iterator, Optional, Union

from ... import ast

Declaration = Union[ast.DataDeclaration, ast.Parameter]


@dataclass(frozen=True, slots=True)
class Site:
    """A statement, where it is: routine, module, and the conditions around it."""

    statement: object
    routine: ast.Routine
    module: ast.Module
    guards: tuple                 # enclosing IF/ELSEIF/WHILE/TEST conditions, outermost first
    section: str = "body"         # body, backward, error, undo


_EXPRESSION_TYPES = (ast.NumLiteral, ast.StringLiteral, ast.BoolLiteral, ast.NameRef,
                     ast.Index, ast.Component, ast.FunctionCall, ast.Unary, ast.Binary,
                     ast.Aggregate, ast.Placeholder)


def subexpressions(expression) -> Iterator:
    """``expression`` and every expression inside it (arguments of calls included)."""
    pending = [expression]
    while pending:
        current = pending.pop()
        yield current
        kind = type(current)
        if kind is ast.Binary:
            pending.append(current.right)
            pending.append(current.left)
        elif kind is ast.Unary:
            pending.append(current.operand)
        elif kind is ast.FunctionCall:
            pending.extend(a.value for a in current.args if a.value is not None)
        elif kind is ast.Index:
            pending.extend(current.indices)
            pending.append(current.base)
        elif kind is ast.Component:
            pending.append(current.base)
        elif kind is ast.Aggregate:
            pending.extend(current.items)


def top_expressions(statement) -> tuple:
    """The expressions a statement holds itself (not those of statements nested in it)."""
    kind = type(statement)
    if kind is ast.Assignment:
        return (statement.target, statement.value)
    if kind is ast.ProcedureCall:
        return tuple(a.value for a in statement.args if a.value is not None)
    if kind is ast.If:
        return tuple(branch.condition for branch in statement.branches)
    if kind is ast.CompactIf or kind is ast.While:
        return (statement.condition,)
    if kind is ast.For:
        return tuple(e for e in (statement.start, statement.stop, statement.step) if e is not None)
    if kind is ast.Test:
        return (statement.subject,) + tuple(v for case in statement.cases for v in case.values)
    if kind is ast.LateBindingCall:
        return (statement.name_expr,) + tuple(a.value for a in statement.args
                                              if a.value is not None)
    if kind is ast.Return or kind is ast.Raise:
        return (statement.value,) if statement.value is not None else ()
    if kind is ast.Connect:
        return (statement.target,)
    return ()


def nested_bodies(statement) -> Iterator[tuple[tuple, Optional[object]]]:
    """(statement list, the condition guarding it or None) of each block inside ``statement``."""
    kind = type(statement)
    if kind is ast.If:
        for branch in statement.branches:
            yield branch.body, branch.condition
        if statement.else_body is not None:
            yield statement.else_body, None
    elif kind is ast.CompactIf:
        yield (statement.statement,), statement.condition
    elif kind is ast.While:
        yield statement.body, statement.condition
    elif kind is ast.For:
        yield statement.body, None
    elif kind is ast.Test:
        for case in statement.cases:
            yield case.body, None
        if statement.default is not None:
            yield statement.default, None


def routine_sections(routine: ast.Routine) -> Iterator[tuple[str, tuple]]:
    yield "body", routine.body
    if routine.backward:
        yield "backward", routine.backward
    if routine.error is not None:
        yield "error", routine.error.body
    if routine.undo:
        yield "undo", routine.undo


class LintContext:
    """The program as the rules see it; every index is built once, on first use."""

    def __init__(self, program: ast.Program, other_tasks_change: frozenset = frozenset()):
        self.program = program
        self.modules = program.modules
        # keys of the PERS data the other tasks of a backup change (``shared_index``)
        self.other_tasks_change = other_tasks_change
        self._calls_at: dict[int, list] = {}
        self.memo: dict[str, dict] = {}        # what a rule computes once per program

    # ------------------------------------------------------------ declarations
    @cached_property
    def global_data(self) -> dict[str, tuple[ast.DataDeclaration, ast.Module]]:
        found = {}
        for module in self.modules:
            for decl in module.data:
                if decl.scope == ast.GLOBAL:
                    found.setdefault(decl.name.key, (decl, module))
        return found

    @cached_property
    def module_data(self) -> dict[tuple[str, str], ast.DataDeclaration]:
        return {(module.name.key, decl.name.key): decl
                for module in self.modules for decl in module.data}

    @cached_property
    def routines(self) -> dict[str, tuple[ast.Routine, ast.Module]]:
        """Every routine by name (global ones win over LOCAL ones of the same name)."""
        found = {}
        for module in self.modules:
            for routine in module.routines:
                if routine.name.key not in found or not routine.local:
                    found[routine.name.key] = (routine, module)
        return found

    @cached_property
    def _routine_scopes(self) -> dict[int, dict[str, Declaration]]:
        scopes = {}
        for module in self.modules:
            for routine in module.routines:
                scope = {p.name.key: p for p in routine.parameters}
                scope.update((d.name.key, d) for d in routine.data)
                scopes[id(routine)] = scope
        return scopes

    def declaration(self, key: str, routine: Optional[ast.Routine],
                    module: ast.Module) -> Optional[Declaration]:
        """The declaration a name refers to from inside ``routine`` of ``module``."""
        if routine is not None:
            found = self._routine_scopes[id(routine)].get(key)
            if found is not None:
                return found
        found = self.module_data.get((module.name.key, key))
        if found is not None:
            return found
        entry = self.global_data.get(key)
        return entry[0] if entry is not None else None

    # ------------------------------------------------------------ statements
    @cached_property
    def sites(self) -> list[Site]:
        """Every statement of every routine, in source order, with its guards."""
        found: list[Site] = []
        for module in self.modules:
            for routine in module.routines:
                for section, body in routine_sections(routine):
                    self._collect(body, routine, module, (), section, found)
        return found

    def _collect(self, body, routine, module, guards, section, found) -> None:
        for statement in body:
            found.append(Site(statement, routine, module, guards, section))
            if type(statement) in _COMPOUND:
                for inner, condition in nested_bodies(statement):
                    inner_guards = guards if condition is None else guards + (condition,)
                    if type(statement) is ast.Test:
                        inner_guards = guards + (statement,)
                    self._collect(inner, routine, module, inner_guards, section, found)

    @cached_property
    def sites_by_routine(self) -> dict[int, list[Site]]:
        found: dict[int, list[Site]] = {}
        for site in self.sites:
            found.setdefault(id(site.routine), []).append(site)
        return found

    @cached_property
    def callers(self) -> dict[str, list[ast.Routine]]:
        """Routine key -> the routines that call it (by procedure or function call)."""
        found: dict[str, dict[int, ast.Routine]] = {}
        for site in self.calls:
            found.setdefault(site.statement.name.key, {})[id(site.routine)] = site.routine
        for call, site, routine, module in self.of_type(ast.FunctionCall):
            if routine is not None:
                found.setdefault(call.name.key, {})[id(routine)] = routine
        return {key: list(routines.values()) for key, routines in found.items()}

    def waiting_routines(self, waits) -> set[str]:
        """The keys of the user routines that run a statement for which ``waits(statement,
        found)`` holds, directly or through the routines they call."""
        found: set[str] = set()
        pending = [site.routine for site in self.sites if waits(site.statement, found)]
        while pending:
            routine = pending.pop()
            if routine.name.key in found:
                continue
            found.add(routine.name.key)
            pending.extend(self.callers.get(routine.name.key, ()))
        return found

    @cached_property
    def calls(self) -> list[Site]:
        """The sites of procedure calls."""
        return [site for site in self.sites if type(site.statement) is ast.ProcedureCall]

    @cached_property
    def expressions(self) -> list[tuple[object, Optional[Site], Optional[ast.Routine], ast.Module]]:
        """(expression, its site or None, routine or None, module) for every expression,
        declarations' initial values and dimensions included."""
        found = []
        for module in self.modules:
            for decl in module.data:
                self._declaration_expressions(decl, None, module, found)
            for routine in module.routines:
                for decl in routine.data:
                    self._declaration_expressions(decl, routine, module, found)
        calls_at = self._calls_at
        for site in self.sites:
            for top in top_expressions(site.statement):
                for expression in subexpressions(top):
                    found.append((expression, site, site.routine, site.module))
                    if type(expression) is ast.FunctionCall:
                        calls_at.setdefault(id(site), []).append(expression)
        return found

    @cached_property
    def used_names(self) -> set[str]:
        """Every name the program uses: data, functions, procedures, traps, FOR variables,
        error names of ERROR (...) lists."""
        used = {entry[0].name.key for entry in self.of_type(ast.NameRef)}
        used.update(entry[0].name.key for entry in self.of_type(ast.FunctionCall))
        for site in self.sites:
            statement = site.statement
            kind = type(statement)
            if kind is ast.ProcedureCall:
                used.add(statement.name.key)
            elif kind is ast.Connect:
                used.add(statement.trap.key)
            elif kind is ast.For:
                used.add(statement.variable.key)
        for module in self.modules:
            for routine in module.routines:
                if routine.error is not None and routine.error.numbers:
                    used.update(e.name.key for e in routine.error.numbers
                                if type(e) is ast.NameRef)
        return used

    def function_calls(self, site: Site) -> list:
        """The function calls in the expressions of ``site``'s statement."""
        self.expressions
        return self._calls_at.get(id(site), _NONE)

    @staticmethod
    def _declaration_expressions(decl, routine, module, found) -> None:
        for top in decl.dims + ((decl.init,) if decl.init is not None else ()):
            for expression in subexpressions(top):
                found.append((expression, None, routine, module))

    def of_type(self, kind: type) -> list:
        """The entries of ``expressions`` whose expression is a ``kind``."""
        return self._by_type.get(kind, [])

    @cached_property
    def _by_type(self) -> dict[type, list]:
        table: dict[type, list] = {}
        for entry in self.expressions:
            table.setdefault(type(entry[0]), []).append(entry)
        return table

    # ------------------------------------------------------------ source text
    def source_line(self, file: str, line: int) -> Optional[str]:
        from ...diagnostics import SourceCache
        return SourceCache.line(file, line)


_NONE: list = []
_COMPOUND = (ast.If, ast.CompactIf, ast.While, ast.For, ast.Test)


def name_of(expression) -> Optional[ast.Name]:
    """The data name at the root of a reference (``a`` of ``a.b{1}``), or None."""
    while True:
        kind = type(expression)
        if kind is ast.NameRef:
            return expression.name
        if kind is ast.Component or kind is ast.Index:
            expression = expression.base
        else:
            return None
