"""Default message domains of socket receives, taken from what the program does with the data.

A socket message may be any text; the checker offers each ``SocketReceive``
(and ``SocketReceiveFrom``) a finite set.  Without ``--socket-messages`` that
set comes from the code that handles the received data.  Starting from the
receive's ``\\Str`` or ``\\RawData`` variable, the data is followed through
assignments (``cmd := StrPart(msg, 1, 3)``), routine parameters and function
results; every place it reaches that chooses between branches gives messages:

* a comparison with a string (``=``, ``<>``, ``TEST ... CASE "PNP":``) gives
  that string, placed where the compared value was taken from the message
  (``StrPart(msg, 4, 3) = "ABC"``: ``"   ABC"``);
* ``StrFind``/``StrMatch`` give a message holding the characters or pattern
  they look for;
* a field of a message split into a string array (``parts{2}``) gives the
  fields joined by the separator sought (one a caller passes counts), those
  the enclosing branches compare holding their texts (``F|SM|[1,2,3]``);
* a comparison of the message's length (``StrLen(msg) > 72``) gives a message
  one character longer than the number;
* ``StrToVal`` gives a well-formed text of the target's type (``[1,2,3,4,5]``
  for a ``num{5}``) and a malformed one;
* ``UnpackRawBytes`` of a received ``rawbytes`` gives, per field the code
  compares with numbers, one message per class of those comparisons (the
  field encoded at its start index, hex pairs as ``--socket-messages`` takes),
  and per string compared with characters unpacked with ``\\ASCII:=n`` (n
  characters long), one message holding it there.

One message the program does not expect (no literal of it) is always added.
The domain is *exact* (every message the peer could send behaves like one of
those tried) only when the received text reaches nothing but equality
comparisons with strings; otherwise coverage warnings say that they hold for
the messages tried (``findings.coverage``).  ``--socket-messages`` replaces
every derived domain.  Closures and timeouts are modelled as before.
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Iterator, Optional

from .. import ast
from ..diagnostics import DOMAIN_ASSUMED, Diagnostic
from ..diagnostics.quoting import quoted
from ..semantics import rawbytes
from ..semantics.errors import RapidError
from ..semantics.literals import parse_literal
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program
from ..semantics.scope import CONSTANT, GLOBAL_DATA
from ..semantics.types import BOOL, RECORD, STRING, ArrayType, default_value
from ..semantics.values import format_num
from .call_graph import called_routine, called_routines
from .input_domains import analog_points, group_points, number_value
from .run_time_offsets import SEQUENCE, walked_starts

MAX_MESSAGES = 24             # per receiving site: the search branches over every one
MAX_COMBINATIONS = 4096       # of all sites' values, before sites that only parse are narrowed
RECEIVES = {"SOCKETRECEIVE": "SocketReceive", "SOCKETRECEIVEFROM": "SocketReceiveFrom"}
EQUALITY = ("=", "<>")
NUMBER_COMPARISONS = ("=", "<>", "<", "<=", ">", ">=")
UNEXPECTED = "?"              # the text a peer sends that no code of the program expects
FILLER = " "                  # what stands before a compared part of a message
MALFORMED = "#"               # text no StrToVal target type accepts
FILLER_LETTER = "a"           # what a message of a given length holds

IDENTITY = ("whole",)         # how a value was taken from the message
LENGTH = ("length",)          # the message's length (StrLen of the whole message)
COUNT = ("count",)            # a number of fields: counted in a loop over the message
SCANS = ("STRFIND", "STRMATCH", "STRPART", "STRTOVAL")   # what a loop over fields does
BRACKETS = {"[": "]", "(": ")", "{": "}", "<": ">"}   # around a list the code reads
TEXT_LIMIT = 80               # characters a string holds (a longer message is cut)
MAX_FIELDS = 16               # the fields of a split message a use may name (parts{16})
MAX_PROBES = 128              # per receiving site: each is one small search for coverage
MAX_VARIANTS = 16             # per command, the fields' values a probe tries together
MAX_CUT = 32                  # probes for the values the domain's cap leaves out
MAX_SEQUENCES = 16            # probes of two commands, the first writing what the second reads
PROBE_STATES = 20000          # states a probe's search may visit (its lines count even so)
ZEROS_SHOWN = 8               # bytes 0 a note shows one by one at a message's end


def site_key(span: ast.Span) -> tuple:
    """How the checker's configuration names a receiving site."""
    return (span.file, span.line, span.column)


@dataclass(frozen=True)
class MessageDomain:
    """The values offered to one reading site, and why."""

    site: ast.Span
    instruction: str              # "SocketReceive", "ReadStr", "TPReadNum"
    kind: str                     # SOCKET, FILE or ANSWERS: which domain of the check
    messages: tuple               # texts (hex pairs for a rawbytes receive), or numbers
    exact: bool                   # every possible value behaves like one of these
    reason: str                   # what the data read is compared with or parsed as
    narrower: tuple = ()          # fewer messages, when the sites' domains multiply too far
    probes: tuple = ()            # messages tried one at a time, for coverage only
    raw: bool = False             # messages of bytes, written as hex pairs

    def note(self) -> Diagnostic:
        shown = ", ".join(self._shown(value) if isinstance(value, str) else format_num(value)
                          for value in self.messages)
        probed = ""
        if self.probes:
            probed = (f"; for coverage also each of {len(self.probes)} messages alone: "
                      + ", ".join(map(self._shown, self.probes[:4]))
                      + (", ..." if len(self.probes) > 4 else ""))
        return Diagnostic(DOMAIN_ASSUMED, f"{self.instruction} at line {self.site.line}: "
                          f"{self.kind} {shown} ({self.reason}){probed}", self.site,
                          severity="note")

    def _shown(self, text) -> str:
        """``text`` quoted; a message of bytes ending in more than ``ZEROS_SHOWN`` bytes 0
        as its other bytes and their count (``'01 00 00 00' and 92 bytes 00``); a pair of
        messages offered together as both (``'30 1 1 1 1 1 1 1 #' with '33 #'``)."""
        if isinstance(text, tuple):
            return " with ".join(map(self._shown, text))
        if not self.raw:
            return _with_runs_counted(text)
        pairs = text.split(" ")
        kept = len(pairs)
        while kept and pairs[kept - 1] == "00":
            kept -= 1
        zeros = len(pairs) - kept
        if zeros <= ZEROS_SHOWN:
            return quoted(text)
        return (quoted(" ".join(pairs[:kept])) + " and " if kept else "") + f"{zeros} bytes 00"


def _with_runs_counted(text: str) -> str:
    """``text`` quoted, its longest run of more than ``RUN_SHOWN`` equal fields (a list of
    forty numbers ``1``) shown as two of them, an ellipsis and the last, with the count:
    ``'1,1,...,1,?' (39 x '1')``."""
    best = None                            # (run length, separator, first field's place)
    for separator in FIELD_SEPARATORS:
        fields = text.split(separator)
        start = 0
        for end in range(1, len(fields) + 1):
            if end == len(fields) or fields[end] != fields[start]:
                if end - start > RUN_SHOWN and (best is None or end - start > best[0]):
                    best = (end - start, separator, start)
                start = end
    if best is None:
        return quoted(text)
    run, separator, start = best
    fields = text.split(separator)
    field = fields[start]
    shown = fields[:start] + [field, field, "...", field] + fields[start + run:]
    return f"{quoted(separator.join(shown))} ({run} x {quoted(field)})"


FIELD_SEPARATORS = (",", ";", "|", " ")
RUN_SHOWN = 8                 # equal fields in a row a note shows one by one

SOCKET, FILE, ANSWERS = "messages", "lines", "answers"
TEXT_FILES = {"READSTR": "ReadStr"}
NUMBER_FILES = {"READNUM": "ReadNum"}
NUMBER_ANSWERS = {"TPREADNUM": "TPReadNum", "TPREADDNUM": "TPReadDnum"}


def message_domains(program: Program) -> tuple:
    """A ``MessageDomain`` per reading site of the program's own code, in source order:
    socket receives, ``x := ReadStr(...)`` / ``x := ReadNum(...)``, ``TPReadNum``."""
    found = []
    shared = _Walked(program)
    for routines in task_routines(program):       # each task's code apart: names are its own
        for routine in routines:
            for node, _ in shared.nodes(routine):
                domain = _site_domain(program, routines, node, routine.ast, shared)
                if domain is not None:
                    found.append(domain)
    return tuple(sorted(_bounded(found), key=lambda d: (d.site.file, d.site.line,
                                                         d.site.column)))


def _bounded(domains: list) -> list:
    """The domains, those with a narrower choice narrowed when together they would offer
    more than ``MAX_COMBINATIONS`` combinations (each received value may stay in the state,
    so the state space grows with their product)."""
    combinations = 1
    for domain in domains:
        combinations *= len(domain.messages) + 1
    if combinations <= MAX_COMBINATIONS:
        return domains
    return [replace(d, messages=d.narrower, exact=False,
                    reason=d.reason + f"; narrowed: the {len(domains)} sites' messages would "
                    f"give {combinations} combinations")
            if d.narrower else d for d in domains]


