"""The RAPID front end: source text to ``rapidmc.ast``.

Example::

    >>> [m.name.text for m in parse_text("MODULE Hello ENDMODULE", "hello.mod")]
    ['Hello']
"""
from __future__ import annotations

import contextlib
import gc

from .. import ast
from ..diagnostics import SourceCache, UserError
from ..diagnostics.error_report import report
from ..load.source import program_paths, read_source
from .parser import parse_modules


def parse_text(text: str, filename: str) -> tuple[ast.Module, ...]:
    """The modules in ``text``; syntax errors raise ``UserError``."""
    SourceCache.remember(filename, text)
    with _garbage_collection_paused():
        return parse_modules(text, filename)


@contextlib.contextmanager
def _garbage_collection_paused():
    """Parsing allocates millions of acyclic objects; the cycle collector's
    repeated scans of them would double the time for a large file.

    Afterwards the new objects join the oldest generation at once (freeze,
    then unfreeze, moves every tracked object there): left in the youngest,
    the first collection after parsing would scan the whole AST, and the
    next generation's collection scan it again.  Nothing is kept from the
    collector; the full collections see these objects as before."""
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        gc.unfreeze()
        if was_enabled:
            gc.enable()


def parse_file(path: str) -> tuple[ast.Module, ...]:
    """The modules in the RAPID file at ``path``."""
    return parse_text(read_source(path), path)


def load_program(paths: list[str]) -> ast.Program:
    """The program made of the given module files (``.pgf`` files expanded).

    The syntax errors of every file are reported together."""
    modules: list[ast.Module] = []
    problems = []
    for path in program_paths(list(paths)):
        try:
            modules.extend(parse_file(path))
        except UserError as failure:
            problems.extend(failure.diagnostics)
    if problems:
        raise UserError(report(problems))
    return ast.Program(tuple(modules))


__all__ = ["parse_text", "parse_file", "load_program"]
