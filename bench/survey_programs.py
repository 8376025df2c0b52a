"""Survey of public programs, task by task: how many reach a verdict (issue 28).

Usage: python bench/survey_programs.py CORPUS [--max-states N] [--cpu S] [--jobs N]
                                       [--no-stubs] [--list] [--only TEXT] [--json FILE]
       python bench/survey_programs.py CORPUS --whole [--cpu S] [--jobs N] [--list] [--json FILE]
       python bench/survey_programs.py CORPUS --recheck ROWS.json [--outcomes LIST]
       python bench/survey_programs.py CORPUS --extract MIRRORS

CORPUS holds public repositories, one folder each (``--extract`` fills it from the git
mirrors ``fetch`` leaves in MIRRORS: the RAPID modules and configuration files of each
mirror's newest snapshot, one folder per mirror, nothing else).  A *program* is what a
controller would load and start:

* each task of a controller backup (a folder with ``RAPID/``; ``rapidmc check BACKUP --task
  FOLDER``);
* outside backups, the module files of one folder when one of them declares ``PROC main``;
  a folder where several files declare ``main`` gives a program per such file, with the
  folder's files that declare none (of files declaring the same global names, copies for
  two tasks, the one whose file name shares most words with the entry module's); an entry
  module a program file (``.pgf``) of its folder lists is checked with the modules that file lists, as the controller loads it (a backup's
  HOME folder keeps several saved programs side by side).  A folder of modules without
  ``main`` is a library:
  counted apart ("no entry"), never checked.

``--whole`` surveys controller backups instead, each as a controller loads it: every task
together with the backup's SYSPAR (``rapidmc check BACKUP``), at ``rapidmc check``'s own state
bound unless ``--max-states`` is given; one that stops at names no module of a task declares
(an installed option's, whose modules a backup does not hold) is checked again with
``--stubs``.  Backups whose RAPID and SYSPAR files have the same texts are counted once.

Programs with the same module texts are counted once.  Each is checked with the default
properties, ``--max-states`` (20,000) and a limit of ``--cpu`` CPU seconds (20) per
command, as the surveys of docs/realworld-survey.md; one that stops at names no module
declares is checked again with the module ``rapidmc stubs`` writes for it.  Outcomes:

* ``verdict``: HOLDS or VIOLATED (exit 0 or 1), with the violated properties;
* ``unknown``: UNKNOWN at the state bound (exit 3), the detail saying how far the first
  search came (``deepest_state``: its depth and where each task stood); ``cpu limit``: the
  limit was reached;
* ``load error``: exit 2, with its diagnostic codes (after stubs, when they were tried);
* ``own error``: a load error the survey's reviewed list (``OWN_ERRORS``) gives as the
  program's own (the controller would refuse it too);
* ``no entry``: a backup task without its entry routine (RMC211); ``no program``: a task of
  system modules only (RMC736); ``encrypted``: every module of the program is encrypted;
* ``internal``: exit 4, or a Python traceback on the command's stderr whatever its exit
  code (the row's detail is the traceback's last lines).

Each row also keeps the most model states a property's search of the program explored and
the CPU seconds of its rapidmc commands (the children's own, whatever ``--jobs``), shown on
the progress lines.  It prints the counts per outcome and per load-error code, and the share of programs reaching
a verdict among those that can: every program but the encrypted ones, those without program
or entry, and those with an error of their own.  ``--list`` prints a row per program,
``--json`` writes the rows; ``--recheck ROWS.json`` reads them back and checks again only
the programs whose outcome ``--outcomes`` names (default ``load error``; ``none``: reclassify
with the current ``OWN_ERRORS`` only), keeping the other rows: a fix's effect in minutes
instead of the whole survey's hour (17 CPU minutes; 62 minutes of wall time on a loaded
2-core machine).
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
import tempfile
import threading
from collections import Counter
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

from rapidmc.load.backup import MODULE_SUFFIXES, backup_tasks, is_backup
from rapidmc.diagnostics import UserError
from rapidmc.load.encrypted import is_encrypted
from rapidmc.load.source import PROGRAM_FILE_SUFFIX, program_file_modules

CONFIG_SUFFIXES = {".cfg", ".txt", ".pgf"}
ENTRY = re.compile(rb"^\s*(LOCAL\s+)?PROC\s+main\s*\(", re.IGNORECASE | re.MULTILINE)
EXTRACTED_LIMIT = 4_000_000       # bytes: larger files of a mirror are not RAPID code

# Load errors reviewed as the program's own: the controller refuses the same files (see
# docs/realworld-survey.md).  Key: a fragment of the program's path and the code.
OWN_ERRORS = {
    ("Topsy/Backups/120-502354_BACKUP_2024-08-08", "RMC204"): "two modules declare main",
    ("abb_communication", "RMC205"): "Present() of a parameter that is not optional",
    ("Keen1949+ABB_ROBOT_Socket", "RMC205"): "Assemble called with 5 of its 6 arguments",
    ("PaletizadoCajasConFrascos", "RMC204"): "two files declare MODULE MainModule",
    ("008_circle_track_v2", "RMC101"): "CommonData\\pStart is no RAPID",
    ("0-robinson-1+abb-rapid-robotics/exercises", "RMC107"):
        "011_pick_and_place.mod ends in the middle of a declaration",
    ("Follansbeast+ABB-IRB-120-Hanoi/src/rapid/", "RMC101"):
        "the folder's HanoiAlgorithm modules index arrays with [ ], which is no RAPID",
    ("HOME/1/1_T_ROB", "RMC101"): "MODULE 1_T_ROB1: a name cannot start with a digit",
    ("SheetformingTODAY", "RMC101"): "instructions after ENDMODULE",
    ("Stena obluk", "RMC101"): "text after ENDMODULE",
    ("Expiremental/BG_Module", "RMC101"): "ENDIF; (a semicolon after ENDIF)",
    ("Expiremental/Test_mod", "RMC101"): "a declaration inside IF, indexing with [ ]",
    ("Expiremental/multitasking_scripts", "RMC101"): "a text document, not a module",
    ("Controller_Pintura_220623-230315", "RMC008"):
        "no task declares its entry routine main (T_ROB1's program starts at mainm4)",
    ("ravenorb+abb-robot-welder/RAPID/PROGMOD", "RMC205"):
        "TPWrite given three positional arguments",
    ("Sensor-Based Automatic Unloading and Arrangement System", "RMC204"):
        "two modules of TASK1 declare main (MainModule, ProgramSelector)",
    ("Springa13+ABBController", "RMC204"): "MoveObject.mod declares VAR jointtarget Move5 twice",
    ("growster+Robot-Piano", "RMC206"):
        "SoundArray{14,2} is given an aggregate of 10 rows (PointModule.mod)",
    ("liamjosephnolan+DiceRobot", "RMC206"):
        "the FUNC reset_dice is called as a procedure (MainModule.mod:26)",
}


@dataclass
class Program:
    name: str                  # path under the corpus (and task)
    command: list[str]         # the files (or BACKUP --task T) given to rapidmc
    files: list[Path]
    outcome: str = ""
    detail: str = ""
    codes: list[str] = field(default_factory=list)
    stubbed: bool = False
    duplicates: int = 0
    states: int = 0            # the most model states a property's search explored
    cpu: float = 0.0           # CPU seconds of the program's rapidmc commands
    trace: str = ""            # the end of a Python traceback a command printed
    deepest: str = ""          # UNKNOWN: where each task stood when the first search stopped


def extract(mirrors: Path, corpus: Path) -> None:
    """Write each mirror's RAPID and configuration files into ``corpus/<mirror>/``."""
    for mirror in sorted(p for p in mirrors.iterdir() if (p / "repo").is_dir()):
        repo = str(mirror / "repo")
        listing = subprocess.run(["git", "-C", repo, "ls-tree", "-r", "-l", "-z", "HEAD"],
                                 capture_output=True, check=True).stdout.split(b"\0")
        wanted = []
        for entry in filter(None, listing):
            meta, path = entry.split(b"\t", 1)
            _, kind, sha, size = meta.split()
            name = Path(path.decode("utf-8", "replace"))
            if kind == b"blob" and size.isdigit() and int(size) <= EXTRACTED_LIMIT and \
                    name.suffix.lower() in MODULE_SUFFIXES | CONFIG_SUFFIXES:
                wanted.append((sha, name))
        blobs = subprocess.run(["git", "-C", repo, "cat-file", "--batch"], capture_output=True,
                               input=b"".join(sha + b"\n" for sha, _ in wanted)).stdout
        at = 0
        for _, name in wanted:
            header_end = blobs.index(b"\n", at)
            header = blobs[at:header_end].split()
            at = header_end + 1
            if len(header) != 3:             # "<sha> missing": the snapshot left it out
                continue
            size = int(header[2])
            target = corpus / mirror.name / name
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(blobs[at:at + size])
            at += size + 1


