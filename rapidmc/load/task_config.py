"""The tasks of a controller backup as the controller names and runs them.

A backup keeps each task's modules in a numbered folder (``RAPID/TASK1``,
``RAPID/TASK2`` ...); the names programs use (``GetTaskName``, the task lists
of ``WaitSyncTask``) are elsewhere:

* ``BACKINFO/backinfo.txt`` maps the folders to names, one section per task::

      >>TASK1: (T_ROB1,Main,)

* ``SYSPAR/SYS.cfg``, section ``CAB_TASKS``, configures each task by name::

      -Name "T_ROB1" -Type "NORMAL" -MotionTask
      -Name "T_BG" -Type "SEMISTATIC" -Entry "bg_main"

  ``-Type`` is NORMAL, STATIC or SEMISTATIC (all three run when the
  controller starts; STATIC and SEMISTATIC ones cannot be stopped from the
  FlexPendant), ``-Entry`` the entry routine (default ``main``),
  ``-MotionTask`` marks the task that moves the robot.

``read_tasks`` joins the three: folder, name, type, entry, motion flag.  A
folder whose name the backup does not give keeps its folder name (backups
written by hand often name the folders T_ROB1 ... themselves).
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from .config_file import instances

_TASK_SECTION = re.compile(r"^>>(\w+):\s*\(\s*([^,)\s]*)", re.MULTILINE)
# a module line of a task's section: its file, " @", and the name it is loaded under (may be
# empty: "PROGMOD/MainModule.mod @")
_MODULE_LINE = re.compile(r"^\s*(.+?)\s+@(?:\s|$)")


@dataclass(frozen=True)
class BackupTask:
    """One task of a backup: where its modules are and how the controller runs it."""

    folder: Path
    name: str                  # T_ROB1 (the folder's name when the backup gives none)
    kind: str = ""             # NORMAL, STATIC, SEMISTATIC ("" when not configured)
    entry: str = "main"
    motion: bool = False
    # the module files backinfo.txt lists for the task's folder ("PROGMOD/MAINMODULE.MOD",
    # upper case): what the controller had loaded when it wrote the backup (None: no list)
    listed: Optional[frozenset] = None

    def describe(self) -> str:
        details = [d for d in (self.kind, "motion task" if self.motion else "") if d]
        return f"{self.name} ({', '.join(details)})" if details else self.name


def read_tasks(backup: Path, folders: list[Path]) -> list[BackupTask]:
    """The task folders ``folders`` of ``backup`` with their configured names and settings."""
    names = _folder_names(backup)
    listed = _listed_modules(backup)
    configured = _configured_tasks(backup)
    tasks = []
    for folder in folders:
        name = names.get(folder.name.upper(), folder.name)
        settings = configured.get(name.upper(), {})
        tasks.append(BackupTask(folder, name, settings.get("TYPE", "").upper(),
                                settings.get("ENTRY") or "main", "MOTIONTASK" in settings,
                                listed.get(folder.name.upper())))
    return tasks


def task_names(backup: Path, tasks: list[BackupTask]) -> tuple[str, ...]:
    """Every task name the controller knows: ``tasks`` (the folders) and the tasks SYS.cfg
    configures, in that order, each once.  The controller declares a ``taskid`` named
    ``<task name>Id`` for each (T_ROB1Id), which code names whether or not that task is
    checked with it."""
    names = [task.name for task in tasks]
    names += [attributes["NAME"] for attributes in _configured_tasks(backup).values()]
    return tuple(dict.fromkeys(names))


def config_file(backup: Path, *parts: str) -> Optional[Path]:
    """``backup/parts...``, each part matched without regard to case (backups vary)."""
    found = backup
    for part in parts:
        if not found.is_dir():
            return None
        found = next((entry for entry in sorted(found.iterdir())
                      if entry.name.upper() == part.upper()), None)
        if found is None:
            return None
    return found


def _folder_names(backup: Path) -> dict[str, str]:
    """TASKn folder (upper case) -> task name, from BACKINFO/backinfo.txt."""
    path = config_file(backup, "BACKINFO", "backinfo.txt")
    if path is None or not path.is_file():
        return {}
    text = path.read_bytes().decode("latin-1")
    return {folder.upper(): name for folder, name in _TASK_SECTION.findall(text)
            if folder.upper().startswith("TASK") and name}


def _listed_modules(backup: Path) -> dict[str, frozenset]:
    """TASKn folder (upper case) -> the module files its backinfo.txt section lists, each
    ``FOLDER/NAME`` in upper case (``PROGMOD/MainModule.mod @ mainmodule.mod``; a virtual
    controller writes ``PROGMOD\\MainModule.mod``); a section that lists none is left out."""
    path = config_file(backup, "BACKINFO", "backinfo.txt")
    if path is None or not path.is_file():
        return {}
    found: dict[str, set] = {}
    section = None
    for line in path.read_bytes().decode("latin-1").splitlines():
        header = _TASK_SECTION.match(line)
        if header is not None:
            section = header.group(1).upper() if header.group(1).upper().startswith("TASK") \
                else None
        elif line.startswith(">>"):
            section = None
        elif section is not None and (module := _MODULE_LINE.match(line)) is not None:
            found.setdefault(section, set()).add(module.group(1).replace("\\", "/").upper())
    return {folder: frozenset(modules) for folder, modules in found.items()}


def _configured_tasks(backup: Path) -> dict[str, dict[str, str]]:
    """Task name (upper case) -> its CAB_TASKS attributes (upper-case keys), from SYS.cfg."""
    path = config_file(backup, "SYSPAR", "SYS.cfg")
    if path is None or not path.is_file():
        return {}
    tasks: dict[str, dict[str, str]] = {}
    for _, attributes in instances(path.read_bytes().decode("latin-1"), ("CAB_TASKS",)):
        if attributes.get("NAME"):
            tasks[attributes["NAME"].upper()] = attributes
    return tasks
