"""Writing a report (JUnit XML, a state graph) to the file named on the command line."""
from __future__ import annotations

from ..diagnostics import OUTPUT_FILE, error


def write_report(path: str, text: str, what: str) -> None:
    """Write ``text`` to ``path`` (UTF-8); a file that cannot be written is RMC506."""
    try:
        with open(path, "w", encoding="utf-8") as handle:
            handle.write(text)
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
        raise error(OUTPUT_FILE, f"cannot write the {what} to '{path}': {reason}") from None
