"""The passes that decide what the walk over the program leaves open (``rapidmc stubs``).

``missing_names`` walks the program (``inference.Inference``) until nothing new is
learnt, then applies, one at a time and each followed by more walks, the last resorts
for what the uses do not tell: a type from the name's prefix, the types and sizes of
aggregates assigned whole, num for TEST on missing names only, num for positions of a
record's value nothing types, and types for parameters no argument types. Between walks,
records the stubs invented give way to a known record with the same components.

Example::

    >>> from rapidmc.syntax import parse_text
    >>> modules = parse_text("MODULE m PROC main() MoveL p1, v100, fine, tGrip; "
    ...                      "IF ok THEN n := 3; ENDIF ENDPROC ENDMODULE", "m.mod")
    >>> [(m.name.text, m.type.name) for m in missing_names(modules)]
    [('p1', 'robtarget'), ('tGrip', 'tooldata'), ('ok', 'bool'), ('n', 'num')]
"""
from __future__ import annotations

from typing import Callable, Optional, Sequence

from ... import ast
from .inference import (ATOMIC, DATA, FUNCTION, PROCEDURE, TYPE, Inference, Missing,
                        Parameter)
from .names import NUM, TypeInfo
from .records import POSITIONAL_COMPONENT, arrange
from .shared_types import needed_by

# Walks to settle the types at most (each learns something, or the walking stops).
MAX_PASSES = 6


def missing_names(modules: tuple[ast.Module, ...], signals=frozenset()) -> list[Missing]:
    """Every undeclared name the modules use, in order of first use, types inferred
    (``signals``: names of configured I/O signals, which are not missing)."""
    return missing_names_of_tasks([modules], signals)[0]


def missing_names_of_tasks(tasks: Sequence[tuple[ast.Module, ...]],
                           signals=frozenset()) -> list[list[Missing]]:
    """For each task (its modules), what it must declare: the names it uses and does not
    declare, each inferred once from the uses of every task that misses it (a whole
    backup's tasks load the same option modules), and the types those need."""
    inference = Inference(tasks, signals)
    _settle(inference, count_uses=True)
    for last_resort in (_types_from_names,      # the last resort; its types reach other names
                        _types_from_written,    # aggregates assigned whole: types and sizes
                        _types_of_tests,        # TEST on missing names only: num assumed
                        _assumed_positions):    # positions of a value nothing types: num
        if _in_each_task(inference, last_resort):
            _settle(inference, count_uses=False)
    _in_each_task(inference, _types_of_passed_values)
    if _in_each_task(inference, _types_of_parameters):  # from aggregates, or num
        _settle(inference, count_uses=False)
    return [sorted(needed_by(inference, number),
                   key=lambda m: (m.first_use.file, m.first_use.line, m.first_use.column))
            for number in range(len(tasks))]


def _in_each_task(inference: Inference, step: Callable[[Inference], Optional[bool]]) -> bool:
    """``step`` run with each task's declarations and view in turn; whether one changed
    anything."""
    changed = False
    for number in range(len(inference.tasks)):
        inference.activate(number)
        changed |= bool(step(inference))
    return changed


def _assumed_positions(inference: Inference) -> bool:
    """Positions of a record's value whose part (``[nSpeed, 2, "weld"]``) and name nothing
    types: num, said so in the record's comment; the parts then learn it from the value."""
    changed = False
    for record in list(inference.missing.values()):
        if record.kind != TYPE or record.shape is None:
            continue
        for position, (name, info) in enumerate(record.fields.items()):
            if info is None and record.shape[position] is None:
                record.shape[position] = NUM
                record.assumed.append(name)
                changed = True
        if changed:
            inference._arrange(record)
    return changed


def _settle(inference: Inference, count_uses: bool) -> None:
    """Walk the program until the walk learns nothing new (uses counted on the first)."""
    for number in range(MAX_PASSES):
        inference.changed = False
        inference.counting = count_uses and number == 0
        inference.walk()
        if not _in_each_task(inference, _types_from_components) and not inference.changed:
            break


