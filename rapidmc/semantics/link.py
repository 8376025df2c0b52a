"""Linking: from an ``ast.Program`` to a checked, compiled ``Program``.

The linker does what the controller's program check does before a program
may run: it resolves types and names across modules, rejects duplicate
declarations, unknown names, bad calls and assignments to constants, folds
CONSTs, computes initial values, gives every data object a slot, and
compiles every routine into instructions.  Any problem is a ``UserError``
(exit code 2) and nothing runs.

Environment modules (``--env``) are linked into the same program in a
namespace of their own: their global names never clash with the program's.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Optional, Sequence

from .. import ast
from ..diagnostics import (BAD_DECLARATION, DUPLICATE, ENVIRONMENT, NO_ENTRY, NOT_CONSTANT,
                           TYPE_MISMATCH, UNKNOWN_NAME, UNKNOWN_TYPE, UserError, error)
from ..diagnostics.error_report import ErrorCollector
from . import configured_signals
from . import program as P
from .library.data import PREDEFINED_DATA
from .calls import ParameterView, bind
from .errors import ERROR_NUMBERS, LONG_JMP_ALL_ERR
from .expressions import ExpressionCompiler
from .machine import ABSENT
from .robots import motion_task_numbers, reads_other_task_robot
from .runtime import PredefinedCalls
from .scope import (CONSTANT, GLOBAL_DATA, LOCAL_DATA, ROUTINE, SIGNAL, SYSTEM_VARIABLES, Scope,
                    Symbol)
from .statements import RoutineCompiler
from .types import (ANYTYPE, DNUM, NUM, PREDEFINED_ALIASES, PREDEFINED_TYPES, RECORD,
                    SEMI_VALUE, ArrayType, ComponentType, RapidType, default_value, element_type)
from . import values

MAX_DIMENSION = 100_000


class Linker:
    def __init__(self, options: Optional[dict] = None):
        self.options = dict(options or {})
        self.routines: list[P.Routine] = []
        self.globals: list[P.GlobalData] = []
        self.signals: list[P.Signal] = []
        # signals the code names (read, written, passed, aliased); None once an AliasIO
        # names one at run time (any signal may then be read)
        self.named_signals: Optional[set] = set()
        self.signal_by_key: dict[str, P.Signal] = {}
        # each AliasIO call's (file, line, column) -> (the target's signal kind, the index of
        # its stand-in signal or None, whether its source is a string): model.alias_bindings
        self.alias_sources: dict[tuple, tuple] = {}
        self.system = Scope()
        self.namespaces: dict[int, Scope] = {}
        self.module_scopes: dict[tuple[int, str], Scope] = {}
        self.type_tables: dict[int, dict[str, object]] = {}
        self.calls = PredefinedCalls(self)
        self.entry_key = "MAIN"
        self.errors = ErrorCollector()
        self.outside_data: dict = {}     # slot -> load.outside_data.OutsideData
        # slots of outside data a wait reads whole with too many combinations to choose
        self.whole_reads_fixed: set = set()
        # slot of outside data -> the spans of its reads taken as an array's index only
        self.outside_indexes: dict = {}
        # (id of a routine's syntax, name) -> whether the routine reads the name only as
        # whole array indexes (``index_reads``), asked where outside data indexes
        self.index_only_reads: dict = {}
        self.failed_names: set[str] = set()     # declarations that failed: uses stay quiet
        self.booked_errors = 0                  # BookErrNo call sites numbered so far
        # the namespace whose code is being compiled: each task has its own USER module
        self.compiling_namespace = P.PROGRAM_NAMESPACE
        # (namespace, key) -> the data of that task's USER module (reg1 ...)
        self.user_module_data: dict[tuple[int, str], Symbol] = {}
        # name -> slot of a controller's memory the library keeps in the state (``controller_data``)
        self.controller_slots: dict[str, int] = {}
        self._predefined_types()

    # ------------------------------------------------------------ errors
    def report(self, failure: UserError, node=None) -> None:
        """Record a static error and go on, unless it only repeats a failed declaration."""
        if node is not None and self.failed_names and ast.referenced_names(node) & self.failed_names:
            return
        self.errors.add(failure)

    def attempt(self, check, *arguments, node=None):
        """``check(*arguments)``, recording its static error (then None) and going on."""
        try:
            return check(*arguments)
        except UserError as failure:
            self.report(failure, node)
            return None

    # ------------------------------------------------------------------ types
    def _predefined_types(self) -> None:
        self.builtin_types: dict[str, RapidType] = dict(PREDEFINED_TYPES)
        for key, (name, base) in PREDEFINED_ALIASES.items():
            self.builtin_types[key] = base

    def resolve_type(self, ref: ast.TypeRef, namespace: int, module: str) -> RapidType:
        key = ref.name.key
        for table_key in ((namespace, module), namespace):
            table = self.type_tables.get(table_key, {})
            if key in table:
                entry = table[key]
                if isinstance(entry, RapidType):
                    return entry
                if entry == "building":        # reached again while it is being built
                    raise error(BAD_DECLARATION, f"type '{ref.name.text}' is defined in "
                                "terms of itself (a record cannot contain itself)", ref.span)
                return self._build_user_type(entry, namespace, module, key)
        found = self.builtin_types.get(key)
        if found is None:
            raise error(UNKNOWN_TYPE, f"unknown data type '{ref.name.text}'", ref.span,
                        subject=key)
        return found

    def _build_user_type(self, definition, namespace, module, key) -> RapidType:
        table_key = (namespace, module) if definition.local else namespace
        table = self.type_tables[table_key]
        if definition is None or table.get(key) == "building":
            raise error(BAD_DECLARATION, f"type '{key}' is defined in terms of itself",
                        definition.span)
        table[key] = "building"
        if isinstance(definition, ast.AliasDefinition):
            result = self.resolve_type(definition.base, namespace, module)
        else:
            components = []
            for component in definition.components:
                component_type = self.resolve_type(component.type, namespace, module)
                if component_type.kind not in ("atomic", RECORD, "non-value"):
                    raise error(BAD_DECLARATION, f"record component '{component.name.text}' "
                                f"must have a value type, not {component_type.name}",
                                component.span)
                components.append(ComponentType(component.name.text, component.name.key,
                                                component_type))
            result = RapidType(key, definition.name.text, RECORD, tuple(components))
        table[key] = result
        return result

    def _collect_types(self, modules: Sequence[ast.Module], namespace: int) -> None:
        for module in modules:
            for definition in module.types:
                key = definition.name.key
                table_key = (namespace, module.name.key) if definition.local else namespace
                table = self.type_tables.setdefault(table_key, {})
                if key in table:
                    self.report(error(DUPLICATE, f"type '{definition.name.text}' is defined "
                                      "twice", definition.span))
                    continue
                table[key] = definition
        for module in modules:
            for definition in module.types:
                found = self.attempt(self.resolve_type, ast.TypeRef(definition.name,
                                                                    definition.span),
                                     namespace, module.name.key)
                if found is None:
                    self._failed_type(definition, namespace, module.name.key)

    def _failed_type(self, definition, namespace: int, module: str) -> None:
        """A type whose definition failed: an empty record, its uses stay quiet."""
        table_key = (namespace, module) if definition.local else namespace
        key = definition.name.key
        self.type_tables[table_key][key] = RapidType(key, definition.name.text, RECORD, ())
        self.failed_names.add(key)

    def data_type(self, decl, namespace: int, module: str, dims: tuple = ()):
        base = self.resolve_type(decl.type, namespace, module)
        if base.key == "SWITCH" or base is ANYTYPE:
            raise error(BAD_DECLARATION, f"data cannot be declared with type {base.name}",
                        decl.type.span)
        if dims:
            return ArrayType(base, dims)
        return base

    # ------------------------------------------------------------ the system
    def system_symbol(self, name: ast.Name) -> Optional[Symbol]:
        symbol = self.system.lookup(name.key)
        if symbol is not None:
            return symbol
        entry = PREDEFINED_DATA.get(name.key)
        if entry is not None and entry.storage in ("VAR", "PERS"):
            return self._system_module_data(entry)
        if entry is not None:
            rapid_type = self.builtin_types.get(entry.type_name.upper())
            symbol = Symbol(CONSTANT, entry.name, rapid_type, value=entry.value,
                            storage=entry.storage)
            self.system.declare(name.key, symbol)
            return symbol
        if name.key in ERROR_NUMBERS:
            symbol = Symbol(CONSTANT, name.text, NUM, value=float(ERROR_NUMBERS[name.key]),
                            storage="CONST")
            self.system.declare(name.key, symbol)
            return symbol
        if name.key == "LONG_JMP_ALL_ERR":
            return Symbol(CONSTANT, name.text, NUM, value=float(LONG_JMP_ALL_ERR), storage="CONST")
        return None

    def _system_module_data(self, entry) -> Symbol:
        """Data of a system module, given a slot on first use: the variables of the USER module
        (reg1..reg5, clock1) and the persistents of BASE (tool0, wobj0, load0), which a program
        may pass to a PERS or INOUT parameter of its own routines.  Every task has its own
        USER module (and its own C_MOTSET), so a variable gets a slot per task (the task's
        namespace); the persistents of BASE are shared, as every PERS is."""
        key = entry.name.upper()
        if entry.storage == "VAR":
            return self._user_module_data(entry, key)
        return self._new_system_module_data(entry, key, P.PROGRAM_NAMESPACE)

    def _new_system_module_data(self, entry, key: str, namespace: int) -> Symbol:
        user = entry.storage == "VAR"
        rapid_type = self.builtin_types[entry.type_name.upper()]
        slot = len(self.globals)
        self.globals.append(P.GlobalData(slot, entry.name, key, rapid_type, entry.storage,
                                         "user" if user else "base", namespace, False, None,
                                         entry.value))
        symbol = Symbol(GLOBAL_DATA, entry.name, rapid_type, slot=slot, storage=entry.storage)
        if user:
            self.user_module_data[(namespace, key)] = symbol
        else:
            self.system.declare(key, symbol)
        return symbol

    def controller_data(self, name: str, rapid_type, initial, span) -> int:
        """The global slot of what the controller remembers for a predefined routine (no
        RAPID name reaches it; given at the first call ``span`` compiles, shared by every
        task): kept with the environment models' data, which no reduction slices."""
        slot = self.controller_slots.get(name)
        if slot is None:
            slot = self.controller_slots[name] = len(self.globals)
            self.globals.append(P.GlobalData(slot, name, name.upper(), rapid_type, "VAR",
                                             "controller", P.ENVIRONMENT_NAMESPACE, True, span,
                                             initial))
        return slot

    def _user_module_data(self, entry, key: str) -> Symbol:
        """A variable of the USER module of the task being compiled (an environment model
        acts on the main task's), declared in that task's scope, so its routines' lookups
        and the analyses (``load.shared_data``, the partial-order reduction) find it."""
        compiling = self.compiling_namespace
        namespace = P.PROGRAM_NAMESPACE if compiling == P.ENVIRONMENT_NAMESPACE else compiling
        symbol = self.user_module_data.get((namespace, key))
        if symbol is None:
            symbol = self._new_system_module_data(entry, key, namespace)
        if compiling in self.namespaces:
            self.namespaces[compiling].declare(key, symbol)
        return symbol

    # ---------------------------------------------------------------- signals
    def note_signal_named(self, index: Optional[int]) -> None:
        """The code names signal ``index`` (None: a signal named only at run time)."""
        if index is None:
            self.named_signals = None
        elif self.named_signals is not None:
            self.named_signals.add(index)

    def physical_signal(self, name: str, kind: str, span=None, driven: bool = False) -> P.Signal:
        key = name.upper()
        signal = self.signal_by_key.get(key)
        if signal is None:
            signal = P.Signal(len(self.signals), name, key, kind, driven, span)
            self.signals.append(signal)
            self.signal_by_key[key] = signal
            self.system.declare(key, Symbol(SIGNAL, name, PREDEFINED_TYPES["SIGNAL" + kind],
                                            slot=signal.index, storage="SIGNAL"))
        elif driven:
            signal.driven = True
        return signal

    def infer_signal(self, name: ast.Name, signal_type: RapidType) -> Symbol:
        """An undeclared name used as a signal: a signal of the I/O configuration."""
        if not self.options.get("infer_signals", True):
            raise error(UNKNOWN_NAME, f"unknown signal '{name.text}'", name.span,
                        subject=name.key)
        self.physical_signal(name.text, signal_type.signal_kind, name.span)
        return self.system.lookup(name.key)

    # ------------------------------------------------------------ declarations
    def link(self, program: ast.Program, environment: Optional[ast.Program],
             entry: str, tasks: Sequence = ()) -> P.Program:
        self.entry_key = entry.upper()
        for signal in self.options.get("configured_signals", ()):
            self.physical_signal(signal.name, signal.kind, signal.span)   # from EIO.cfg
        groups = [(P.PROGRAM_NAMESPACE, program.modules)]
        if environment is not None and environment.modules:
            groups.append((P.ENVIRONMENT_NAMESPACE, environment.modules))
        task_namespaces = []
        for number, task in enumerate(tasks):
            namespace = P.FIRST_TASK_NAMESPACE + number
            groups.append((namespace, task.program.modules))
            task_namespaces.append((namespace, task))
        for namespace, modules in groups:
            self.namespaces[namespace] = Scope(self.system)
            self._collect_types(modules, namespace)
        for namespace, modules in groups:
            self._declare_routines(modules, namespace)
        for namespace, modules in groups:
            self._declare_data(modules, namespace)
        self._values_declared_elsewhere()
        self._configured_signals([m for namespace, modules in groups
                                  if namespace != P.ENVIRONMENT_NAMESPACE for m in modules])
        self._task_identities()
        for namespace, modules in groups:
            self._prepare_routines(namespace)
        # PERS written from outside the loaded code, read as choices (load.outside_data)
        finder = self.options.get("outside_data")
        self.outside_data = finder(self) if finder is not None and not self.errors else {}
        for found in self.outside_data.values():
            if found.unset:             # declared without a value: a valid one, not zeros
                self.globals[found.slot].initial = found.initial
        # outputs no loaded code sets, read like free inputs (load.outside_outputs)
        finder = self.options.get("outside_outputs")
        for index, who in (finder(self) if finder is not None and not self.errors else {}).items():
            self.signals[index].outside = who
        finder = self.options.get("outputs_set_by_both")
        for index, who in (finder(self) if finder is not None and not self.errors else {}).items():
            self.signals[index].also_set_by = who
        # the names GetTaskName answers: a backup's (T_ROB1 ...), else T_ROB1 for the main task
        self.task_names = (self.options.get("main_task_name") or "T_ROB1",) + tuple(
            task.name for _, task in task_namespaces)
        # the names the check shows (traces, waits, properties): "main task" unless named
        self.shown_task_names = (self.options.get("main_task_name") or "main task",) + \
            self.task_names[1:]
        for routine in self.routines:
            compiler = RoutineCompiler(self, routine, routine.scope)
            self.compiling_namespace = routine.namespace
            self.attempt(compiler.compile, routine.ast)
        self.compiling_namespace = P.PROGRAM_NAMESPACE
        entry_index = self.attempt(self._entry, entry)
        task_entries = tuple(self.attempt(self._entry, task.entry, namespace, task.name)
                             for namespace, task in task_namespaces)
        if environment is not None and environment.modules:
            environment_init = self.attempt(self._environment_routine, "INIT", False)
            environment_react = self.attempt(self._environment_routine, "REACT", True,
                                             environment.modules[0].span)
        self.errors.raise_if_any()
        linked = P.Program(self.routines, self.globals, self.signals, entry_index,
                           options=self.options, signal_index=self.signal_by_key)
        linked.alias_sources = self.alias_sources
        linked.named_signals = (None if self.named_signals is None
                                else frozenset(self.named_signals))
        linked.task_entries = task_entries
        linked.task_names = self.shown_task_names
        linked.motion_tasks = motion_task_numbers(self, self.task_names,
                                                  self.options.get("motion_tasks", ()))
        linked.robot_per_task = len(linked.motion_tasks) > 1
        linked.registers_per_task = bool(task_entries)
        linked.reads_task_robots = linked.robot_per_task and \
            reads_other_task_robot(self.routines, self.task_names)
        if environment is not None and environment.modules:
            linked.environment_init = environment_init
            linked.environment_react = environment_react
        linked.scopes = self
        linked.outside_data = self.outside_data
        linked.whole_reads_fixed = frozenset(self.whole_reads_fixed)
        linked.outside_indexes = {slot: frozenset(spans)
                                  for slot, spans in self.outside_indexes.items()}
        linked.environment_reads_io = any(
            instruction.reads_io for routine in self.routines
            if routine.namespace == P.ENVIRONMENT_NAMESPACE for instruction in routine.code)
        return linked

    def _declare(self, scope: Scope, key: str, symbol: Symbol, span, what: str) -> None:
        existing = scope.declare(key, symbol)
        if existing is not None:
            where = f" (first declared at {existing.span})" if existing.span else ""
            notes = ()
            if what == "routine" and key == self.entry_key:
                notes = ("every RAPID task has its own entry routine: modules of different tasks "
                         "(T_ROB1, T_ROB2, ...) cannot be loaded together; give the modules of one "
                         "task (other tasks' writes to shared PERS data are not modelled)",)
            raise error(DUPLICATE, f"{what} '{symbol.name}' is declared twice in one "
                        f"scope{where}", span, *notes)

    def _module_scope(self, namespace: int, module: ast.Module) -> Scope:
        key = (namespace, module.name.key)
        scope = self.module_scopes.get(key)
        if scope is None:
            scope = Scope(self.namespaces[namespace])
            self.module_scopes[key] = scope
        return scope

    def _persistent_of_other_task(self, key: str, namespace: int) -> Optional[Symbol]:
        """A global PERS of another task: tasks share their (non-TASK) persistents."""
        if namespace == P.ENVIRONMENT_NAMESPACE:
            return None
        for other, scope in self.namespaces.items():
            if other in (namespace, P.ENVIRONMENT_NAMESPACE):
                continue
            symbol = scope.names.get(key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.storage == "PERS" \
                    and not self.globals[symbol.slot].task_local:
                return symbol
        return None

    def _configured_signals(self, modules) -> None:
        """Undeclared names the program passes as signals are signals of the I/O configuration."""
        if not self.options.get("infer_signals", True):
            return
        declared = configured_signals.declared_names(modules)
        uses = list(configured_signals.signal_uses(modules))
        uses += configured_signals.compared_names(modules)     # after the calls: they know the kind
        for name, kind in uses:
            if name.key in declared or name.key in SYSTEM_VARIABLES or \
                    self.system_symbol(name) is not None:
                continue
            self.physical_signal(name.text, kind, name.span)
        for name in configured_signals.unit_uses(modules):
            if name.key in declared or self.system_symbol(name) is not None:
                continue
            # a mechanical unit of the motion configuration, as the predefined ROB_1
            self.system.declare(name.key, Symbol(CONSTANT, name.text,
                                                 self.builtin_types["MECUNIT"], value=None,
                                                 storage="CONST"))

    def _task_identities(self) -> None:
        """The controller's ``taskid`` of each task it runs, named ``<task name>Id`` (T_ROB1Id):
        a backup's every task, loaded or not; else the one task T_ROB1.  System data, so a
        program's own declaration of the name hides it."""
        names = self.options.get("task_names") or (self.options.get("main_task_name") or "T_ROB1",)
        for name in names:
            key = f"{name}ID".upper()
            if re.fullmatch(r"[A-Z][A-Z0-9_]*", key) and self.system.lookup(key) is None:
                self.system.declare(key, Symbol(CONSTANT, f"{name}Id", self.builtin_types["TASKID"],
                                                value=None, storage="CONST"))

    def _declare_routines(self, modules, namespace: int) -> None:
        seen_modules = set()
        for module in modules:
            if module.name.key in seen_modules:
                self.report(error(DUPLICATE, f"module '{module.name.text}' is loaded twice",
                                  module.span))
                continue
            seen_modules.add(module.name.key)
            module_scope = self._module_scope(namespace, module)
            module_names: dict[str, object] = {}
            for decl in module.routines:
                index = len(self.routines)
                routine = P.Routine(index, decl.name.text, decl.name.key, decl.kind,
                                    module.name.text, namespace, decl.local, decl.span,
                                    decl.end_span, ast=decl)
                routine.module_key = module.name.key
                self.routines.append(routine)
                symbol = Symbol(ROUTINE, decl.name.text, None, slot=index, span=decl.span)
                if self.attempt(self._declare_unique, module_names, decl.name, decl.span) is None:
                    continue
                self.attempt(self._declare, module_scope if decl.local else
                             self.namespaces[namespace], decl.name.key, symbol, decl.name.span,
                             "routine")

    def _declare_unique(self, names: dict, name: ast.Name, span) -> None:
        if name.key in names:
            raise error(DUPLICATE, f"'{name.text}' is declared twice in this module "
                        f"(first at {names[name.key]})", span)
        names[name.key] = span
        return True

    def _declare_data(self, modules, namespace: int) -> None:
        pending = []
        for module in modules:
            module_scope = self._module_scope(namespace, module)
            names = {r.name.key: r.span for r in module.routines}
            for decl in module.data:
                if self.attempt(self._declare_unique, names, decl.name, decl.span):
                    pending.append((module, module_scope, decl))
        # CONSTs (and dimensions) may refer to CONSTs declared later: retry until stable
        while pending:
            progress = False
            retry = []
            failures = []
            for module, scope, decl in pending:
                try:
                    self._declare_global(module, scope, decl, namespace)
                    progress = True
                except UserError as exc:
                    if exc.diagnostics[0].code is UNKNOWN_NAME:
                        retry.append((module, scope, decl))
                        failures.append((exc, module, scope, decl))
                    else:
                        self._failed_global(exc, module, scope, decl, namespace)
            if not progress:
                for exc, module, scope, decl in failures:
                    self._failed_global(exc, module, scope, decl, namespace)
                return
            pending = retry

    def _values_declared_elsewhere(self) -> None:
        """A shared PERS declared without a value takes the value of a declaration of a task
        not loaded (``persistent_values``: a task checked alone), as the controller gives one
        persistent object the value of the declaration that has one.  A value that does not
        compile here (another type, a constant of that task) leaves the default value."""
        declared = self.options.get("persistent_values") or {}
        for data in self.globals:
            found = declared.get(data.key)
            if found is None or data.storage != "PERS" or not data.declared_without_value \
                    or data.local or data.task_local or data.type is None:
                continue
            decl, where = found
            module_key = data.module.upper()
            scope = self.module_scopes.get((data.namespace, module_key))
            if scope is None or len(decl.dims) != len(getattr(data.type, "dims", ())):
                continue
            try:
                if self.resolve_type(decl.type, data.namespace, module_key) \
                        != element_type(data.type):
                    continue
                value = self.initial_value(decl, data.type, scope)
            except UserError:
                continue
            data.initial = value
            data.declared_without_value = False
            data.initial_from = where

    def _failed_global(self, failure: UserError, module, scope: Scope, decl,
                       namespace: int) -> None:
        """Report a data declaration that failed; its name stays declared, of unknown type."""
        self.report(failure, decl)
        target = scope if decl.scope == ast.LOCAL else self.namespaces[namespace]
        if target.names.get(decl.name.key) is not None:
            return
        slot = len(self.globals)
        self.globals.append(P.GlobalData(slot, decl.name.text, decl.name.key, None, decl.storage,
                                         module.name.text, namespace, decl.scope == ast.LOCAL,
                                         decl.span, None))
        target.declare(decl.name.key, Symbol(GLOBAL_DATA, decl.name.text, None, slot=slot,
                                             storage=decl.storage, span=decl.span))
        self.failed_names.add(decl.name.key)

    def _dims(self, dims: Sequence[ast.Expr], scope: Scope) -> tuple:
        result = []
        compiler = ExpressionCompiler(self, scope, constant_only=True)
        for dim in dims:
            value = compiler.value(dim, NUM)
            size = value.constant
            if not value.is_constant or size != int(size) or not 1 <= size <= MAX_DIMENSION:
                raise error(BAD_DECLARATION, "an array dimension must be a positive integer "
                            "constant", dim.span)
            result.append(int(size))
        if len(result) > 3:
            raise error(BAD_DECLARATION, "arrays have at most 3 dimensions", dims[3].span)
        return tuple(result)

    def initial_value(self, decl, rapid_type, scope: Scope):
        if decl.init is None:
            if decl.storage == "CONST":
                raise error(BAD_DECLARATION, f"CONST '{decl.name.text}' needs a value", decl.span)
            return default_value(rapid_type)
        if isinstance(rapid_type, RapidType) and rapid_type.kind in ("semi-value", "non-value"):
            raise error(BAD_DECLARATION, f"{rapid_type.name} data cannot have an initial value",
                        decl.init.span)
        compiler = ExpressionCompiler(self, scope, constant_only=True)
        compiled = compiler.value(decl.init, rapid_type)
        if not compiled.is_constant:
            raise error(NOT_CONSTANT, "the initial value must be a constant expression",
                        decl.init.span)
        return compiled.constant

    def _declare_global(self, module, scope: Scope, decl: ast.DataDeclaration,
                        namespace: int) -> None:
        rapid_type = self.data_type(decl, namespace, module.name.key,
                                    self._dims(decl.dims, scope))
        value = self.initial_value(decl, rapid_type, scope)
        target = scope if decl.scope == ast.LOCAL else self.namespaces[namespace]
        if decl.storage == "CONST":
            symbol = Symbol(CONSTANT, decl.name.text, rapid_type, value=value, storage="CONST",
                            span=decl.span)
            self._declare(target, decl.name.key, symbol, decl.name.span, "data")
            return
        is_signal = isinstance(rapid_type, RapidType) and rapid_type.kind == SEMI_VALUE
        if is_signal and namespace == P.ENVIRONMENT_NAMESPACE:
            signal = self.physical_signal(decl.name.text, rapid_type.signal_kind, decl.span,
                                          driven=rapid_type.signal_kind.endswith("I"))
            value = signal.index
        if decl.storage == "PERS" and decl.scope != ast.LOCAL:
            shared = target.names.get(decl.name.key)
            if shared is None and decl.scope != ast.TASK:
                shared = self._persistent_of_other_task(decl.name.key, namespace)
                if shared is not None:
                    target.declare(decl.name.key, shared)
            if shared is not None and shared.kind == GLOBAL_DATA and shared.storage == "PERS":
                # one persistent declared in several modules is one object
                data = self.globals[shared.slot]
                if data.type != rapid_type:
                    raise error(TYPE_MISMATCH, f"persistent '{decl.name.text}' is declared "
                                f"with another type ({data.type}) elsewhere", decl.span)
                if decl.init is not None and data.declared_without_value:
                    data.initial = value
                    data.declared_without_value = False
                return
        slot = len(self.globals)
        data = P.GlobalData(slot, decl.name.text, decl.name.key, rapid_type, decl.storage,
                            module.name.text, namespace, decl.scope == ast.LOCAL, decl.span,
                            value)
        data.declared_without_value = decl.init is None
        data.task_local = decl.scope == ast.TASK
        self.globals.append(data)
        symbol = Symbol(GLOBAL_DATA, decl.name.text, rapid_type, slot=slot, storage=decl.storage,
                        span=decl.span)
        self._declare(target, decl.name.key, symbol, decl.name.span, "data")

    # --------------------------------------------------------------- routines
    def _prepare_routines(self, namespace: int) -> None:
        self.compiling_namespace = namespace
        for routine in self.routines:
            if routine.namespace == namespace:
                self._prepare_routine(routine, namespace)
        self.compiling_namespace = P.PROGRAM_NAMESPACE

    def _prepare_routine(self, routine: P.Routine, namespace: int) -> None:
        """Scope, parameters and routine data of one routine (errors recorded, not raised)."""
        decl: ast.Routine = routine.ast
        module_scope = self.module_scopes[(namespace, routine.module_key)]
        scope = Scope(module_scope)
        routine.scope = scope
        routine.local_names = []
        routine.loop_counters = []
        routine.initial = []
        routine.parameters = ()
        if decl.kind == "FUNC":
            routine.return_type = self.attempt(self.resolve_type, decl.return_type,
                                               namespace, routine.module_key)
        parameters = []
        for param in decl.parameters:
            param_type = self.attempt(self.resolve_type, param.type, namespace,
                                      routine.module_key)
            if param_type is None:
                self.failed_names.add(param.name.key)
            if param.array_rank and param_type is not None:
                param_type = ArrayType(param_type, (None,) * param.array_rank)
            slot = routine.add_local(param.name.text, ABSENT)
            parameter = P.Parameter(param.name.text, param.name.key, param_type, param.mode,
                                    param.optional, param.alternative_group,
                                    param.array_rank, slot, param.span)
            parameters.append(parameter)
            self.attempt(self._declare, scope, param.name.key, Symbol(
                LOCAL_DATA, param.name.text, param_type, slot=slot, storage=param.mode,
                optional=param.optional, by_reference=param.mode != "IN",
                span=param.span), param.name.span, "parameter")
        routine.parameters = tuple(parameters)
        for data in decl.data:
            if self.attempt(self._declare_local, routine, scope, data, namespace,
                            node=data) is None:
                self._failed_local(routine, scope, data)
        if decl.error is not None:
            routine.handler_numbers = self.attempt(self._handler_numbers, decl.error, scope,
                                                   routine)

    def _declare_local(self, routine, scope: Scope, decl: ast.DataDeclaration,
                       namespace: int) -> None:
        if decl.storage == "PERS":
            raise error(BAD_DECLARATION, "PERS data cannot be declared inside a routine "
                        "(declare it at module level)", decl.span)
        if decl.scope != ast.GLOBAL:
            raise error(BAD_DECLARATION, f"{decl.scope} is not allowed on routine data",
                        decl.span)
        rapid_type = self.data_type(decl, namespace, routine.module_key,
                                    self._dims(decl.dims, scope))
        value = self.initial_value(decl, rapid_type, scope)
        if decl.storage == "CONST":
            symbol = Symbol(CONSTANT, decl.name.text, rapid_type, value=value, storage="CONST",
                            span=decl.span)
        else:
            slot = routine.add_local(decl.name.text, value)
            symbol = Symbol(LOCAL_DATA, decl.name.text, rapid_type, slot=slot, storage="VAR",
                            span=decl.span)
        self._declare(scope, decl.name.key, symbol, decl.name.span, "data")
        return symbol

    def _failed_local(self, routine, scope: Scope, decl) -> None:
        """Routine data whose declaration failed: declared with an unknown type."""
        if scope.names.get(decl.name.key) is None:
            slot = routine.add_local(decl.name.text, None)
            scope.declare(decl.name.key, Symbol(LOCAL_DATA, decl.name.text, None, slot=slot,
                                                storage="VAR", span=decl.span))
        self.failed_names.add(decl.name.key)

    def _handler_numbers(self, handler: ast.ErrorHandler, scope: Scope,
                         routine: P.Routine) -> Optional[frozenset]:
        """The constant numbers of an ``ERROR (n1, ...)`` list; module data in the list (an
        errnum booked at run time with BookErrNo) go to ``routine.handler_slots``."""
        if handler.numbers is None:
            return None
        numbers, slots = set(), []
        compiler = ExpressionCompiler(self, scope, constant_only=False)
        for expr in handler.numbers:
            if isinstance(expr, ast.NameRef) and expr.name.key == "LONG_JMP_ALL_ERR":
                numbers.add(LONG_JMP_ALL_ERR)
                continue
            compiled = compiler.value(expr, NUM)
            if compiled.is_constant:
                numbers.add(int(compiled.constant))
                continue
            symbol = scope.lookup(expr.name.key) if isinstance(expr, ast.NameRef) else None
            if symbol is None or symbol.kind != GLOBAL_DATA:
                raise error(NOT_CONSTANT, "ERROR handler lists need constant error numbers or "
                            "module data holding one (booked with BookErrNo)", expr.span)
            slots.append(symbol.slot)
        routine.handler_slots = tuple(slots)
        return frozenset(numbers)

    def routine_by_index(self, index: int) -> P.Routine:
        return self.routines[index]

    def parameter_views(self, routine: P.Routine) -> list[ParameterView]:
        views = []
        for p in routine.parameters:
            element = p.type.element if isinstance(p.type, ArrayType) else p.type
            types = () if element is ANYTYPE or element is None else (element,)
            views.append(ParameterView(p.name, p.key, p.mode, p.optional, p.group,
                                       p.is_switch, types, p.rank))
        return views

    def bind_user_call(self, compiler, routine: P.Routine, args, span,
                       sources: Optional[list] = None):
        return bind(compiler, routine.name, self.parameter_views(routine), args, span, sources)

    def procedures_visible(self, routine: P.Routine):
        for candidate in self.routines:
            if candidate.kind != "PROC" or candidate.namespace != routine.namespace:
                continue
            if candidate.local and candidate.module != routine.module:
                continue
            yield candidate

    # ------------------------------------------------------------------ entry
    def _entry(self, entry: str, namespace: int = P.PROGRAM_NAMESPACE,
               task: str = "") -> int:
        key = entry.upper()
        symbol = self.namespaces[namespace].lookup(key)
        if symbol is None or symbol.kind != ROUTINE:
            where = f"task {task}" if task else "the program"
            raise error(NO_ENTRY, f"{where} has no procedure '{entry}' to start from "
                        f"(use --entry NAME to choose another)",
                        None, *self._entry_candidates_note(namespace))
        routine = self.routines[symbol.slot]
        if routine.kind != "PROC" or routine.parameters:
            raise error(NO_ENTRY, f"entry routine '{routine.name}' must be a procedure "
                        "without parameters", routine.span)
        return routine.index

    def _entry_candidates_note(self, namespace: int) -> tuple[str, ...]:
        """A library without main: the procedures one could start from, as a note."""
        names = [r.name for r in self.routines if r.namespace == namespace and r.kind == "PROC"
                 and not r.local and not r.ast.parameters]
        if not names:
            return ("no global procedure without parameters could be the entry either",)
        shown = ", ".join(names[:20]) + (f", ... ({len(names) - 20} more)" if len(names) > 20 else "")
        return (f"procedures without parameters to start from with --entry: {shown}",)

    def _environment_routine(self, key: str, required: bool, span=None) -> Optional[int]:
        symbol = self.namespaces[P.ENVIRONMENT_NAMESPACE].lookup(key)
        if symbol is None or symbol.kind != ROUTINE:
            if required:
                raise error(ENVIRONMENT, "an environment model needs a procedure "
                            f"'{key.lower()}()' that reacts after every program step", span)
            return None
        routine = self.routines[symbol.slot]
        if routine.kind != "PROC" or routine.parameters:
            raise error(ENVIRONMENT, f"environment routine '{routine.name}' must be a procedure "
                        "without parameters", routine.span)
        return routine.index


@dataclass(frozen=True)
class Task:
    """A further RAPID task running beside the main task (its own modules and entry)."""

    name: str
    program: ast.Program
    entry: str = "main"


def build(program: ast.Program, entry: str = "main",
          environment: Optional[ast.Program] = None, options: Optional[dict] = None,
          tasks: Sequence[Task] = ()) -> P.Program:
    """Link and compile ``program`` (and environment modules, and further tasks).

    Static errors raise UserError."""
    return Linker(options).link(program, environment, entry, tasks)
