"""What an editor shows about the modules being edited: their diagnostics.

A Language Server (``rapidmc lsp``) hands the text of every open document
to ``Workspace.update``; ``Workspace.diagnostics(file)`` then gives what
``rapidmc parse``, ``check`` and ``lint`` would report for that document,
with no cap: its syntax errors, or, when it parses, the static (link) errors
of the program it belongs to, and the lint findings (``findings.lint``; with
``read_folders``, configured by the nearest pyproject.toml as ``rapidmc
lint`` is).

Which program a document belongs to: the document, and the other documents
of the workspace that declare a global name it uses (routine, data or type),
and theirs in turn.  With ``read_folders``, the module files in the
document's folder that are not open count as documents too (read from disk
again when they change there): a program's modules are usually side by side.  So a module calling a routine of another open module
links with that module, while two main modules open side by side (program
A and program B of one cell) are checked apart.  A module without ``main``
is a library being edited: the missing entry routine is not reported.

Example::

    >>> space = Workspace()
    >>> space.update("a.mod", "MODULE A\\nPROC main()\\n  Helper;\\nENDPROC\\nENDMODULE\\n")
    >>> [d.message for d in space.diagnostics("a.mod")]
    ["unknown procedure 'Helper'"]
    >>> space.update("b.mod", "MODULE B\\nPROC Helper()\\nENDPROC\\nENDMODULE\\n")
    >>> space.diagnostics("a.mod")
    []
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from functools import cached_property
from typing import Optional

from .. import ast
from ..diagnostics import NO_ENTRY, Diagnostic, UserError
from ..diagnostics.error_report import merge_unknown_names, without_repeats
from ..load.backup import MODULE_SUFFIXES
from ..load.source import read_source
from ..semantics.link import build
from ..syntax import parse_text
from .declarations import global_declarations
from .lint import LintConfig, lint_program
from .lint.config import make_config, read_pyproject

# The linker's diagnostics an editor leaves out: a module edited alone need not hold main.
NOT_FOR_EDITORS = (NO_ENTRY,)
MAX_FOLDER_ENTRIES = 500      # a folder's first entries (by name) that ``read_folders`` reads


@dataclass(frozen=True)
class Parsed:
    """One document as parsed: its modules, or its syntax errors."""

    file: str
    text: str
    modules: tuple[ast.Module, ...] = ()
    errors: tuple[Diagnostic, ...] = ()

    @cached_property
    def declared(self) -> frozenset:
        """The keys of the global names its modules declare (not LOCAL)."""
        return frozenset(declaration.name.key for module in self.modules
                         for declaration in global_declarations(module))

    @cached_property
    def used(self) -> frozenset:
        """The keys of the names its modules use: data, routines and types."""
        keys = set()
        for module in self.modules:
            for node, _ in ast.walk(module):
                if isinstance(node, (ast.NameRef, ast.FunctionCall, ast.ProcedureCall,
                                     ast.TypeRef)):
                    keys.add(node.name.key)
        return frozenset(keys)


def parse_document(file: str, text: str) -> Parsed:
    """The document's modules, or its syntax errors."""
    try:
        return Parsed(file, text, modules=parse_text(text, file))
    except UserError as failure:
        return Parsed(file, text, errors=tuple(failure.diagnostics))


class Workspace:
    """The documents open in an editor, parsed once per version."""

    def __init__(self, read_folders: bool = False) -> None:
        self.documents: dict[str, Parsed] = {}
        self.read_folders = read_folders
        self.on_disk: dict[str, tuple] = {}    # path -> ((mtime, size), Parsed or None)

    def update(self, file: str, text: str) -> None:
        known = self.documents.get(file)
        if known is None or known.text != text:
            self.documents[file] = parse_document(file, text)

    def remove(self, file: str) -> None:
        self.documents.pop(file, None)

    def program_of(self, file: str) -> list[Parsed]:
        """The document and the parsed documents declaring names it needs, transitively:
        a document joins when it declares a name the chosen ones use and none declares."""
        chosen = {file: self.documents[file]}
        missing = set(chosen[file].used - chosen[file].declared)
        candidates = sorted({**self.neighbours(file), **self.documents}.items())
        added = True
        while added and missing:
            added = False
            for name, parsed in candidates:
                if name not in chosen and parsed.modules and parsed.declared & missing:
                    chosen[name] = parsed
                    missing = (missing | parsed.used) - frozenset().union(
                        *(p.declared for p in chosen.values()))
                    added = True
        return list(chosen.values())

    def neighbours(self, file: str) -> dict[str, Parsed]:
        """The module files beside ``file`` on disk, not open, that parse (``read_folders``)."""
        folder = os.path.dirname(file)
        if not self.read_folders or not os.path.isabs(file) or not os.path.isdir(folder):
            return {}
        found = {}
        for entry in sorted(os.listdir(folder))[:MAX_FOLDER_ENTRIES]:
            path = os.path.join(folder, entry)
            if path not in self.documents and os.path.splitext(entry)[1].lower() in \
                    MODULE_SUFFIXES:
                parsed = self._from_disk(path)
                if parsed is not None and parsed.modules:
                    found[path] = parsed
        return found

    def _from_disk(self, path: str) -> Optional[Parsed]:
        """The file as parsed, again only when its time or size changed; None: unreadable."""
        try:
            status = os.stat(path)
        except OSError:
            return None
        stamp = (status.st_mtime_ns, status.st_size)
        known = self.on_disk.get(path)
        if known is None or known[0] != stamp:
            try:
                parsed = parse_document(path, read_source(path))
            except UserError:
                parsed = None
            known = self.on_disk[path] = (stamp, parsed)
        return known[1]

    def diagnostics(self, file: str) -> list[Diagnostic]:
        """Every diagnostic about ``file``: syntax errors, else static errors and lint."""
        parsed = self.documents[file]
        if parsed.errors:
            return list(parsed.errors)
        program = ast.Program(tuple(self.program_modules(file)))
        folder = os.path.dirname(file) if self.read_folders and os.path.isabs(file) else None
        found = static_errors(program) + lint_findings(program, folder)
        return [d for d in without_repeats(merge_unknown_names(found))
                if d.span is None or d.span.file == file]

    def program_modules(self, file: str) -> list[ast.Module]:
        """The modules of the program ``file`` belongs to (none while it does not parse)."""
        if file not in self.documents:
            return []
        return [module for parsed in self.program_of(file) for module in parsed.modules]

    def text(self, file: str) -> Optional[str]:
        parsed = self.documents.get(file)
        return None if parsed is None else parsed.text


def static_errors(program: ast.Program) -> list[Diagnostic]:
    """The linker's errors (all at once), without those an editor leaves out."""
    try:
        build(program)
    except UserError as failure:
        return [d for d in failure.diagnostics if d.code not in NOT_FOR_EDITORS]
    return []


def lint_findings(program: ast.Program, folder: Optional[str] = None) -> list[Diagnostic]:
    """The lint rules' findings, configured by the ``[tool.rapidmc.lint]`` of the nearest
    pyproject.toml at or above ``folder`` as ``rapidmc lint`` is from its working folder; a
    malformed configuration is a diagnostic (RMC840), and the rules then run as by default."""
    config, problems = LintConfig(), []
    if folder is not None:
        try:
            table, origin = read_pyproject(Path(folder))
            config = make_config(table, str(origin or "pyproject.toml"))
        except UserError as failure:
            problems = list(failure.diagnostics)
    return problems + lint_program(program, config)