# the nodes ``Uses._spread`` acts on (``_incremented``'s too: an assignment or Incr)
SPREADING = (ast.Assignment, ast.Return, ast.ProcedureCall, ast.FunctionCall)


class _Walked:
    """What every reading site's ``Uses`` reads of one program, computed once: the
    routines some call reaches, and each routine's syntax nodes with their ancestors (a
    menu program with hundreds of TPReadNum sites walked its whole code for each, many
    times over: 40 CPU s before a search started)."""

    def __init__(self, program: Program):
        self.called = called_routines(program)
        self._nodes: dict[int, tuple] = {}
        self._names: dict[int, tuple] = {}
        self._spreading: dict[int, tuple] = {}       # (routine.ast kept by ``_nodes``)
        # (routine indexes, upper-case name) -> its ``Uses`` (``_followed``), which no
        # reader changes
        self.followed: dict[tuple, "Uses"] = {}

    def nodes(self, routine) -> tuple:
        """``ast.walk(routine.ast)`` as a tuple (the trees are immutable)."""
        return self.under(routine.ast)

    def under(self, tree) -> tuple:
        """``ast.walk(tree)`` as a tuple, kept by the tree's identity (the tree is kept too,
        so no other object takes its id)."""
        found = self._nodes.get(id(tree))
        if found is None:
            found = self._nodes[id(tree)] = (tree, tuple(ast.walk(tree)))
        return found[1]

    def spreading(self, routine) -> tuple:
        """The (node, ancestors) of ``routine`` that ``Uses._spread`` acts on: assignments,
        RETURNs and calls (the rest it passes over, at each round of its fixpoint)."""
        found = self._spreading.get(id(routine.ast))
        if found is None:
            found = self._spreading[id(routine.ast)] = tuple(
                (node, parents) for node, parents in self.nodes(routine)
                if isinstance(node, SPREADING))
        return found

    def names(self, expr) -> tuple:
        """(the upper-case names, the functions called) in ``expr``."""
        found = self._names.get(id(expr))
        if found is None:
            nodes = [node for node, _ in self.under(expr)]
            found = self._names[id(expr)] = (
                frozenset(n.name.key for n in nodes if isinstance(n, ast.NameRef)),
                frozenset(n.name.key for n in nodes if isinstance(n, ast.FunctionCall)))
        return found


def _site_domain(program, routines, node, routine=None,
                 shared: Optional[_Walked] = None) -> Optional[MessageDomain]:
    """The domain of ``node`` when it reads from the environment into named data."""
    if isinstance(node, ast.ProcedureCall) and node.name.key in RECEIVES \
            and _named_argument(node, "DATA") is not None:
        return _data_domain(routines, node)
    if isinstance(node, ast.ProcedureCall) and node.name.key in RECEIVES:
        raw = _named_argument(node, "RAWDATA")
        target = raw if raw is not None else _named_argument(node, "STR")
        uses = _followed(program, routines, target, shared)
        if uses is None:
            return None
        wanted = _literal_number(_named_argument(node, "READNOOFBYTES"))
        messages, reason = uses.raw_messages(min(int(wanted or 0), rawbytes.MAX_BYTES)) \
            if raw is not None \
            else uses.text_messages()
        prefix = _length_prefix(routine, raw, wanted) if raw is not None else None
        probes = uses.raw_probes(min(int(wanted or 0), rawbytes.MAX_BYTES)) \
            if raw is not None else ()
        if prefix is not None:
            messages, reason = _framed(uses.raw_messages()[0], *prefix), \
                reason + f"; each after its length ({int(wanted)} bytes), and a length of 0"
            probes = _framed(uses.raw_probes(), *prefix)[:-1] if probes else ()
        probes = tuple(probe for probe in probes if probe not in messages)
        return MessageDomain(node.span, RECEIVES[node.name.key], SOCKET, messages,
                             uses.exact and raw is None, reason,
                             uses.well_formed_only() if raw is None else (),
                             uses.probe_messages() if raw is None else probes,
                             raw=raw is not None)
    if isinstance(node, ast.ProcedureCall) and node.name.key in NUMBER_ANSWERS:
        positional = [a.value for a in node.args if a.kind == ast.REQUIRED and a.name is None]
        uses = _followed(program, routines, positional[0] if positional else None, shared)
        if uses is None or not uses.numbers:
            return None
        return MessageDomain(node.span, NUMBER_ANSWERS[node.name.key], ANSWERS,
                             _number_points(uses.numbers), uses.exact, uses.number_reason())
    if isinstance(node, ast.Assignment) and isinstance(node.value, ast.FunctionCall):
        call = node.value
        uses = _followed(program, routines, node.target, shared) \
            if call.name.key in TEXT_FILES or call.name.key in NUMBER_FILES else None
        if uses is None:
            return None
        if call.name.key in TEXT_FILES:
            lines, reason = uses.text_messages()
            return MessageDomain(call.span, TEXT_FILES[call.name.key], FILE, lines,
                                 uses.exact, reason)
        if uses.numbers:
            lines = tuple(format_num(n) for n in _number_points(uses.numbers)) + (MALFORMED,)
            return MessageDomain(call.span, NUMBER_FILES[call.name.key], FILE, lines,
                                 uses.exact, uses.number_reason() + "; and a line that is "
                                 "not a number")
    return None


def _length_prefix(routine, buffer, wanted) -> Optional[tuple]:
    """(encoding, network) when this receive of ``wanted`` bytes into ``buffer`` reads a
    length prefix: its routine unpacks a whole number of that size from byte 1 of the
    buffer, and another receive into the buffer reads that many bytes (ROS_receive_msg)."""
    if routine is None or not isinstance(buffer, ast.NameRef) or not wanted:
        return None
    lengths, sizes = {}, set()
    for node, _ in ast.walk(routine):
        if not isinstance(node, ast.ProcedureCall):
            continue
        positional = [a.value for a in node.args if a.kind == ast.REQUIRED and a.name is None]
        if node.name.key == "UNPACKRAWBYTES" and len(positional) >= 3 \
                and isinstance(positional[0], ast.NameRef) \
                and positional[0].name.key == buffer.name.key \
                and _literal_number(positional[1]) == 1 \
                and isinstance(positional[2], ast.NameRef):
            encoding = _encoding(node)
            if encoding is not None and encoding[0] == "int" and _size(encoding) == wanted:
                network = any(a.name is not None and a.name.key == "NETWORK" for a in node.args)
                lengths[positional[2].name.key] = (encoding, network)
        elif node.name.key in RECEIVES:
            data, count = _named_argument(node, "RAWDATA"), _named_argument(node, "READNOOFBYTES")
            if isinstance(data, ast.NameRef) and data.name.key == buffer.name.key \
                    and isinstance(count, ast.NameRef):
                sizes.add(count.name.key)
    found = [lengths[name] for name in sizes if name in lengths]
    return found[0] if found else None


def _framed(messages: tuple, encoding: tuple, network: bool) -> tuple:
    """Each message after its length, and a length of 0 with nothing after it."""
    frames = []
    for text in messages:
        body = rawbytes.from_text(text)
        frames.append(rawbytes.to_text(rawbytes.pack(b"", 1, len(body), encoding, network)
                                       + body))
    frames.append(rawbytes.to_text(rawbytes.pack(b"", 1, 0, encoding, network)))
    return tuple(dict.fromkeys(frames))


def _followed(program, routines, target, shared: Optional[_Walked] = None) -> Optional["Uses"]:
    """Where the data ``target`` names goes in ``routines`` (one task's code), and in the
    code of each other task that reads shared PERS data it reaches (a socket task keeps
    the command in a PERS string, the motion task compares it): the followed code grows
    until no other task shares a datum the data reaches."""
    if not isinstance(target, ast.NameRef):
        return None
    if shared is None:
        return _followed_from(program, routines, target.name.key, None)
    key = (tuple(routine.index for routine in routines), target.name.key)
    found = shared.followed.get(key)
    if found is None:       # (a task receiving into one name at 32 sites follows it once)
        found = shared.followed[key] = _followed_from(program, routines, target.name.key,
                                                      shared)
    return found


def _followed_from(program, routines, name: str, shared: Optional[_Walked]) -> "Uses":
    """``_followed`` of the data named ``name`` (upper case), followed afresh."""
    followed = list(routines)
    while True:
        uses = Uses(program, followed, shared)
        uses.follow({name: {IDENTITY}})
        sharing = _sharing_tasks(program, uses, followed)
        if not sharing:
            return uses
        followed += sharing


def _sharing_tasks(program, uses: "Uses", followed: list) -> list:
    """The routines of the tasks, none of whose code ``followed`` holds, that name a PERS
    datum (one store slot for every task declaring it) the data ``uses`` follows reaches."""
    slots = _shared_slots(followed, uses.views)
    if not slots:
        return []
    inside = {routine.namespace for routine in followed}
    found = []
    for task in task_routines(program):
        if task[0].namespace not in inside and _shared_slots(task, uses.views) & slots:
            found += task
    return found


def _shared_slots(routines: list, names) -> set:
    """The store slots of the PERS data shared between tasks that ``names`` denote in
    ``routines`` (a TASK PERS is each task's own)."""
    slots = set()
    for routine in routines:
        for key in names:
            symbol = routine.scope.lookup(key)
            if symbol is not None and symbol.kind == GLOBAL_DATA and symbol.storage == "PERS":
                slots.add(symbol.slot)
    return slots


