"""How much of ABB's RAPID reference the predefined library covers.

``docs/reference-names.txt`` lists the reference's names by section (its header says where
they come from); ``coverage()`` looks each one up in the registry of the same kind.
``python -m rapidmc.semantics.library.reference_coverage`` prints the figures and every missing name;
docs/predefined.md shows the same (``rapidmc.semantics.library.documentation``).

Example::

    >>> sections = coverage()
    >>> [section.name for section in sections]
    ['instructions', 'functions', 'data types', 'data objects']
"""
from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from ..errors import ERROR_NUMBERS
from . import lookup_function, lookup_procedure
from .data import PREDEFINED_DATA
from ..types import PREDEFINED_ALIASES, PREDEFINED_TYPES

REFERENCE = Path(__file__).resolve().parents[3] / "docs" / "reference-names.txt"

KNOWN: dict[str, Callable[[str], bool]] = {
    "instructions": lambda key: lookup_procedure(key) is not None,
    "functions": lambda key: lookup_function(key) is not None,
    "data types": lambda key: key in PREDEFINED_TYPES or key in PREDEFINED_ALIASES,
    "data objects": lambda key: key in PREDEFINED_DATA or key in ERROR_NUMBERS,
}


ROUTINE_LOOKUPS = {"instructions": lookup_procedure, "functions": lookup_function}


def known_by_name_only(section: str, key: str) -> bool:
    """A routine registered with an open parameter list ``(...)``: rapidmc found no evidence
    of its parameters, so calls load unchecked and stop the run where they are reached."""
    lookup = ROUTINE_LOOKUPS.get(section)
    entry = lookup(key) if lookup else None
    return entry is not None and entry.signature.open_parameters


@dataclass(frozen=True)
class Section:
    """One section of the reference: its names, those the library lacks, and those it knows
    by name only."""

    name: str
    names: tuple[str, ...]
    missing: tuple[str, ...]
    name_only: tuple[str, ...] = ()

    @property
    def covered(self) -> int:
        return len(self.names) - len(self.missing)


def read_reference(path: Path = REFERENCE) -> dict[str, list[str]]:
    """The names of each section, in file order (``#`` lines are comments)."""
    sections: dict[str, list[str]] = {}
    current = None
    for line in path.read_text(encoding="utf-8").splitlines():
        text = line.strip()
        if not text or text.startswith("#"):
            continue
        if text.startswith("[") and text.endswith("]"):
            current = sections.setdefault(text[1:-1], [])
        elif current is None:
            raise ValueError(f"{path}: name {text!r} before the first [section]")
        else:
            current.append(text)
    return sections


def coverage(path: Path = REFERENCE) -> list[Section]:
    """Each section of the reference with the names the registry does not know."""
    result = []
    for name, names in read_reference(path).items():
        known = KNOWN[name]
        missing = tuple(n for n in names if not known(n.upper()))
        name_only = tuple(n for n in names if known_by_name_only(name, n.upper()))
        result.append(Section(name, tuple(names), missing, name_only))
    return result


def report(sections: list[Section]) -> str:
    lines = []
    for section in sections:
        lines.append(f"{section.name}: {section.covered} of {len(section.names)}")
        if section.name_only:
            lines.append(f"  by name only, signature (...): {len(section.name_only)}")
        if section.missing:
            lines.append("  missing: " + " ".join(section.missing))
    return "\n".join(lines)


def main(argv: list[str]) -> int:
    print(report(coverage()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
