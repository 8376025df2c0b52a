"""Controller backups and I/O configuration files.

A RobotWare backup is a folder::

    BACKUP/
      BACKINFO/              (backup information)
      RAPID/TASK1/SYSMOD/    system modules (*.sys)
      RAPID/TASK1/PROGMOD/   program modules (*.mod, *.modx)
      SYSPAR/EIO.cfg         I/O configuration: the signals programs use by name
      SYSPAR/*.cfg           the configuration ReadCfgData reads (load.configuration)

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
from ..diagnostics import (EXIT_OK, FILE_NOT_FOUND, MODULE_UNLISTED, NO_PROGRAM, PROGRAM_FILE,
                           TASKS_LOADED, Diagnostic, SourceCache, UserError, error)
from .config_file import instances
from .encrypted import (declared_from_uses, interface_of, is_encrypted, missing_of,
                        only_encrypted_note, skipped_note)
from .other_writers import (declared_values, other_writers, task_output_writers,
                            written_constants)
from .outside_outputs import controller_writers
from .task_config import BackupTask, config_file, read_tasks, task_names
from ..semantics.library.configuration import Configuration
from .configuration import read_configuration

MODULE_SUFFIXES = {".mod", ".modx", ".sys", ".prg"}
SIGNAL_KINDS = {"DI", "DO", "AI", "AO", "GI", "GO"}


@dataclass(frozen=True)
class ConfiguredSignal:
    name: str
    kind: str                  # DI, DO, AI, AO, GI, GO
    span: Span
    width: Optional[int] = None   # bits of a group signal's device map ("0-3": 4)
    low: Optional[float] = None   # an analog signal's logical range (-MinLog, -MaxLog)
    high: Optional[float] = None


def is_backup(path: Path) -> bool:
    return path.is_dir() and (path / "RAPID").is_dir()


def expand_backup(path: Path, task: Optional[str] = None) -> tuple[list[str], Optional[str]]:
    """The module files of one task of the backup at ``path``, and its EIO.cfg (if any)."""
    tasks = backup_tasks(path)
    chosen = _choose_task(path, tasks, task)
    return task_modules(path, chosen), backup_eio(path)


def backup_tasks(path: Path) -> list[BackupTask]:
    """The backup's tasks, in folder order (TASK1, TASK2 ...), with their configured names."""
    folders = _task_folders(path)
    if not folders:
        raise error(PROGRAM_FILE, f"backup '{path}' has no task folder under RAPID/")
    return read_tasks(path, folders)


def task_modules(path: Path, task: BackupTask) -> list[str]:
    """The module files of ``task`` rapidmc can read: its SYSMOD, then its PROGMOD modules,
    the encrypted ones left out (``task_encrypted``)."""
    every = _module_files(task)
    modules = [m for m in every if not is_encrypted(m)]
    if not modules:
        more = " but encrypted ones" if every else ""
        raise error(PROGRAM_FILE, f"task {task.name} of backup '{path}' holds no module{more}")
    return modules


def task_modules_readable(task: BackupTask) -> bool:
    """Whether ``task`` holds a module that is not encrypted."""
    return any(not is_encrypted(m) for m in _module_files(task))


def task_encrypted(task: BackupTask) -> list[str]:
    """The encrypted module files of ``task`` (load.encrypted)."""
    return [m for m in _module_files(task) if is_encrypted(m)]


def _module_files(task: BackupTask) -> list[str]:
    """The task's module files the controller had loaded: those its backinfo.txt section
    lists (``task_unlisted`` are the others), else every one of its folders."""
    every = _folder_modules(task)
    listed = [path for key, path in every if task.listed is None or key in task.listed]
    return listed or [path for _, path in every]


def task_unlisted(task: BackupTask) -> list[str]:
    """The module files in the task's folders that its backinfo.txt section does not list:
    put there after the controller wrote the backup, so left out, as the controller that
    restores it leaves them (none when no module of the folders is listed)."""
    kept = set(_module_files(task))
    return [path for _, path in _folder_modules(task) if path not in kept]