def _number_points(numbers) -> tuple:
    """One number per class of the comparisons with ``numbers``."""
    return analog_points(sorted(numbers))


def _data_domain(routines, call) -> Optional[MessageDomain]:
    """A receive into an array of byte (``\\Data:=request``): messages of bytes, one per
    class of each element the code compares with numbers (``request{1} = 2``: the element
    written as a literal index), the other bytes 0; one of zeros and one of bytes ff.  The
    message is as long as the largest element compared or ``\\ReadNoOfBytes`` (a literal)."""
    target = _named_argument(call, "DATA")
    if not isinstance(target, ast.NameRef):
        return None
    compared: dict = {}                 # element (1-based) -> numbers it is compared with
    for routine in routines:
        for node, _ in ast.walk(routine.ast):
            pairs = ((node.left, node.right), (node.right, node.left)) \
                if isinstance(node, ast.Binary) and node.op in NUMBER_COMPARISONS else \
                [(node.subject, value) for case in node.cases for value in case.values] \
                if isinstance(node, ast.Test) else ()
            for side, other in pairs:
                element = _literal_element(side, target.name.key)
                number = _byte_value(other, routine.scope)
                if element is not None and number is not None:
                    compared.setdefault(element, set()).add(number)
    wanted = _literal_number(_named_argument(call, "READNOOFBYTES"))
    length = int(max([wanted or 1] + list(compared)))
    length = min(length, rawbytes.MAX_BYTES)
    base = bytes(length)
    messages = [rawbytes.to_text(base)]
    for element, numbers in sorted(compared.items()):
        for value in group_points(sorted(numbers), 255):
            if element <= length:
                data = base[:element - 1] + bytes([int(value)]) + base[element:]
                messages.append(rawbytes.to_text(data))
    messages = list(dict.fromkeys(messages))[:MAX_MESSAGES - 1]
    messages.append(rawbytes.to_text(bytes([0xFF] * length)))
    shown = "; ".join(f"byte {element} compared with "
                      + ", ".join(_number_text(n) for n in sorted(numbers))
                      for element, numbers in sorted(compared.items()))
    reason = (shown or "no byte of the array compared with a number") + \
        f"; {length} bytes, the others 0, and one message of bytes ff"
    return MessageDomain(call.span, RECEIVES[call.name.key], SOCKET, tuple(dict.fromkeys(messages)),
                         False, reason)


BYTE_BASES = {"CHAR": None, "HEX": 16, "OKT": 8, "BIN": 2}    # StrToByte's switches


def _byte_value(expr, scope) -> Optional[float]:
    """The number a literal or CONST denotes, or that ``StrToByte("c" \\Char)`` of a string
    literal gives (the character's code; ``\\Hex``, ``\\Okt``, ``\\Bin``: the digits in that
    base; else decimal digits), as byte protocols write their commands."""
    value = number_value(expr, scope)
    if value is not None or not (isinstance(expr, ast.FunctionCall)
                                 and expr.name.key == "STRTOBYTE" and expr.args):
        return value
    text = expr.args[0].value
    if not isinstance(text, ast.StringLiteral):
        return None
    switches = [a.name.key for a in expr.args[1:] if a.name is not None]
    base = next((BYTE_BASES[key] for key in switches if key in BYTE_BASES), 10)
    try:
        return float(ord(text.value)) if base is None else float(int(text.value, base))
    except (TypeError, ValueError):
        return None


def _literal_element(expr, name: str) -> Optional[int]:
    """``k`` of ``name{k}`` with a literal whole index, else None."""
    if not (isinstance(expr, ast.Index) and isinstance(expr.base, ast.NameRef)
            and expr.base.name.key == name and len(expr.indices) == 1):
        return None
    index = _literal_number(expr.indices[0])
    return int(index) if index is not None and index == int(index) and index >= 1 else None


def _named_argument(call, key: str):
    for argument in call.args:
        if argument.name is not None and argument.name.key == key:
            return argument.value
    return None


# ===========================================================================
# Following the received data
# ===========================================================================

