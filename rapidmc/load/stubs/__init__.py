"""``rapidmc stubs``: declarations for the names a program uses and no module declares.

``inference`` finds the names and infers their types from their uses;
``module_text`` writes them as one RAPID module.

Example::

    >>> from rapidmc.syntax import parse_text
    >>> modules = parse_text("MODULE m PROC main() MoveL p1, v100, fine, tool0; "
    ...                      "ENDPROC ENDMODULE", "m.mod")
    >>> print(*stub_module(modules, "Missing").text.splitlines()[4:6], sep=chr(10))
      ! p1: first use m.mod:1:28 (MoveL argument ToPoint)
      PERS robtarget p1 := [[0,0,0],[1,0,0,0],[0,0,0,0],[9E+09,9E+09,9E+09,9E+09,9E+09,9E+09]];
"""
from __future__ import annotations

from dataclasses import dataclass

from ... import ast
from .inference import Missing
from .passes import missing_names_of_tasks
from .module_text import StubWriter
from .names import Declarations


@dataclass(frozen=True)
class Stubs:
    """The module text, the names it declares, and those it could only comment on."""

    text: str
    declared: tuple[Missing, ...]
    undeclared: tuple[Missing, ...]


def stub_module(modules: tuple[ast.Module, ...], module_name: str,
                signals: frozenset = frozenset()) -> Stubs:
    """The module declaring what ``modules`` use and do not declare (``signals``: the
    canonical names of the I/O configuration's signals, which are declared there)."""
    return stub_modules([(modules, module_name)], signals)[0]


def stub_modules(tasks: list[tuple[tuple[ast.Module, ...], str]],
                 signals: frozenset = frozenset()) -> list[Stubs]:
    """For each task (its modules, the name of its module of stubs), the module declaring
    what it uses and does not declare; a name several tasks miss is inferred once from all
    their uses and declared alike in each (a whole backup's option modules)."""
    found = missing_names_of_tasks([modules for modules, _ in tasks], signals)
    stubs = []
    for (modules, module_name), missing in zip(tasks, found):
        writer = StubWriter(Declarations(modules, signals))
        text = writer.module(module_name, missing)
        stubs.append(Stubs(text, tuple(writer.declared), tuple(writer.undeclared)))
    return stubs
