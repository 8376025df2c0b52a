"""What every written form of a counterexample shares: the options, how a file and a long
value are shown, and which datum a shown name is about.

``counterexample`` (the steps), ``headline`` (the error and the data its line reads), SARIF
and JSON write a trace with these.

    >>> shorten("[[932.4,1557.5,2189.5],[1,0,0,0],[1,1,0,0]]", 30)
    '[[932.4,1557.5,2189.5],...]'
"""
from __future__ import annotations

import os
import re
from dataclasses import dataclass, field
from typing import Mapping, Optional, Sequence

from ..check.trace import TransitionInfo

WIDTH = 100            # a value's text in a step, at most (then shortened)
STRING_WIDTH = 48      # a string value's, at most (then shortened, with its length)
WAS_WIDTH = 60         # the previous value beside it
SOURCE_WIDTH = 160     # a source line or FlexPendant output
IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
INDEX = re.compile(r"\{[^}]*\}")
SHORT_PATH = 40        # a file relative to the common folder, at most, to be named so


# --- files ---------------------------------------------------------------------------


@dataclass(frozen=True)
class FileNames:
    """How a report names files: relative to ``root`` (named once above the steps when
    ``announced``), or by their base names with each folder of ``folders`` (``(folder,
    (name, ...))``) named once; as given when neither."""

    root: str = ""
    announced: bool = False
    folders: tuple[tuple[str, tuple[str, ...]], ...] = ()

    def shown(self, file: str) -> str:
        """The name ``file`` is shown by."""
        if self.folders:
            return os.path.basename(file)
        if self.root:
            return os.path.relpath(os.path.abspath(file), self.root)
        return file

    def legend(self) -> list[str]:
        """The lines that name the folders, once: ``(files relative to /backups/cell_3)``,
        ``(files in /work/cell: prog.mod; in /tmp/stubs: Missing.mod)``."""
        if self.folders:
            return ["(files in " + "; in ".join(f"{folder}: {', '.join(names)}"
                                                 for folder, names in self.folders) + ")"]
        if not self.announced:
            return []
        here = os.getcwd()
        root = (os.path.relpath(self.root, here)
                if os.path.commonpath([here, self.root]) == here else self.root)
        return [f"(files relative to {root})"]


def file_names(files: Sequence[str]) -> FileNames:
    """How to name ``files`` briefly: relative to the current folder when it holds them all
    and that leaves each at most ``SHORT_PATH`` characters (a backup below the current
    folder would repeat its folders at every step); else relative to the deepest folder that holds them all, named once, when that leaves
    each at most ``SHORT_PATH`` characters; else by base name, each folder named once, when
    no two share one; else relative to the common folder (as given when that is only the
    file system's root)."""
    absolute = list(dict.fromkeys(os.path.abspath(file) for file in files))
    if not absolute:
        return FileNames()
    here = os.getcwd()
    if all(os.path.commonpath([here, file]) == here
           and len(os.path.relpath(file, here)) <= SHORT_PATH for file in absolute):
        return FileNames(here)
    try:
        common = os.path.commonpath([os.path.dirname(file) for file in absolute])
    except ValueError:                         # different drives
        common = ""
    deep = bool(common) and common != os.path.dirname(common)  # more than the root
    if deep and all(len(os.path.relpath(file, common)) <= SHORT_PATH for file in absolute):
        return FileNames(common, True)
    names = [os.path.basename(file) for file in absolute]
    if len(set(names)) == len(names):
        folders: dict[str, list[str]] = {}
        for file in absolute:
            folders.setdefault(os.path.dirname(file), []).append(os.path.basename(file))
        return FileNames(folders=tuple((folder, tuple(names))
                                       for folder, names in folders.items()))
    return FileNames(common, True) if deep else FileNames()


def shown_location(transition: TransitionInfo, files: FileNames) -> str:
    """``file:line`` with the file named as ``files`` says."""
    location = transition.location
    if not transition.file:
        return location
    return files.shown(transition.file) + location[len(transition.file):]


