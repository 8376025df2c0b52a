"""docs/predefined.md, generated from the predefined library's registry.

``python -m rapidmc.semantics.library.documentation`` rewrites the file; ``python -m
rapidmc.semantics.library.documentation --check`` exits 1 when the committed file differs from
what the registry gives (tests/test_predefined_doc.py does the same).  The
page lists every predefined routine with its signature and how rapidmc
models it, every predefined data type and data object, and the figures:
names by kind and by modelling.

Example::

    >>> from rapidmc.semantics.library import lookup_function
    >>> signature_text(lookup_function("ROUND").signature)
    'num Round(num Val \\\\num Dec)'
"""
from __future__ import annotations

import importlib
import sys
from collections import Counter
from pathlib import Path

from .reference_coverage import REFERENCE, coverage
from ..errors import ERROR_NUMBERS
from . import TOPICS, all_entries
from .data import PREDEFINED_DATA
from .registry import MODELLED_AS, Signature
from ..types import PREDEFINED_ALIASES, PREDEFINED_TYPES, RECORD

DOC = Path(__file__).resolve().parents[3] / "docs" / "predefined.md"
HIDDEN_TYPES = ("SWITCH", "ANYTYPE")


def parameter_text(spec) -> str:
    mode = "" if spec.mode == "IN" else spec.mode + " "
    dims = "{" + ",".join("*" * spec.array_rank) + "}" if spec.array_rank else ""
    return f"{mode}{spec.type_name} {spec.name}{dims}"


def signature_text(signature: Signature) -> str:
    """The signature in the RAPID-like notation it was registered with."""
    parts: list[str] = []
    previous_group = None
    for spec in signature.parameters:
        text = parameter_text(spec)
        same_group = spec.alternative_group is not None and spec.alternative_group == previous_group
        if same_group:
            parts[-1] += " | " + text
        elif spec.optional:
            parts.append("\\" + text)
        else:
            parts.append(text)
        previous_group = spec.alternative_group
    head = f"{signature.return_type} {signature.name}" if signature.return_type else signature.name
    if signature.open_parameters:
        return f"{head}(...)"
    body = ""
    for part in parts:
        body += (" " if part.startswith("\\") and body else ", " if body else "") + part
    return f"{head}({body})"


def _cell(text: str) -> str:
    """Table cell text: a pipe would end the cell (GitHub tables take it escaped, also in code)."""
    return text.replace("|", "\\|")


def topic_summary(topic: str) -> list[str]:
    """The topic module's docstring (what it holds and how it is modelled), as a paragraph."""
    module = importlib.import_module(f"rapidmc.semantics.library.{topic}")
    text = (module.__doc__ or "").split("\n\n")
    paragraphs = [" ".join(part.split()) for part in text if part.strip()]
    paragraphs = [p for p in paragraphs if not p.startswith(("Example", ">>>"))]
    return [line for paragraph in paragraphs for line in (paragraph, "")]


def routine_sections(entries) -> list[str]:
    lines: list[str] = []
    for topic in TOPICS:
        chosen = sorted((e for e in entries if e.topic == topic), key=lambda e: e.key)
        if not chosen:
            continue
        lines += ["", f"### {topic.replace('_', ' ')}", ""]
        lines += topic_summary(topic)
        lines += ["| name | kind | signature | modelled |", "|---|---|---|---|"]
        for entry in chosen:
            kind = "function" if entry.signature.return_type else "instruction"
            lines.append(f"| {entry.signature.name} | {kind} | "
                         f"`{_cell(signature_text(entry.signature))}` | {entry.modelled} |")
    return lines


def components_text(rapid_type) -> str:
    """A record type's components, ``pos trans, orient rot, ...`` (empty for other types)."""
    if rapid_type.kind != RECORD:
        return ""
    return ", ".join(f"{c.type.name} {c.name}" for c in rapid_type.components)


def type_section() -> list[str]:
    lines = ["", "## Data types", "", "| type | kind | components or base |", "|---|---|---|"]
    for key in sorted(PREDEFINED_TYPES):
        if key in HIDDEN_TYPES:
            continue
        rapid_type = PREDEFINED_TYPES[key]
        lines.append(f"| {rapid_type.name} | {rapid_type.kind} | {components_text(rapid_type)} |")
    for key in sorted(PREDEFINED_ALIASES):
        name, base = PREDEFINED_ALIASES[key]
        lines.append(f"| {name} | alias | {base.name} |")
    return lines


