"""Names the program uses and nobody declares, with types inferred from their uses.

Each use of an undeclared name is evidence: passed as MoveL's ``ToPoint``
it is a ``robtarget``; as ``\\Tool:=`` a ``tooldata``; assigned ``3`` a
``num``; tested by ``IF`` a ``bool``; compared with a string a ``string``.
A called procedure gets parameters typed from its arguments, a function the
type its call's context expects.  The walk repeats until nothing new is
learnt, since one inferred name types the next (``x := y;`` with ``x``
known later).

The passes around the walk are in ``passes`` (``missing_names``).
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Optional, Sequence

from ... import ast
from ...semantics.library import registry
from ...semantics.configured_signals import COMPARISONS
from .names import BOOL, NUM, STRING, Declarations, TypeInfo
from .records import SOME_RECORD, arrange
from .task_views import TaskViews

DATA, PROCEDURE, FUNCTION, TRAP, TYPE = "data", "procedure", "function", "trap", "type"
ARITHMETIC = ("+", "-", "*", "/")
LOGICAL = ("AND", "OR", "XOR")


@dataclass
class Parameter:
    """A parameter of a missing routine, typed from the arguments of its calls."""

    name: str
    type: Optional[TypeInfo]
    optional: bool = False
    switch: bool = False
    assumed: bool = False            # num, as nothing tells the type
    aggregates: list = field(default_factory=list)      # aggregates given as the argument


@dataclass
class Missing:
    """One undeclared name: how it is used, and what that says about it."""

    name: ast.Name
    kind: str
    first_use: ast.Span
    use: str                                  # the first use, in words
    uses: int = 0
    type: Optional[TypeInfo] = None
    evidence: str = ""                        # where the type comes from
    storage: str = "PERS"
    dims: list[int] = field(default_factory=list)
    components: list[str] = field(default_factory=list)
    parameters: list[Parameter] = field(default_factory=list)
    fields: dict = field(default_factory=dict)          # a missing RECORD: component -> type
    named: dict = field(default_factory=dict)           # its components the uses name -> type
    shape: Optional[list] = None                        # its positions' types, from a value
    left_out: list = field(default_factory=list)        # names no position of the shape takes
    value: Optional[object] = None                      # the aggregate that gave the shape
    assumed: list = field(default_factory=list)         # components num is assumed for
    sizes_array: bool = False                           # used as an array dimension
    array_size: Optional[tuple] = None                  # (size, array) a declared value fixes
    indexes_array: bool = False                         # used as an array index
    assigned: bool = False
    array_argument: bool = False                        # dims from an array parameter
    alias_of: Optional[str] = None                      # a missing type declared with a value
    alternative: Optional[tuple] = None                 # (number, count) among compared names
    exact_dims: bool = False                            # dims from an aggregate assigned whole
    written: list = field(default_factory=list)         # aggregates assigned to it whole
    tasks: set = field(default_factory=set)             # the tasks whose uses name it (0 ...)
    valued_by: str = ""                 # the module of another task whose PERS gives its value

    def learn(self, info: Optional[TypeInfo], evidence: str) -> bool:
        """Take ``info`` as the type if none is known yet; whether anything changed."""
        if info is None or self.type is not None or info.name.lower() in ("anytype", "anynum",
                                                                          "switch"):
            return False
        self.type = TypeInfo(info.name, 0)
        self.evidence = evidence
        return True


class Inference:
    """One walk over the program; ``missing`` accumulates across walks.

    ``tasks``: the modules of each task (one for a program). The tasks of a whole backup are
    walked in turn, each with its own declarations, and their uses of one missing name
    teach the same ``Missing`` (``task_views``): a type, a constant or a routine several
    tasks need is inferred once from all their uses."""

    def __init__(self, tasks: Sequence[tuple[ast.Module, ...]], signals=frozenset()):
        self.tasks = [(Declarations(modules, signals), modules) for modules in tasks]
        self.missing = TaskViews(len(self.tasks))
        # PERS data a task declares: key -> (type, sizes, module); another task's uses of
        # the name are of that one object (tasks share a PERS by its name)
        self.persistents = _persistents(tasks) if len(tasks) > 1 else {}
        self.activate(0)
        self.changed = False
        self.counting = True
        self.local: dict[str, TypeInfo] = {}
        self.routine: Optional[ast.Routine] = None
        self.in_declaration = False           # declaration values and sizes are constant
        # FOR variable -> the largest value its literal bounds reach (None: not literal)
        self.loop_bounds: dict = {}
        # a missing function whose value is an argument of a missing routine: that
        # routine and the parameter's key (both untyped until one of them is known)
        self.feeds: dict[str, tuple[Missing, str]] = {}
        self.invented: set[str] = set()       # keys of record types named by the stubs
        # a missing function whose value is assigned to an untyped component of a missing
        # record: that record and the component's name
        self.component_feeds: dict[str, tuple[Missing, str]] = {}
        # TEST statements whose subject and CASE values are all missing names: the keys
        self.untyped_tests: list[tuple[str, ...]] = []
        # two missing names compared with each other (= or <>), neither typed there
        self.untyped_comparisons: list[tuple[str, str]] = []
        # datum key -> the bare names it is given or compared with (``Status := NG``,
        # ``VAR num Res := OK``, ``WHILE Status <> OK``): status codes (``_codes``)
        self.codes: dict[str, list] = {}

    # ------------------------------------------------------------ bookkeeping
    def note(self, name: ast.Name, kind: str, use: str) -> Missing:
        found = self.missing.get(name.key) or self.missing.of_any_task(name.key)
        if found is None:
            found = Missing(name, kind, name.span, use)
            self.missing[name.key] = found
            self.changed = True
            if kind == DATA and name.key in self.persistents:
                info, sizes, module, valued = self.persistents[name.key]
                found.learn(info, f"declared so by {module} of another task, whose PERS it is")
                found.dims, found.exact_dims = list(sizes), bool(sizes)
                found.valued_by = module if valued else ""
        found.tasks.add(self.missing.current)
        if self.counting:
            found.uses += 1
        if self.in_declaration and kind == DATA:
            found.storage = "CONST"
        return found

    def expect(self, expr, info: Optional[TypeInfo], evidence: str) -> None:
        """``expr`` should have type ``info``: an undeclared name in it learns so."""
        if isinstance(expr, ast.NameRef) and self.undeclared_data(expr.name):
            missing = self.note(expr.name, DATA, evidence)
            self.changed |= missing.learn(info, evidence)
            if info is not None and info.rank and not missing.dims and missing.type is not None \
                    and missing.type.key == info.key:     # an array argument (``tasks{*}``)
                missing.dims = [1] * info.rank
                missing.array_argument = True
                self.changed = True
        elif isinstance(expr, ast.Index) and isinstance(expr.base, ast.NameRef) \
                and self.undeclared_data(expr.base.name):
            missing = self.note(expr.base.name, DATA, evidence)
            self._array_use(missing, expr)
            self.changed |= missing.learn(info, evidence)
        elif isinstance(expr, ast.FunctionCall) and self.undeclared_routine(expr.name, FUNCTION):
            missing = self.note(expr.name, FUNCTION, evidence)
            self.changed |= missing.learn(info, f"its value: {evidence}")
        elif isinstance(expr, ast.Binary) and expr.op in ARITHMETIC and info is not None:
            for side in (expr.left, expr.right):
                self.expect(side, info if info.name in ("num", "dnum", "string") else None,
                            evidence)
        elif isinstance(expr, ast.Unary) and expr.op in ("-", "+"):
            self.expect(expr.operand, info, evidence)
        elif isinstance(expr, ast.Component):
            self._field(expr, info)
        elif isinstance(expr, ast.Aggregate) and info is not None and not info.rank:
            self._aggregate_items(expr, info, evidence)

    def _aggregate_items(self, expr: ast.Aggregate, info: TypeInfo, evidence: str) -> None:
        """An aggregate given where a known record is expected: each part has the type of
        its component (``position.trans := [x, -y, zh]``: ``x`` is a num of a pos)."""
        components = self.names.components(info.name)
        record = self.missing.get(self.names.base(info).key)
        if components is None and record is not None and record.kind == TYPE:
            components = [(name, known.name) for name, known in record.fields.items()
                          if known is not None and known is not SOME_RECORD]
        if components is None or len(components) != len(expr.items):
            return
        for item, (name, type_name) in zip(expr.items, components):
            self.expect(item, TypeInfo(type_name), f"component {name} of {evidence}")

    def _field(self, expr: ast.Component, info: Optional[TypeInfo]) -> None:
        """A component of data whose type is missing: the RECORD gets that component (an
        ``anytype`` parameter, ErrWrite's or a logging routine's, tells no type)."""
        if info is not None and info.key in UNTYPED:
            info = None
        if isinstance(expr.base, ast.Component):
            self._nested_record(expr.base)
        base = self.type_of(expr.base)
        record = self.missing.get(base.key) if base is not None else None
        if record is None or record.kind != TYPE:
            return
        self._name_component(record, expr.name.text, info)

    def _name_component(self, record: Missing, name: str, info: Optional[TypeInfo]) -> None:
        """A use names component ``name`` of a missing record, of type ``info`` if the use
        tells it: the record gets it (on a position of the value that shapes it, if any).
        RAPID names are not case-sensitive: the first spelling used stays."""
        name = _spelled(record.named, name)
        if name not in record.named or info is not None and \
                self._replaces(record.named[name], info):
            record.named[name] = info
            self._arrange(record)

    def _arrange(self, record: Missing) -> None:
        """The record's components from its names and shape (records.arrange); a position
        of a record the stubs shaped from a value alone that a name of another record type
        took (``_shaped_alike``) takes that type everywhere."""
        components, left_out = arrange(record.named, record.shape, self._fits)
        if components != record.fields or left_out != record.left_out:
            record.fields, record.left_out = components, left_out
            self.changed = True
        for slot, info in zip(record.shape or (), list(components.values())):
            if slot is not None and info is not None and slot.key != info.key and \
                    slot.key in self.invented and self._shaped_alike(info, slot):
                self.replace_type(slot.key, info.name)
                return

    def _fits(self, info: Optional[TypeInfo], slot: Optional[TypeInfo]) -> bool:
        """Whether a component of type ``info`` can stand at a position of type ``slot``:
        the same type, or a record the stubs shaped from a value alone (named ``c1``,
        ``c2`` ...) where the use names a record of the same structure (one task declares
        ``[TRUE, ["a.mod", "b.mod"]]``, another passes that component as a
        ``pm_moduleinfo`` whose ten strings its uses name); ``_arrange`` then gives the
        position that type."""
        if info is SOME_RECORD:
            return slot is not None and self._is_record(slot)
        return info is None or slot is None or \
            self.names.base(info).key == self.names.base(slot).key or \
            self._shaped_alike(info, slot)

    def _shaped_alike(self, info: TypeInfo, slot: TypeInfo) -> bool:
        record = self.missing.get(slot.key)
        if record is None or slot.key not in self.invented or record.value is None or \
                record.named or info.rank or slot.rank:
            return False
        shape = self.structure(slot)
        return shape is not None and not isinstance(shape, str) and \
            self.structure(info) == shape

    def structure(self, info: TypeInfo, depth: int = 0):
        """A type's shape: the atomic type's key, or the tuple of its components' shapes
        (the positions' for a record the stubs shape from a value); None when a part is
        unknown."""
        base = self.names.base(info).key
        if base in ATOMIC or depth > 8:
            return base
        record = self.missing.get(base)
        if record is not None and record.kind == TYPE:
            parts = record.shape if record.shape is not None else list(record.fields.values())
        else:
            parts = [TypeInfo(t) for _, t in self.names.components(info.name) or ()]
        if not parts or None in parts:
            return None
        shapes = tuple(self.structure(part, depth + 1) for part in parts)
        return None if None in shapes else shapes

    def _is_record(self, info: TypeInfo) -> bool:
        known = self.missing.get(info.key)
        if known is not None and known.kind == TYPE:
            return not known.alias_of
        return bool(self.names.components(info.name))

    def _replaces(self, known: Optional[TypeInfo], info: TypeInfo) -> bool:
        """A component's type ``info`` from a use takes the place of none, or of a record
        type the stubs invented only because the component had components of its own
        (``ee.tool.tframe.rot := ...`` and then ``tGrip := ee.tool``: a tooldata)."""
        return known is None or known is SOME_RECORD or \
            known.key in self.invented and info.key not in self.invented

    def replace_type(self, key: str, type_name: str) -> None:
        """The stubs' type ``key`` gives way to ``type_name`` wherever a missing name uses it."""
        self.missing.every.pop(key, None)
        self.invented.discard(key)

        def replaced(info):
            return TypeInfo(type_name, info.rank) if info is not None and info.key == key \
                else info
        for owner in self.missing.every.values():
            owner.named = {name: replaced(info) for name, info in owner.named.items()}
            if owner.shape is not None:
                owner.shape = [replaced(slot) for slot in owner.shape]
            owner.type = replaced(owner.type)
            for parameter in owner.parameters:
                parameter.type = replaced(parameter.type)
            if owner.kind == TYPE:
                self._arrange(owner)
        self.changed = True

    def _shape_assigned(self, target: Optional[TypeInfo], value) -> None:
        """An aggregate assigned whole to data of a missing record type shapes it as a
        declared value does (``pack.Header := [PACK_HEADER, 96, 1, 0, 0, 0, 0]``: seven
        components, which the names the code reads then take)."""
        record = self.missing.get(target.key) if target is not None and not target.rank \
            else None
        if record is not None and record.kind == TYPE and not record.alias_of and \
                isinstance(value, ast.Aggregate) and value.items:
            self._shape_record(record, value)

    def _unify_invented(self, target: Optional[TypeInfo], value: Optional[TypeInfo]) -> None:
        """Data of two record types the stubs invented (``bufA{i} := bmEmpty`` and ``bufB{i}
        := bmEmpty``, each array's ``<data>_rec``) assigned one to the other: one type, the
        one invented first, with the components both are read by (a value's shape kept)."""
        if target is None or value is None or target.key == value.key or \
                target.key not in self.invented or value.key not in self.invented:
            return
        kept, merged = self.missing.get(target.key), self.missing.get(value.key)
        if kept is None or merged is None or merged.shape is not None and kept.shape is not None:
            return
        if _place_of(merged) < _place_of(kept):
            kept, merged = merged, kept
        if kept.shape is None and merged.shape is not None:
            kept.shape, kept.value = merged.shape, merged.value
        for name, info in merged.named.items():
            self._name_component(kept, name, info)
        self.replace_type(merged.name.key, kept.name.text)

    def _nested_record(self, expr: ast.Component) -> None:
        """``msgs.state.joints``: when ``msgs`` has a missing RECORD type and its component
        ``state`` has no known type, ``state`` is itself a record, of a type named after
        both (``<record>_<component>``, said so in its comment)."""
        if isinstance(expr.base, ast.Component):
            self._nested_record(expr.base)
        owner = self.type_of(expr.base)
        record = self.missing.get(owner.key) if owner is not None else None
        if record is None or record.kind != TYPE or \
                record.fields.get(_spelled(record.fields, expr.name.text)):
            return
        if record.shape is not None:     # a position holding a record of its own takes it
            self._name_component(record, expr.name.text, SOME_RECORD)
            return
        invented = self._fresh_type_name(f"{record.name.text}_{expr.name.text}",
                                         expr.name.span)
        self.note(invented, TYPE, f"type of component {expr.name.text} of "
                  f"{record.name.text}, which has components itself; name invented")
        self.invented.add(invented.key)
        self._name_component(record, expr.name.text, TypeInfo(invented.text))

    def _fresh_type_name(self, text: str, span) -> ast.Name:
        """``text`` cut to RAPID's 32 characters, numbered if that is taken."""
        name, number = ast.Name.of(text[:32], span), 1
        while any(names.is_type(name.key) for names, _ in self.tasks) or \
                self.missing.taken(name.key):
            number += 1
            suffix = f"_{number}"
            name = ast.Name.of(text[:32 - len(suffix)] + suffix, span)
        return name

    def _array_use(self, missing: Missing, expr: ast.Index) -> None:
        while len(missing.dims) < len(expr.indices):
            missing.dims.append(1)
        for number, index in enumerate(expr.indices):
            # a literal index, or a FOR variable whose literal bounds it runs to
            # (``FOR i FROM 1 TO 11 DO stVideo{i}``: 11 elements, not the default 10)
            reach = int(index.value) if isinstance(index, ast.NumLiteral) else \
                self.loop_bounds.get(index.name.key) if isinstance(index, ast.NameRef) \
                else None
            if reach is not None and reach > missing.dims[number]:
                missing.dims[number] = reach

    def undeclared_data(self, name: ast.Name) -> bool:
        return not self.names.is_data(name.key, self.local) and name.key not in self.names.routines

    def undeclared_routine(self, name: ast.Name, use: str) -> bool:
        """Neither a routine of that kind nor of the other (a misuse is not a missing name)."""
        return not (self.names.is_routine(name.key, FUNCTION)
                    or self.names.is_routine(name.key, PROCEDURE)) and name.key not in self.local

    # ------------------------------------------------------------------ types
    def type_of(self, expr) -> Optional[TypeInfo]:
        """The static type of ``expr`` as far as declarations and inferences tell."""
        if isinstance(expr, ast.NumLiteral):
            return NUM
        if isinstance(expr, ast.StringLiteral):
            return STRING
        if isinstance(expr, ast.BoolLiteral):
            return BOOL
        if isinstance(expr, ast.NameRef):
            known = self.names.data_type(expr.name.key, self.local)
            if known is None and expr.name.key in self.missing:
                known = self.missing[expr.name.key].type
            return known
        if isinstance(expr, ast.Index):
            base = self.type_of(expr.base)
            return base.element() if base is not None else None
        if isinstance(expr, ast.Component):
            base = self.type_of(expr.base)
            if base is not None and base.key in self.missing:
                fields = self.missing[base.key].fields
                return fields.get(_spelled(fields, expr.name.text))
            return self.names.component_type(base.name, expr.name.text) if base else None
        if isinstance(expr, ast.FunctionCall):
            return self._call_type(expr)
        if isinstance(expr, ast.Unary):
            return BOOL if expr.op == "NOT" else self.type_of(expr.operand)
        if isinstance(expr, ast.Binary):
            if expr.op in COMPARISONS or expr.op in LOGICAL:
                return BOOL
            if expr.op in ("DIV", "MOD"):
                return NUM
            return self.type_of(expr.left) or self.type_of(expr.right)
        return None

    def _call_type(self, call: ast.FunctionCall) -> Optional[TypeInfo]:
        routine = self.names.routines.get(call.name.key)
        if routine is not None and routine.return_type is not None:
            return TypeInfo(routine.return_type.name.text)
        entry = registry.lookup_function(call.name.key)
        if entry is not None and entry.signature.return_type:
            return TypeInfo(entry.signature.return_type)
        missing = self.missing.get(call.name.key)
        return missing.type if missing is not None else None

    # -------------------------------------------------------------- the walk
    def activate(self, number: int) -> None:
        """Task ``number``'s declarations and modules are those the walk and passes see."""
        self.names, self.modules = self.tasks[number]
        self.missing.show(number, self.names)

    def walk(self) -> None:
        for number in range(len(self.tasks)):
            self.activate(number)
            self.codes = {}
            for module in self.modules:
                for definition in module.types:
                    self._record_components(definition)
                for decl in module.data:
                    self.local = {}
                    self._declaration(decl)
                for routine in module.routines:
                    self._routine(routine)
            for names in self.codes.values():
                self._alternatives(names)
        for record in list(self.missing.every.values()):
            if record.kind == TYPE and record.left_out:     # a name's record typed since
                self._arrange(record)

    def _code(self, subject, value) -> None:
        """Note that datum ``subject`` is given, or compared with, ``value`` when both are
        bare names: missing names one datum holds in turn are codes of different values
        (``Status := NG; WHILE Status <> OK``: with both 0 the loop never runs)."""
        if isinstance(subject, ast.NameRef) and isinstance(value, ast.NameRef):
            self.codes.setdefault(subject.name.key, []).append(value.name)

    def _record_components(self, definition) -> None:
        """A RECORD of the program whose component has a type no module declares."""
        for component in getattr(definition, "components", ()):
            if not self.names.is_type(component.type.name.key):
                self.note(component.type.name, TYPE,
                          f"type of component {component.name.text} of {definition.name.text}")

    def _declaration(self, decl: ast.DataDeclaration) -> None:
        if not self.names.is_type(decl.type.name.key):
            self.note(decl.type.name, TYPE, f"type of {decl.name.text}")
        self.in_declaration = True
        self._declaration_values(decl)
        self.in_declaration = False

    def _declaration_values(self, decl: ast.DataDeclaration) -> None:
        for axis, dim in enumerate(decl.dims):
            if isinstance(dim, ast.NameRef) and self.undeclared_data(dim.name):
                size = self.note(dim.name, DATA, f"array size of {decl.name.text}")
                size.sizes_array = True
                length = _length_along(decl.init, axis)
                if length is not None and size.array_size is None:
                    size.array_size = (length, decl.name.text)
                    self.changed = True
            self.expect(dim, NUM, f"array size of {decl.name.text}")
            self.expression(dim)
        if decl.init is not None:
            self._code(ast.NameRef(decl.name, decl.span), decl.init)
            self._type_from_value(decl)
            self.expect(decl.init, TypeInfo(decl.type.name.text), f"value of {decl.name.text}")
            self.expression(decl.init)

    def _type_from_value(self, decl: ast.DataDeclaration) -> None:
        """A missing type whose data is declared with a value: with an aggregate (``PERS
        clampdata c := ["seq 1", 2, TRUE]``) a RECORD with one component per part, of the
        part's type, which the names the uses give then take (records.arrange); with a single
        atomic value (``CONST gunnum g := 2``) and no component named, an ALIAS of its type.
        An array's value shapes its elements' type."""
        record = self.missing.get(decl.type.name.key)
        if record is None or record.kind != TYPE or record.alias_of:
            return
        value = decl.init
        for _ in decl.dims:
            value = value.items[0] if isinstance(value, ast.Aggregate) and value.items else None
        if isinstance(value, ast.Aggregate) and value.items:
            self._shape_record(record, value)
        elif value is not None and not decl.dims and not record.named and record.shape is None:
            known = self.type_of(value)
            if known is not None and known.key in ATOMIC:
                record.alias_of = known.name
                self.changed = True

    def _alias_from_assigned(self, target: Optional[TypeInfo], value: Optional[TypeInfo]) -> None:
        """A missing type whose data is assigned a single atomic value (``VAR toolno t; t :=
        GInput(gi)``), with no component named and no aggregate seen, is an ALIAS of that
        value's type, as one declared with such a value is (a tool changer's ``toolno`` of
        an encrypted module): a record would refuse every use of it as a number."""
        if target is None or value is None or target.rank or value.rank or \
                value.key not in ATOMIC:
            return
        record = self.missing.get(target.key)
        if record is not None and record.kind == TYPE and not record.alias_of and \
                not record.named and record.shape is None:
            record.alias_of = value.name
            self.changed = True

    def _shape_record(self, record: Missing, aggregate: ast.Aggregate) -> None:
        """The positions of ``record`` from the value ``aggregate``: the first value shapes
        it; a position whose part's type is not known (a missing name) learns it from a
        later walk or from another value of as many parts."""
        if record.shape is not None and (None not in record.shape
                                         or len(record.shape) != len(aggregate.items)):
            return
        shape = self._parts(record.name, aggregate, record.name.text)
        if record.shape is not None:
            shape = [old if old is not None else new for old, new in zip(record.shape, shape)]
        if shape != record.shape:
            record.shape, record.value = shape, record.value or aggregate
            self._arrange(record)

    def _parts(self, owner: ast.Name, aggregate: ast.Aggregate, top: str) -> list:
        """The type of each part of a record's value (None while unknown). A nested
        aggregate (``trackdata`` of ArcWare: ``[0,TRUE,50,[0,0,...],[0,...]]``) is a record
        of its own, named ``<owner>_c<n>`` and shaped the same way; nested aggregates of
        one shape share that record (the three jointtargets of a MultiMove group)."""
        parts = []
        for number, item in enumerate(aggregate.items, 1):
            if isinstance(item, ast.Aggregate) and item.items:
                parts.append(self._nested_shape(owner, number, item, top))
            else:
                known = self.type_of(item)
                parts.append(known.element() if known is not None and not known.rank
                             else None)
        return parts

    def _nested_shape(self, owner: ast.Name, number: int, aggregate: ast.Aggregate,
                      top: str) -> TypeInfo:
        nested = self._fresh_type_name(f"{owner.text}_c{number}", owner.span)
        inner = self._parts(nested, aggregate, top)      # nested ones are shaped first
        for key in sorted(self.invented):
            known = self.missing.get(key)
            if known is not None and known.shape == inner and known.value is not None \
                    and known.name.text.startswith(top + "_c"):
                return TypeInfo(known.name.text)
        record = self.note(nested, TYPE, f"type of component c{number} of {owner.text}, "
                           "shaped by a declared value; name invented")
        record.shape, record.value = inner, aggregate
        self.invented.add(nested.key)
        self._arrange(record)
        return TypeInfo(nested.text)

    def _routine(self, routine: ast.Routine) -> None:
        self.routine = routine
        self.local = {}
        for param in routine.parameters:
            self.local[param.name.key] = TypeInfo(param.type.name.text, param.array_rank)
            if not self.names.is_type(param.type.name.key):
                self.note(param.type.name, TYPE, f"type of parameter {param.name.text}")
        for decl in routine.data:
            self.local[decl.name.key] = TypeInfo(decl.type.name.text, len(decl.dims))
            self._declaration(decl)
        if routine.return_type is not None and not self.names.is_type(routine.return_type.name.key):
            self.note(routine.return_type.name, TYPE, f"return type of {routine.name.text}")
        sections = [routine.body, routine.backward or (), routine.undo or (),
                    routine.error.body if routine.error else ()]
        for statements in sections:
            self.statements(statements)

    def statements(self, statements) -> None:
        for statement in statements:
            method = getattr(self, "_" + type(statement).__name__, None)
            if method is not None:
                method(statement)

    # ------------------------------------------------------------ statements
    def _Assignment(self, statement: ast.Assignment) -> None:
        target = self.type_of(statement.target)
        value = self.type_of(statement.value)
        root = statement.target
        while isinstance(root, (ast.Index, ast.Component)):
            root = root.base
        self._code(statement.target, statement.value)
        self._shape_assigned(target, statement.value)
        self._unify_invented(target, value)
        self._alias_from_assigned(target, value)
        self._same_sizes(statement.target, statement.value)
        self.expect(statement.target, value, f"assigned a {value.name}" if value else "assigned")
        self.expression(statement.target)
        if isinstance(root, ast.NameRef) and root.name.key in self.missing:
            self.missing[root.name.key].assigned = True
        self.expect(statement.value, target,
                    f"assigned to {target.name} data" if target else "read")
        self.expression(statement.value)
        if isinstance(statement.target, ast.NameRef) and isinstance(statement.value, ast.Aggregate):
            written = self.missing.get(statement.target.name.key)
            if written is not None and written.kind == DATA and \
                    all(a is not statement.value for a in written.written):
                written.written.append(statement.value)
        if target is None and value is None and isinstance(statement.target, ast.NameRef) \
                and isinstance(statement.value, ast.Aggregate):
            self._array_of_records(statement.target.name, statement.value)
        if target is None and value is None and isinstance(statement.value, ast.FunctionCall) \
                and isinstance(statement.target, ast.Component):
            owner = self.type_of(statement.target.base)
            record = self.missing.get(owner.key) if owner is not None else None
            if record is not None and record.kind == TYPE:
                self.component_feeds.setdefault(statement.value.name.key,
                                                (record, statement.target.name.text))

    def _same_sizes(self, target, value) -> None:
        """``a := b`` of two missing names, one of them an array (indexed elsewhere): the
        other is an array of the same sizes, not a single value of its element type."""
        if not (isinstance(target, ast.NameRef) and isinstance(value, ast.NameRef)):
            return
        pair = [self.missing.get(target.name.key), self.missing.get(value.name.key)]
        if any(m is None or m.kind != DATA for m in pair):
            return
        for one, other in (pair, pair[::-1]):
            if not one.dims or other.exact_dims or other.dims == one.dims:
                continue
            if one.exact_dims or len(other.dims) != len(one.dims):
                sizes = list(one.dims)                  # the sizes an aggregate fixed
            else:
                sizes = [max(a, b) for a, b in zip(one.dims, other.dims)]
            if sizes != other.dims:
                other.dims, other.exact_dims = sizes, one.exact_dims
                self.changed = True

    def _array_of_records(self, name: ast.Name, aggregate: ast.Aggregate) -> None:
        """Missing data assigned an aggregate of aggregates of one shape
        (``stations := [["A", 1], ["B", 2]]``) is an array of the one record of the program
        of that shape, as long as the shape fits exactly one. A predefined record is not
        taken for a plain aggregate (``[["img", "text"]]`` is no ``listitem`` for that alone;
        a task list passed to WaitSyncTask is typed ``tasks`` by that use)."""
        missing = self.missing.get(name.key)
        if missing is None or missing.kind != DATA or missing.type is not None:
            return
        shapes = set()
        for item in aggregate.items:
            if not isinstance(item, ast.Aggregate):
                return
            parts = [self.type_of(part) for part in item.items]
            if not parts or any(p is None or p.key not in ATOMIC for p in parts):
                return
            shapes.add(tuple(p.key for p in parts))
        if len(shapes) != 1:
            return
        fitting = self.names.records_shaped(list(shapes.pop()), predefined=False)
        if len(fitting) == 1 and missing.learn(TypeInfo(fitting[0]),
                                               f"assigned an array of {fitting[0]} aggregates"):
            missing.dims = [len(aggregate.items)]
            missing.exact_dims = True
            self.changed = True

    def _ProcedureCall(self, statement: ast.ProcedureCall) -> None:
        self.call(statement.name, statement.args, PROCEDURE, None)

    def _LateBindingCall(self, statement: ast.LateBindingCall) -> None:
        self.expect(statement.name_expr, STRING, "procedure name of a late-bound call")
        self.expression(statement.name_expr)
        for arg in statement.args:
            if arg.value is not None:
                self.expression(arg.value)

    def _Return(self, statement: ast.Return) -> None:
        if statement.value is not None:
            routine = self.routine
            wanted = TypeInfo(routine.return_type.name.text) if routine.return_type else None
            self.expect(statement.value, wanted, f"returned by {routine.name.text}")
            self.expression(statement.value)

    def _Raise(self, statement: ast.Raise) -> None:
        if statement.value is not None:
            self.expect(statement.value, TypeInfo("errnum"), "raised as an error number")
            self.expression(statement.value)

    def _Connect(self, statement: ast.Connect) -> None:
        self.expect(statement.target, TypeInfo("intnum"), "connected to a trap")
        self.expression(statement.target)
        if statement.trap.key not in self.names.routines:
            self.note(statement.trap, TRAP, "trap of a CONNECT")

    def _If(self, statement: ast.If) -> None:
        for branch in statement.branches:
            self.condition(branch.condition, "IF")
            self.statements(branch.body)
        self.statements(statement.else_body or ())
        compared = [_compared_with(branch.condition) for branch in statement.branches]
        subjects = {subject for subject, _ in filter(None, compared)}
        if len(subjects) == 1 and all(compared):
            self._alternatives([name for _, name in compared])

    def _alternatives(self, names: list) -> None:
        """Missing names one subject is compared with in turn (``IF axisNo = axisX ...
        ELSEIF axisNo = axisY``, ``CASE PICK_TYPE: ... CASE PLACE_TYPE:``) stand for
        different values: they get the numbers 1, 2, ... in order, not one neutral 0 that
        would leave every branch after the first unreachable."""
        keys = dict.fromkeys(name.key for name in names
                             if isinstance(name, ast.Name) and self.undeclared_data(name))
        missing = [self.missing[key] for key in keys
                   if key in self.missing and self.missing[key].kind == DATA]
        if len(missing) < 2:
            return
        for number, item in enumerate(missing, 1):
            if item.alternative is None:
                item.alternative = (number, len(missing))
                self.changed = True

    def _CompactIf(self, statement: ast.CompactIf) -> None:
        self.condition(statement.condition, "IF")
        self.statements((statement.statement,))

    def _While(self, statement: ast.While) -> None:
        self.condition(statement.condition, "WHILE")
        self.statements(statement.body)

    def _For(self, statement: ast.For) -> None:
        for bound in (statement.start, statement.stop, statement.step):
            if bound is not None:
                self.expect(bound, NUM, "FOR bound")
                self.expression(bound)
        saved = dict(self.local)
        saved_bounds = dict(self.loop_bounds)
        self.local[statement.variable.key] = NUM
        self.loop_bounds[statement.variable.key] = _loop_reach(statement)
        self.statements(statement.body)
        self.local = saved
        self.loop_bounds = saved_bounds

    def _Test(self, statement: ast.Test) -> None:
        values = [v for case in statement.cases for v in case.values]
        subject = self.type_of(statement.subject) or next(
            (t for t in map(self.type_of, values) if t is not None), None)
        self.expect(statement.subject, subject, "TEST subject")
        self.expression(statement.subject)
        for case in statement.cases:
            for value in case.values:
                self.expect(value, subject, "CASE value")
                self.expression(value)
            self.statements(case.body)
        self.statements(statement.default or ())
        self._alternatives([value.name for case in statement.cases for value in case.values
                            if isinstance(value, ast.NameRef)])
        names = [statement.subject, *values]
        if subject is None and all(isinstance(n, ast.NameRef) for n in names):
            keys = tuple(n.name.key for n in names)
            if keys not in self.untyped_tests:
                self.untyped_tests.append(keys)

    def condition(self, expr, keyword: str) -> None:
        self.expect(expr, BOOL, f"{keyword} condition")
        self.expression(expr)

    # ----------------------------------------------------------- expressions
    def expression(self, expr) -> None:
        """Note every undeclared name in ``expr`` and what its place says about it."""
        if isinstance(expr, ast.NameRef):
            if self.undeclared_data(expr.name):
                self.note(expr.name, DATA, "read")
        elif isinstance(expr, ast.Index):
            if isinstance(expr.base, ast.NameRef) and self.undeclared_data(expr.base.name):
                self._array_use(self.note(expr.base.name, DATA, "indexed"), expr)
            else:
                self.expression(expr.base)
            self._indices(expr.indices)
        elif isinstance(expr, ast.Component):
            self._component(expr)
        elif isinstance(expr, ast.FunctionCall):
            self.call(expr.name, expr.args, FUNCTION, expr)
        elif isinstance(expr, ast.Unary):
            if expr.op == "NOT":
                self.expect(expr.operand, BOOL, "operand of NOT")
            self.expression(expr.operand)
        elif isinstance(expr, ast.Binary):
            self._binary(expr)
        elif isinstance(expr, ast.Aggregate):
            for item in expr.items:
                self.expression(item)

    def _indices(self, indices) -> None:
        """Array indices are numbers; a missing name used as one starts at the first element."""
        for index in indices:
            self.expect(index, NUM, "array index")
            found = self.missing.get(index.name.key) if isinstance(index, ast.NameRef) else None
            if found is not None and found.kind == DATA:
                found.indexes_array = True
            self.expression(index)

    def _component(self, expr: ast.Component) -> None:
        root = expr.base
        indexed = isinstance(root, ast.Index) and isinstance(root.base, ast.NameRef) \
            and self.undeclared_data(root.base.name)
        if indexed or isinstance(root, ast.NameRef) and self.undeclared_data(root.name):
            name = root.base.name if indexed else root.name
            missing = self.note(name, DATA, f"component .{expr.name.text} read")
            if indexed:                  # ``traj{1}.pos``: an array of records
                self._array_use(missing, root)
                self._indices(root.indices)
            if expr.name.text not in missing.components:
                missing.components.append(expr.name.text)
                self.changed = True
            self._field(expr, None)
        else:
            self._field(expr, None)
            self.expression(root)

    def _binary(self, expr: ast.Binary) -> None:
        if expr.op in LOGICAL:
            self.expect(expr.left, BOOL, f"operand of {expr.op}")
            self.expect(expr.right, BOOL, f"operand of {expr.op}")
        elif expr.op in COMPARISONS or expr.op in ARITHMETIC:
            if expr.op in ("=", "<>"):
                self._code(expr.left, expr.right)
                self._code(expr.right, expr.left)
            left, right = self.type_of(expr.left), self.type_of(expr.right)
            what = "compared with" if expr.op in COMPARISONS else "combined with"
            if expr.op in ("=", "<>") and left is None and right is None and \
                    isinstance(expr.left, ast.NameRef) and isinstance(expr.right, ast.NameRef):
                # two names compared with each other, as a TEST compares its CASE values
                # (``PM_PROJECT_STATUS = PM_PROJECT_STOPPED``): ``_types_of_tests``
                keys = (expr.left.name.key, expr.right.name.key)
                if keys not in self.untyped_comparisons:
                    self.untyped_comparisons.append(keys)
            if right is not None:
                self.expect(expr.left, right, f"{what} {right.name}")
            if left is not None:
                self.expect(expr.right, left, f"{what} {left.name}")
        elif expr.op in ("DIV", "MOD"):
            self.expect(expr.left, NUM, f"operand of {expr.op}")
            self.expect(expr.right, NUM, f"operand of {expr.op}")
        self.expression(expr.left)
        self.expression(expr.right)

    # ----------------------------------------------------------------- calls
    def call(self, name: ast.Name, args, use: str, expr) -> None:
        routine = self.names.routines.get(name.key)
        entry = None if routine is not None else (
            registry.lookup_function(name.key) if use == FUNCTION
            else registry.lookup_procedure(name.key))
        if routine is not None:
            self._arguments(name, args, user_parameters(routine))
        elif entry is not None:
            self._arguments(name, args, predefined_parameters(entry))
        elif self.undeclared_routine(name, use):
            missing = self.note(name, use, "called")
            self._learn_parameters(missing, args)
        for arg in args:
            if arg.value is not None:
                self.expression(arg.value)

    def _arguments(self, name: ast.Name, args, parameters) -> None:
        """Match arguments to ``(key, name, type, optional, mode)`` parameters; expect their
        types. Missing data given to a VAR parameter (an interrupt number, a socket) must be
        a variable: the stubs declare it VAR, not PERS."""
        required = [p for p in parameters if not p[3]]
        position = 0
        for arg in args:
            if arg.value is None:
                continue
            if arg.kind == ast.REQUIRED and arg.name is None:
                spec = required[position] if position < len(required) else None
                position += 1
            else:
                spec = next((p for p in parameters if arg.name and p[0] == arg.name.key), None)
            if spec is not None:
                self.expect(arg.value, spec[2], f"{name.text} argument {spec[1]}")
                if spec[4] == "VAR" and isinstance(arg.value, ast.NameRef) and \
                        arg.value.name.key in self.missing:
                    self.missing[arg.value.name.key].storage = "VAR"
                if spec[0] == "PROCNAME":
                    self._named_procedure(name, arg.value)

    def _named_procedure(self, caller: ast.Name, value) -> None:
        """A procedure named by a string literal (``MoveJSync p, v, z, t, "StartCycle"``):
        the stubs declare it, without parameters, when no module does."""
        if not isinstance(value, ast.StringLiteral) or not IDENTIFIER.fullmatch(value.value):
            return
        name = ast.Name.of(value.value, value.span)
        if self.undeclared_routine(name, PROCEDURE) and name.key not in self.names.data:
            self.note(name, PROCEDURE, f"named by a string given to {caller.text}")

    def _learn_parameters(self, missing: Missing, args) -> None:
        known = {p.name.upper(): p for p in missing.parameters}
        position = 0
        for arg in args:
            if arg.kind == ast.REQUIRED and arg.name is None:
                position += 1
                key, text = f"P{position}", f"p{position}"
            elif arg.name is not None:
                key, text = arg.name.key, arg.name.text
            else:
                continue
            info = self.type_of(arg.value) if arg.value is not None else None
            if info is None and isinstance(arg.value, ast.Aggregate):
                info = _text_array(self.type_of(item) for item in arg.value.items) or \
                    _target_shaped(arg.value)
            if info is None and isinstance(arg.value, ast.FunctionCall) \
                    and arg.value.name.key in self.missing:
                self.feeds.setdefault(arg.value.name.key, (missing, key))
            if info is None and arg.value is not None and key in CONVENTIONAL_PARAMETERS:
                info = TypeInfo(CONVENTIONAL_PARAMETERS[key])
                self.expect(arg.value, info, f"{missing.name.text} argument \\{text}, named "
                            "like the motion instructions' parameter")
            parameter = known.get(key)
            if parameter is None:
                parameter = Parameter(text, info, optional=arg.kind != ast.REQUIRED,
                                      switch=arg.kind == ast.SWITCH)
                missing.parameters.append(parameter)
                known[key] = parameter
                self.changed = True
            elif parameter.type is None and info is not None:
                parameter.type = info.element() if info.rank == 0 else info
                self.changed = True
            if isinstance(arg.value, ast.Aggregate) and \
                    all(a is not arg.value for a in parameter.aggregates):
                parameter.aggregates.append(arg.value)
            if parameter.type is not None and arg.value is not None and not parameter.switch:
                # the other calls' arguments have the type one call's argument gave
                self.expect(arg.value, parameter.type, f"{missing.name.text} argument "
                            f"{parameter.name}" + (", num assumed" if parameter.assumed else ""))


# the nested shapes of the motion targets written as literals (parts per component)
TARGET_SHAPES = {(3, 4, 4, 6): TypeInfo("robtarget"), (6, 6): TypeInfo("jointtarget")}


def _target_shaped(aggregate: ast.Aggregate) -> Optional[TypeInfo]:
    """robtarget or jointtarget for an aggregate of number aggregates shaped like one
    (``[[x,y,z],[q1..q4],[cf1..cfx],[e1..e6]]``: an add-in's weld instruction given a
    target literal), else None: a plain number list could be any array."""
    shape = []
    for item in aggregate.items:
        if not isinstance(item, ast.Aggregate) or not all(
                isinstance(part, ast.NumLiteral) or
                isinstance(part, ast.Unary) and isinstance(part.operand, ast.NumLiteral)
                for part in item.items):
            return None
        shape.append(len(item.items))
    return TARGET_SHAPES.get(tuple(shape))


def _persistents(tasks) -> dict:
    """``key -> (type, sizes, module name, whether with a value)`` of the PERS data the
    tasks' modules declare for every task (neither LOCAL nor TASK), the first declaration
    of each name; sizes only when every dimension is a number."""
    found = {}
    for modules in tasks:
        for module in modules:
            for decl in module.data:
                if decl.storage != "PERS" or decl.scope in (ast.LOCAL, ast.TASK) or \
                        decl.name.key in found:
                    continue
                sizes = [int(dim.value) for dim in decl.dims
                         if isinstance(dim, ast.NumLiteral)]
                if len(sizes) != len(decl.dims):
                    continue
                found[decl.name.key] = (TypeInfo(decl.type.name.text), sizes, module.name.text,
                                        decl.init is not None)
    return found


def _place_of(missing: Missing) -> tuple:
    span = missing.first_use
    return span.file, span.line, span.column


def _spelled(names: dict, name: str) -> str:
    """``name`` as ``names`` spell it (RAPID names ignore case), or as given if absent."""
    return next((known for known in names if known.upper() == name.upper()), name)


def _length_along(value, axis: int) -> Optional[int]:
    """The number of parts of an array's declared value along dimension ``axis`` (0 the
    first): ``[[1,2,3],[4,5,6]]`` has 2 along 0 and 3 along 1; None without an aggregate."""
    for _ in range(axis):
        if not isinstance(value, ast.Aggregate) or not value.items:
            return None
        value = value.items[0]
    return len(value.items) if isinstance(value, ast.Aggregate) else None


def _text_array(item_types) -> Optional[TypeInfo]:
    """``["SELECT", "EXIT"]`` as an argument: an array of strings (or of bools); an
    aggregate of numbers stays unknown (it may as well be a pos or a confdata)."""
    names = {info.name if info is not None and info.rank == 0 else None for info in item_types}
    if len(names) == 1 and names <= {"string", "bool"}:
        return TypeInfo(names.pop(), 1)
    return None


def user_parameters(routine: ast.Routine) -> list[tuple]:
    return [(p.name.key, p.name.text, TypeInfo(p.type.name.text, p.array_rank), p.optional,
             p.mode) for p in routine.parameters]


def predefined_parameters(entry) -> list[tuple]:
    """Parameters of a predefined routine; a group of required alternatives takes one place."""
    found, groups = [], set()
    for spec in entry.signature.parameters:
        optional = spec.optional
        if not optional and spec.alternative_group is not None:
            optional = spec.alternative_group in groups
            groups.add(spec.alternative_group)
        found.append((spec.key, spec.name, TypeInfo(spec.type_name, spec.array_rank), optional,
                      spec.mode))
    return found


# A RAPID identifier (a procedure named by a string must be one).
IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]{0,31}")