class Uses:
    """Where data taken from one message goes, and what the code there tells apart.

    Data is named program-wide by its name (a local of one routine and a global
    of the same name are one): following too much only adds messages.
    """

    def __init__(self, program: Program, routines: list, shared: Optional[_Walked] = None):
        self.program, self.routines = program, routines
        self.named = _routines_by_name(routines)    # looked up at every call the data reaches
        self.walked = shared if shared is not None else _Walked(program)
        self.views: dict[str, set] = {}          # name key -> how it was taken from the message
        self.functions: set[str] = set()         # FUNCs returning data from the message
        self.compared: list[tuple] = []          # (view, string) compared
        self.searched: list[str] = []            # characters/patterns looked for
        self.parsed: list = []                   # (view, type) StrToVal targets
        self.fields: dict[tuple, set] = {}       # (start, encoding, network) -> numbers compared
        self.numbers: set = set()                # numbers the whole value is compared with
        self.extent = 0                          # bytes the unpacked fields span
        self.bounds: set = set()                 # bytes a RawBytesLen comparison asks for
        # (target path, starts per level of the walk, encoding, network): fields unpacked
        # at a start computed at run time (``load.run_time_offsets``)
        self.sub_fields: set = set()
        self.parsed_numbers: list = []           # (view of the text, number) parsed, compared
        self.lengths: set = set()                # numbers the message's length is compared with
        self.counted: list = []                  # (dispatch, number): a count of fields compared
        # (dispatch, k, op, number): element k of an array the fields are parsed into,
        # compared (``IF params{1} = 1`` in ``CASE 9``)
        self.elements: list = []
        self.lists: dict[str, int] = {}          # routine -> StrToVal calls on parts cut at run time
        self.paths: dict[tuple, set] = {}        # (name, component, ...) -> views of that part
        self.exact = True                        # every read tells apart only what was tried
        self.string_arrays: set = set()          # string arrays the message's fields go into
        # what a routine no call reaches compares chooses nothing a search can reach
        self.called = self.walked.called

    def follow(self, start: dict) -> None:
        """Every name and function the data reaches, to a fixpoint, then what is done there."""
        for key, views in start.items():
            self.views.setdefault(key, set()).update(views)
        size = -1
        while size != self._size():
            size = self._size()
            for routine in self.routines:
                for node, parents in self.walked.spreading(routine):
                    self._spread(node, parents, routine)
        for routine in self.routines:
            for key in self.views:
                symbol = routine.scope.lookup(key)
                if symbol is not None and isinstance(symbol.type, ArrayType) \
                        and symbol.type.element is STRING:
                    self.string_arrays.add(key)
        for routine in self.routines:
            if self.called is not None and routine.name not in self.called:
                continue
            for node, parents in self.walked.nodes(routine):
                self._observe(node, parents, routine)

    def _size(self) -> int:
        return sum(len(v) for v in self.views.values()) + len(self.functions) \
            + sum(len(v) for v in self.paths.values())

    # --- spreading: assignments, arguments, function results ------------------

    def _spread(self, node, parents, routine) -> None:
        counter = _incremented(node)
        if counter is not None and self._in_message_loop(parents):
            self.views.setdefault(counter, set()).add(COUNT)
        if isinstance(node, ast.Assignment):
            self._flow(node.value, node.target)
            self._copy_paths(_path(node.value), _path(node.target))
        elif isinstance(node, ast.Return) and node.value is not None \
                and self.carries(node.value) and routine.ast.kind == ast.FUNC:
            self.functions.add(routine.ast.name.key)
        elif isinstance(node, ast.FunctionCall) and node.name.key == "STRTOVAL":
            self._parsed_into(node)
        elif isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
            self._arguments(node, routine)

    def _copy_paths(self, source: Optional[tuple], target: Optional[tuple]) -> None:
        """The parts of ``source`` (``raw_message.header``) become those of ``target``."""
        if not source or not target or source == target:
            return
        for path, views in list(self.paths.items()):
            if path[:len(source)] == source:
                self.paths.setdefault(target + path[len(source):], set()).update(views)

    def _in_message_loop(self, parents) -> bool:
        """Whether the innermost loop around the node walks over the parts of the message:
        it cuts, searches or parses data taken from it (a server's loop over whole messages
        counts messages, not fields, and cuts them in a routine it calls)."""
        loop = next((p for p in reversed(parents) if isinstance(p, (ast.While, ast.For))), None)
        return loop is not None and any(
            isinstance(node, ast.FunctionCall) and node.name.key in SCANS and node.args
            and isinstance(node.args[0].value, ast.NameRef)
            and IDENTITY in self.views.get(node.args[0].value.name.key, ())
            for node, _ in self.walked.under(loop))

    def _flow(self, value, target) -> None:
        base = _base_name(target)
        if base is None or not self.carries(value):
            return
        views = self.views.setdefault(base, set())
        views.update(self.view_of(value) if isinstance(target, ast.NameRef) else {None})

    def _arguments(self, call, routine=None) -> None:
        """A user routine's parameter takes on what its argument carries; so does the
        target of ``UnpackRawBytes`` (a field) or ``StrToVal`` (parsed data)."""
        key = call.name.key
        if key == "UNPACKRAWBYTES":
            self._unpacked(call, routine)
            return
        if key == "COPYRAWBYTES":
            self._copied(call)
            return
        symbol = _routine_named(self.named, key, routine)
        if symbol is None or symbol.ast is None:
            return
        parameters = [p for p in symbol.ast.parameters if not p.optional]
        positional = [a for a in call.args if a.kind == ast.REQUIRED and a.name is None]
        for parameter, argument in zip(parameters, positional):
            # the parts of a record argument are the parameter's, and back out of VAR/INOUT
            inside, outside = (parameter.name.key,), _path(argument.value)
            self._copy_paths(outside, inside)
            if parameter.mode in ("VAR", "INOUT"):
                self._copy_paths(inside, outside)
        for parameter, argument in zip(parameters, positional):
            if argument.value is not None and self.carries(argument.value):
                self.views.setdefault(parameter.name.key, set()).update(
                    self.view_of(argument.value))
        named = {p.name.key: p for p in symbol.ast.parameters}
        for argument in call.args:
            if argument.name is not None and argument.value is not None \
                    and argument.name.key in named and self.carries(argument.value):
                self.views.setdefault(argument.name.key, set()).update(
                    self.view_of(argument.value))
        # what a routine receives into a VAR/INOUT parameter, its caller's argument holds
        for parameter, argument in zip(parameters, positional):
            target = _base_name(argument.value) if argument.value is not None else None
            if parameter.mode in ("VAR", "INOUT") and parameter.name.key in self.views \
                    and target is not None:
                self.views.setdefault(target, set()).update(self.views[parameter.name.key])

    def _parsed_into(self, call) -> None:
        """The target of ``StrToVal(text, x)`` holds a number parsed from where ``text``
        was taken: its comparisons give texts of the numbers (``TEST code CASE 1, 2``)."""
        values = [a.value for a in call.args if a.kind == ast.REQUIRED]
        if len(values) != 2 or not self.carries(values[0]):
            return
        target = _base_name(values[1])
        if target is not None:
            self.views.setdefault(target, set()).update(
                ("parsed", view) for view in self.view_of(values[0]))

    def _unpacked(self, call, routine=None) -> None:
        positional = [a.value for a in call.args if a.kind == ast.REQUIRED and a.name is None]
        if len(positional) < 3 or not self.carries(positional[0]):
            return
        target, start = _base_name(positional[2]), _literal_number(positional[1])
        encoding = _encoding(call)
        if target is None:
            return
        offset = self._offset(positional[0])
        if start is not None and offset is not None:
            start += offset                # a field of bytes copied from further in
        network = any(a.name is not None and a.name.key == "NETWORK" for a in call.args)
        levels = walked_starts(positional[1], routine.ast, routine.scope) \
            if start is None and routine is not None and offset is not None \
            and encoding is not None else None
        if levels is not None:             # a sub-message's field, at i + k
            self.sub_fields.add((_path(positional[2]) or (target,),
                             tuple(frozenset(v + offset for v in level) for level in levels),
                             encoding, network))
        if start is not None and encoding is not None:
            self.extent = max(self.extent, int(start) - 1 + _size(encoding))
        view = ("field", int(start), encoding, network) \
            if start is not None and encoding is not None and offset is not None else None
        path = _path(positional[2])
        if isinstance(positional[2], ast.NameRef) or view is None or path is None:
            self.views.setdefault(target, set()).add(view)
        else:                              # a record's component: message.header.msg_type
            self.views.setdefault(target, set()).add(None)
            self.paths.setdefault(path, set()).add(view)

    def _offset(self, expr) -> Optional[int]:
        """How far into the message byte 1 of ``expr`` lies: 0 for the received bytes, n for
        bytes CopyRawBytes took from byte n + 1 (None: not known)."""
        path = _path(expr)
        if path is not None and len(path) > 1:
            slices = {view[1] for view in self.paths.get(path, ()) if view[0] == "slice"}
            return slices.pop() if len(slices) == 1 else None
        return 0 if isinstance(expr, ast.NameRef) else None

    def _copied(self, call) -> None:
        """``CopyRawBytes buffer, 13, message.data, 1``: message.data holds the message from
        byte 13 on."""
        positional = [a.value for a in call.args if a.kind == ast.REQUIRED and a.name is None]
        if len(positional) < 4 or not self.carries(positional[0]):
            return
        source_start, target_start = (_literal_number(positional[1]),
                                      _literal_number(positional[3]))
        offset, target = self._offset(positional[0]), _base_name(positional[2])
        if target is None:
            return
        self.views.setdefault(target, set()).add(None)
        path = _path(positional[2])
        if None not in (source_start, target_start, offset, path) and len(path) > 1:
            self.paths.setdefault(path, set()).add(
                ("slice", int(offset + source_start - target_start)))

    # --- what an expression carries ---------------------------------------------

    def carries(self, expr) -> bool:
        """Whether ``expr`` holds data taken from the message."""
        if expr is None:
            return False
        names, functions = self.walked.names(expr)
        return not names.isdisjoint(self.views) or not functions.isdisjoint(self.functions)

    def view_of(self, expr) -> set:
        """How ``expr``'s value was taken from the message: the views of a name, a
        ``StrPart`` of the whole message at a constant position, else unknown (None)."""
        if isinstance(expr, ast.NameRef):
            return set(self.views.get(expr.name.key, {None}))
        if isinstance(expr, ast.Index) and isinstance(expr.base, ast.NameRef) \
                and expr.base.name.key in self.string_arrays and len(expr.indices) == 1:
            number = _literal_number(expr.indices[0])
            if number is not None and number == int(number) and 1 <= number <= MAX_FIELDS:
                return {("element", int(number))}     # parts{2}: the message's second field
        if isinstance(expr, ast.FunctionCall) and expr.name.key == "STRLEN" and expr.args \
                and expr.args[0].value is not None \
                and IDENTITY in self.view_of(expr.args[0].value):
            return {LENGTH}
        if isinstance(expr, ast.FunctionCall) and expr.name.key == "STRPART":
            values = [a.value for a in expr.args if a.kind == ast.REQUIRED]
            start = _literal_number(values[1]) if len(values) == 3 else None
            if start is not None and start == int(start) and start >= 1 \
                    and IDENTITY in self.view_of(values[0]):
                return {("part", int(start))}
        path = _path(expr)
        if path is not None and len(path) > 1 and path in self.paths:
            return {view for view in self.paths[path] if view[0] != "slice"} or {None}
        if isinstance(expr, ast.Binary) and expr.op in ("+", "-"):
            sides = (expr.left, expr.right)
            if any(_literal_number(side) is not None for side in sides) and any(
                    COUNT in self.view_of(side) for side in sides):
                return {COUNT}      # nParams := indParam - 1: still the number of fields
        return {None}

    # --- observing: what the code tells apart -----------------------------------

    def _observe(self, node, parents, routine) -> None:
        scope = routine.scope
        if isinstance(node, ast.NameRef) and node.name.key in self.views \
                and not _plain_read(node, parents, self.named, scope):
            self.exact = False
        if isinstance(node, ast.Binary) and (self.carries(node.left) or self.carries(node.right)):
            self._comparison(node, scope, parents)
        elif isinstance(node, ast.Test) and self.carries(node.subject):
            for case in node.cases:
                for value in case.values:
                    self._compared(node.subject, value, "=", scope, parents + (node, case))
        elif isinstance(node, ast.FunctionCall) and node.name.key in ("STRFIND", "STRMATCH",
                                                                       "STRMEMB"):
            self._searched(node, scope, routine)
        elif isinstance(node, ast.FunctionCall) and node.name.key == "STRTOVAL":
            self._parse(node, scope, parents)
            self._listed(node, routine)

    def _kept_between(self) -> tuple:
        """Per command's branch (a dispatch): the data it writes (an assignment's), and
        the data its conditions read (an IF, compact IF, WHILE or TEST, a FOR's bounds),
        the message's own data left out.  Walked only for a site with commands' probes."""
        written: dict = {}
        guards: dict = {}
        for routine in self.routines:
            if self.called is not None and routine.name not in self.called:
                continue
            for node, parents in self.walked.nodes(routine):
                if isinstance(node, ast.Assignment):
                    name, found = _base_name(node.target), written
                    names = {name} if name is not None else set()
                elif isinstance(node, (ast.IfBranch, ast.CompactIf, ast.While)):
                    names, found = set(self.walked.names(node.condition)[0]), guards
                elif isinstance(node, ast.For):
                    names, found = set(self.walked.names(node.start)[0]) \
                        | set(self.walked.names(node.stop)[0]), guards
                elif isinstance(node, ast.Test):
                    names, found = set(self.walked.names(node.subject)[0]), guards
                else:
                    continue
                names -= set(self.views)
                dispatch = self._dispatch(parents + (node,), routine.scope) if names else None
                if dispatch is not None:
                    found.setdefault(dispatch, set()).update(names)
        return written, guards

    def _comparison(self, node, scope, parents=()) -> None:
        if node.op in NUMBER_COMPARISONS:
            carried = node.left if self.carries(node.left) else node.right
            other = node.right if carried is node.left else node.left
            self._compared(carried, other, node.op, scope, parents + (node,))
        elif node.op not in ("AND", "OR", "XOR"):
            self.exact = False

    def _compared(self, carried, other, op: str, scope, parents=()) -> None:
        if isinstance(carried, ast.FunctionCall) and carried.name.key == "RAWBYTESLEN" \
                and carried.args and carried.args[0].value is not None:
            # RawBytesLen(message.data) < 52: the message must reach that far
            offset, number = self._offset(carried.args[0].value), number_value(other, scope)
            if offset is not None and number is not None:
                self.extent = max(self.extent, int(offset + number))
                self.bounds.add(int(offset + number))
        text = _string_value(other, scope)
        element = self._parsed_element(carried)
        if element is not None and number_value(other, scope) is not None:
            self.elements.append((self._dispatch(parents, scope), element, op,
                                  number_value(other, scope)))
        views = {self._in_branches(view, parents, scope) for view in self.view_of(carried)}
        if text is not None and op in EQUALITY:
            self.compared.extend((view, text) for view in _in_view_order(views))
            self.exact = self.exact and views == {IDENTITY}
            return
        number = number_value(other, scope)
        if number is None or views != {IDENTITY}:
            self.exact = self.exact and number is not None and all(
                view is not None and view[0] == "field" for view in views)
        if number is None:
            return
        if IDENTITY in views:
            self.numbers.add(number)
        if LENGTH in views:
            self.lengths.add(number)
        for view in _in_view_order(views):
            if view is not None and view[0] == "field":
                self.fields.setdefault(view[1:], set()).add(number)
            elif view is not None and view[0] == "parsed":
                self.parsed_numbers.append((view[1], number))
            elif view == COUNT and number >= 0 and number == int(number):
                self.counted.append((self._dispatch(parents, scope), int(number)))

    def _parsed_element(self, expr) -> Optional[int]:
        """``k`` when ``expr`` is ``name{k}`` (a literal whole index) of an array that
        fields of the message are parsed into (``StrToVal(part, params{i})``)."""
        if not (isinstance(expr, ast.Index) and isinstance(expr.base, ast.NameRef)
                and len(expr.indices) == 1):
            return None
        if not any(view is not None and view[0] == "parsed"
                   for view in self.views.get(expr.base.name.key, ())):
            return None
        index = _literal_number(expr.indices[0])
        return int(index) if index is not None and index == int(index) \
            and 1 <= index <= MAX_FIELDS else None

    def _dispatch(self, parents, scope) -> Optional[tuple]:
        """The innermost choice on a value taken from the message that the node (the last
        of ``parents``) lies in a branch of: (view of the text, the text that takes that
        branch); None when there is none.  ``TEST code CASE 1: IF nParams = 7`` -> the
        parsed code's field and '1'."""
        for depth in range(len(parents) - 2, -1, -1):
            outer, inner = parents[depth], parents[depth + 1]
            if isinstance(outer, ast.Test) and isinstance(inner, ast.TestCase) \
                    and self.carries(outer.subject) and inner.values \
                    and not _within(parents[-1], outer.subject):
                chosen = self._branch_text(outer.subject, inner.values[0], scope)
                if chosen is not None:
                    return chosen
            if isinstance(outer, ast.IfBranch) and isinstance(outer.condition, ast.Binary) \
                    and outer.condition.op == "=" and inner is not outer.condition:
                condition = outer.condition
                for carried, other in ((condition.left, condition.right),
                                       (condition.right, condition.left)):
                    if self.carries(carried) and not self.carries(other):
                        chosen = self._branch_text(carried, other, scope)
                        if chosen is not None:
                            return chosen
        return None

    def _in_branches(self, view, parents, scope):
        """A field's view (``("element", k)``) with the fields and texts of the branches on
        other fields that the use lies in (``TEST parts{2}`` inside ``IF parts{1} = "F"``:
        ``("element", 2, ((1, "F"),))``); any other view as it is."""
        if view is None or view[0] != "element":
            return view
        chain = []
        for depth in range(len(parents) - 1):
            outer, inner = parents[depth], parents[depth + 1]
            chosen = None
            if isinstance(outer, ast.Test) and isinstance(inner, ast.TestCase) \
                    and inner.values and not _within(parents[-1], outer.subject):
                chosen = self._element_text(outer.subject, inner.values[0], scope)
            elif isinstance(outer, ast.IfBranch) and isinstance(outer.condition, ast.Binary) \
                    and outer.condition.op == "=" and inner is not outer.condition:
                condition = outer.condition
                chosen = self._element_text(condition.left, condition.right, scope) or \
                    self._element_text(condition.right, condition.left, scope)
            if chosen is not None and chosen[0] != view[1]:
                chain.append(chosen)
        return view[:2] + (tuple(chain),)

    def _element_text(self, carried, value, scope) -> Optional[tuple]:
        """(k, text) when ``carried`` is the message's k-th field and ``value`` a string."""
        text = _string_value(value, scope)
        fields = [view[1] for view in self.view_of(carried)
                  if view is not None and view[0] == "element"]
        return (fields[0], text) if text is not None and fields else None

    def _branch_text(self, carried, value, scope) -> Optional[tuple]:
        """(view, text) of a message part for which ``carried`` equals ``value``."""
        text = _string_value(value, scope)
        number = number_value(value, scope) if text is None else None
        for view in sorted(self.view_of(carried), key=repr):
            if view is None or view == COUNT:
                continue
            if text is not None and view[0] != "parsed":
                return view, text
            if number is not None and view[0] == "parsed":
                return view[1], format_num(number)
        return None

    def _searched(self, call, scope, routine=None) -> None:
        values = [a.value for a in call.args if a.kind == ast.REQUIRED]
        if not values or not self.carries(values[0]):
            return
        self.exact = False
        sought = values[-1] if len(values) >= 2 else None
        wanted = _string_value(sought, scope) if sought is not None else None
        found = [wanted] if wanted else self._passed_strings(sought, routine)
        for wanted in found:
            self.searched.append(wanted if call.name.key == "STRMATCH" else wanted[0])

    def _passed_strings(self, expr, routine) -> list:
        """The string constants the calls of ``routine`` pass to its parameter ``expr``
        (``strSplit received, "|", parts, n`` seeks ``split``: ``"|"``)."""
        if routine is None or not isinstance(expr, ast.NameRef):
            return []
        parameters = [p for p in routine.ast.parameters if not p.optional]
        position = next((i for i, p in enumerate(parameters)
                         if p.name.key == expr.name.key), None)
        if position is None:
            return []
        found = []
        for caller in self.routines:
            for node, _ in self.walked.nodes(caller):
                if isinstance(node, (ast.ProcedureCall, ast.FunctionCall)) \
                        and node.name.key == routine.key:
                    positional = [a.value for a in node.args
                                  if a.kind == ast.REQUIRED and a.name is None]
                    text = _string_value(positional[position], caller.scope) \
                        if position < len(positional) else None
                    if text:
                        found.append(text)
        return list(dict.fromkeys(found))

    def _listed(self, call, routine) -> None:
        """Count a StrToVal of a part the code cut at run-time positions (``StrFind(msg,
        i, ",")``): a routine that parses N such parts reads a list of N values."""
        values = [a.value for a in call.args if a.kind == ast.REQUIRED]
        if len(values) == 2 and self.carries(values[0]) and self.view_of(values[0]) == {None}:
            self.lists[routine.key] = self.lists.get(routine.key, 0) + 1

    def _parse(self, call, scope, parents=()) -> None:
        values = [a.value for a in call.args if a.kind == ast.REQUIRED]
        if len(values) != 2 or not self.carries(values[0]):
            return
        self.exact = False
        symbol = scope.lookup(_base_name(values[1]) or "")
        if symbol is not None and isinstance(values[1], ast.NameRef):
            self.parsed.extend((self._in_branches(view, parents + (call,), scope), symbol.type)
                               for view in self.view_of(values[0]))

    # --- the messages -----------------------------------------------------------

    def text_messages(self) -> tuple[tuple, str]:
        """The string messages that tell the code's choices apart, and what they come from."""
        messages = self._in_order()
        bounded = messages[:MAX_MESSAGES - 1]
        if self.compared or self.searched or not self.parsed:
            # (data only parsed: the malformed text is already one nothing expects)
            unexpected = UNEXPECTED
            while unexpected in messages:
                unexpected += UNEXPECTED
            bounded.append(unexpected)
        return tuple(bounded), self._reason()

    def _ranked_forms(self) -> list:
        """Per value the code tells apart, the messages that give it, likeliest first (the
        domain keeps the first ``MAX_MESSAGES`` - 1 of ``_rank_major``'s order; values left
        without a message there get probes)."""
        heads = [text for view, text in self.compared if view in (IDENTITY, ("part", 1))]
        wanted = [(view, text) for view, text in self.compared]
        wanted += [(view, format_num(number)) for view, number in self.parsed_numbers]
        # and per text parsed and compared, a number none of those comparisons names
        # (it takes a TEST's DEFAULT: ``TEST code CASE 1, 2`` -> '3')
        for view in dict.fromkeys(view for view, _ in self.parsed_numbers):
            named = {number for seen, number in self.parsed_numbers if seen == view}
            wanted.append((view, format_num(_unnamed(named))))
        for view, rapid_type in self.parsed:
            good = well_formed(rapid_type)
            wanted += [(view, text) for text in ((good,) if good is not None else ())
                       + (MALFORMED,)]
        # each value's likeliest message first, then the next of each (the cap keeps the first)
        # a word the code matches (``StrMatch(cmd, 1, "MOVE,")``) names a command, not
        # where fields end: fields are split at the characters it seeks
        separators = [text for text in self.searched if len(text) == 1]
        ranked = [list(_placed(view, text, separators, heads)) for view, text in wanted]
        # a list of as many numbers as a routine parses from parts it cuts ('[1,1,1]'),
        # and each word matched, alone and heading such a list ('MOVE,1,1')
        ranked[1:1] = [[form] for form in self._words()] + self._list_forms()
        return ranked

    def _in_order(self) -> list:
        """Every message of ``_ranked_forms`` in ``_rank_major``'s order, then the texts
        searched for and the lengths compared, each once."""
        return list(dict.fromkeys(_rank_major(self._ranked_forms()) + self.searched
                                  + self._length_forms()))

    def _list_forms(self) -> list:
        """Per number of parts a routine cuts and parses, a list of that many "1"s after the
        opening bracket the code seeks (and before its closing one, if sought), split at the
        separator it seeks most: ``[1,1,1]`` for ``StrFind(s, 1, "[")``, then three
        ``StrFind(s, i, ",")``/``StrFind(s, i, "]")`` parts parsed.  Per head, three groups
        of forms (``_ranked_forms``' values): the longest list; the longest with its last
        part malformed (``[1,1,?]``: the last parse's failure); and each shorter list, whose
        missing part fails to parse (``[1,1]``), as one value's forms, so that a routine
        parsing forty numbers does not push the commands the code compares out of the cap."""
        others = [text for text in _ordered(self.searched) if text not in BRACKETS.values()
                  and text not in BRACKETS and len(text) == 1]
        if not others:
            return []
        opener = next((text for text in self.searched if text in BRACKETS), "")
        closer = BRACKETS[opener] if opener and BRACKETS[opener] in self.searched else ""
        # without a bracket, a list follows each word the code matches ('MOVE,1,1' for
        # 'StrMatch(cmd, 1, "MOVE,")'), with the separator between them; with no word
        # either, the list is the whole message ('1,1,1' for "x,y,z")
        openers = [opener] if opener else \
            [word if word.endswith(others[0]) else word + others[0]
             for word in self._words()] or [""]
        longest = max(self.lists.values(), default=0)
        if longest <= 1:
            return []
        def listed(head: str, parts: list) -> str:
            return head + others[0].join(parts) + closer
        shorter = [listed(head, ["1"] * count) for head in openers
                   for count in range(longest - 1, 1, -1)]
        return [[listed(head, ["1"] * longest)] for head in openers] + \
            [[listed(head, ["1"] * (longest - 1) + [UNEXPECTED])] for head in openers] + \
            ([shorter] if shorter else [])

    def _words(self) -> list:
        """The texts of more than one character the code matches (StrMatch), in order."""
        return [text for text in dict.fromkeys(self.searched) if len(text) > 1]

    def _length_forms(self) -> list:
        """Per number the message's length is compared with (``StrLen(msg) > 72``), a
        message one character longer (the shorter ones are the other messages); none
        longer than a string holds."""
        return [FILLER_LETTER * (int(n) + 1) for n in sorted(self.lengths)
                if n >= 0 and n == int(n) and int(n) + 1 <= TEXT_LIMIT]

    def _parsed_texts(self) -> set:
        return {(view, format_num(number)) for view, number in self.parsed_numbers}

    def probe_messages(self) -> tuple:
        """Messages that reach the branches comparing a count of fields (``IF nParams =
        7`` in ``CASE 1``), each the dispatch's text followed by that many fields "1", and
        one with another count per dispatch (``_counted``: and their variants); and the
        messages the domain's cap (``MAX_MESSAGES``) leaves out.  They are probes: tried
        one at a time, for coverage only, since the settings such branches store multiply
        the states of a search offered them all together."""
        counts, forms, firsts = self._counts(), [], {}
        for view, text in self._parsed_texts():
            if view is None and counts:
                numbers = counts.get((view, text), set())
                other = next(n for n in range(len(numbers) + 1) if n not in numbers)
                counted = self._counted(text, sorted(numbers) + [other], (view, text))
                forms += counted
                if numbers:              # its first count, then after one field more
                    firsts[(view, text)] = [next((form for tier, form in counted
                                                  if tier == wanted), None)
                                            for wanted in (0, 2)]
        forms += self._counted("1", sorted(counts.get(None, ())), None)
        # and, first, the likeliest two messages of each value the domain's cap
        # (``MAX_MESSAGES``) leaves without one (the malformed code after twenty commands'
        # numbers): each tells a choice of the code apart
        ranked = self._ranked_forms() + [[text] for text in self.searched
                                         + self._length_forms()]
        offered = set(self._in_order()[:MAX_MESSAGES - 1])
        texts = {text for _, text in forms}
        cut = [text for value in ranked if offered.isdisjoint(value)
               for text in value[:2] if text not in texts]
        cut = list(dict.fromkeys(cut))[:MAX_CUT]
        # the counted forms by kind (every command's count first, then values, extra
        # fields, zeros), as many as the cap leaves room for, in the commands' order
        tiers = {text: tier for tier, text in sorted(forms, reverse=True)
                 if text not in offered}
        sequences = self._sequences(firsts)
        kept = sorted(tiers.items(), key=lambda item: (item[1], _natural(item[0])))[
            :MAX_PROBES - len(cut) - len(sequences)]
        return tuple(cut) + tuple(sorted((text for text, _ in kept), key=_natural)) \
            + sequences

    def _sequences(self, firsts: dict) -> tuple:
        """Pairs of messages offered together at every receive (a probe's search then
        tries them in either order): each command whose branch writes data (``BUFFER_POS
        := BUFFER_POS + 1`` under ``CASE 30``) with each other command whose branch's
        conditions read it (``FOR i FROM 1 TO BUFFER_POS`` under ``CASE 33``), each as its
        probe (its code and first count of fields), both with one field more too; at most
        ``MAX_SEQUENCES``."""
        if not firsts:
            return ()
        pairs = []
        writes, guards = self._kept_between()
        for first, written in sorted(writes.items(), key=repr):
            for second, read in sorted(guards.items(), key=repr):
                if first != second and written & read:
                    pairs += [pair for pair in zip(firsts.get(first, ()),
                                                   firsts.get(second, ())) if all(pair)]
        return tuple(dict.fromkeys(pairs))[:MAX_SEQUENCES]

    def _counts(self) -> dict:
        """The counts of fields compared, by the dispatch whose branch compares them
        ((view, text), or None outside any); empty when the code seeks no separator."""
        if _separators(self.searched)[0] is None:
            return {}
        counts: dict = {}
        for dispatch, count in self.counted:
            counts.setdefault(dispatch, set()).add(count)
        return counts

    def _counted(self, head: str, counts: list, dispatch) -> list:
        """``head`` followed by each count of fields "1", as the code splits them, and by
        one field more (a field the code reads before those it counts: mcubelab's id
        code); and, per element of the array the fields are parsed into that the
        dispatch's branch compares with numbers (``IF params{1} = 1``), the fields with
        that element at each class of those comparisons (``ELSE``: '9 2 1 1 1 #')."""
        separator, last = _separators(self.searched)
        variants = self._element_variants(dispatch)
        forms = []                  # (tier, text): the likelier kinds first
        for count in counts:
            for before in (0, 1):
                for number, values in enumerate(variants):
                    fields = ["1"] * (before + count)
                    for k, value in values.items():
                        if k <= count:
                            fields[before + k - 1] = format_num(value)
                    forms.append((before * 2 + (number > 0),
                                  head + "".join(separator + f for f in fields)
                                  + separator + last))
                # and zeros (joints a command may check against limits), and zeros ending
                # in the identity rotation (1 0 0 0) when there are four fields or more: a
                # pose a command may check for a unit quaternion
                zeros = ["1"] * before + ["0"] * count
                pose = zeros[:-4] + ["1", "0", "0", "0"] if count >= 4 else zeros
                forms += [(4, head + "".join(separator + f for f in fields) + separator + last)
                          for fields in (zeros, pose)]
        return [(tier, form) for tier, form in forms if len(form) <= TEXT_LIMIT]

    def _element_variants(self, dispatch) -> list:
        """The element values to try together in a probe of ``dispatch`` (element k ->
        value; {} first: every field "1"): one per class of the comparisons of each element
        (its numbers, and one other where they are only = and <>; else a number between
        and beyond them), every combination when there are at most ``MAX_VARIANTS``, else
        each element's alone."""
        compared: dict = {}
        for where, k, op, number in self.elements:
            if where == dispatch:
                compared.setdefault(k, []).append((op, number))
        points = {}
        for k, uses in sorted(compared.items()):
            numbers = sorted({number for _, number in uses})
            if all(op in EQUALITY for op, _ in uses):
                points[k] = tuple(numbers) + (_unnamed(set(numbers)),)
            else:
                points[k] = analog_points(numbers)
        combinations = [{}]
        total = 1
        for values in points.values():
            total *= len(values)
        if total <= MAX_VARIANTS:
            for k, values in points.items():
                combinations = [dict(c, **{str(k): v}) for c in combinations for v in values]
            combinations = [{int(k): v for k, v in c.items()} for c in combinations]
        else:
            combinations += [{k: v} for k, values in points.items() for v in values]
        return [{}] + [c for c in combinations if c and any(v != 1 for v in c.values())]

    def _reason(self) -> str:
        parts = []
        strings = list(dict.fromkeys(text for _, text in self.compared))
        if strings:
            parts.append("compared with " + ", ".join(map(quoted, strings[:8]))
                         + (", ..." if len(strings) > 8 else ""))
        if self.searched:
            parts.append("searched for " + ", ".join(map(quoted, dict.fromkeys(self.searched))))
        types = list(dict.fromkeys(str(t) for _, t in self.parsed))
        if types:
            parts.append("parsed by StrToVal as " + ", ".join(types))
        numbers = list(dict.fromkeys(n for _, n in self.parsed_numbers))
        counts = sorted(set(n for _, n in self.counted))
        if self.lengths:
            parts.append("length compared with " + ", ".join(
                _number_text(n) for n in sorted(self.lengths)))
        if counts and _separators(self.searched)[0] is not None:
            parts.append("counts of fields compared with " + ", ".join(map(str, counts)))
        if numbers:
            parts.append("parsed numbers compared with "
                         + ", ".join(_number_text(n) for n in numbers[:8])
                         + (", ..." if len(numbers) > 8 else ""))
        if not parts:
            return "not compared with anything: one text"
        if not strings and not self.searched and not numbers and not self.lengths:
            return "; ".join(parts) + ": a well-formed and a malformed text"
        return "; ".join(parts) + "; and one the program does not expect"

    def well_formed_only(self) -> tuple:
        """For data only parsed (StrToVal), not compared or searched: the well-formed texts
        alone (a narrower domain); else ()."""
        if self.compared or self.searched or self.parsed_numbers or not self.parsed:
            return ()
        texts = (well_formed(rapid_type) for _, rapid_type in self.parsed)
        return tuple(dict.fromkeys(text for text in texts if text is not None))

    def number_reason(self) -> str:
        return "compared with " + ", ".join(_number_text(n) for n in sorted(self.numbers))

    def raw_messages(self, wanted: int = 0) -> tuple[tuple, str]:
        """Hex-pair messages of at least ``wanted`` bytes (the receive's ``\\ReadNoOfBytes``)
        spanning every field unpacked: one per class of each field's comparisons, the other
        bytes 0, and one of bytes ff.  With no field compared, one message of zeros (a byte
        stream of ff would read as a huge length and the next read would never end)."""
        fields = sorted(self.fields.items(), key=lambda item: item[0][0])
        texts = self._text_fields()
        length = max([start - 1 + _size(encoding) for (start, encoding, _), _ in fields]
                     + [start - 1 + size for start, size, _ in texts]
                     + [self.extent, wanted, 1])
        base = self._base(length)
        if not fields and not texts:
            return (rawbytes.to_text(base),), "no field of the received bytes is compared " \
                "with a number: one message of zeros"
        messages = [rawbytes.to_text(base[:start - 1] + text.encode("latin-1", "replace")
                                     + base[start - 1 + size:])
                    for start, size, text in texts]
        for (start, encoding, network), numbers in fields:
            for value in _field_points(sorted(numbers), encoding):
                data = rawbytes.pack(base, start, value, encoding, network)
                messages.append(rawbytes.to_text(data))
        # and the first message one byte short of each length a RawBytesLen comparison asks
        # for (a frame of the right type with too little data: 'RawBytesLen(data) < 52')
        messages += [rawbytes.to_text(base[:bound - 1]) for bound in sorted(self.bounds)
                     if 1 < bound <= len(base)]
        # and each message of a field's class long enough for the sub-messages read at
        # starts computed at run time (a message only as long as its first header makes
        # the next field's UnpackRawBytes fail, and the sub-messages' branches go unrun)
        walked = self._walked_extent()
        padding = bytes(max(0, walked - length))
        messages += [rawbytes.to_text(rawbytes.from_text(text) + padding)
                     for text in list(messages) if padding]
        messages = list(dict.fromkeys(messages))[:MAX_MESSAGES - 1]
        unexpected = rawbytes.to_text(bytes([0xFF] * length))
        if unexpected not in messages:
            messages.append(unexpected)
        shown = [f"bytes from {start} compared with "
                 + ", ".join(_number_text(n) for n in sorted(numbers))
                 for (start, _, _), numbers in fields]
        for start in dict.fromkeys(start for start, _, _ in texts):
            shown.append(f"characters from {start} compared with " + ", ".join(
                quoted(text) for at, _, text in texts if at == start))
        if padding:
            shown.append(f"each also {walked} bytes long, for the fields read at starts "
                         f"computed at run time over {SEQUENCE + 1} sub-messages")
        return tuple(messages), f"UnpackRawBytes fields: {', '.join(shown)}"

    def _base(self, length: int) -> bytes:
        """``length`` bytes 0 with every field compared at the first number it is compared
        with (a header's expected type): the others' branches are then reached past that
        check."""
        base = bytes(length)
        for (start, encoding, network), numbers in sorted(self.fields.items(),
                                                          key=lambda item: item[0][0]):
            try:
                base = rawbytes.pack(base, start, min(numbers), encoding, network)
            except RapidError:
                pass                       # (a number the field cannot hold: left 0)
        return base

    def _walked_extent(self) -> int:
        """The bytes the fields read at starts computed at run time span, over every level
        of the walk (0: none such)."""
        return min(rawbytes.MAX_BYTES, max(
            [max(level) - 1 + _size(encoding)
             for _, levels, encoding, _ in self.sub_fields for level in levels if level],
            default=0))

    def raw_probes(self, wanted: int = 0) -> tuple:
        """Two sub-messages in a row: per header read again at a start computed at run time
        (the loop's ``UnpackRawBytes raw_message.data, i, raw_message.header.msg_type``),
        whose first copy is a field at a literal start compared with numbers, each pair of
        those numbers, the first at the literal start and the second at each start the walk
        reaches after one sub-message; the rest as ``raw_messages``' long messages.  Probes:
        tried one at a time, for coverage only (at most ``MAX_PROBES``)."""
        length = max(self._walked_extent(), wanted, 1)
        base, probes = self._base(length), []
        for path, levels, encoding, network in sorted(self.sub_fields, key=repr):
            heads = self.paths.get(path, ()) if len(path) > 1 else self.views.get(path[0], ())
            for view in sorted((v for v in heads if v is not None and v[0] == "field"
                                and v[2:] == (encoding, network)), key=repr):
                numbers = sorted(self.fields.get(view[1:], ()))
                # the base's own header (the least number) last: the others open a branch
                for first in numbers[1:] + numbers[:1]:
                    for second in numbers:
                        for start in sorted(levels[1] if len(levels) > 1 else ()):
                            try:
                                data = rawbytes.pack(base, view[1], first, encoding, network)
                                data = rawbytes.pack(data, start, second, encoding, network)
                            except RapidError:
                                continue
                            probes.append(rawbytes.to_text(data))
        return tuple(dict.fromkeys(probes))[:MAX_PROBES]

    def _text_fields(self) -> list:
        """(start, size, text) per string compared with characters unpacked with
        ``\\ASCII:=size`` from byte ``start`` of the message; a text of another length
        never equals them and gives nothing."""
        found = []
        for view, text in self.compared:
            if view is not None and view[0] == "field" and view[2][0] == "ascii" \
                    and len(text) == view[2][1]:
                found.append((view[1], view[2][1], text))
        return list(dict.fromkeys(found))