def find_programs(corpus: Path) -> tuple[list[Program], list[Program]]:
    """(programs to check, programs classified without a check), one per distinct text."""
    backups = sorted(p for p in corpus.rglob("RAPID") if p.is_dir() and _is_backup(p.parent))
    backup_rapid = {p.resolve() for p in backups}
    programs: list[Program] = []
    for rapid in backups:
        backup = rapid.parent
        try:
            tasks = backup_tasks(backup)
        except Exception:              # a RAPID folder without task folders
            continue
        for task in tasks:
            files = sorted(f for f in task.folder.rglob("*")
                           if f.is_file() and f.suffix.lower() in MODULE_SUFFIXES)
            programs.append(Program(f"{backup.relative_to(corpus)} --task {task.folder.name}",
                                    [str(backup), "--task", task.folder.name], files))
    folders: dict[Path, list[Path]] = {}
    for path in sorted(corpus.rglob("*")):
        if path.is_file() and path.suffix.lower() in MODULE_SUFFIXES and \
                not any(parent.resolve() in backup_rapid for parent in path.parents):
            folders.setdefault(path.parent, []).append(path)
    for folder, files in folders.items():
        entries = [f for f in files if ENTRY.search(f.read_bytes())]
        others = [f for f in files if f not in entries]
        listed = _program_files(folder)
        groups = [files] if len(entries) <= 1 and not listed else \
            [listed.get(entry) or [entry, *_sides_of(entry, others)] for entry in entries]
        for group in groups:
            name = str(folder.relative_to(corpus)) if len(groups) == 1 else \
                str(group[0].relative_to(corpus))
            programs.append(Program(name, [str(f) for f in group], group))
    return _distinct(programs)


