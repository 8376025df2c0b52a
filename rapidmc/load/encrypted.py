"""Encrypted modules in a controller backup or among module files: check everything else
(issue 28).

A licensed add-in ships its modules encrypted (the file's first byte is 0xF0
or above); a controller runs them, rapidmc cannot read them.  Instead of
refusing the whole backup or program (RMC005 stays when every module given by
name is encrypted):

* the task's other modules are checked; what they use and no module declares
  is taken, as ``rapidmc stubs`` does, from its uses: a generated module
  (``interface_of``) declares it with empty routines and neutral values.
  Its header carries the stubs' marker, so every verdict names each of those
  declarations under ``assumes:`` (``findings.assumptions``), and a line
  naming the encrypted modules (``ENCRYPTED_MARKER``);
* PERS data the encrypted code may write is data written from outside the
  loaded code (``outside_data``): the interface's PERS are not kept at their
  neutral values as a user's stubs are, their reads take any value of their
  domains;
* a task made only of encrypted modules is left out (RMC735 note): it runs
  as a party that may write its PERS at any time, which is what data written
  from outside means for the tasks that read them.
"""
from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Optional, Sequence

from .. import ast
from ..diagnostics import ENCRYPTED_SKIPPED, Diagnostic
from ..diagnostics import SourceCache

ENCRYPTED_MARKER = "Interface of encrypted modules"


def is_encrypted(path: str) -> bool:
    """Whether the module file is encrypted (its first byte 0xF0-0xFF, as RMC005 tells)."""
    try:
        with open(path, "rb") as stream:
            first = stream.read(1)
    except OSError:
        return False
    return bool(first) and first[0] >= 0xF0


def skipped_note(path: str, task: Optional[str]) -> Diagnostic:
    """RMC735: the encrypted module is checked as the interface its uses show (``task``
    None: a module given as a file)."""
    owner = f"task {task}" if task else "the program"
    what = "the task" if task else "the program"
    return Diagnostic(ENCRYPTED_SKIPPED, f"module {Path(path).name} of {owner} is "
                      f"encrypted: {what} is checked without it; what the other modules use "
                      "from it is declared from those uses (stubs, named under assumes:), and "
                      "PERS data it may write is data written from outside",
                      ast.Span(path, 0, 0), severity="note")


def only_encrypted_note(path: str, task: str) -> Diagnostic:
    """RMC735: a task of encrypted modules only is a party writing its PERS at any time."""
    return Diagnostic(ENCRYPTED_SKIPPED, f"task {task} is made only of encrypted modules: it "
                      "is not checked; it runs as a party that may write its PERS data at any "
                      "time (data written from outside for the tasks that read it)",
                      ast.Span(path, 0, 0), severity="note")


@dataclass(frozen=True)
class Generated:
    """A module to declare from a task's uses: its name (or a free variant), the file it is
    said to be (``path_for(name)``) and a header line before the stubs' own."""

    modules: tuple
    name: str
    path_for: Callable[[str], str]
    header: str = ""


def interface_of(modules: Sequence[ast.Module], encrypted: Sequence[str]) -> Generated:
    """The module declaring what ``modules`` use and nobody declares, taken as the
    interface of the ``encrypted`` module files."""
    names = ", ".join(Path(p).name for p in encrypted)
    return Generated(
        tuple(modules), "Encrypted_interface",
        lambda name: str(Path(encrypted[0]).with_name(f"{Path(encrypted[0]).name} (interface)")),
        f"! {ENCRYPTED_MARKER} ({names}), taken from their uses\n")


def missing_of(modules: Sequence[ast.Module]) -> Generated:
    """``check --stubs``: the module ``rapidmc stubs`` writes for ``modules`` (a task's),
    beside their first file; its marker names each declaration under ``assumes:``."""
    return Generated(tuple(modules), "Missing",
                     lambda name: str(Path(modules[0].span.file).with_name(f"{name}.mod (stubs)")))


def declared_from_uses(tasks: Sequence[Generated],
                       signals: frozenset) -> list[tuple[ast.Module, ...]]:
    """For each of ``tasks`` the module of stubs (``load.stubs``) for what its modules use
    and nobody declares, parsed (empty when nothing is); a name several tasks miss is
    inferred once from all their uses (``stubs.stub_modules``)."""
    from ..syntax import parse_text
    from .stubs import stub_modules
    if not tasks:
        return []
    names = []
    for task in tasks:
        taken = {module.name.key for module in task.modules}
        name = task.name
        while name.upper() in taken:
            name += "_"
        names.append(name)
    found = []
    for task, name, stubs in zip(tasks, names, stub_modules(
            [(task.modules, name) for task, name in zip(tasks, names)], signals)):
        if not stubs.declared:
            found.append(())
            continue
        path = task.path_for(name)
        text = task.header + stubs.text
        SourceCache.remember(path, text)
        found.append(parse_text(text, path))
    return found


def from_encrypted_interface(file: str) -> bool:
    """Whether ``file`` is a module ``interface_module`` wrote."""
    line = SourceCache.line(file, 1)
    return line is not None and ENCRYPTED_MARKER in line