def _folder_modules(task: BackupTask) -> list[tuple[str, str]]:
    """(``FOLDER/NAME`` in upper case, path) of each module file in the task's SYSMOD, then
    its PROGMOD folder."""
    modules = []
    for folder in ("SYSMOD", "PROGMOD"):
        directory = _child(task.folder, folder)
        if directory is not None:
            modules.extend(sorted(((f"{folder}/{f.name.upper()}", str(f))
                                   for f in directory.iterdir()
                                   if f.is_file() and f.suffix.lower() in MODULE_SUFFIXES),
                                  key=lambda found: found[1]))
    return modules


def backup_eio(path: Path) -> Optional[str]:
    syspar = _child(path, "SYSPAR")
    eio = _child(syspar, "EIO.cfg") if syspar is not None else None
    return str(eio) if eio is not None else None


def _task_folders(path: Path) -> list[Path]:
    """The task folders under RAPID/, in name order (TASK1, TASK2 ...)."""
    return sorted(p for p in (path / "RAPID").iterdir() if p.is_dir())


def _child(directory: Path, name: str) -> Optional[Path]:
    """``directory/name``, matching the name without regard to case (backups vary)."""
    for entry in directory.iterdir():
        if entry.name.upper() == name.upper():
            return entry
    return None


def _choose_task(path: Path, tasks: list[BackupTask], task: Optional[str]) -> BackupTask:
    names = ", ".join(t.name for t in tasks)
    if task is not None:
        for candidate in tasks:
            if task.upper() in (candidate.name.upper(), candidate.folder.name.upper()):
                return candidate
        raise error(PROGRAM_FILE, f"backup '{path}' has no task '{task}' (tasks: {names})")
    if len(tasks) == 1:
        return tasks[0]
    with_main = [t for t in tasks if _has_entry(t)]
    if len(with_main) == 1:
        return with_main[0]
    raise error(PROGRAM_FILE, f"backup '{path}' has several tasks ({names}): choose one with "
                "--task NAME")


def _has_entry(task: BackupTask) -> bool:
    pattern = re.compile(rf"^\s*(LOCAL\s+)?PROC\s+{re.escape(task.entry)}\s*\(",
                         re.IGNORECASE | re.MULTILINE)
    for file in task.folder.rglob("*"):
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
    for number, attributes in instances(text, ("EIO_SIGNAL", "EIO_USER_SIGNAL")):
        name, kind = attributes.get("NAME"), (attributes.get("SIGNALTYPE") or "").upper()
        if name and kind in SIGNAL_KINDS:
            mapping = attributes.get("DEVICEMAP") or attributes.get("UNITMAP")
            signals.append(ConfiguredSignal(name, kind, Span(path, number, 1),
                                            map_width(mapping), _number(attributes.get("MINLOG")),
                                            _number(attributes.get("MAXLOG"))))
    return signals


def _number(text: Optional[str]) -> Optional[float]:
    try:
        return float(text) if text is not None else None
    except ValueError:
        return None


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


def add_program_arguments(parser) -> None:
    """Options of run and check for backups and I/O configuration."""
    parser.add_argument("--task", metavar="NAME",
                        help="the one task to load from a controller backup, by its name "
                             "(T_ROB1) or folder (TASK1) (default: every task, together)")
    parser.add_argument("--add-task", action="append", default=[], metavar="FILE[,FILE...]",
                        help="a further RAPID task, made of these module files (entry: main), "
                             "running beside the program (repeatable)")
    parser.add_argument("--all-tasks", action="store_true",
                        help="with a backup and --task: the chosen task is the main task and "
                             "every other task runs beside it (without --task, the default)")
    parser.add_argument("--eio", metavar="EIO.cfg",
                        help="I/O configuration whose signals the program uses by name "
                             "(a backup's SYSPAR/EIO.cfg is read automatically)")
    parser.add_argument("--stubs", action="store_true",
                        help="declare what each task uses and none of its modules declares, "
                             "as 'rapidmc stubs' would (the modules of options a backup does "
                             "not hold); each declaration is named under assumes:")