def _sides_of(entry: Path, others: list[Path]) -> list[Path]:
    """The modules without main that go with ``entry`` in a folder holding several
    programs: all of them, except that of modules declaring the same global names (copies
    of one driver for two tasks: ``HandDriver_left.sys``, ``HandDriver_right.sys``), which
    no task loads together, only the one sharing most words of its file name with the
    entry module's (``ROS_motion_left.mod``); all of them when that one is not single."""
    names = {path: _global_names(path) for path in others}
    words = _words(entry)
    kept = []
    for path in others:
        rivals = [other for other in others
                  if other != path and names[path] & names[other]]
        if not rivals:
            kept.append(path)
            continue
        shared = {other: len(words & _words(other)) for other in [path, *rivals]}
        best = max(shared.values())
        if [other for other, count in shared.items() if count == best] == [path] or \
                list(shared.values()).count(best) > 1:
            kept.append(path)
    return kept


def _words(path: Path) -> set[str]:
    return {word for word in re.split(r"[^a-z0-9]+", path.stem.lower()) if word}


def _global_names(path: Path) -> set[str]:
    """The names a module declares for the whole task (not LOCAL), upper case; none
    when it does not parse."""
    from rapidmc.syntax import parse_file
    try:
        modules = parse_file(str(path))
    except Exception:
        return set()
    return {declaration.name.key for module in modules
            for declaration in (*module.data, *module.routines)
            if not getattr(declaration, "local", False)
            and getattr(declaration, "scope", "") != "LOCAL"}


def find_backups(corpus: Path) -> tuple[list[Program], list[Program]]:
    """(whole backups to check, backups classified without a check), one per distinct text
    of its RAPID and SYSPAR files; a backup nested in another's HOME folder is one of its own."""
    programs = []
    for rapid in sorted(p for p in corpus.rglob("RAPID") if p.is_dir() and _is_backup(p.parent)):
        backup = rapid.parent
        files = sorted(f for f in rapid.rglob("*")
                       if f.is_file() and f.suffix.lower() in MODULE_SUFFIXES)
        syspar = next((d for d in backup.iterdir() if d.is_dir() and d.name.upper() == "SYSPAR"),
                      None)
        configuration = sorted(f for f in syspar.rglob("*") if f.is_file()) if syspar else []
        programs.append(Program(str(backup.relative_to(corpus)), [str(backup)],
                                files + configuration))
    return _distinct(programs, libraries=False)


