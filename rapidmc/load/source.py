"""Reading RAPID source files: Latin-1 or UTF-8 text, with every failure a diagnostic.

A file is refused (with its own diagnostic code) when it does not exist, is
a directory, cannot be read, is larger than ``MAX_FILE_BYTES`` (8 MiB: well
above hand-written modules, some 150,000 lines; the parser manages some
60,000 lines a second), is an encrypted module (first byte 0xF0-0xFF), or is binary (NUL bytes or many
control characters).  A ``.pgf`` program file is an XML list of
``<Module>name.mod</Module>`` entries, relative to the ``.pgf`` itself; it
stands for those modules.

Example::

    >>> program_paths(["cell.pgf"])        # doctest: +SKIP
    ['MainModule.mod', 'Sorter.mod']
"""
from __future__ import annotations

import os
import xml.etree.ElementTree as ElementTree

from ..diagnostics import (FILE_BINARY, FILE_EMPTY, FILE_ENCRYPTED, FILE_IS_DIRECTORY,
                          FILE_NOT_FOUND, FILE_TOO_LARGE, FILE_UNREADABLE, PROGRAM_FILE,
                          SourceCache, error)

MAX_FILE_BYTES = 8 * 1024 * 1024
PROGRAM_FILE_SUFFIX = ".pgf"
UTF8_BOM = b"\xef\xbb\xbf"
# Control characters that ordinary text files contain.
TEXT_CONTROLS = frozenset(b"\t\n\r\f\v\x1a")
# Share of other control characters (in the first block) that marks a binary file.
BINARY_CONTROL_SHARE = 0.05
SNIFF_BYTES = 8192


def read_source(path: str) -> str:
    """The text of a RAPID source file, remembered for diagnostics."""
    data = read_bytes(path)
    text = decode_source(data, path)
    SourceCache.remember(path, text)
    return text


def read_bytes(path: str) -> bytes:
    """The raw content of ``path``; missing, directory, unreadable, huge: diagnostics."""
    if not os.path.exists(path):
        raise error(FILE_NOT_FOUND, f"no such file: '{path}'")
    if os.path.isdir(path):
        raise error(FILE_IS_DIRECTORY, f"'{path}' is a directory, not a RAPID file")
    try:
        size = os.path.getsize(path)
        if size > MAX_FILE_BYTES:
            raise error(FILE_TOO_LARGE, f"'{path}' has {size} bytes; the limit is "
                        f"{MAX_FILE_BYTES} bytes")
        with open(path, "rb") as stream:
            return stream.read()
    except OSError as exc:
        raise error(FILE_UNREADABLE, f"cannot read '{path}': {exc.strerror or exc}") from None


def decode_source(data: bytes, path: str) -> str:
    """Bytes to text: Latin-1 (RobotWare's ISO 8859-1), or UTF-8 when the file starts
    with a UTF-8 BOM or, without one, is valid UTF-8 with some non-ASCII character
    (files of RobotWare 7 and of today's editors; Latin-1 text with accented letters
    is practically never valid UTF-8)."""
    if not data.strip():
        raise error(FILE_EMPTY, f"'{path}' is empty")
    if data[0] >= 0xF0:
        raise error(FILE_ENCRYPTED, f"'{path}' is an encrypted module; it cannot be analysed",
                    None, "to analyse the rest of the task, give its other modules as files "
                    "and 'rapidmc stubs' a module declaring what the program uses from this one")
    if is_binary(data):
        raise error(FILE_BINARY, f"'{path}' is a binary file, not RAPID source text")
    if data.startswith(UTF8_BOM):
        try:
            return data[len(UTF8_BOM):].decode("utf-8")
        except UnicodeDecodeError:
            return data[len(UTF8_BOM):].decode("latin-1")
    if not data.isascii():
        try:
            return data.decode("utf-8")
        except UnicodeDecodeError:
            pass
    return data.decode("latin-1")


def is_binary(data: bytes) -> bool:
    """Whether ``data`` looks like a binary file rather than text."""
    if b"\0" in data:
        return True
    head = data[:SNIFF_BYTES]
    controls = sum(1 for byte in head if byte < 0x20 and byte not in TEXT_CONTROLS)
    return controls > BINARY_CONTROL_SHARE * len(head)


def program_paths(paths: list[str]) -> list[str]:
    """The module files named by ``paths``, with each ``.pgf`` expanded in place."""
    result: list[str] = []
    for path in paths:
        if path.lower().endswith(PROGRAM_FILE_SUFFIX):
            result.extend(program_file_modules(path))
        else:
            result.append(path)
    return result


def program_file_modules(path: str) -> list[str]:
    """The module paths listed in a ``.pgf`` program file, relative to its folder."""
    data = read_bytes(path)
    decode_source(data, path)  # refuses empty, binary and encrypted files
    try:
        root = ElementTree.fromstring(data)
    except ElementTree.ParseError as exc:
        raise error(PROGRAM_FILE, f"'{path}' is not a valid program file: {exc}") from None
    folder = os.path.dirname(path)
    names = [(element.text or "").strip() for element in root.iter() if element.tag == "Module"]
    if not names:
        raise error(PROGRAM_FILE, f"program file '{path}' lists no <Module> entries")
    modules = []
    for name in names:
        module_path = os.path.join(folder, name)
        if not os.path.isfile(module_path):
            raise error(PROGRAM_FILE, f"program file '{path}' names module '{name}', "
                        f"but '{module_path}' does not exist")
        modules.append(module_path)
    return modules