def _rank_major(ranked: list) -> list:
    """The messages of ``ranked`` (per value, its messages): each value's first, then each
    one's second, and so on, each once."""
    messages = [forms[rank] for rank in range(max(map(len, ranked), default=0))
                for forms in ranked if rank < len(forms)]
    return list(dict.fromkeys(messages))


def _placed(view, text: str, separators: list, heads: list) -> Iterator[str]:
    """Messages in which a value taken by ``view`` reads ``text``.

    The whole message: ``text``.  A part at a position: after the filler, or after each
    text compared with the message's start that ends just before it (``"JNT:"`` for
    ``StrPart(msg, 5, ...)``).  A part whose end, or a value whose place, the code finds
    at run time (StrFind, StrMatch): the text as the first of fields split at the
    separator sought most often and ended by each other one (``"1 1 #"``), alone, and
    followed by each separator."""
    if view == IDENTITY:
        yield text
        return
    if view is not None and view[0] == "element":
        # the k-th of fields split at the separator sought, the fields the branches it
        # lies in compare holding their texts: 'F|SM|[1,2,3]'
        order = _ordered(separators)
        fields = dict(view[2])
        fields[view[1]] = text
        yield (order[0] if order else FILLER).join(
            fields.get(k, "") for k in range(1, max(fields) + 1))
        return
    prefixes = [""]
    if view is not None and view[0] == "part":
        before = view[1] - 1
        prefixes = [FILLER * before] + [head + FILLER * (before - len(head))
                                         for head in dict.fromkeys(heads)
                                         if 0 < len(head) <= before]
    for prefix in prefixes:
        for form in _fields(text, separators):
            yield prefix + form