def _types_from_components(inference: Inference) -> bool:
    """A record whose components are read: the first record type that has them all
    (also for a record type the stubs invented: the known type replaces it)."""
    changed = _known_for_invented(inference)
    for missing in list(inference.missing.values()):
        if missing.type is None and missing.components:
            candidates = [name for name in inference.names.records_with(missing.components)
                          if _fits_written(inference, missing, name)]
            shown = ", ".join("." + c for c in missing.components)
            if candidates:
                changed |= missing.learn(TypeInfo(candidates[0]), f"has components {shown}")
            elif missing.kind == DATA:
                changed |= _invent_record(inference, missing, shown)
    return changed


def _invent_record(inference: Inference, missing: Missing, shown: str) -> bool:
    """Data (or an array's elements) whose components are read (``traj{1}.pos``,
    ``cmds.GET_TIME``) and that no known record has all of: a RECORD the stubs declare,
    named ``<data>_rec``, with the components the uses type (survey rounds 5 and 7)."""
    whose = "the elements of " if missing.dims else ""
    invented = inference._fresh_type_name(f"{missing.name.text}_rec", missing.name.span)
    record = inference.note(invented, TYPE, f"type of {whose}{missing.name.text}, "
                            f"whose components {shown} no known record has; name invented")
    record.named.update({component: None for component in missing.components})
    inference._arrange(record)
    inference.invented.add(invented.key)
    having = "its elements have" if missing.dims else "has"
    return missing.learn(TypeInfo(invented.text), f"{having} components {shown}")


# Name prefixes that say the type in controller programs (wobjTable, tool_gun, loadPart);
# used only when the uses tell nothing, and said so in the written comment.
NAME_PREFIXES = (("wobj", "wobjdata"), ("tool", "tooldata"), ("load", "loaddata"))


def _types_from_names(inference: Inference) -> bool:
    changed = False
    for missing in inference.missing.values():
        if missing.kind != DATA or missing.type is not None:
            continue
        for prefix, type_name in NAME_PREFIXES:
            if missing.name.text.lower().startswith(prefix):
                changed |= missing.learn(TypeInfo(type_name),
                                         f"guessed from the name's prefix '{prefix}'")
                break
    return changed


def _types_of_passed_values(inference: Inference) -> None:
    """A missing function whose value only ever goes to an untyped parameter of another
    missing routine (``MoveRob(GetTarget())``) or to an untyped component of a missing
    record (``msg.width := GetWidth()``): nothing tells the type, so both take the
    assumed ``num`` and the function's comment says so."""
    for key, (routine, parameter_key) in inference.feeds.items():
        function = inference.missing.get(key)
        if function is None or function.type is not None:
            continue
        parameter = next((p for number, p in enumerate(routine.parameters, 1)
                          if p.name.upper() == parameter_key or f"P{number}" == parameter_key),
                         None)
        if parameter is not None and parameter.type is None:
            function.learn(NUM, f"passed to {routine.name.text}, whose parameter type is not "
                           "known either: num assumed")
    for key, (record, component) in inference.component_feeds.items():
        function = inference.missing.get(key)
        if function is not None and function.type is None \
                and record.fields.get(component) is None:
            function.learn(NUM, f"assigned to component {component} of {record.name.text}, "
                           "whose type is not known either: num assumed")


def _types_of_parameters(inference: Inference) -> bool:
    """Parameters of missing routines that no argument types: an aggregate given as the
    argument makes an array of its parts' one atomic type (``[10, 20, 30]``: ``num{*}``) or
    a record the stubs declare shaped by it (``<routine>_<parameter>``); otherwise num is
    assumed, and said so. The missing data passed as such an argument then has that type
    (the walk that follows expects it), instead of being left undeclared."""
    changed = False
    for routine in list(inference.missing.values()):
        if routine.kind not in (PROCEDURE, FUNCTION):
            continue
        for parameter in routine.parameters:
            if parameter.type is not None or parameter.switch:
                continue
            parameter.type = _type_of_aggregates(inference, routine, parameter)
            if parameter.type is None:
                parameter.type, parameter.assumed = NUM, True
            changed = True
    return changed


