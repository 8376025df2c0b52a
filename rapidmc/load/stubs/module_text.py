"""The RAPID module that declares the missing names (``rapidmc stubs``).

Data become PERS with neutral values (0, FALSE, "", the identity rotation,
``9E9`` for unused external axes, ``tool0``/``wobj0``/``load0`` for tools,
work objects and loads), or CONST when a declaration's value or size needs
them; data of non-value types (``iodev``, ``clock`` ...) become VAR.
Routines get empty bodies (a function returns a neutral value).  Every
declaration follows a comment naming its first use; a name whose type the
uses do not tell gets a comment instead of a declaration.
"""
from __future__ import annotations

from pathlib import Path
from typing import Optional

from ...diagnostics import SourceCache
from ...semantics.link import MAX_DIMENSION
from ...semantics.library.data import PREDEFINED_DATA
from ...semantics.types import NON_VALUE, PREDEFINED_ALIASES, PREDEFINED_TYPES, SEMI_VALUE
from .inference import DATA, FUNCTION, PROCEDURE, TRAP, TYPE, Missing
from .names import Declarations, TypeInfo

# Types whose neutral value is a predefined data object's: a tool, a work object and a load
# that change nothing, a moderate speed, a fine point.
KNOWN_VALUES = {"TOOLDATA": "tool0", "WOBJDATA": "wobj0", "LOADDATA": "load0",
                "SPEEDDATA": "v100", "ZONEDATA": "fine"}
MIN_ARRAY_SIZE = 10
UNUSED_AXIS = 9e9
MAX_ARRAY_LITERAL = 1000
# neutral values that are also what a declaration without a value starts with
DEFAULT_VALUE_TEXTS = ("0", "FALSE", '""')
# The header comment that marks a module as written by ``rapidmc stubs``: findings.assumptions
# recognises stub declarations by it, and a trace names the values they give.
STUB_MARKER = "Declarations written by 'rapidmc stubs'"


def is_stub_module(file: Optional[str]) -> bool:
    """Whether ``file`` (read before, so remembered by SourceCache) is a module ``rapidmc
    stubs`` wrote: its marker is on one of its first three lines."""
    lines = SourceCache.lines(file) if file else None
    return any(STUB_MARKER in line for line in (lines or ())[:3])


def number_text(value: float) -> str:
    if value == int(value) and abs(value) < 1e7:
        return str(int(value))
    return format(value, "G")


def value_text(value) -> str:
    """A Python value of rapidmc's representation as a RAPID literal."""
    if isinstance(value, bool):
        return "TRUE" if value else "FALSE"
    if isinstance(value, str):
        return '"' + value.replace('"', '""') + '"'
    if isinstance(value, tuple):
        return "[" + ",".join(value_text(v) for v in value) + "]"
    return number_text(float(value))


class Neutral:
    """Neutral literals of RAPID types (predefined and the program's own records)."""

    def __init__(self, names: Declarations, records: Optional[dict] = None):
        self.names = names
        # the RECORDs the stubs declare themselves: key -> [(component, type)]
        self.records = records or {}
        self.aliases: dict[str, str] = {}        # ALIASes the stubs declare: key -> base key

    def components(self, type_name: str) -> Optional[list[tuple[str, str]]]:
        found = self.names.components(type_name)
        return found if found is not None else self.records.get(type_name.upper())

    def literal(self, type_name: str) -> Optional[str]:
        """A neutral value of the type, or None for non-value types and unknown ones."""
        key = self.names.base(TypeInfo(type_name)).key
        key = self.aliases.get(key, key)
        if key in PREDEFINED_ALIASES:
            key = PREDEFINED_ALIASES[key][1].key
        if key in KNOWN_VALUES:
            return value_text(PREDEFINED_DATA[KNOWN_VALUES[key].upper()].value)
        if key in ("NUM", "DNUM"):
            return "0"
        if key == "BOOL":
            return "FALSE"
        if key == "STRING":
            return '""'
        if key == "ORIENT":
            return "[1,0,0,0]"
        if key == "EXTJOINT":
            return "[" + ",".join([number_text(UNUSED_AXIS)] * 6) + "]"
        components = self.components(type_name)
        if not components:
            return None
        parts = [self.literal(component_type) for _, component_type in components]
        return None if None in parts else "[" + ",".join(parts) + "]"

    def is_value_type(self, type_name: str) -> bool:
        key = self.names.base(TypeInfo(type_name)).key
        found = PREDEFINED_TYPES.get(key)
        return found is None or found.kind not in (NON_VALUE, SEMI_VALUE)


