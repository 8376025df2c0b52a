"""Survey of the socket programs of public repositories: what "never reached" says (issue 33).

Usage: python bench/survey_sockets.py CORPUS [--max-states N] [--max-seconds S] [--long TEXT]...
                                      [--cpu S] [--jobs N] [--only TEXT] [--list] [--json FILE]

CORPUS is the folder ``bench/survey_programs.py --extract`` fills (one folder per public
repository).  Every RAPID module of it that calls SocketCreate, SocketConnect, SocketAccept,
SocketReceive or SocketSend makes a program, as docs/realworld-survey.md's socket rounds
(round 3 on) took them:

* in a controller backup, the whole task: every module of its PROGMOD and SYSMOD folders;
* in a ROS driver folder (the socket calls in a ``.sys`` module beside ``*Server*.mod``
  files), each server module with the folder's ``.sys`` modules;
* otherwise the file alone, but for two programs whose entry or second module the round
  named (``SPECIAL``): MARC-HT25's server with ``Server_functions.mod`` and
  ``--entry single_client_communication``, IRB120_PyControllerV1 with ``--entry socket_loop``.

RobotStudio's ``INTERNAL`` copies are left out; programs with the same module texts (and
entry) count once, their copies named on the row.  Each is checked as ``rapidmc check FILES
--format json --quiet --max-states 200000 --max-seconds 60`` (``--long TEXT``: programs whose
name holds TEXT run without the time limit), under a limit of ``--cpu`` CPU seconds, and the
row keeps what round 9 counted: the RMC701 "never reached" warnings, those "under any
input", the lines they and their places span, the verdicts, the most model states a
property's search explored, and the wall and CPU seconds (the child's own, whatever
``--jobs``).  rapidmc runs as ``sys.executable -m rapidmc``, so the python that runs this
script chooses the rapidmc measured.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import re
import resource
import subprocess
import sys
import threading
import time
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from rapidmc.load.backup import MODULE_SUFFIXES

SOCKET_CALL = re.compile(rb"\bSocket(Create|Connect|Accept|Receive|Send)\b", re.IGNORECASE)
# Programs whose second module or entry routine the socket survey's round 3 named: a path
# fragment, the modules of the same folder to add, the entry.
SPECIAL = {
    "MARC-HT25/robotstudio/scripts/RAPID/communication/server.mod":
        (["Server_functions.mod"], "single_client_communication"),
    "IRB120_PyControllerV1/": ([], "socket_loop"),
}
UNREACHED = "RMC701"
ANY_INPUT = "under any input"


@dataclass
class Program:
    name: str                        # repository folder and path (and task)
    files: list[Path]
    entry: Optional[str] = None
    copies: list[str] = field(default_factory=list)
    exit: Optional[int] = None       # rapidmc's exit code (None: killed at the CPU limit)
    outcome: str = ""                # verdicts / unknown / cpu limit / load error / internal
    verdicts: dict = field(default_factory=dict)
    states: int = 0
    unreached: int = 0               # RMC701 warnings
    any_input: int = 0               # of them "never reached under any input"
    lines: int = 0                   # lines the warnings and their places span
    places: int = 0                  # the warnings' places (a warning counts as one at least)
    errors: list[str] = field(default_factory=list)
    warnings: list[dict] = field(default_factory=list)   # the RMC701 warnings as reported
    wall: float = 0.0
    cpu: float = 0.0


def find_programs(corpus: Path) -> list[Program]:
    """Every socket program of ``corpus``, one per distinct text, copies named."""
    programs: dict[tuple, Program] = {}
    for module in sorted(f for f in corpus.rglob("*") if f.is_file() and
                         f.suffix.lower() in MODULE_SUFFIXES and
                         "INTERNAL" not in f.relative_to(corpus).parts):
        if not SOCKET_CALL.search(module.read_bytes()):
            continue
        for name, files, entry in _programs_of(module, corpus):
            key = (_digest(files), entry)
            if key in programs:
                if name != programs[key].name and name not in programs[key].copies:
                    programs[key].copies.append(name)
            else:
                programs[key] = Program(name, files, entry)
    return sorted(programs.values(), key=lambda p: p.name)


def _programs_of(module: Path, corpus: Path):
    """(name, files, entry) of each program ``module`` belongs to."""
    task = _task_folder(module)
    if task is not None:
        files = sorted(f for f in task.rglob("*") if f.is_file() and
                       f.suffix.lower() in MODULE_SUFFIXES)
        yield f"{task.parent.parent.relative_to(corpus)} {task.name}", files, None
        return
    folder = module.parent
    modules = sorted(f for f in folder.iterdir() if f.is_file() and
                     f.suffix.lower() in MODULE_SUFFIXES)
    servers = [f for f in modules if "server" in f.stem.lower() and f.suffix.lower() != ".sys"]
    if module.suffix.lower() == ".sys" and servers:
        system = [f for f in modules if f.suffix.lower() == ".sys"]
        for server in servers:
            yield str(server.relative_to(corpus)), [server, *system], None
        return
    path = module.relative_to(corpus).as_posix()
    for fragment, (partners, entry) in SPECIAL.items():
        if fragment in path:
            yield path, [module, *(folder / p for p in partners)], entry
            return
    yield path, [module], None


def _task_folder(module: Path) -> Optional[Path]:
    """The backup task folder (``.../RAPID/TASKn``) holding ``module``, if any."""
    for folder in module.parents:
        if folder.parent.name.upper() == "RAPID" and any(
                (folder / part).is_dir() for part in ("PROGMOD", "SYSMOD", "progmod", "sysmod")):
            return folder
    return None


def _digest(files: list[Path]) -> str:
    return hashlib.sha1(b"".join(sorted(hashlib.sha1(f.read_bytes()).digest()
                                        for f in files))).hexdigest()


def check(program: Program, options: list[str], cpu: int) -> Program:
    """Run ``rapidmc check`` on ``program`` and fill its row."""
    words = ["check", *map(str, program.files), "--format", "json", "--quiet", *options]
    if program.entry:
        words += ["--entry", program.entry]

    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
    started = time.monotonic()
    child = subprocess.Popen([sys.executable, "-m", "rapidmc", *words], stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True, errors="replace",
                             preexec_fn=limit)
    output = child.stdout.read()
    child.stdout.close()
    _, status, usage = os.wait4(child.pid, 0)
    program.wall = round(time.monotonic() - started, 1)
    program.cpu = round(usage.ru_utime + usage.ru_stime, 1)
    code = os.waitstatus_to_exitcode(status)
    program.exit = code if code >= 0 else None
    try:
        report = json.loads(output)
    except ValueError:
        report = {}
    _fill(program, report)
    return program


def _fill(program: Program, report: dict) -> None:
    properties = report.get("properties") or []
    program.verdicts = {p["name"]: p["verdict"] for p in properties}
    program.states = max((p["stats"]["model_states"] for p in properties if p.get("stats")),
                         default=0)
    program.errors = sorted({e["code"] for e in report.get("errors") or []})
    program.warnings = [w for w in report.get("warnings") or [] if w["code"] == UNREACHED]
    program.unreached = len(program.warnings)
    program.any_input = sum(ANY_INPUT in w["message"] for w in program.warnings)
    program.places = sum(max(1, len(w.get("places") or [])) for w in program.warnings)
    program.lines = sum(_span(w) for w in program.warnings)
    if program.exit is None:
        program.outcome = "cpu limit"
    elif program.exit == 2:
        program.outcome = "load error"
    elif program.exit == 4 or not properties:
        program.outcome = "internal"
    elif all(v in ("HOLDS", "VIOLATED") for v in program.verdicts.values()):
        program.outcome = "verdicts"
    else:
        program.outcome = "unknown"


def _span(warning: dict) -> int:
    """Lines a warning spans: its own and its places' (each place counted once; a place is
    a flat location, as the warning's own)."""
    spans = {(at["file"], at["line"], at.get("end_line"))
             for at in [warning.get("location"), *(warning.get("places") or [])] if at}
    return sum(max(end or line, line) - line + 1 for _, line, end in spans)