def _program_files(folder: Path) -> dict[Path, list[Path]]:
    """entry module -> the modules a program file (``.pgf``) of ``folder`` lists with it:
    what the controller loads from that folder (a HOME folder of saved programs holds
    modules of several programs side by side)."""
    programs = {}
    for pgf in sorted(f for f in folder.iterdir() if f.suffix.lower() == PROGRAM_FILE_SUFFIX):
        try:
            modules = [Path(m) for m in program_file_modules(str(pgf))]
        except UserError:                 # lists nothing, or a module not there
            continue
        for entry in (m for m in modules if ENTRY.search(m.read_bytes())):
            programs.setdefault(entry, modules)
    return programs


def earlier_rows(path: Path, outcomes: set[str]) -> tuple[list[Program], list[Program]]:
    """The rows of an earlier ``--json`` run: (those to check again, those kept)."""
    rows = [Program(**{**row, "files": [Path(f) for f in row["files"]]})
            for row in json.loads(path.read_text())]
    again = [row for row in rows if row.outcome in outcomes]
    for row in again:
        row.outcome, row.detail, row.codes, row.stubbed, row.trace, row.deepest = \
            "", "", [], False, "", ""
    for row in rows:                 # the reviewed list as it is now
        _own_error(row)
    chosen = {id(row) for row in again}
    return again, [row for row in rows if id(row) not in chosen]


def _is_backup(folder: Path) -> bool:
    """A controller backup: a RAPID folder whose task folders hold SYSMOD or PROGMOD (not a
    repository's own RAPID folder of loose modules or of backups)."""
    return is_backup(folder) and any(
        (task / part).is_dir() for task in (folder / "RAPID").iterdir() if task.is_dir()
        for part in ("SYSMOD", "PROGMOD", "sysmod", "progmod"))


def _distinct(programs: list[Program], libraries: bool = True) -> tuple[list[Program], list[Program]]:
    seen: dict[str, Program] = {}
    to_check, settled = [], []
    for program in programs:
        digest = hashlib.sha1(b"".join(sorted(hashlib.sha1(f.read_bytes()).digest()
                                              for f in program.files))).hexdigest()
        if digest in seen:
            seen[digest].duplicates += 1
            continue
        seen[digest] = program
        modules = [f for f in program.files if f.suffix.lower() in MODULE_SUFFIXES]
        readable = [f for f in modules if not is_encrypted(str(f))]
        if modules and not readable:
            program.outcome = "encrypted"
        elif libraries and "--task" not in program.command and \
                not any(ENTRY.search(f.read_bytes()) for f in program.files):
            program.outcome, program.detail = "no entry", "library: no module declares main"
        (settled if program.outcome else to_check).append(program)
    return to_check, settled


def rapidmc(words: list[str], cpu: int, program: Optional[Program] = None) -> tuple[int, dict]:
    """Exit code and JSON report of one rapidmc command under a CPU limit (-1: reached);
    its CPU seconds are added to ``program.cpu``, and a traceback it printed to
    ``program.trace``."""
    return run_child([sys.executable, "-m", "rapidmc", *words], cpu, program)


TRACEBACK = "Traceback (most recent call last)"


def run_child(argv: list[str], cpu: int, program: Optional[Program] = None) -> tuple[int, dict]:
    """``rapidmc`` for any command line ``argv`` (its stderr kept in a file, never a pipe
    that could fill while stdout is read)."""
    def limit() -> None:
        resource.setrlimit(resource.RLIMIT_CPU, (cpu, cpu + 1))
    with tempfile.TemporaryFile(mode="w+", errors="replace") as errors:
        child = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=errors, text=True,
                                 errors="replace", preexec_fn=limit)
        output = child.stdout.read()
        child.stdout.close()
        _, status, usage = os.wait4(child.pid, 0)    # the child's own CPU time, not the jobs'
        errors.seek(0)
        printed = errors.read()
    child.returncode = os.waitstatus_to_exitcode(status)
    if program is not None:
        program.cpu += usage.ru_utime + usage.ru_stime
        if TRACEBACK in printed and not program.trace:
            program.trace = _last_lines(printed[printed.index(TRACEBACK):])
    if child.returncode < 0:
        return -1, {}
    try:
        return child.returncode, json.loads(output)
    except ValueError:
        return child.returncode, {}