def _ordered(separators: list) -> list:
    """The separators sought, the one sought most often (most likely splitting fields)
    first."""
    counts = {separator: separators.count(separator) for separator in separators}
    return sorted(counts, key=lambda s: (-counts[s], separators.index(s)))


def _separators(separators: list) -> tuple:
    """(the separator of fields, the text that ends the last one); (None, "") when the code
    seeks none."""
    order = _ordered(separators)
    if not order:
        return None, ""
    return order[0], (order[1] if len(order) > 1 else "")


def _fields(text: str, separators: list) -> Iterator[str]:
    counts = {separator: separators.count(separator) for separator in separators}
    # the separator sought most often most likely splits fields; each other ends them
    for field in _ordered(separators):
        for last in counts:
            if last != field:
                yield text + field + text + field + last
    yield text
    for separator in counts:
        yield text + separator


def _field_points(numbers: list, encoding: tuple) -> tuple:
    """Whole values, one per class of the comparisons with ``numbers``, that fit the field."""
    if encoding == rawbytes.FLOAT4:
        return analog_points(numbers)
    top = 255 if encoding == rawbytes.HEX1 else 2 ** (8 * abs(int(encoding[1]))) - 1
    signed = encoding[0] == "int" and encoding[1] < 0
    low = -(top + 1) // 2 if signed else 0
    points = group_points([n - low for n in numbers], top)
    return tuple(p + low for p in points)


