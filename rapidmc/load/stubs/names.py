"""What the program declares, and the types of what it declares.

``Declarations`` answers, for a name at a place in the program, whether it
is declared (by a module, a routine, or predefined) and with which type.
Types are ``TypeInfo(name, rank)``: a RAPID type name as written
(``robtarget``, ``num``, a user RECORD) and the number of array dimensions.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

from ... import ast
from ...semantics import configured_signals
from ...semantics.library import registry
from ...semantics.library.data import PREDEFINED_DATA
from ...semantics.errors import ERROR_NUMBERS
from ...semantics.types import NON_VALUE, PREDEFINED_ALIASES, PREDEFINED_TYPES, RECORD


@dataclass(frozen=True)
class TypeInfo:
    name: str
    rank: int = 0

    @property
    def key(self) -> str:
        return self.name.upper()

    def element(self) -> "TypeInfo":
        return TypeInfo(self.name, 0)


NUM, BOOL, STRING, DNUM = TypeInfo("num"), TypeInfo("bool"), TypeInfo("string"), TypeInfo("dnum")
IMPLICIT_DATA = {"ERRNO": TypeInfo("errnum"), "INTNO": TypeInfo("intnum")}


def predefined_type_name(key: str) -> Optional[str]:
    """The spelling of a predefined type or alias, or None."""
    if key in PREDEFINED_TYPES:
        return PREDEFINED_TYPES[key].name
    if key in PREDEFINED_ALIASES:
        return PREDEFINED_ALIASES[key][0]
    return None


class Declarations:
    """The names a program declares: data, routines and types, and the predefined ones."""

    def __init__(self, modules: tuple[ast.Module, ...], signals=frozenset()):
        self.modules = modules
        self.data: dict[str, TypeInfo] = {}
        self.routines: dict[str, ast.Routine] = {}
        self.records: dict[str, list[tuple[str, str]]] = {}
        self.spelling: dict[str, str] = {}
        self.aliases: dict[str, str] = {}
        for module in modules:
            for decl in module.data:
                self.data[decl.name.key] = TypeInfo(decl.type.name.text, len(decl.dims))
            for routine in module.routines:
                self.routines[routine.name.key] = routine
            for definition in module.types:
                self.spelling[definition.name.key] = definition.name.text
                if isinstance(definition, ast.RecordDefinition):
                    self.records[definition.name.key] = [
                        (c.name.text, c.type.name.text) for c in definition.components]
                else:
                    self.aliases[definition.name.key] = definition.base.name.text
        self.signals = set(signals)
        self.signals |= {name.key for name, _ in configured_signals.signal_uses(modules)}
        declared = configured_signals.declared_names(modules)
        self.signals |= {name.key for name, _ in configured_signals.compared_names(modules)
                         if name.key not in declared}
        self.units = {name.key for name in configured_signals.unit_uses(modules)} - declared
        self.shadowed = _valued_non_value_types(modules, set(self.spelling))

    # ------------------------------------------------------------------ data
    def data_type(self, key: str, local: dict[str, TypeInfo]) -> Optional[TypeInfo]:
        """The type of declared data ``key`` (routine data in ``local`` first), or None."""
        if key in local:
            return local[key]
        if key in self.data:
            return self.data[key]
        if key in IMPLICIT_DATA:
            return IMPLICIT_DATA[key]
        predefined = PREDEFINED_DATA.get(key)
        if predefined is not None:
            return TypeInfo(predefined.type_name)
        if key in ERROR_NUMBERS or key == "LONG_JMP_ALL_ERR":
            return TypeInfo("errnum")
        if key in self.signals:
            return NUM                  # a signal read as a value
        if key in self.units:
            return TypeInfo("mecunit")  # a mechanical unit of the motion configuration
        return None

    def is_data(self, key: str, local: dict[str, TypeInfo]) -> bool:
        return self.data_type(key, local) is not None or key in self.signals

    # -------------------------------------------------------------- routines
    def is_routine(self, key: str, use: str) -> bool:
        if key in self.routines:
            return True
        lookup = registry.lookup_function if use == "function" else registry.lookup_procedure
        return lookup(key) is not None

    # ----------------------------------------------------------------- types
    def is_type(self, key: str) -> bool:
        return key in self.records or key in self.aliases or (
            predefined_type_name(key) is not None and key not in self.shadowed)

    def base(self, info: TypeInfo) -> TypeInfo:
        """An alias resolved to its base type (the alias itself for predefined aliases)."""
        seen = set()
        while info.key in self.aliases and info.key not in seen:
            seen.add(info.key)
            info = TypeInfo(self.aliases[info.key], info.rank)
        return info

    def components(self, type_name: str) -> Optional[list[tuple[str, str]]]:
        """``(component, type)`` of a record type, or None if it is not a record."""
        key = self.base(TypeInfo(type_name)).key
        if key in self.records:
            return self.records[key]
        found = PREDEFINED_TYPES.get(key)
        if found is not None and found.kind == RECORD:
            return [(c.name, c.type.name) for c in found.components]
        return None

    def component_type(self, type_name: str, component: str) -> Optional[TypeInfo]:
        for name, component_type in self.components(type_name) or ():
            if name.upper() == component.upper():
                return TypeInfo(component_type)
        return None

    def records_shaped(self, parts: list[str], predefined: bool = True) -> list[str]:
        """The record types (predefined first, unless not wanted, then the program's) whose
        components have exactly the types ``parts`` (upper-case keys of atomic types), in
        order."""
        names = [t.name for t in PREDEFINED_TYPES.values() if t.kind == RECORD] if predefined \
            else []
        names += [self.spelling[key] for key in self.records]
        return [name for name in names
                if [self.base(TypeInfo(t)).key for _, t in self.components(name) or ()] == parts]

    def records_with(self, components: list[str]) -> list[str]:
        """The record types (predefined first, then the program's) having every component."""
        wanted = {c.upper() for c in components}
        names = [t.name for t in PREDEFINED_TYPES.values() if t.kind == RECORD]
        names += [self.spelling[key] for key in self.records]
        return [name for name in names
                if wanted <= {c.upper() for c, _ in self.components(name) or ()}]


def _valued_non_value_types(modules, declared: set) -> set:
    """Predefined non-value types (``datapos``, ``jointgroup`` ...) the program declares data
    of with a value, or as PERS, which no non-value type allows: the program means a type of
    its own, of a module not given, that happens to have that name (issue 19); the stubs
    declare it as a record shaped by the value. ``declared``: the program's own types."""
    found = set()
    for module in modules:
        declarations = list(module.data)
        for routine in module.routines:
            declarations.extend(routine.data)
        for decl in declarations:
            key = decl.type.name.key
            predefined = PREDEFINED_TYPES.get(key)
            if predefined is not None and predefined.kind == NON_VALUE and key not in declared \
                    and (decl.init is not None or decl.storage == "PERS"):
                found.add(key)
    return found