# Parameter types that say nothing about the argument's type.
UNTYPED = ("ANYTYPE", "ANYNUM", "SWITCH")

# Types whose values a declaration can show by a literal alone.
ATOMIC = ("NUM", "DNUM", "STRING", "BOOL")


def _compared_with(condition) -> Optional[tuple]:
    """(subject name key, other name) of a condition ``subject = name`` (either order)
    whose sides are both bare names, or None."""
    if not (isinstance(condition, ast.Binary) and condition.op == "="):
        return None
    left, right = condition.left, condition.right
    if not (isinstance(left, ast.NameRef) and isinstance(right, ast.NameRef)):
        return None
    return left.name.key, right.name

# The optional parameters every motion instruction of ABB's and of its options has
# (``PaintL ... \WObj:=woPanel``): a missing routine called with them takes these types.
CONVENTIONAL_PARAMETERS = {"WOBJ": "wobjdata", "TOOL": "tooldata", "TLOAD": "loaddata"}


def _loop_reach(loop: ast.For) -> Optional[int]:
    """The largest index a FOR loop's variable takes when its bounds are positive integer
    literals, else None."""
    bounds = [bound for bound in (loop.start, loop.stop)
              if isinstance(bound, ast.NumLiteral) and float(bound.value) == int(bound.value)]
    if len(bounds) != 2 or (loop.step is not None and not isinstance(loop.step, ast.NumLiteral)):
        return None
    reach = max(int(bound.value) for bound in bounds)
    return reach if reach >= 1 else None