def cell(program: Program) -> str:
    """Round 9's cell: RMC701 (lines), under any input, verdicts, states, time."""
    letters = "/".join(v[0] for v in program.verdicts.values()) or "-"
    text = (f"{program.unreached} ({program.lines}), {program.any_input}, {letters}, "
            f"{program.states:,}, {program.wall:.0f} s ({program.cpu:.0f} CPU s)")
    return text if program.outcome in ("verdicts", "unknown") else \
        f"{program.outcome} {' '.join(program.errors)}".strip() + f", {program.cpu:.0f} CPU s"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", type=Path)
    parser.add_argument("--max-states", default="200000")
    parser.add_argument("--max-seconds", default="60")
    parser.add_argument("--long", action="append", default=[], metavar="TEXT",
                        help="programs whose name holds TEXT run without --max-seconds")
    parser.add_argument("--cpu", type=int, default=1800, help="CPU seconds per program")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--only", action="append", default=[], metavar="TEXT",
                        help="only programs whose name holds TEXT (repeatable)")
    parser.add_argument("--list", action="store_true", help="print the programs, check none")
    parser.add_argument("--json", type=Path, default=None, help="write every row to FILE")
    args = parser.parse_args()
    programs = find_programs(args.corpus.resolve())
    if args.only:
        programs = [p for p in programs if any(t in p.name for t in args.only)]
    if args.list:
        for p in programs:
            entry = f" --entry {p.entry}" if p.entry else ""
            print(f"{p.name} ({len(p.files)} modules{entry}; {len(p.copies)} copies)")
        print(f"{len(programs)} socket programs")
        return 0
    done = iter(range(1, len(programs) + 1))
    finished: list[Program] = []
    writing = threading.Lock()

    def one(program: Program) -> Program:
        options = ["--max-states", args.max_states]
        if not any(t in program.name for t in args.long):
            options += ["--max-seconds", args.max_seconds]
        check(program, options, args.cpu)
        print(f"[{next(done)}/{len(programs)}] {cell(program)}: {program.name}",
              file=sys.stderr, flush=True)
        with writing:
            finished.append(program)
            if args.json is not None:        # the rows so far: an interrupted run keeps them
                write_rows(args.json, finished)
        return program

    with ThreadPoolExecutor(args.jobs) as pool:
        checked = list(pool.map(one, programs))
    report(checked)
    return 0