@dataclass(frozen=True)
class ProgramFiles:
    """What to load: the main task's modules, further tasks, configured signals."""

    modules: list
    tasks: list                # (task name, module paths, entry routine)
    signals: list
    main_task: Optional[str] = None     # the main task's name in a backup (None: not one)
    main_entry: str = "main"            # its configured entry routine
    notes: tuple = ()                   # Diagnostic notes: which tasks were loaded
    alone: Optional[str] = None         # a backup's task checked without its other tasks
    configuration: Optional[Configuration] = None   # the backup's SYSPAR files
    # task name (None: the main task) -> its encrypted module files (load.encrypted)
    encrypted: Optional[dict] = None
    motion_tasks: tuple = ()            # the backup's tasks SYS.cfg marks -MotionTask
    # upper-case PERS name -> a party not loaded that may write it (load.other_writers)
    outside_writers: Optional[dict] = None
    task_names: tuple = ()              # every task of the backups (their taskid T_ROB1Id ...)
    # upper-case output name -> who sets it outside the loaded code (load.outside_outputs)
    output_writers: Optional[dict] = None
    # upper-case PERS name -> (a task not loaded's declaration with a value, where): the
    # value a loaded declaration without one takes (load.other_writers.declared_values)
    persistent_values: Optional[dict] = None
    # --stubs: each task's missing names declared from their uses (``with_interfaces``)
    stub_missing: bool = False
    # upper-case PERS name -> what the tasks not loaded write to it, when known
    # (load.other_writers.written_constants; None: unknown)
    written_constants: Optional[dict] = None


def resolve_program_files(args) -> ProgramFiles:
    """The files named on the command line (backups expanded), further tasks and signals."""
    task = getattr(args, "task", None)
    eio = getattr(args, "eio", None)
    paths: list[str] = []
    tasks: list[tuple[str, list[str], str]] = []
    eio_paths = [eio] if eio else []
    main_task, main_entry, notes, alone = None, "main", [], None
    encrypted: dict = {}
    writers: dict = {}
    constants: dict = {}
    output_writers: dict = {}
    values: dict = {}
    configuration = None
    motion_tasks: list[str] = []
    names: list[str] = []
    for name in args.files:
        path = Path(name)
        if not is_backup(path):
            paths.append(name)
            continue
        loaded = backup_tasks(path)
        if task is not None:
            chosen = [_choose_task(path, loaded, task)]
            if getattr(args, "entry", "main") == "main" and \
                    not getattr(args, "all_tasks", False) and not _holds_program(chosen[0]):
                raise _task_without_program(path, chosen[0])
            if getattr(args, "all_tasks", False):
                chosen += [t for t in loaded if t is not chosen[0]]
            elif len(loaded) > 1:
                alone = chosen[0].name
        else:
            if not any(_holds_program(t) for t in loaded):
                raise _no_program(path, loaded)
            chosen, skipped = _runnable_tasks(path, loaded)
            notes.extend(skipped)
        becomes_main = main_task is None and not paths
        for number, t in enumerate(chosen):
            notes.extend(_unlisted_note(path, t, f) for f in task_unlisted(t))
            sealed = task_encrypted(t)
            if sealed:
                encrypted[None if becomes_main and number == 0 else t.name] = sealed
                notes.extend(skipped_note(f, t.name) for f in sealed)
        outside_writers, unparsed = other_writers(path, [t.name for t in chosen])
        for key, who in outside_writers.items():
            writers.setdefault(key, who)
        notes.extend(unparsed)
        for key, found in written_constants(path, [t.name for t in chosen]).items():
            constants.setdefault(key, found)
        for key, found in declared_values(path, [t.name for t in chosen]).items():
            values.setdefault(key, found)
        for key, who in task_output_writers(path, [t.name for t in chosen]).items():
            output_writers.setdefault(key, who)
        if becomes_main:
            main_task, main_entry = chosen[0].name, chosen[0].entry
            paths.extend(task_modules(path, chosen[0]))
            chosen = chosen[1:]
        tasks.extend((t.name, task_modules(path, t), t.entry) for t in chosen)
        if len(loaded) > 1 and task is None:
            notes.append(_loaded_note(path, [t for t in loaded if t.name == main_task or
                                             any(t.name == other[0] for other in tasks)]))
        motion_tasks.extend(t.name for t in loaded if t.motion)
        names.extend(task_names(path, loaded))
        configuration = read_configuration(_child(path, "SYSPAR"))
        backup = backup_eio(path)
        if backup and not eio:
            eio_paths.append(backup)
    for number, spec in enumerate(getattr(args, "add_task", []) or [], start=1):
        files = [f for f in spec.split(",") if f]
        tasks.append((f"task {number + 1} ({Path(files[0]).stem})" if files else "", files,
                      "main"))
    paths, sealed = _readable_files(paths)
    if sealed:
        encrypted[None] = encrypted.get(None, []) + sealed
        notes.extend(skipped_note(f, main_task) for f in sealed)
    signals = [signal for eio_path in eio_paths for signal in read_eio(eio_path)]
    for eio_path in eio_paths:
        for key, who in controller_writers(eio_path).items():
            output_writers.setdefault(key, who)
    return ProgramFiles(paths, tasks, signals, main_task, main_entry, tuple(notes), alone,
                        configuration, encrypted, tuple(motion_tasks), writers,
                        tuple(dict.fromkeys(names)), output_writers, values,
                        bool(getattr(args, "stubs", False)), written_constants=constants)


