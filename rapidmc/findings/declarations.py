"""Where a name is declared: the declaration a use at a place in a module refers to.

RAPID's scopes, innermost first: the routine around the place (its
parameters, routine data and labels), then the module (every declaration
at module level, LOCAL ones included), then the global declarations of the
program's other modules.  Go to definition in the editor (``rapidmc lsp``)
and the hover text of a user's routine or data come from here.

Example::

    >>> from rapidmc.syntax import parse_text
    >>> modules = parse_text("MODULE A\\nVAR num n;\\nPROC main()\\n  n := 1;\\nENDPROC\\n"
    ...                      "ENDMODULE\\n", "a.mod")
    >>> found = declaration_at(modules, "a.mod", 4, "n")
    >>> found.kind, str(found.name.span)
    ('data', 'a.mod:2:9')
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Iterator, Optional, Sequence

from .. import ast

ROUTINE, DATA, PARAMETER, RECORD, ALIAS, LABEL = (
    "routine", "data", "parameter", "record", "alias", "label")
IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")


@dataclass(frozen=True)
class Declaration:
    """A declared name, what declares it, and the module it is in."""

    name: ast.Name
    kind: str
    node: object
    module: ast.Module


def word_at(line_text: str, character: int) -> Optional[tuple[str, int]]:
    """The identifier covering 0-based ``character`` of a line, and its first character.

    >>> word_at("  MoveL p10, v100;", 4)
    ('MoveL', 2)
    """
    for match in IDENTIFIER.finditer(line_text):
        if match.start() <= character <= match.end():
            return match.group(), match.start()
    return None


def declaration_at(modules: Sequence[ast.Module], file: str, line: int,
                   word: str) -> Optional[Declaration]:
    """The declaration that ``word``, used on ``line`` of ``file``, refers to (None: none
    in these modules, e.g. a predefined routine)."""
    key = ast.canonical(word)
    module = _module_at(modules, file, line)
    if module is not None:
        routine = _routine_at(module, line)
        if routine is not None:
            found = _first(_routine_declarations(routine, module), key)
            if found is not None:
                return found
        found = _first(_module_declarations(module), key)
        if found is not None:
            return found
    others = (d for other in modules if other is not module for d in global_declarations(other))
    return _first(others, key)


def _first(declarations: Iterator[Declaration], key: str) -> Optional[Declaration]:
    return next((d for d in declarations if d.name.key == key), None)


def _module_at(modules: Sequence[ast.Module], file: str, line: int) -> Optional[ast.Module]:
    """The module of ``file`` whose text holds ``line`` (the last one starting before it)."""
    here = [m for m in modules if m.span.file == file and m.span.line <= line]
    return max(here, key=lambda m: m.span.line, default=None)


def _routine_at(module: ast.Module, line: int) -> Optional[ast.Routine]:
    for routine in module.routines:
        end = routine.end_span.line if routine.end_span.line else routine.span.line
        if routine.span.line <= line <= end:
            return routine
    return None


def _routine_declarations(routine: ast.Routine, module: ast.Module) -> Iterator[Declaration]:
    for parameter in routine.parameters:
        yield Declaration(parameter.name, PARAMETER, parameter, module)
    for data in routine.data:
        yield Declaration(data.name, DATA, data, module)
    for node, _ in ast.walk(routine):
        if isinstance(node, ast.Label):
            yield Declaration(node.name, LABEL, node, module)


def global_declarations(module: ast.Module) -> Iterator[Declaration]:
    """The module's declarations that other modules see (those not LOCAL)."""
    for declaration in _module_declarations(module):
        node = declaration.node
        if not getattr(node, "local", False) and getattr(node, "scope", "") != "LOCAL":
            yield declaration


def _module_declarations(module: ast.Module) -> Iterator[Declaration]:
    for routine in module.routines:
        yield Declaration(routine.name, ROUTINE, routine, module)
    for data in module.data:
        yield Declaration(data.name, DATA, data, module)
    for definition in module.types:
        kind = RECORD if isinstance(definition, ast.RecordDefinition) else ALIAS
        yield Declaration(definition.name, kind, definition, module)