@dataclass(frozen=True)
class TextOptions:
    """How a counterexample is written: ``full`` (nothing left out), the property's ``names``
    (upper case: the initial state shows them) and the ``stub_data`` (a stub module's data)."""

    full: bool = False
    names: frozenset = frozenset()
    stub_data: frozenset = frozenset()
    files: FileNames = FileNames()        # how files are named
    handler_starts: frozenset = frozenset()   # (file, line) of each ERROR handler's start
    # (file, line) of an IF/FOR/WHILE/TEST -> (its last line, (file, line) of the statement
    # after it): ``RapidDescriber.compound_exits``
    compound_exits: Mapping = field(default_factory=dict)


# --- names ---------------------------------------------------------------------------


def data_names(name: str) -> tuple[str, ...]:
    """The identifiers a shown name may be about, upper case.

    ``main.reg1{2}`` is routine data (``REG1``) and ``pose.trans`` a record's
    component (``POSE``): a shown name does not say which, so both are given.
    """
    if name.startswith("signal "):
        name = name[len("signal "):]
    return tuple(part.upper() for part in INDEX.sub("", name).split(".")[:2])


def datum_of(name: str, words: Sequence[str]) -> str:
    """Which datum a shown name is about, given the ``words`` of a line: ``waypoints{2}.trans``
    is about WAYPOINTS when the line names it, ``main.i`` about I (MAIN is no datum there)."""
    parts = data_names(name)
    return parts[0] if parts[0] in words or len(parts) == 1 else parts[1]


# --- shortening --------------------------------------------------------------------


def shorten(text: str, width: Optional[int]) -> str:
    """``text`` cut to at most ``width`` characters at an element boundary, ending in ``...``.

    An aggregate keeps its first elements and its closing brackets
    (``[[932.4,1557.5,2189.5],...]``); a string keeps its closing quote.
    """
    if width is None or len(text) <= width:
        return text
    depth, quoted, cut, cut_depth = 0, False, -1, 0
    for position, char in enumerate(text[:width]):
        if char == '"':
            quoted = not quoted
        elif quoted:
            continue
        elif char == "[":
            depth += 1
        elif char == "]":
            depth -= 1
        elif char == "," and position + 4 + depth <= width:    # room for "..." and "]"s
            cut, cut_depth = position, depth
    if cut > 0:
        return text[:cut + 1] + "..." + "]" * cut_depth
    if quoted or text.startswith('"'):
        return text[:width - 4] + '..."'
    return text[:width - 3] + "..."


def shown_value(text: str, width: Optional[int], string_width: Optional[int] = None) -> str:
    """``text`` shortened to ``width`` (a string value to ``string_width``, when given),
    saying how long the whole is: an array's element count, a string's length; an array
    whose elements are all one value shows the first (``[0,...] (120 elements, all 0)``,
    ``(512 elements, all equal)`` when that value is long).

    >>> shown_value('"The gripper reported a fault at station four"', 100, 24)
    '"The gripper reporte..." (44 characters)'
    """
    string = len(text) >= 2 and text[0] == text[-1] == '"' and not getattr(text, "parts", ())
    short = shorten(text, string_width if string and string_width else width)
    if short == text:
        return text
    if string:
        return f"{short} ({string_length(text)} characters)"
    elements = array_elements(text)
    if not elements:
        return short
    depth = len(text) - len(text.lstrip("["))     # a matrix's first element is nested
    room = len(elements[0][1]) + 2 * depth + 4      # "[[" element ",...]]"
    if len({value for _, value in elements}) == 1 and room < len(short):
        # every element says the same: the first one is enough ("[0,...]", "[[0,...]]")
        first = shorten(text, room)
        same = elements[0][1] if len(elements[0][1]) <= width // 4 else "equal"
        return f"{first} ({len(elements)} elements, all {same})"
    return f"{short} ({len(elements)} elements)"


def string_length(literal: str) -> int:
    """The length of the string a RAPID string literal writes (``""`` and ``\\\\`` are one)."""
    return len(literal[1:-1].replace('""', '"').replace("\\\\", "\\"))


def array_elements(value: str) -> tuple[tuple[str, str], ...]:
    """The ``({i}, value)`` parts of an array value; none for any other value."""
    parts = getattr(value, "parts", ())
    return parts if parts and all(suffix.startswith("{") for suffix, _ in parts) else ()