def data_section() -> list[str]:
    by_type: dict[str, list[str]] = {}
    for data in PREDEFINED_DATA.values():
        by_type.setdefault(data.type_name, []).append(data.name)
    lines = ["", "## Data objects", "", "| type | names |", "|---|---|"]
    for type_name in sorted(by_type):
        lines.append(f"| {type_name} | {', '.join(by_type[type_name])} |")
    lines.append(f"| errnum | the {len(ERROR_NUMBERS)} ERR_ error numbers of "
                 "rapidmc/semantics/errors.py |")
    return lines


def figures(entries) -> list[str]:
    functions = sum(1 for e in entries if e.signature.return_type)
    instructions = len(entries) - functions
    types = len([k for k in PREDEFINED_TYPES if k not in HIDDEN_TYPES]) + len(PREDEFINED_ALIASES)
    data = len(PREDEFINED_DATA) + len(ERROR_NUMBERS)
    modelled = Counter(e.modelled for e in entries)
    lines = ["| what | how many |", "|---|---|",
             f"| instructions | {instructions} |", f"| functions | {functions} |",
             f"| data types (records, atomic, non-value, aliases) | {types} |",
             f"| data objects (constants, speeds, zones, tools, error numbers ...) | {data} |",
             "", "| routines modelled | how many |", "|---|---|"]
    lines += [f"| {how} | {modelled[how]} |" for how in MODELLED_AS if modelled[how]]
    return lines


def coverage_section() -> list[str]:
    """How many of the reference's names (docs/reference-names.txt) the library has, and
    which it lacks."""
    sections = coverage()
    lines = ["", "## Coverage of the reference", "",
             f"The names of ABB's RAPID reference listed in `docs/{REFERENCE.name}` (its header "
             "says which manual and options, and where the list comes from) against the registry "
             "(`python -m rapidmc.semantics.library.reference_coverage`).", "",
             "| section | in the reference | in the library | of them by name only | missing |",
             "|---|---|---|---|---|"]
    for section in sections:
        lines.append(f"| {section.name} | {len(section.names)} | {section.covered} | "
                     f"{len(section.name_only)} | {len(section.missing)} |")
    lines += ["", "*By name only*: no manual text or public call showed the routine's parameters, "
              "so it is registered with the signature `(...)`: programs calling it load with any "
              "arguments (not matched to parameters; undeclared names in them are reported), "
              "and reaching the call stops the run with RMC305."]
    for section in sections:
        if section.name_only:
            lines += ["", f"{section.name.capitalize()} by name only: "
                      f"{', '.join(section.name_only)}."]
        if section.missing:
            lines += ["", f"Missing {section.name}: {', '.join(section.missing)}."]
    return lines


def document() -> str:
    entries = list(all_entries())
    lines = ["# The predefined library", "",
             "Generated from the registry (`rapidmc/semantics/library`) by "
             "`python -m rapidmc.semantics.library.documentation`; a test keeps it in step. How a routine is "
             "modelled: **exact** (the documented result or effect), **nondeterministic "
             "outcomes** (the controller or the world decides: every outcome is a choice when "
             "model checking, stdin answers in `run`), **robot state only** (the modelled "
             "position, tool or work object changes), **fixed value** (a controller-dependent "
             "result, one fixed value), **no effect** (checked against its signature, changes "
             "nothing rapidmc observes), **stops the run: not modelled** (the program loads; "
             "reaching the call stops with RMC305).", ""]
    lines += figures(entries)
    lines += coverage_section()
    lines += ["", "## Routines by topic"]
    lines += routine_sections(entries)
    lines += type_section()
    lines += data_section()
    return "\n".join(lines) + "\n"


def main(argv: list[str]) -> int:
    return write_or_check(DOC, document(), "rapidmc.semantics.library.documentation", argv)


def write_or_check(page: Path, text: str, module: str, argv: list[str]) -> int:
    """A generated page's command: write ``text`` to ``page``, or with ``--check`` exit 1
    when the page differs from it (docs/lint.md's generator uses it too)."""
    if "--check" in argv:
        current = page.read_text(encoding="utf-8") if page.exists() else ""
        if current != text:
            print(f"{page} is out of date: run python -m {module}", file=sys.stderr)
            return 1
        return 0
    page.write_text(text, encoding="utf-8")
    print(f"wrote {page}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
