"""Controller backups and I/O configuration files.

A RobotWare backup is a folder::

    BACKUP/
      BACKINFO/              (backup information)
      RAPID/TASK1/SYSMOD/    system modules (*.sys)
      RAPID/TASK1/PROGMOD/   program modules (*.mod, *.modx)
      SYSPAR/EIO.cfg         I/O configuration: the signals programs use by name

``expand_backup`` turns it into the module files of one task and the path of
its EIO.cfg; ``read_eio`` reads the signals (name and type) of an EIO.cfg, so
configured signals have their real kinds instead of guessed ones.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from ..ast import Span
from ..diagnostics import FILE_NOT_FOUND, PROGRAM_FILE, SourceCache, UserError, error

MODULE_SUFFIXES = {".mod", ".modx", ".sys", ".prg"}
SIGNAL_KINDS = {"DI", "DO", "AI", "AO", "GI", "GO"}
_ATTRIBUTE = re.compile(r'-(\w+)\s+(?:"([^"]*)"|(\S+))')


@dataclass(frozen=True)
class ConfiguredSignal:
    name: str
    kind: str                  # DI, DO, AI, AO, GI, GO
    span: Span
    width: Optional[int] = None   # bits of a group signal's device map ("0-3": 4)


def is_backup(path: Path) -> bool:
    return path.is_dir() and (path / "RAPID").is_dir()


def expand_backup(path: Path, task: Optional[str] = None) -> tuple[list[str], Optional[str]]:
    """The module files of one task of the backup at ``path``, and its EIO.cfg (if any)."""
    tasks = _task_folders(path)
    if not tasks:
        raise error(PROGRAM_FILE, f"backup '{path}' has no task folder under RAPID/")
    chosen = _choose_task(path, tasks, task)
    modules = []
    for folder in ("SYSMOD", "PROGMOD"):
        directory = _child(chosen, folder)
        if directory is not None:
            modules.extend(sorted(str(f) for f in directory.iterdir()
                                  if f.is_file() and f.suffix.lower() in MODULE_SUFFIXES))
    if not modules:
        raise error(PROGRAM_FILE, f"task {chosen.name} of backup '{path}' holds no module")
    syspar = _child(path, "SYSPAR")
    eio = _child(syspar, "EIO.cfg") if syspar is not None else None
    return modules, str(eio) if eio is not None else None


def _task_folders(path: Path) -> list[Path]:
    """The task folders under RAPID/, in name order (TASK1, TASK2 ...)."""
    return sorted(p for p in (path / "RAPID").iterdir() if p.is_dir())


def _child(directory: Path, name: str) -> Optional[Path]:
    """``directory/name``, matching the name without regard to case (backups vary)."""
    for entry in directory.iterdir():
        if entry.name.upper() == name.upper():
            return entry
    return None


def _choose_task(path: Path, tasks: list[Path], task: Optional[str]) -> Path:
    names = ", ".join(t.name for t in tasks)
    if task is not None:
        for candidate in tasks:
            if candidate.name.upper() == task.upper():
                return candidate
        raise error(PROGRAM_FILE, f"backup '{path}' has no task '{task}' (tasks: {names})")
    if len(tasks) == 1:
        return tasks[0]
    with_main = [t for t in tasks if _has_main(t)]
    if len(with_main) == 1:
        return with_main[0]
    raise error(PROGRAM_FILE, f"backup '{path}' has several tasks ({names}): choose one with "
                "--task NAME")


def _has_main(task: Path) -> bool:
    pattern = re.compile(r"^\s*(LOCAL\s+)?PROC\s+main\s*\(", re.IGNORECASE | re.MULTILINE)
    for file in task.rglob("*"):
        if file.is_file() and file.suffix.lower() in MODULE_SUFFIXES:
            if pattern.search(file.read_bytes().decode("latin-1", "replace")):
                return True
    return False


def read_eio(path: str) -> list[ConfiguredSignal]:
    """The signals of an EIO.cfg (section EIO_SIGNAL, or EIO_USER_SIGNAL of old systems)."""
    file = Path(path)
    if not file.is_file():
        raise error(FILE_NOT_FOUND, f"I/O configuration '{path}' does not exist")
    text = file.read_bytes().decode("latin-1")
    SourceCache.remember(path, text)
    signals = []
    section = ""
    for number, line in _logical_lines(text):
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        if re.fullmatch(r"[A-Z_]+:", stripped):
            section = stripped[:-1]
            continue
        if section not in ("EIO_SIGNAL", "EIO_USER_SIGNAL"):
            continue
        attributes = {m.group(1).upper(): m.group(2) if m.group(2) is not None else m.group(3)
                      for m in _ATTRIBUTE.finditer(stripped)}
        name, kind = attributes.get("NAME"), (attributes.get("SIGNALTYPE") or "").upper()
        if name and kind in SIGNAL_KINDS:
            mapping = attributes.get("DEVICEMAP") or attributes.get("UNITMAP")
            signals.append(ConfiguredSignal(name, kind, Span(path, number, 1),
                                            map_width(mapping)))
    return signals


def map_width(mapping: Optional[str]) -> Optional[int]:
    """The number of bits a device map names: ``"0-3"`` 4, ``"0-3,8"`` 5; None if unreadable."""
    if not mapping:
        return None
    bits: set[int] = set()
    for part in mapping.split(","):
        match = re.fullmatch(r"\s*(\d+)\s*(?:-\s*(\d+))?\s*", part)
        if match is None:
            return None
        first = int(match.group(1))
        last = int(match.group(2)) if match.group(2) is not None else first
        bits.update(range(min(first, last), max(first, last) + 1))
    return len(bits)


def _logical_lines(text: str):
    """(first line number, text) with backslash-continued lines joined."""
    pending, start = "", 0
    for number, line in enumerate(text.splitlines(), start=1):
        if not pending:
            start = number
        if line.rstrip().endswith("\\"):
            pending += line.rstrip()[:-1] + " "
            continue
        yield start, pending + line
        pending = ""
    if pending:
        yield start, pending


def add_program_arguments(parser) -> None:
    """Options of run and check for backups and I/O configuration."""
    parser.add_argument("--task", metavar="NAME",
                        help="the task to load from a controller backup (default: the only "
                             "task, or the only one with a main procedure)")
    parser.add_argument("--add-task", action="append", default=[], metavar="FILE[,FILE...]",
                        help="a further RAPID task, made of these module files (entry: main), "
                             "running beside the program (repeatable)")
    parser.add_argument("--all-tasks", action="store_true",
                        help="with a backup: run every task (the one chosen with --task, or "
                             "the first, is the main task)")
    parser.add_argument("--eio", metavar="EIO.cfg",
                        help="I/O configuration whose signals the program uses by name "
                             "(a backup's SYSPAR/EIO.cfg is read automatically)")


@dataclass(frozen=True)
class ProgramFiles:
    """What to load: the main task's modules, further tasks, configured signals."""

    modules: list
    tasks: list                # (task name, module paths)
    signals: list