def _type_of_aggregates(inference: Inference, routine: Missing,
                        parameter: Parameter) -> Optional[TypeInfo]:
    shapes = {None if s is None else (tuple(s[0]), tuple(s[1]))
              for s in (_shape(inference, a) for a in parameter.aggregates)}
    if len(shapes) != 1 or None in shapes:
        return None
    dims, parts = shapes.pop()
    if len(set(parts)) == 1:
        return TypeInfo(_ATOMIC_NAMES[parts[0]], len(dims))
    if len(dims) != 1:
        return None
    invented = inference._fresh_type_name(f"{routine.name.text}_{parameter.name}",
                                          routine.name.span)
    record = inference.note(invented, TYPE, f"type of parameter {parameter.name} of "
                            f"{routine.name.text}, given an aggregate of values of several "
                            "types; name invented")
    record.shape = [TypeInfo(_ATOMIC_NAMES[key]) for key in parts]
    record.value = parameter.aggregates[0]
    inference._arrange(record)
    inference.invented.add(invented.key)
    return TypeInfo(invented.text)


def _known_for_invented(inference: Inference) -> bool:
    """An invented record type whose components a declared or predefined record has all:
    its uses take that type. Without a value's shape two names are needed (``.robax``,
    ``.extax``: a jointtarget); with one, a single name does when the known record has the
    same shape (``g.JointG.extax`` with ``[[0,0,0,0,0,0],[9E9,...]]`` declared)."""
    changed = False
    for key in sorted(inference.invented):
        record = inference.missing.get(key)
        if record is None:
            continue
        names = [name for name in record.named if not POSITIONAL_COMPONENT.fullmatch(name)]
        if not names or record.shape is None and len(names) < 2:
            continue          # one name alone says too little; c1, c2 ... name positions
        candidates = inference.names.records_with(names)
        if record.shape is not None:
            shape = inference.structure(TypeInfo(record.name.text))
            candidates = [c for c in candidates
                          if shape is not None and inference.structure(TypeInfo(c)) == shape]
        if not candidates:
            continue
        inference.replace_type(key, candidates[0])
        changed = True
    return _drop_unused_invented(inference) or changed


def _drop_unused_invented(inference: Inference) -> bool:
    """Invented record types no component uses any more (they belonged to one replaced, or
    a use gave the component a known type); whether any was dropped."""
    dropped = False
    while True:
        used = {info.key for owner in inference.missing.every.values()
                for info in (*owner.fields.values(), *owner.named.values(), *(owner.shape or ()),
                             owner.type, *(parameter.type for parameter in owner.parameters))
                if info is not None}
        unused = [key for key in inference.invented if key not in used]
        if not unused:
            return dropped
        dropped = True
        for key in unused:
            inference.missing.every.pop(key, None)
            inference.invented.discard(key)


# ---------------------------------------------------------------------------------------
# Aggregates the program assigns whole (issue 19): component counts and array sizes
# ---------------------------------------------------------------------------------------

def _shape(inference: Inference, aggregate: ast.Aggregate) -> Optional[tuple]:
    """``(dims, part types)`` of a regular aggregate: ``[[1,2],[3,4],[5,6]]`` gives
    ``([3, 2], ['NUM'] * 6)``; None when its parts are of mixed nesting, ragged or of no
    atomic type."""
    if not aggregate.items:
        return None
    if all(isinstance(item, ast.Aggregate) for item in aggregate.items):
        inner = [_shape(inference, item) for item in aggregate.items]
        if any(i is None for i in inner) or len({tuple(i[0]) for i in inner}) != 1:
            return None
        return [len(aggregate.items)] + inner[0][0], [t for i in inner for t in i[1]]
    parts = [inference.type_of(item) for item in aggregate.items]
    if any(p is None or p.key not in ATOMIC for p in parts):
        return None
    return [len(parts)], [p.key for p in parts]


def _fits_written(inference: Inference, missing: Missing, record: str) -> bool:
    """Whether ``record`` can take the aggregates assigned whole to ``missing`` (as many
    components as the aggregate has parts); true when nothing is assigned whole."""
    count = len(inference.names.components(record) or ())
    shapes = [_shape(inference, a) for a in missing.written]
    return all(shape is None or shape[0][-1] == count for shape in shapes)