def write_rows(path: Path, programs: list[Program]) -> None:
    rows = sorted((vars(p) | {"files": [str(f) for f in p.files]} for p in programs),
                  key=lambda row: row["name"])
    scratch = path.with_name(path.name + ".part")
    scratch.write_text(json.dumps(rows, indent=1))
    scratch.replace(path)


def report(programs: list[Program]) -> None:
    for p in sorted(programs, key=lambda p: p.name):
        copies = f" (+{len(p.copies)} copies)" if p.copies else ""
        print(f"| {p.name}{copies} | {cell(p)} |")
    outcomes: dict[str, int] = {}
    for p in programs:
        outcomes[p.outcome] = outcomes.get(p.outcome, 0) + 1
    both = [p for p in programs if p.outcome == "verdicts"]
    print(f"\n{len(programs)} socket programs: " +
          ", ".join(f"{n} {o}" for o, n in sorted(outcomes.items())))
    print(f"with both verdicts ({len(both)}): RMC701 {sum(p.unreached for p in both)} "
          f"({sum(p.lines for p in both)} lines, {sum(p.places for p in both)} places), "
          f"under any input {sum(p.any_input for p in both)}; "
          f"all programs: RMC701 {sum(p.unreached for p in programs)}, under any input "
          f"{sum(p.any_input for p in programs)}")


if __name__ == "__main__":
    sys.exit(main())