def _size(encoding: tuple) -> int:
    if encoding[0] in ("int", "ascii"):
        return abs(int(encoding[1]))
    return 1 if encoding == rawbytes.HEX1 else 4


def _encoding(call) -> Optional[tuple]:
    """The byte layout of an ``UnpackRawBytes`` with a constant format (None: other)."""
    for argument in call.args:
        key = argument.name.key if argument.name is not None else ""
        if key == "HEX1":
            return rawbytes.HEX1
        if key == "FLOAT4":
            return rawbytes.FLOAT4
        if key == "INTX":
            size = _inttype(argument.value)
            return ("int", size) if size is not None else None
        if key == "ASCII":
            size = _literal_number(argument.value)
            return ("ascii", int(size)) if size is not None and size == int(size) \
                and 1 <= size <= TEXT_LIMIT else None
    return None


def _inttype(expr) -> Optional[float]:
    if isinstance(expr, ast.NameRef):
        return dict(rawbytes.INTTYPES).get(expr.name.key)
    value = _literal_number(expr)
    return value if value is not None and int(value) in rawbytes.INT_SIZES else None


def _unnamed(numbers: set) -> float:
    """A whole number above every one of ``numbers``."""
    return float(int(max(numbers)) + 1)


def _natural(text: str) -> tuple:
    """Sort key: texts by their leading number, then as text."""
    head = text.split(" ", 1)[0]
    try:
        return (float(head), text)
    except ValueError:
        return (float("inf"), text)