def _types_from_written(inference: Inference) -> bool:
    """The last resort for missing data assigned an aggregate whole: sizes and types.

    An array (typed by another use, or indexed) has the sizes of the aggregate assigned
    (``nList := [1,2,3,4,5,6,7]``: 7 elements, not the 10 assumed from an index). Untyped
    data takes the aggregate's shape: parts of one atomic type make an array of that type
    (``pOffs := [10,20,30]``: ``num pOffs{3}``, no pos or other record is guessed); parts
    of several types a RECORD ``<data>_rec`` with components ``c1`` ... ``cN``. A record
    invented for components the program reads gets the aggregate's other parts as further
    components, when the parts' types agree."""
    changed = False
    for missing in list(inference.missing.values()):
        shapes = [s for s in (_shape(inference, a) for a in missing.written) if s is not None]
        if missing.kind != DATA or not shapes or len({tuple(s[0]) for s in shapes}) != 1:
            continue
        dims, parts = shapes[0]
        if missing.type is None:
            changed |= _type_from_shape(inference, missing, dims, parts)
        elif missing.dims or missing.type.rank:
            record = inference.names.components(missing.type.name)
            sizes = dims[:-1] if record is not None and len(record) == dims[-1] else dims
            if sizes and (sizes != missing.dims or not missing.exact_dims):
                missing.dims, missing.exact_dims = list(sizes), True
                changed = True
        else:
            changed |= _widen_invented(inference, missing, dims, parts)
    return changed


def _type_from_shape(inference: Inference, missing: Missing, dims: list, parts: list) -> bool:
    if len(set(parts)) == 1 and len(dims) <= 3:
        info = TypeInfo(_ATOMIC_NAMES[parts[0]])
        if missing.learn(info, f"assigned an aggregate of {info.name} values"):
            missing.dims, missing.exact_dims = list(dims), True
            return True
        return False
    if len(dims) > 2 or len(set(tuple(parts[i:i + dims[-1]])
                                for i in range(0, len(parts), dims[-1]))) != 1:
        return False
    invented = inference._fresh_type_name(f"{missing.name.text}_rec", missing.name.span)
    record = inference.note(invented, TYPE, f"type of {missing.name.text}, assigned an "
                            "aggregate of values of several types; name invented")
    record.shape = [TypeInfo(_ATOMIC_NAMES[key]) for key in parts[:dims[-1]]]
    inference._arrange(record)
    inference.invented.add(invented.key)
    if missing.learn(TypeInfo(invented.text), "assigned an aggregate of values of several types"):
        missing.dims, missing.exact_dims = list(dims[:-1]), True
    return True


def _widen_invented(inference: Inference, missing: Missing, dims: list, parts: list) -> bool:
    """``r.name := "a"; r := ["a", 2, 3];``: the record invented for the components the
    program reads of ``r`` gets one component per part of the aggregate: a read ``c3`` is
    the third, a read name a place of its type (records.arrange), and the other places are
    ``c1``, ``c2`` ... of the parts' types; nothing changes when not every name fits."""
    record = inference.missing.get(missing.type.key)
    if record is None or record.kind != TYPE or missing.type.key not in inference.invented \
            or len(dims) != 1 or record.shape is not None:
        return False
    shape = [TypeInfo(_ATOMIC_NAMES[key]) for key in parts]
    if arrange(record.named, shape, inference._fits)[1]:
        return False
    record.shape = shape
    inference._arrange(record)
    return True


_ATOMIC_NAMES = {"NUM": "num", "DNUM": "dnum", "STRING": "string", "BOOL": "bool"}


def _types_of_tests(inference: Inference) -> bool:
    """``TEST nResume CASE RESUME_KILL: ...`` where the subject and every CASE value are missing
    names that nothing else types: num, the type TEST is mostly used with, assumed and said
    so in their comments (the values then get 1, 2 ... as names compared in turn); so too
    two missing names compared with ``=`` or ``<>`` and typed by nothing else
    (``IF PM_PROJECT_STATUS = PM_PROJECT_STOPPED``: a PickMaster status and its codes)."""
    changed = False
    groups = [(keys, "TEST subject or CASE value, nothing else tells the type")
              for keys in inference.untyped_tests] + \
        [(keys, "compared only with names nothing types") for keys in
         inference.untyped_comparisons]
    for keys, use in groups:
        group = [inference.missing.get(key) for key in keys]
        if any(m is None or m.kind != DATA or m.type is not None for m in group):
            continue
        for missing in group:
            changed |= missing.learn(NUM, f"{use}: num assumed")
    return changed
