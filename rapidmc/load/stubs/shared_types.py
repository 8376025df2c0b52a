"""What one task's module of stubs declares when several tasks share the inference.

A task declares the missing names its own uses name, and every type those need that it
does not declare: a type the stubs invented while another task was walked (a PERS both
tasks miss takes its record from the first use), or a type another task of the backup
declares (a use there typed the shared name with it, or this task misses the type that
task declares). That other task's RECORD or ALIAS is declared again, component for
component, so that a PERS the tasks share has one type in each (RMC206 otherwise). With a
single task this is exactly what it misses.
"""
from __future__ import annotations

from pathlib import Path
from typing import Iterator, Optional

from ... import ast
from .inference import TYPE, Inference, Missing
from .names import TypeInfo


def needed_by(inference: Inference, number: int) -> list[Missing]:
    """The declarations the module of task ``number`` must hold (see the top)."""
    names = inference.tasks[number][0]
    chosen = {key: item for key, item in inference.missing.every.items()
              if number in item.tasks}
    for key, item in chosen.items():     # a type another task declares: as it declares it
        if item.kind == TYPE:
            chosen[key] = _declared_elsewhere(inference, key) or item
    pending = list(chosen.values())
    while pending:
        for info in _types_used(pending.pop()):
            key = info.key
            if key in chosen or names.is_type(key):
                continue
            found = inference.missing.every.get(key)
            if found is None or found.kind != TYPE:
                found = _declared_elsewhere(inference, key)
            if found is not None:
                chosen[key] = found
                pending.append(found)
    return list(chosen.values())


def _types_used(item: Missing) -> Iterator[TypeInfo]:
    """The types a declaration of ``item`` names: its own, its parameters', its
    components' (a record)."""
    if item.type is not None:
        yield item.type
    for parameter in item.parameters:
        if parameter.type is not None:
            yield parameter.type
    if item.kind == TYPE:
        yield from (info for info in item.fields.values() if info is not None)
        if item.alias_of:
            yield TypeInfo(item.alias_of)


def _declared_elsewhere(inference: Inference, key: str) -> Optional[Missing]:
    """Type ``key`` as the first task declaring it does, as a declaration of the stubs."""
    for names, modules in inference.tasks:
        for module in modules:
            for definition in module.types:
                if definition.name.key == key:
                    return _copy(definition, module)
    return None


def _copy(definition, module: ast.Module) -> Missing:
    where = f"declared so by {module.name.text} ({Path(definition.span.file).name}) of " \
        "another task"
    copy = Missing(definition.name, TYPE, definition.span, where)
    if isinstance(definition, ast.RecordDefinition):
        copy.fields = {c.name.text: TypeInfo(c.type.name.text) for c in definition.components}
        copy.named = dict(copy.fields)
    else:
        copy.alias_of = definition.base.name.text
    return copy