def resolve_program_files(args) -> ProgramFiles:
    """The files named on the command line (backups expanded), further tasks and signals."""
    task = getattr(args, "task", None)
    eio = getattr(args, "eio", None)
    paths: list[str] = []
    tasks: list[tuple[str, list[str]]] = []
    eio_paths = [eio] if eio else []
    for name in args.files:
        path = Path(name)
        if is_backup(path):
            chosen = task
            if chosen is None and getattr(args, "all_tasks", False):
                chosen = _task_folders(path)[0].name if _task_folders(path) else None
            modules, backup_eio = expand_backup(path, chosen)
            paths.extend(modules)
            if getattr(args, "all_tasks", False):
                tasks.extend(other_tasks(path, modules))
            if backup_eio and not eio:
                eio_paths.append(backup_eio)
        else:
            paths.append(name)
    for number, spec in enumerate(getattr(args, "add_task", []) or [], start=1):
        files = [f for f in spec.split(",") if f]
        tasks.append((f"task {number + 1} ({Path(files[0]).stem})" if files else "", files))
    signals = [signal for eio_path in eio_paths for signal in read_eio(eio_path)]
    return ProgramFiles(paths, tasks, signals)


def load_tasks(files: ProgramFiles) -> list:
    """The further tasks, parsed, for ``semantics.link.build``."""
    from ..semantics.link import Task
    from ..syntax import load_program
    return [Task(name, load_program(paths)) for name, paths in files.tasks]


def every_task(path: Path) -> list[tuple[str, list[str]]]:
    """(task name, module files) of each task of the backup at ``path`` holding a module."""
    tasks = []
    for task in _task_folders(path):
        try:
            modules, _ = expand_backup(path, task.name)
        except UserError:                # a task folder without modules
            continue
        tasks.append((task.name, modules))
    return tasks


def other_tasks(path: Path, main_modules: list[str]) -> list[tuple[str, list[str]]]:
    """The backup's tasks other than the one whose modules are ``main_modules``."""
    result = []
    for task in _task_folders(path):
        modules, _ = expand_backup(path, task.name)
        if modules != main_modules:
            result.append((task.name, modules))
    return result
