"""Writing a report (JUnit XML, a state graph) to the file named on the command line."""
from __future__ import annotations

from pathlib import Path
from typing import Optional

from ..diagnostics import OUTPUT_FILE, error


def unwritable_reason(path: str) -> Optional[str]:
    """Why ``path`` surely cannot be written (a folder, or in no folder), else None."""
    target = Path(path)
    if target.is_dir():
        return "it is a directory"
    if not target.resolve().parent.is_dir():
        return "its directory does not exist"
    return None


def check_report_target(path: str, what: str) -> None:
    """Refuse, before any search, a report path that cannot be written (RMC506)."""
    reason = unwritable_reason(path)
    if reason is not None:
        raise error(OUTPUT_FILE, f"cannot write the {what} to '{path}': {reason}")


def write_report(path: str, text: str, what: str) -> None:
    """Write ``text`` to ``path`` (UTF-8); a file that cannot be written is RMC506."""
    try:
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(text)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise error(OUTPUT_FILE, f"cannot write the {what} to '{path}': {reason}") from None
