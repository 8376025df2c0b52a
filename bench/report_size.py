"""How long ``rapidmc check`` reports are: text-report size of the programs with a violation.

Usage: python bench/report_size.py FOLDER [--max-states N] [--max-seconds S] [--jobs N]
                                   [--no-stubs] [--list] [--keep DIR] [--only LIST]
                                   [--rows ROWS.json] [-- CHECK-OPTIONS...]

Every ``.mod``/``.modx``/``.sys`` file under FOLDER is checked as a program of its own
(files with the same text once); one that stops at unknown names is checked again with
the declarations ``rapidmc stubs`` writes for it.  Each file is named by its absolute path,
as a user who checks a file outside the current folder names it.  The text report is what a
user sees: stdout and stderr of ``rapidmc check FILE --quiet`` together; the counterexample
text is the part of it under each VIOLATED verdict (the verdict line and the indented lines
after it).  For the programs whose check says VIOLATED (exit 1) it prints the count, and of
the counterexample texts and of the whole reports the median and largest size and the
longest line; ``--list`` prints one row per such program (``--keep DIR`` keeps the reports
there, one file each; ``--only LIST`` checks only the files LIST names, relative to FOLDER,
one a line).  Options after ``--`` go to every check (e.g. ``--full-trace``).

The figures of issue 19 were taken with ``--max-states 20000 --max-seconds 20``.

``--rows ROWS.json`` measures instead the programs a task survey found VIOLATED
(``survey_programs.py --json``): each row's own command (a backup and ``--task``, or its
files), with ``--stubs`` where the row was checked with stubs.  Issue 28's figures
(median under 3 KB, largest under 8 KB) were taken so, with ``--max-seconds 40``.
"""
from __future__ import annotations

import argparse
import hashlib
import json
import os
import statistics
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

SUFFIXES = (".mod", ".modx", ".sys")
STATIC_ERRORS = 2


def programs(folder: Path) -> list[Path]:
    """The module files under ``folder``, one per distinct text, in path order."""
    seen: set[str] = set()
    found = []
    for path in sorted(folder.rglob("*")):
        if not path.is_file() or path.suffix.lower() not in SUFFIXES:
            continue
        digest = hashlib.sha1(path.read_bytes()).hexdigest()
        if digest not in seen:
            seen.add(digest)
            found.append(path)
    return found


def rapidmc(*words: str, timeout: float) -> tuple[int, str]:
    """Exit code and stdout then stderr of one rapidmc command (exit -1: it timed out)."""
    command = [sys.executable, "-m", "rapidmc", *words]
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                              errors="replace")
    except subprocess.TimeoutExpired:
        return -1, ""
    return done.returncode, done.stdout + done.stderr


def check(path: Path, options: list[str], stubs: bool, timeout: float) -> tuple[int, str, bool]:
    """(exit code, report, stubbed) of one program, with stubs when it needs them."""
    code, report = rapidmc("check", str(path), "--quiet", *options, timeout=timeout)
    if code != STATIC_ERRORS or not stubs:
        return code, report, False
    with tempfile.TemporaryDirectory() as scratch:
        missing = os.path.join(scratch, "Missing.mod")
        made, _ = rapidmc("stubs", str(path), "-o", missing, timeout=timeout)
        if made != 0:
            return code, report, False
        code, report = rapidmc("check", str(path), missing, "--quiet", *options,
                               timeout=timeout)
        return code, report, True


def counterexample_text(report: str) -> str:
    """The lines under each VIOLATED verdict: the verdict line and the indented lines after it."""
    kept, inside = [], False
    for line in report.splitlines():
        if not line[:1].isspace():
            inside = ": VIOLATED" in line and not line.startswith("(")
        if inside and line:
            kept.append(line)
    return "\n".join(kept) + "\n" if kept else ""


def figures(texts: list[str]) -> str:
    """``median 2,316 B, largest 6,250 B, longest line 266 characters``."""
    sizes = [len(text.encode()) for text in texts]
    longest = max((len(line) for text in texts for line in text.splitlines()), default=0)
    return (f"median {statistics.median(sizes):,.0f} B, largest {max(sizes):,} B, "
            f"longest line {longest:,} characters")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("folder", type=Path)
    parser.add_argument("--max-states", default="20000")
    parser.add_argument("--max-seconds", default="20")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--no-stubs", action="store_true")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--keep", type=Path, default=None)
    parser.add_argument("--only", type=Path, default=None,
                        help="a file of paths under FOLDER, one a line: check only these")
    parser.add_argument("--rows", type=Path, default=None,
                        help="a JSON file of survey_programs.py rows: check the rows whose "
                             "verdicts include VIOLATED, each with its own command (and "
                             "--stubs where the row used stubs), instead of every file")
    parser.add_argument("extra", nargs="*", help="options for every check (after --)")
    args = parser.parse_args()
    args.folder = args.folder.resolve()
    options = ["--max-states", args.max_states, "--max-seconds", args.max_seconds, *args.extra]
    timeout = 10 * float(args.max_seconds) + 60
    if args.rows is not None:
        rows = [row for row in json.loads(args.rows.read_text())
                if row["outcome"] == "verdict" and "VIOLATED" in row["detail"]]
        files = [row["name"] for row in rows]

        def one(row):
            stubs = ["--stubs"] if row["stubbed"] else []
            code, report = rapidmc("check", *row["command"], *stubs, "--quiet", *options,
                                   timeout=timeout)
            return row["name"], code, report, bool(stubs)
    else:
        files = programs(args.folder)
        if args.only is not None:
            wanted = {line.strip() for line in args.only.read_text().splitlines()
                      if line.strip()}
            files = [path for path in files if str(path.relative_to(args.folder)) in wanted]
        rows = files

        def one(path: Path):
            return path.relative_to(args.folder), *check(path, options, not args.no_stubs,
                                                         timeout)

    with ThreadPoolExecutor(args.jobs) as pool:
        outcomes = list(pool.map(one, rows))
    violated = [(path, report, stubbed) for path, code, report, stubbed in outcomes if code == 1]
    if args.keep is not None:
        args.keep.mkdir(parents=True, exist_ok=True)
    if args.list and violated:
        print("counterexample  report  longest line  program")
    for relative, report, stubbed in violated:
        if args.list:
            shown = counterexample_text(report)
            print(f"{len(shown.encode()):>7,} B  {len(report.encode()):>7,} B  longest "
                  f"{max(map(len, report.splitlines()), default=0):>5,}  "
                  f"{'stubs ' if stubbed else ''}{relative}")
        if args.keep is not None:
            (args.keep / (str(relative).replace("/", "__") + ".txt")).write_text(report)
    codes = [code for _, code, _, _ in outcomes]
    print(f"programs: {len(files)} (exit 0: {codes.count(0)}, 1: {codes.count(1)}, "
          f"2: {codes.count(2)}, 3: {codes.count(3)}, 4: {codes.count(4)}, "
          f"timed out: {codes.count(-1)})")
    if not violated:
        print("no program with a violation")
        return 0
    reports = [report for _, report, _ in violated]
    print(f"violations: {len(violated)} programs")
    print(f"  counterexample text: {figures([counterexample_text(r) for r in reports])}")
    print(f"  whole text report:   {figures(reports)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