def _number_text(number: float) -> str:
    return str(int(number)) if float(number).is_integer() else str(number)


# ===========================================================================
# Parsing targets: a text StrToVal accepts
# ===========================================================================

def well_formed(rapid_type) -> Optional[str]:
    """A literal of ``rapid_type`` that StrToVal accepts, numbers counting from 1 (None:
    no such text for this type)."""
    from ..semantics.library.system import format_typed, value_kind
    if rapid_type is None:
        return None
    counter = iter(range(1, 10 ** 6))
    value = _counting(rapid_type, counter)
    text = format_typed(value, value_kind(rapid_type))
    return text if parse_literal(text, rapid_type) is not None else None


def _counting(rapid_type, counter):
    if isinstance(rapid_type, ArrayType):
        inner = ArrayType(rapid_type.element, rapid_type.dims[1:]) if rapid_type.rank > 1 \
            else rapid_type.element
        return tuple(_counting(inner, counter) for _ in range(rapid_type.dims[0] or 1))
    if rapid_type.kind == RECORD:
        return tuple(_counting(c.type, counter) for c in rapid_type.components)
    if rapid_type is BOOL:
        return True
    if rapid_type is STRING:
        return "a"
    value = default_value(rapid_type)
    return float(next(counter)) if isinstance(value, float) else value


# ===========================================================================
# Helpers
# ===========================================================================

def _base_name(expr) -> Optional[str]:
    """The data a target names: ``x``, ``x{i}``, ``x.c`` -> ``X``."""
    while isinstance(expr, (ast.Index, ast.Component)):
        expr = expr.base
    return expr.name.key if isinstance(expr, ast.NameRef) else None


def _path(expr) -> Optional[tuple]:
    """``message.header.msg_type`` -> ("MESSAGE", "HEADER", "MSG_TYPE"); None when an index
    or anything but names and components is in the way."""
    names = []
    while isinstance(expr, ast.Component):
        names.append(expr.name.key)
        expr = expr.base
    if not isinstance(expr, ast.NameRef):
        return None
    return (expr.name.key, *reversed(names))


def _incremented(node) -> Optional[str]:
    """The name a statement counts up by a constant (``n := n + 1``, ``Incr n``), or None."""
    if isinstance(node, ast.ProcedureCall) and node.name.key == "INCR" and node.args \
            and isinstance(node.args[0].value, ast.NameRef):
        return node.args[0].value.name.key
    if isinstance(node, ast.Assignment) and isinstance(node.target, ast.NameRef) \
            and isinstance(node.value, ast.Binary) and node.value.op == "+":
        key, sides = node.target.name.key, (node.value.left, node.value.right)
        if any(isinstance(side, ast.NameRef) and side.name.key == key for side in sides) \
                and any(_literal_number(side) is not None for side in sides):
            return key
    return None


def _within(node, tree) -> bool:
    return any(inner is node for inner, _ in ast.walk(tree))


def _string_value(expr, scope) -> Optional[str]:
    if isinstance(expr, ast.StringLiteral):
        return expr.value
    if isinstance(expr, ast.NameRef) and scope is not None:
        symbol = scope.lookup(expr.name.key)
        if symbol is not None and symbol.kind == CONSTANT and isinstance(symbol.value, str):
            return symbol.value
    return None


def task_routines(program: Program) -> list[list]:
    """The routines of the program's own code (the environment model's left out), one list
    per task: the main task's first."""
    tasks: dict[int, list] = {}
    for routine in program.routines:
        if routine.ast is not None and routine.namespace != ENVIRONMENT_NAMESPACE:
            tasks.setdefault(routine.namespace, []).append(routine)
    return [tasks[namespace] for namespace in sorted(tasks)]


def _in_view_order(views: set) -> list:
    """``views`` in an order fixed across runs: a set's order is not (strings hash with a
    per-process seed, and ``None``, the unknown view, by its address)."""
    return sorted(views, key=lambda view: (view is not None, repr(view)))


def _routines_by_name(routines: list) -> dict[str, list]:
    """``routines`` (one task's, or several tasks' that share data) by upper-case name, each
    name's in the order of ``routines``."""
    named: dict[str, list] = {}
    for routine in routines:
        named.setdefault(routine.key, []).append(routine)
    return named


def _routine_named(named: dict[str, list], key: str, caller=None):
    """The routine ``key`` among the routines ``named`` indexes (``_routines_by_name``):
    the one ``caller`` calls by that name when it is given (its task's; of LOCAL routines
    of one name, its module's)."""
    named = named.get(key, [])
    if caller is not None:
        called = called_routine(caller, key, {routine.index: routine for routine in named})
        own = [routine for routine in named if routine.namespace == caller.namespace]
        named = [called] if called is not None else own or named
    return named[0] if named else None


def _literal_number(expr) -> Optional[float]:
    """A number written as a literal (no scope to look constants up in)."""
    if expr is None or isinstance(expr, ast.NameRef):
        return None
    return number_value(expr, None)


# instructions that only pass data on, never choose by it
OUTPUTS = {"SOCKETSEND", "TPWRITE", "WRITE", "ERRWRITE", "ERRLOG"} | set(RECEIVES) \
    | set(NUMBER_ANSWERS)


def _plain_read(ref: ast.NameRef, parents: tuple, named: dict[str, list], scope) -> bool:
    """Whether this use of received data can only tell apart what the tried values do:
    a comparison operand (its other side is judged where it is compared), a TEST subject,
    a copy, a write, an argument of a routine of the program (followed there) or of an
    instruction that only passes it on."""
    parent = parents[-1] if parents else None
    if isinstance(parent, ast.Binary):
        return parent.op in NUMBER_COMPARISONS
    if isinstance(parent, ast.Test):
        return parent.subject is ref
    if isinstance(parent, ast.Assignment):
        return True
    if isinstance(parent, ast.Argument) and len(parents) >= 2:
        call = parents[-2]
        key = getattr(getattr(call, "name", None), "key", "")
        return key in OUTPUTS or _routine_named(named, key) is not None
    return False
