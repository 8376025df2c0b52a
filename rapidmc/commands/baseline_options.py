"""``--baseline FILE`` and ``--write-baseline FILE`` of ``check`` and ``lint`` (docs/ci.md)."""
from __future__ import annotations

import argparse
import sys
from typing import Sequence, TypeVar

from ..report.baseline import format_baseline, read_baseline, split_known
from ..report.ci_findings import Finding
from .report_file import check_report_target, write_report

T = TypeVar("T")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--baseline", metavar="FILE", default=None,
                       help="leave out the findings this baseline records (matched by rule or "
                            "property, file and message, not by line): fail only on new ones")
    group.add_argument("--write-baseline", metavar="FILE", default=None,
                       help="record every finding of this run in FILE, to be given to "
                            "--baseline later; the run then passes on them")


def refuse_unwritable_target(args: argparse.Namespace) -> None:
    if args.write_baseline:
        check_report_target(args.write_baseline, "baseline")


def read_known(args: argparse.Namespace, command: str):
    """The baseline's recorded findings (read before any search, so a bad file fails fast)."""
    return read_baseline(args.baseline, command) if args.baseline else None


def new_findings(args: argparse.Namespace, command: str, findings: Sequence[Finding],
                 items: Sequence[T], known=None) -> tuple[list[T], list[T]]:
    """``items`` (one per finding) split into (new, in the baseline); writes the baseline
    when asked, after which every finding is in it.  Says on stderr how many were left out."""
    if args.write_baseline:
        write_report(args.write_baseline, format_baseline(command, findings), "baseline")
        new, old = [], list(items)
        print(f"rapidmc: wrote {len(findings)} finding(s) to the baseline "
              f"'{args.write_baseline}'", file=sys.stderr)
    elif known is not None:
        new, old = split_known(findings, items, known)
        if old:
            print(f"rapidmc: {len(old)} finding(s) recorded in the baseline '{args.baseline}' "
                  "left out", file=sys.stderr)
    else:
        new, old = list(items), []
    return new, old