def _readable_files(paths: list[str]) -> tuple[list[str], list[str]]:
    """(modules to load, encrypted modules left out) of the main task's files: an encrypted
    module beside readable ones is left out as a backup's is, its interface taken from the
    uses; a program of encrypted modules only keeps them (RMC005: nothing to analyse)."""
    sealed = [p for p in paths if Path(p).suffix.lower() in MODULE_SUFFIXES and is_encrypted(p)]
    if not sealed or len(sealed) == len(paths):
        return paths, []
    return [p for p in paths if p not in sealed], sealed


def _runnable_tasks(path: Path, tasks: list[BackupTask]) -> tuple[list[BackupTask], list]:
    """The tasks of a backup that run when the controller starts (each has its entry
    routine), and a note per task left out."""
    if len(tasks) == 1:
        return tasks, []
    sealed = [t for t in tasks if _module_files(t) and not task_modules_readable(t)]
    tasks = [t for t in tasks if t not in sealed]
    notes = [only_encrypted_note(str(t.folder), t.name) for t in sealed]
    runnable = [t for t in tasks if _has_entry(t)]
    if not runnable:
        raise error(PROGRAM_FILE, f"no task of backup '{path}' has its entry routine "
                    f"({', '.join(f'{t.name}: {t.entry}' for t in tasks)}): choose one with "
                    "--task NAME and --entry ROUTINE")
    skipped = [Diagnostic(TASKS_LOADED, f"task {t.name} is not checked: none of its modules "
                          f"declares its entry routine {t.entry}", _task_span(path, t),
                          severity="note")
               for t in tasks if t not in runnable]
    return runnable, notes + skipped


def _holds_program(task: BackupTask) -> bool:
    """Whether ``task`` has a program: a readable program module, or its entry routine."""
    directory = _child(task.folder, "PROGMOD")
    programs = [f for f in _module_files(task)
                if directory is not None and Path(f).parent == directory]
    return any(not is_encrypted(f) for f in programs) or _has_entry(task)


def _no_program(path: Path, tasks: list[BackupTask]) -> UserError:
    """RMC736, exit 0: a backup of system modules only (a factory backup) runs nothing."""
    return UserError([Diagnostic(
        NO_PROGRAM, f"backup '{path}' holds no program: no task has a program module or its "
        f"entry routine ({', '.join(f'{t.name}: {t.entry}' for t in tasks)}); nothing runs, "
        "so there is nothing to check", _task_span(path, tasks[0]), severity="note")],
        EXIT_OK)


def _task_without_program(path: Path, task: BackupTask) -> UserError:
    """RMC736, exit 0: the task ``--task`` chose holds system modules only (a shared task,
    a command task): started alone, it runs nothing, as a backup of such tasks does."""
    return UserError([Diagnostic(
        NO_PROGRAM, f"task {task.name} of backup '{path}' holds no program: it has no program "
        f"module and no module declares its entry routine {task.entry}; nothing runs, so there "
        "is nothing to check", _task_span(path, task), severity="note",
        notes=("--entry NAME checks one of its routines",))], EXIT_OK)


