"""Library routines as entries of ``check --entry all``: FUNCs and procedures with parameters.

A module of FUNCs only (a library a user's main program calls) has no routine a
controller could start, yet users check libraries (held-out survey, issue 28: a
FlexPendant dialogue module of two FUNCs, refused with RMC211 even with ``--entry
all``).  Each global FUNC, and each global procedure with parameters, that no loaded
routine calls is checked through a driver procedure rapidmc writes
(``rapidmc_entries.mod`` in a temporary folder, loaded with the program's files for that
entry's check only), which calls it once with arguments chosen as a check chooses inputs:

* a num or dnum argument is a free analog input named ``ROUTINE_PARAMETER``, bound
  with AliasIO: its values are those the routine compares the parameter with, their
  neighbours and 0 (``load.input_domains``, exact where the routine only compares it,
  else ``load.stated_domains`` named under ``assumes:``);
* a bool argument is a free digital input of that name (both values);
* any other argument (a string, a record) holds its type's neutral value: one value,
  said in the entry's note;
* optional parameters are left out.

A routine with a PERS parameter or an array parameter is not checked; the note says so.
Each driver's note (RMC515) names the arguments and how they were chosen.
"""
from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Optional

from .. import ast
from ..diagnostics import DOMAIN_ASSUMED, Diagnostic
from ..syntax import parse_file

DRIVER_FILE = "rapidmc_entries.mod"
DRIVER_PREFIX = "rapidmc_entry"
ANALOG = ("NUM", "DNUM")


@dataclass(frozen=True)
class LibraryEntry:
    """One library routine and how its driver calls it."""

    routine: str                 # as written
    driver: Optional[str]        # the driver procedure, None when the routine is not checked
    data: tuple                  # the driver's module data (signal data), RAPID lines
    text: str                    # the driver procedure's RAPID text
    arguments: str               # how the arguments are chosen, or why it is not checked
    span: ast.Span

    def note(self) -> Diagnostic:
        return Diagnostic(DOMAIN_ASSUMED, f"entry {self.routine}: {self.arguments}", self.span,
                          severity="note")


def library_entries(files: list) -> list[LibraryEntry]:
    """The library routines of the module ``files`` (none for a backup folder), in
    program order."""
    chosen = [routine for routine in _uncalled(files)
              if routine.kind == ast.FUNC or (routine.kind == ast.PROC and routine.parameters)]
    return [_entry(routine, number) for number, routine in enumerate(chosen, 1)]


def start_procedures(files: list) -> list[str]:
    """The global procedures without parameters of the module ``files`` that no routine
    calls (what a program without ``main`` is started from by hand), in program order."""
    return [routine.name.text for routine in _uncalled(files)
            if routine.kind == ast.PROC and not routine.parameters]


def _uncalled(files: list) -> list:
    """The global routines of the module ``files`` that no routine calls by name (none for
    a backup folder, whose tasks ``--entry`` does not range over)."""
    if any(Path(path).is_dir() for path in files):
        return []
    modules = [module for path in files for module in parse_file(path)]
    routines = [routine for module in modules for routine in module.routines]
    called = {node.name.key for routine in routines for node, _ in ast.walk(routine)
              if isinstance(node, (ast.ProcedureCall, ast.FunctionCall))}
    late = any(isinstance(node, ast.LateBindingCall) for routine in routines
               for node, _ in ast.walk(routine))
    return [routine for routine in routines
            if not routine.local and routine.name.key not in called and routine.kind != ast.TRAP
            and not (late and routine.kind == ast.PROC)]


def _entry(routine: ast.Routine, number: int) -> LibraryEntry:
    """The driver of ``routine``, the ``number``-th library entry (RAPID names are at most
    32 characters: the driver's own names are numbered, the signals named after the
    routine and its parameter)."""
    name = routine.name.text
    refused = [p for p in routine.parameters if not p.optional
               and (p.mode == "PERS" or p.array_rank > 0)]
    if refused:
        p = refused[0]
        why = "a PERS parameter" if p.mode == "PERS" else "an array parameter"
        return LibraryEntry(name, None, (), "", f"not checked: {p.name.text} is {why}, which "
                            "no driver can pass", routine.span)
    signals, lines, passed, said = [], [], [], []
    for position, p in enumerate((p for p in routine.parameters if not p.optional), 1):
        local = f"arg{position}"
        type_name = p.type.name.text
        lines.append(f"    VAR {type_name} {local};")
        signal = f"{name}_{p.name.text}"
        key = p.type.name.key
        if key in ANALOG or key == "BOOL":
            variable = f"sig{number}_{position}"
            signals.append(f"  VAR {'signaldi' if key == 'BOOL' else 'signalai'} {variable};")
            lines.append(f"    AliasIO \"{signal}\", {variable};")
            value = f"DInput({variable}) = 1" if key == "BOOL" else \
                f"NumToDnum(AInput({variable}))" if key == "DNUM" else f"AInput({variable})"
            lines.append(f"    {local} := {value};")
            said.append(f"{p.name.text} the free {'digital' if key == 'BOOL' else 'analog'} "
                        f"input {signal}")
        else:
            said.append(f"{p.name.text} its {type_name}'s neutral value")
        passed.append(local)
    arguments = ", ".join(passed)
    if routine.kind == ast.FUNC:
        lines.append(f"    VAR {routine.return_type.name.text} result;")
        lines.append(f"    result := {name}({arguments});")
    else:
        lines.append(f"    {name}{' ' + arguments if arguments else ''};")
    driver = f"{DRIVER_PREFIX}{number}"
    declarations = [line for line in lines if line.lstrip().startswith("VAR ")]
    statements = [line for line in lines if not line.lstrip().startswith("VAR ")]
    text = "\n".join([f"  PROC {driver}()"] + declarations + statements + ["  ENDPROC"])
    how = ("called once with " + "; ".join(said)) if said else "called once, with no arguments"
    return LibraryEntry(name, driver, tuple(signals), text, how, routine.span)


def write_driver(entry: LibraryEntry) -> str:
    """The path of a module holding ``entry``'s driver alone (in a new temporary folder), so
    that each entry's check holds only its own arguments' inputs."""
    text = "\n".join(["MODULE rapidmc_entries",
                      "  ! Written by 'rapidmc check --entry all': a library routine called"
                      " once, its arguments free inputs (library_entries)."]
                     + list(entry.data) + [entry.text, "ENDMODULE", ""])
    path = Path(tempfile.mkdtemp(prefix="rapidmc-entries-")) / DRIVER_FILE
    path.write_text(text)
    return str(path)