def array_literal(element: str, dims: list[int], separator: str = ",\n    ") -> str:
    """The array value, one element (or row) per line when elements are long."""
    if len(element) * dims[-1] < 60:
        separator = ","
    if len(dims) == 1:
        return "[" + separator.join([element] * dims[0]) + "]"
    inner = array_literal(element, dims[1:], ",")
    return "[" + separator.join([inner] * dims[0]) + "]"


def where(missing: Missing) -> str:
    span = missing.first_use
    return f"{Path(span.file).name}:{span.line}:{span.column}"



class StubWriter:
    """Renders the missing names as declarations of one module."""

    def __init__(self, names: Declarations):
        self.neutral = Neutral(names)
        self.declared: list[Missing] = []
        self.undeclared: list[Missing] = []
        self.too_large: set = set()        # ids of the undeclared arrays too large to write

    def module(self, module_name: str, missing: list[Missing]) -> str:
        self.neutral.records = {item.name.key: record_components(item)
                                for item in missing if item.kind == TYPE and not item.alias_of}
        self.neutral.aliases = {item.name.key: item.alias_of.upper()
                                for item in missing if item.kind == TYPE and item.alias_of}
        lines = [f"MODULE {module_name}",
                 f"  ! {STUB_MARKER} for the names the program uses and no module declares.",
                 "  ! Types come from the uses; values are neutral: replace them with the "
                 "cell's real data."]
        order = [TYPE, DATA, PROCEDURE, FUNCTION, TRAP]
        for kind in order:
            for item in (m for m in missing if m.kind == kind):
                lines.append("")
                lines.extend("  " + line for line in self.declaration(item))
        lines.append("ENDMODULE")
        return "\n".join(lines) + "\n"

    def declaration(self, item: Missing) -> list[str]:
        text = getattr(self, "_" + item.kind)(item)
        if text is None:
            self.undeclared.append(item)
            if id(item) in self.too_large:
                return [f"! {item.name.text}: first use {where(item)} ({item.use}); an array of "
                        f"more than {MAX_ARRAY_LITERAL} elements of {item.type.name}, too large "
                        "for a written value: declare it here"]
            return [f"! {item.name.text}: first use {where(item)} ({item.use}); its type could "
                    "not be inferred from its uses: declare it here"]
        self.declared.append(item)
        return [f"! {item.name.text}: first use {where(item)} ({item.use})"] + text

    def _data(self, item: Missing) -> Optional[list[str]]:
        if item.type is None:
            return None
        type_name = item.type.name
        sizes = list(item.dims) if item.exact_dims else [max(d, MIN_ARRAY_SIZE) for d in item.dims]
        dims = "{" + ",".join(str(d) for d in sizes) + "}" if sizes else ""
        notes = [f"type from: {item.evidence}"] if item.evidence and item.evidence != item.use \
            else []
        if not self.neutral.is_value_type(type_name):
            return [f"VAR {type_name} {item.name.text}{dims};" + _comment(notes)]
        value = self.neutral.literal(type_name)
        if value is None:
            return None
        if _size(sizes) > MAX_ARRAY_LITERAL:
            return self._large_array(item, type_name, sizes, dims, value, notes)
        if sizes:
            value = array_literal(value, sizes)
            notes.append(f"an array argument: size {MIN_ARRAY_SIZE} assumed" if item.array_argument
                         else "size: the elements of the aggregate assigned" if item.exact_dims
                         else f"size: the largest constant index or FOR bound used, at least "
                         f"{MIN_ARRAY_SIZE}")
        if item.sizes_array and item.array_size is not None:
            size, array = item.array_size
            value = str(size)
            notes.append(f"an array size: {size}, as in the value declared for {array}")
        elif item.sizes_array:
            value = str(MIN_ARRAY_SIZE)
            notes.append(f"an array size: {MIN_ARRAY_SIZE} assumed")
        elif item.indexes_array and not sizes and type_name == "num":
            value = "1"
            notes.append("an array index: 1, the first element (RAPID arrays start at 1)")
        elif item.alternative and not sizes and type_name == "num":
            number, count = item.alternative
            value = str(number)
            notes.append(f"{number} of the {count} names one value is compared with in turn")
        storage = "VAR" if item.storage == "VAR" else \
            "CONST" if item.storage == "CONST" and not item.assigned else "PERS"
        if storage == "PERS" and item.valued_by:     # the one value of a PERS tasks share
            notes = [f"its value: the declaration in {item.valued_by}, of another task"]
            return [f"PERS {type_name} {item.name.text}{dims};" + _comment(notes)]
        return [f"{storage} {type_name} {item.name.text}{dims} := {value};" + _comment(notes)]

    def _large_array(self, item: Missing, type_name: str, sizes: list, dims: str,
                     value: str, notes: list) -> Optional[list[str]]:
        """An array too large for a written value: declared without one where its elements'
        default (zero, FALSE, empty) is the neutral value, as a VAR (a PERS declared
        without a value would count as data written outside, ``load.outside_data``);
        else left to the user (``too_large``)."""
        if value not in DEFAULT_VALUE_TEXTS or item.storage == "CONST" or \
                _size(sizes) > MAX_DIMENSION:     # (an index far beyond any real array)
            self.too_large.add(id(item))
            return None
        notes.append(f"more than {MAX_ARRAY_LITERAL} elements: declared without a value, "
                     f"each element starts at {value}")
        return [f"VAR {type_name} {item.name.text}{dims};" + _comment(notes)]

    def _parameters(self, item: Missing) -> tuple[str, list[str]]:
        texts, guessed = [], []
        for parameter in item.parameters:
            if parameter.switch:
                texts.append(f"\\switch {parameter.name}")
                continue
            info = parameter.type
            if info is None or parameter.assumed:
                guessed.append(parameter.name)
            type_name, rank = (info.name, info.rank) if info is not None else ("num", 0)
            mode = "" if self.neutral.is_value_type(type_name) else "VAR "
            array = "{" + ",".join("*" * rank) + "}" if rank else ""
            optional = "\\" if parameter.optional else ""
            texts.append(f"{optional}{mode}{type_name} {parameter.name}{array}")
        notes = [f"! parameter types not inferred ({', '.join(guessed)}): num assumed"] \
            if guessed else []
        return ", ".join(texts), notes

    def _procedure(self, item: Missing) -> list[str]:
        parameters, notes = self._parameters(item)
        return notes + [f"PROC {item.name.text}({parameters})", "ENDPROC"]

    def _function(self, item: Missing) -> Optional[list[str]]:
        if item.type is None:
            return None
        own_record = item.type.key in self.neutral.records
        value = None if own_record else self.neutral.literal(item.type.name)
        parameters, notes = self._parameters(item)
        head = f"FUNC {item.type.name} {item.name.text}({parameters})"
        if value is None:       # no literal for it (a record the stubs declare): a local
            return notes + [head, f"  VAR {item.type.name} result;", "  RETURN result;",
                            "ENDFUNC"]
        return notes + [head, f"  RETURN {value};", "ENDFUNC"]

    def _trap(self, item: Missing) -> list[str]:
        return [f"TRAP {item.name.text}", "ENDTRAP"]

    def _type(self, item: Missing) -> list[str]:
        if item.alias_of:
            return ["! declared or assigned with a value of that type", f"ALIAS {item.alias_of} {item.name.text};"]
        if not item.fields:
            return ["! its components are not known: one num component stands in for them",
                    f"RECORD {item.name.text}", "  num value;", "ENDRECORD"]
        guessed = [name for name, info in item.fields.items()
                   if info is None or name in item.assumed]
        notes = [f"! component types not inferred ({', '.join(guessed)}): num assumed"] \
            if guessed else []
        if item.left_out:
            them = "it" if len(item.left_out) == 1 else "them"
            notes.append(f"! the value declared has no place for {', '.join(item.left_out)}, "
                         f"which the uses also name: declare {them} here")
        components = [f"  {type_name} {name};" for name, type_name in record_components(item)]
        return notes + [f"RECORD {item.name.text}"] + components + ["ENDRECORD"]


def record_components(item: Missing) -> list[tuple[str, str]]:
    """The components a RECORD of the stubs declares (num where the uses tell nothing)."""
    if not item.fields:
        return [("value", "num")]
    return [(name, info.name if info else "num") for name, info in item.fields.items()]


def _comment(notes: list[str]) -> str:
    return " ! " + "; ".join(notes) if notes else ""


def _size(dims: list[int]) -> int:
    size = 1
    for dim in dims:
        size *= dim
    return size