def _unlisted_note(path: Path, task: BackupTask, module: str) -> Diagnostic:
    """RMC737: a module file the backup's list of the task's modules does not name."""
    return Diagnostic(MODULE_UNLISTED, f"module {Path(module).name} is in the folder of task "
                      f"{task.name} but backinfo.txt does not list it among the modules the "
                      "controller had loaded: the task is checked without it",
                      _task_span(path, task), severity="warning",
                      notes=("it was put there after the backup was written; to check it, give "
                             "the task's module files themselves",))


def _loaded_note(path: Path, tasks: list[BackupTask]) -> Diagnostic:
    what = "the one task of the backup" if len(tasks) == 1 else \
        f"the {len(tasks)} tasks of the backup together"
    return Diagnostic(TASKS_LOADED, f"checking {what}: "
                      f"{', '.join(t.describe() for t in tasks)} (--task NAME checks one)",
                      _task_span(path, tasks[0]), severity="note")


def _task_span(path: Path, task: BackupTask) -> Span:
    """Where the backup names ``task``: its line of backinfo.txt, else its folder."""
    info = config_file(path, "BACKINFO", "backinfo.txt")
    if info is not None and info.is_file():
        text = info.read_bytes().decode("latin-1")
        for number, line in enumerate(text.splitlines(), start=1):
            if line.upper().startswith(f">>{task.folder.name.upper()}:"):
                SourceCache.remember(str(info), text)
                return Span(str(info), number, 1)
    return Span(str(task.folder), 0, 0)


def link_options(files: ProgramFiles) -> dict:
    """What the linker learns from the files: configured signals, the task names, whether
    every task of a backup is loaded (a task list naming another task is then an error)."""
    return {"configured_signals": files.signals, "main_task_name": files.main_task,
            "all_tasks_loaded": files.main_task is not None and files.alone is None,
            "configuration": files.configuration, "motion_tasks": files.motion_tasks,
            "outside_writers": files.outside_writers or {}, "task_names": files.task_names,
            "written_constants": files.written_constants or {},
            "output_writers": files.output_writers or {},
            "persistent_values": files.persistent_values or {}}


def with_interfaces(parsed, files: ProgramFiles) -> tuple:
    """``(main program, further tasks)`` for ``semantics.link.build``: ``parsed`` (the main
    task's modules) and each further task, parsed, with the interface of the task's
    encrypted modules taken from their uses (``load.encrypted``); with ``--stubs``, else
    with what the task uses and none of its modules declares (``load.stubs``). The tasks'
    missing names are inferred together: a type, constant, routine or PERS several tasks
    miss is declared alike in each."""
    from .. import ast
    from ..semantics.link import Task
    from ..syntax import load_program
    programs = [parsed] + [load_program(paths) for _, paths, _ in files.tasks]
    owners = [None] + [name for name, _, _ in files.tasks]
    signals = frozenset(signal.name.upper() for signal in files.signals)
    wanted = {}
    for number, (owner, program) in enumerate(zip(owners, programs)):
        sealed = (files.encrypted or {}).get(owner)
        if sealed:
            wanted[number] = interface_of(program.modules, sealed)
        elif files.stub_missing and program.modules:
            wanted[number] = missing_of(program.modules)
    for number, added in zip(wanted, declared_from_uses(list(wanted.values()), signals)):
        programs[number] = ast.Program(tuple(programs[number].modules) + added)
    return programs[0], [Task(name, program, entry) for (name, _, entry), program
                         in zip(files.tasks, programs[1:])]


def every_task(path: Path) -> list[tuple[str, list[str]]]:
    """(task name, module files) of each task of the backup at ``path`` holding a module."""
    tasks = []
    for task in backup_tasks(path):
        try:
            tasks.append((task.name, task_modules(path, task)))
        except UserError:                # a task folder without modules
            continue
    return tasks