def _last_lines(text: str, count: int = 3) -> str:
    """A traceback's exception, then the ``count`` - 1 lines above it, last first (what
    was raised and where, in the row's first 90 characters)."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return " <- ".join(reversed(lines[-count:]))


def survey(program: Program, options: list[str], cpu: int, stubs: bool) -> Program:
    check = ["check", *program.command, "--quiet", "--format", "json", *options]
    program.cpu = 0.0
    code, report = rapidmc(check, cpu, program)
    if code == 2 and stubs and _stubbable(report) and _whole(program):
        code, report = rapidmc([*check, "--stubs"], cpu, program)    # each task's own stubs
        program.stubbed = True
    elif code == 2 and stubs and _stubbable(report):
        with tempfile.TemporaryDirectory() as scratch:
            missing = str(Path(scratch) / "Missing.mod")
            rapidmc(["stubs", *program.command, "-o", missing], cpu, program)
            if Path(missing).is_file():
                code, report = rapidmc(["check", *_with(program.command, missing), "--quiet",
                                        "--format", "json", *options], cpu, program)
                program.stubbed = True
    _classify(program, code, report)
    return program


def _whole(program: Program) -> bool:
    """Whether ``program`` is a whole backup (``find_backups``)."""
    return len(program.command) == 1 and _is_backup(Path(program.command[0]))


def _stubbable(report: dict) -> bool:
    return any(e.get("code") in {"RMC201", "RMC202", "RMC203"} for e in report.get("errors", ()))


def _with(command: list[str], extra: str) -> list[str]:
    if "--task" in command:
        at = command.index("--task")
        return [*command[:at], extra, *command[at:]]
    return [*command, extra]


def _classify(program: Program, code: int, report: dict) -> None:
    errors = report.get("errors", [])
    if program.trace:                   # rapidmc's own fault, whatever the exit code says
        program.outcome, program.detail = "internal", program.trace
        return
    program.codes = sorted({e.get("code", "?") for e in errors})
    program.states = max((p.get("stats", {}).get("model_states") or 0
                          for p in report.get("properties", ())), default=0)
    program.deepest = next((deepest_text(p) for p in report.get("properties", ())
                            if p.get("deepest_state")), "")
    notes = {w.get("code") for w in report.get("warnings", ())}
    if code == -1:
        program.outcome = "cpu limit"
    elif code in (0, 1) and "RMC736" in notes | set(program.codes):
        program.outcome = "no program"
    elif code in (0, 1):
        violated = [p["name"] for p in report.get("properties", ())
                    if p.get("verdict") == "VIOLATED"]
        program.outcome = "verdict"
        program.detail = "VIOLATED " + ",".join(violated) if violated else "HOLDS"
    elif code == 3:
        program.outcome, program.detail = "unknown", program.deepest
    elif code == 2:
        first = errors[0] if errors else {}
        program.outcome = "no entry" if "RMC211" in program.codes else "load error"
        program.detail = f"{first.get('code', '?')}: {first.get('message', '')[:110]}"
        _own_error(program)
    else:
        program.outcome = "internal"


def deepest_text(entry: dict) -> str:
    """``depth 158: T_ROB1 r_RRC_InitCell:87, T_RX r_RRC_InitVar:164`` of a property's
    ``deepest_state`` (how far an UNKNOWN search came)."""
    places = ", ".join(f"{place['task']} {place['routine'] or 'ended'}"
                       + (f":{place['line']}" if place["routine"] else "")
                       for place in entry["deepest_state"])
    return f"depth {entry['stats']['max_depth']}: {places}"


def _own_error(program: Program) -> None:
    """A load error the reviewed list gives as the program's own becomes ``own error``."""
    own = [reason for (where, rmc), reason in OWN_ERRORS.items()
           if where in program.name and rmc in program.codes]
    if program.outcome == "load error" and own:
        program.outcome, program.detail = "own error", own[0]


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", type=Path)
    parser.add_argument("--extract", type=Path, metavar="MIRRORS",
                        help="first fill CORPUS from the git mirrors in MIRRORS")
    parser.add_argument("--whole", action="store_true",
                        help="check each controller backup whole, all its tasks together")
    parser.add_argument("--max-states", default=None,
                        help="the state bound (20,000; with --whole: rapidmc check's own)")
    parser.add_argument("--cpu", type=int, default=20, help="CPU seconds per command")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-stubs", action="store_true")
    parser.add_argument("--list", action="store_true", help="a row per program")
    parser.add_argument("--only", default=None, help="only programs whose name holds TEXT")
    parser.add_argument("--json", type=Path, default=None, help="write every row to FILE")
    parser.add_argument("--recheck", type=Path, default=None, metavar="JSON",
                        help="take the rows of an earlier --json run and check again only the "
                             "programs whose outcome --outcomes names")
    parser.add_argument("--outcomes", default="load error",
                        help="with --recheck: the outcomes to check again, comma-separated")
    args = parser.parse_args()
    corpus = args.corpus.resolve()
    if args.extract is not None:
        extract(args.extract, corpus)
        return 0
    if args.recheck is not None:
        to_check, settled = earlier_rows(args.recheck, set(args.outcomes.split(",")))
    elif args.whole:
        to_check, settled = find_backups(corpus)
    else:
        to_check, settled = find_programs(corpus)
    if args.only:
        to_check = [p for p in to_check if args.only in p.name]
        settled = [p for p in settled if args.only in p.name]
    bound = args.max_states or (None if args.whole else "20000")
    options = ["--max-states", bound] if bound else []
    done = iter(range(1, len(to_check) + 1))

    finished: list[Program] = []
    writing = threading.Lock()

    def one(program: Program) -> Program:
        survey(program, options, args.cpu, not args.no_stubs)
        print(f"[{next(done)}/{len(to_check)}] {program.outcome} ({program.states:,} states, "
              f"{program.cpu:.1f} CPU s): {program.name}", file=sys.stderr, flush=True)
        with writing:
            finished.append(program)
            if args.json is not None:    # the rows so far: an interrupted run keeps them
                write_rows(args.json, finished + settled)
        return program

    with ThreadPoolExecutor(args.jobs) as pool:
        checked = list(pool.map(one, to_check))
    report(checked + settled, corpus, args.list)
    if args.json is not None:
        write_rows(args.json, checked + settled)
    return 0


