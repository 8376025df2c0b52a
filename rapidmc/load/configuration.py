"""A backup's configuration files (SYSPAR/*.cfg) as the database ReadCfgData reads.

A configuration file opens with its domain (``MOC:CFG_1.0:6:0::``); each type
is a line ``TYPE:`` and each instance a group of ``-attribute value`` pairs,
continued over lines ending in a backslash, instances apart by blank lines::

    ARM:

          -name "rob1_1" -use_arm_type "ROB1_1" -upper_joint_bound 2.44347\\
          -lower_joint_bound -2.44347

A flag written without a value (``-valid_com_offset``) reads TRUE.  Which
instances the files give, and what rapidmc assumes without them, is
``semantics.library.configuration``.
"""
from __future__ import annotations

import re
from pathlib import Path
from typing import Iterator, Optional

from ..semantics.library.configuration import Configuration
from .config_file import logical_lines

_DOMAIN = re.compile(r"^([A-Z]+):CFG_")
_TYPE = re.compile(r"^([A-Za-z0-9_]+):$")
_TOKEN = re.compile(r'"([^"]*)"|(\S+)')


def read_configuration(syspar: Optional[Path]) -> Optional[Configuration]:
    """The instances of every ``*.cfg`` in a backup's SYSPAR folder (None without one)."""
    if syspar is None or not syspar.is_dir():
        return None
    configuration = Configuration()
    for file in sorted(syspar.iterdir()):
        if file.is_file() and file.suffix.lower() == ".cfg":
            read_file(file.read_bytes().decode("latin-1"), configuration)
    return configuration


def read_file(text: str, configuration: Configuration) -> None:
    """Add the instances of one configuration file's text."""
    lines = [line for _, line in logical_lines(text)]
    match = _DOMAIN.match(lines[0].strip()) if lines else None
    if match is None:
        return
    types = configuration.domains.setdefault(match.group(1), {})
    current: Optional[list] = None
    for line in lines[1:]:
        stripped = line.strip()
        if not stripped or stripped.startswith("#"):
            continue
        heading = _TYPE.match(stripped)
        if heading is not None:
            current = types.setdefault(heading.group(1).upper(), [])
        elif current is not None and stripped.startswith("-"):
            current.append(dict(attributes(stripped)))


def attributes(line: str) -> Iterator[tuple[str, object]]:
    """``-name "rob1_1" -valid_com_offset -lower_joint_bound -2.4`` -> (name, text) pairs;
    TRUE for a flag; a negative number is a value, not an attribute."""
    name: Optional[str] = None
    for match in _TOKEN.finditer(line):
        quoted, bare = match.group(1), match.group(2)
        if bare is not None and re.fullmatch(r"-[A-Za-z_]\w*", bare):
            if name is not None:
                yield name, True
            name = bare[1:].lower()
        elif name is not None:
            yield name, quoted if quoted is not None else bare
            name = None
    if name is not None:
        yield name, True
