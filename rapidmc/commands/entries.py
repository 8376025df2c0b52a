"""``rapidmc check ... --entry all``: the program from its entry and from each service routine.

A procedure without parameters that no routine calls is, on a real controller, most often
started by hand from the FlexPendant ("PP to routine"). With ``--entry all`` each such
routine of the main task (a backup's first motion task: ``--entry`` names its routines) is
checked as an entry of its own, after the program's entry routine, with the
same properties and options: one verdict table per entry, in every output format (text:
a heading per entry; JSON: ``entries``; SARIF: a run per entry; JUnit: a suite per entry;
HTML: a page per entry). Coverage covers every entry together: a line is reported as never
reached only when no entry's search ran it, and only when every search was complete.

Library routines (FUNCs, procedures with parameters) that no routine calls are entries
too, each through a driver procedure that chooses its arguments as inputs
(``library_entries``), after the service routines; a program of module files without a
``main`` is checked this way by default, every routine no routine calls an entry (a
library, or procedures an operator starts by hand).
"""
from __future__ import annotations

import argparse
import shutil
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from .. import api
from ..diagnostics import (EXIT_OK, EXIT_UNKNOWN, EXIT_VIOLATED, NEVER_REACHED, NO_ENTRY,
                           Diagnostic, UserError)
from ..findings.coverage import ANY_INPUT, coverage_warnings, service_routines
from ..findings.tried_inputs import called_routines
from .library_entries import library_entries, start_procedures, write_driver

EVERY_ENTRY = "ALL"


def every_entry(args: argparse.Namespace) -> bool:
    """Does ``--entry`` ask for every entry (``all``, in any case as RAPID names are)?"""
    return args.entry.upper() == EVERY_ENTRY


@dataclass
class EntryChecks:
    """The reports of one program checked from each of its entries, the first the
    program's own entry routine."""

    entries: list[tuple[str, api.CheckReport]]
    warnings: list[Diagnostic]
    drivers: tuple = ()          # the library entries' driver modules (removed when reported)

    def remove_drivers(self) -> None:
        """Remove the drivers' temporary folders, once every report is written."""
        for path in self.drivers:
            shutil.rmtree(Path(path).parent, ignore_errors=True)

    def exit_code(self, fail_on_vacuous: bool = False) -> int:
        codes = {report.exit_code(fail_on_vacuous) for _, report in self.entries}
        return next((code for code in (EXIT_VIOLATED, EXIT_UNKNOWN) if code in codes), EXIT_OK)

    def tables(self) -> list[tuple]:
        """(entry, results, describer) for each entry, as the report formats take them."""
        return [(entry, report.results, report.describer) for entry, report in self.entries]


def check_every_entry(args: argparse.Namespace,
                      prepare: Callable[[argparse.Namespace], api.Model],
                      progress) -> EntryChecks:
    """Check the program from its entry routine (when it has one), then from each service
    routine, then from each library routine (through its driver)."""
    library = library_entries(args.files)
    checked = [entry for entry in library if entry.driver is not None]
    drivers = {entry.driver: write_driver(entry) for entry in checked}
    try:
        first = prepare(_with_entry(args, "main"))
    except UserError as exc:
        if not missing_main(exc) or not is_library(args):
            raise
        first = None                          # no main: every routine an entry
    starts = [(entry.routine, entry.driver) for entry in checked]
    if first is None:
        starts = [(name, name) for name in start_procedures(args.files)] + starts
    if first is not None:
        program = first.program
        entry = program.routines[program.entry]
        starts = [(entry.name, None)] + [
            (routine.name, routine.name) for routine in service_routines(program)
            if routine.namespace == entry.namespace] + starts    # the main task's
    entries, programs = [], []
    for name, start in starts:
        model = first if start is None else prepare(_with_driver(args, start, drivers))
        programs.append(model.program)
        entries.append((name, api.check_model(model, progress=progress)))
    program = programs[0]
    notes = [library_entry.note() for library_entry in library]
    return EntryChecks(entries, notes + _merged_warnings(program, entries),
                       tuple(drivers.values()))


def _with_driver(args: argparse.Namespace, start: str, drivers: dict) -> argparse.Namespace:
    """The arguments of the check from ``start``: with its driver module when it is one."""
    files = list(args.files) + ([drivers[start]] if start in drivers else [])
    return argparse.Namespace(**{**vars(args), "entry": start, "files": files})


def missing_main(exc: UserError) -> bool:
    """Whether a load failed only because the program has no ``main`` (RMC211)."""
    return len(exc.diagnostics) == 1 and exc.diagnostics[0].code is NO_ENTRY \
        and "has no procedure" in exc.diagnostics[0].message


def is_library(args: argparse.Namespace) -> bool:
    """Module files without ``main`` whose routines can be checked one by one (the default
    of ``check`` for a library, or for procedures an operator starts by hand)."""
    return any(entry.driver for entry in library_entries(args.files)) \
        or bool(start_procedures(args.files))


def _with_entry(args: argparse.Namespace, entry: str) -> argparse.Namespace:
    return argparse.Namespace(**{**vars(args), "entry": entry})


def _merged_warnings(program, entries) -> list[Diagnostic]:
    """The first entry's warnings but coverage, then coverage of every entry's search."""
    first = entries[0][1]
    warnings = [w for w in first.warnings if w.code is not NEVER_REACHED]
    executed = [report.executed for _, report in entries]
    if all(lines is not None for lines in executed):
        tried = [r.inputs_tried for _, r in entries if r.inputs_tried != ANY_INPUT]
        inputs = "; ".join(dict.fromkeys(tried)) if tried else ANY_INPUT
        called = called_routines(program) if tried else None
        warnings.extend(coverage_warnings(program, frozenset().union(*executed), inputs,
                                          called))
    return warnings


def html_paths(path: str, entries: list[str]) -> list[str]:
    """The page of each entry: the given path for the first, ``NAME.ENTRY.html`` beside it
    for the others."""
    given = Path(path)
    return [path] + [str(given.with_name(f"{given.stem}.{entry}{given.suffix or '.html'}"))
                     for entry in entries[1:]]