def write_rows(path: Path, programs: list[Program]) -> None:
    text = json.dumps([vars(p) | {"files": [str(f) for f in p.files]} for p in programs],
                      indent=1, default=str)
    scratch = path.with_name(path.name + ".part")
    scratch.write_text(text)
    scratch.replace(path)


OUTSIDE = ("encrypted", "no entry", "no program", "own error")


def report(programs: list[Program], corpus: Path, rows: bool) -> None:
    programs = sorted(programs, key=lambda p: p.name)
    if rows:
        for p in programs:
            stub = " (stubs)" if p.stubbed else ""
            print(f"{p.outcome + stub:<22} {p.detail[:90]:<60}  {p.name}")
        print()
    outcomes = Counter(p.outcome for p in programs)
    tasks = [p for p in programs if "--task" in p.command]
    whole = [p for p in programs if _whole(p)]
    print(f"corpus {corpus}: {len(programs)} distinct programs "
          f"({len(whole)} whole backups, {len(tasks)} backup tasks, "
          f"{len(programs) - len(tasks) - len(whole)} module folders); "
          f"{sum(p.duplicates for p in programs)} duplicates left out")
    for outcome, count in outcomes.most_common():
        stubbed = sum(1 for p in programs if p.outcome == outcome and p.stubbed)
        print(f"  {outcome:<12} {count:>4}" + (f"  ({stubbed} with stubs)" if stubbed else ""))
    verdicts = [p for p in programs if p.outcome == "verdict"]
    violated = Counter(name for p in verdicts if p.detail.startswith("VIOLATED")
                       for name in p.detail.split()[1].split(","))
    print(f"  verdicts: HOLDS {sum(p.detail == 'HOLDS' for p in verdicts)}, VIOLATED "
          f"{len(verdicts) - sum(p.detail == 'HOLDS' for p in verdicts)} "
          f"({', '.join(f'{n} {c}' for n, c in violated.most_common())})")
    codes = Counter(code for p in programs if p.outcome == "load error" for code in p.codes)
    if codes:
        print("  load errors by code (a program counts once per code): " +
              ", ".join(f"{c} {n}" for c, n in codes.most_common()))
    eligible = [p for p in programs if p.outcome not in OUTSIDE]
    share = 100 * len(verdicts) / len(eligible) if eligible else 0
    print(f"verdict: {len(verdicts)} of {len(eligible)} programs that can reach one "
          f"({share:.1f} %); of all {len(programs)}: "
          f"{100 * len(verdicts) / max(len(programs), 1):.1f} %")


if __name__ == "__main__":
    sys.exit(main())
