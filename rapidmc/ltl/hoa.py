"""The HOA v1 format (Hanoi Omega-Automata): writing and reading Büchi automata.

``write_hoa`` prints state-based Büchi acceptance with explicit labels.
``read_hoa`` accepts Büchi acceptance (``Acceptance: 1 Inf(0)``) marked on
states or on transitions, plus the trivial ``0 t`` / ``0 f``; labels are
boolean formulas over AP indices (``[0&!1 | 2]``, ``t``, ``f``).  Labels in
DNF become one edge per cube.  Transition-based acceptance is turned into
state-based acceptance by the standard construction: a state remembers
whether the transition that entered it was accepting.  Several ``Start:``
states get a fresh initial state with the union of their edges.

Malformed input raises ``UserError`` [AUTOMATON] pointing at the line.

Example::

    >>> from .buchi import Buchi, Edge
    >>> print(write_hoa(Buchi(("p",), 0, frozenset({0}), ((Edge(1, 0, 0),),)), name="G p"))
    HOA: v1
    name: "G p"
    States: 1
    Start: 0
    AP: 1 "p"
    acc-name: Buchi
    Acceptance: 1 Inf(0)
    properties: trans-labels explicit-labels state-acc
    --BODY--
    State: 0 {0}
    [0] 0
    --END--
"""
from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import Optional

from ..ast import Span
from ..diagnostics import AUTOMATON, error
from .buchi import Buchi, Edge
from .guards import cubes
from .syntax import And, Atom, FalseF, Formula, Not, Or, TrueF


def _quoted(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def cube_label(positive: int, negative: int, atom_count: int) -> str:
    literals = [f"{'!' if negative >> i & 1 else ''}{i}" for i in range(atom_count)
                if (positive | negative) >> i & 1]
    return "&".join(literals) or "t"


def write_hoa(automaton: Buchi, name: Optional[str] = None) -> str:
    lines = ["HOA: v1"]
    if name is not None:
        lines.append(f"name: {_quoted(name)}")
    lines += [f"States: {automaton.state_count}",
              f"Start: {automaton.initial}",
              f"AP: {len(automaton.atoms)}" + "".join(f" {_quoted(a)}" for a in automaton.atoms),
              "acc-name: Buchi",
              "Acceptance: 1 Inf(0)",
              "properties: trans-labels explicit-labels state-acc",
              "--BODY--"]
    for state, out in enumerate(automaton.edges):
        lines.append(f"State: {state}" + (" {0}" if state in automaton.accepting else ""))
        lines += [f"[{cube_label(e.positive, e.negative, len(automaton.atoms))}] {e.target}"
                  for e in out]
    lines.append("--END--")
    return "\n".join(lines)


# --------------------------------------------------------------------------
# Reading
# --------------------------------------------------------------------------

TOKEN = re.compile(r'\s*(?:(?P<marker>--[A-Z]+--)|(?P<string>"(?:[^"\\]|\\.)*")|(?P<int>\d+)|(?P<word>[A-Za-z_@][\w@.-]*:?)'
                   r'|(?P<symbol>[][{}()!&|]))')


@dataclass
class _Transition:
    cubes: tuple
    target: int
    marked: bool
    line: int


@dataclass
class _Reading:
    """What the reader collected: header values and the body."""

    states: Optional[int] = None
    starts: list[int] = field(default_factory=list)
    atoms: Optional[tuple[str, ...]] = None
    acceptance: str = ""
    acceptance_line: int = 0
    marked_states: set[int] = field(default_factory=set)
    transitions: dict[int, list[_Transition]] = field(default_factory=dict)


class _LineReader:
    def __init__(self, file: str):
        self.file = file

    def fail(self, number: int, message: str):
        return error(AUTOMATON, message, Span(self.file, number, 1))

    def tokens(self, text: str, number: int) -> list[str]:
        found, position = [], 0
        text = text.rstrip()
        while position < len(text):
            match = TOKEN.match(text, position)
            if not match or match.end() == position:
                raise self.fail(number, f"cannot read {text[position:].strip()!r}")
            found.append(match.group().strip())
            position = match.end()
        return found


def read_hoa(text: str, file: str = "<hoa>") -> Buchi:
    """Parse one HOA v1 automaton with Büchi acceptance into a ``Buchi``."""
    reader = _LineReader(file)
    lines = text.splitlines()
    reading = _Reading()
    body_start = _read_header(lines, reader, reading)
    _read_body(lines, body_start, reader, reading)
    return _to_buchi(reading, reader, len(lines))


def _read_header(lines: list[str], reader: _LineReader, reading: _Reading) -> int:
    if not lines or lines[0].split() != ["HOA:", "v1"]:
        raise reader.fail(1, "not an HOA v1 automaton (the first line must be 'HOA: v1')")
    for number, line in enumerate(lines[1:], start=2):
        words = reader.tokens(line, number)
        if not words:
            continue
        key, values = words[0], words[1:]
        if key == "--BODY--":
            return number
        if key == "States:":
            reading.states = _integer(values, reader, number)
        elif key == "Start:":
            if "&" in values:
                raise reader.fail(number, "alternating automata (Start with '&') are not supported")
            reading.starts.append(_integer(values, reader, number))
        elif key == "AP:":
            count = _integer(values[:1], reader, number)
            names = values[1:]
            if len(names) != count or not all(n.startswith('"') for n in names):
                raise reader.fail(number, f"AP: announces {count} names but lists {len(names)}")
            reading.atoms = tuple(_unquote(n) for n in names)
        elif key == "Acceptance:":
            reading.acceptance_line = number
            reading.acceptance = " ".join(values).replace(" (", "(").replace("( ", "(")
            reading.acceptance = reading.acceptance.replace(" )", ")")
        elif key == "Alias:":
            raise reader.fail(number, "label aliases (Alias:) are not supported")
        elif not key.endswith(":"):
            raise reader.fail(number, f"expected a header item, found {key!r}")
    raise reader.fail(len(lines), "missing --BODY--")


def _integer(values: list[str], reader: _LineReader, number: int) -> int:
    if len(values) != 1 or not values[0].isdigit():
        raise reader.fail(number, f"expected one number, found {' '.join(values) or 'nothing'!r}")
    return int(values[0])


def _unquote(text: str) -> str:
    return re.sub(r"\\(.)", r"\1", text[1:-1])


def _read_body(lines: list[str], start: int, reader: _LineReader, reading: _Reading) -> None:
    state: Optional[int] = None
    for number, line in enumerate(lines[start:], start=start + 1):
        words = reader.tokens(line, number)
        if not words:
            continue
        if words == ["--END--"]:
            return
        if words[0] == "State:":
            state = _state_line(words[1:], reader, number, reading)
        elif state is None:
            raise reader.fail(number, "an edge before the first 'State:'")
        else:
            reading.transitions[state].append(_edge_line(words, reader, number, reading))
    raise reader.fail(len(lines), "missing --END--")


def _state_line(words: list[str], reader: _LineReader, number: int, reading: _Reading) -> int:
    if not words or not words[0].isdigit():
        raise reader.fail(number, "expected a state number after 'State:'")
    state = int(words[0])
    rest = [w for w in words[1:] if not w.startswith('"')]
    if rest and rest[0] == "[":
        raise reader.fail(number, "state labels are not supported (label the edges)")
    if state in reading.transitions:
        raise reader.fail(number, f"state {state} is defined twice")
    reading.transitions[state] = []
    if _marks(rest, reader, number):
        reading.marked_states.add(state)
    return state


def _marks(words: list[str], reader: _LineReader, number: int) -> bool:
    """Whether an acceptance-set mark ``{0}`` is present (only set 0 exists)."""
    if not words:
        return False
    if words[0] != "{" or words[-1] != "}" or not all(w == "0" for w in words[1:-1]):
        raise reader.fail(number, f"expected acceptance marks like {{0}}, found {' '.join(words)!r}")
    return len(words) > 2


def _edge_line(words: list[str], reader: _LineReader, number: int,
               reading: _Reading) -> _Transition:
    if words[0] != "[":
        raise reader.fail(number, "edges need explicit labels like [0&!1]")
    if "]" not in words:
        raise reader.fail(number, "unclosed label '['")
    close = words.index("]")
    label = _Label(words[1:close], reader, number).parse()
    rest = words[close + 1:]
    if not rest or not rest[0].isdigit():
        raise reader.fail(number, "expected a target state after the label")
    atom_count = len(reading.atoms or ())

    def index(name: str) -> int:
        if int(name) >= atom_count:
            raise reader.fail(number, f"label uses AP {name} but only {atom_count} are declared")
        return int(name)
    return _Transition(cubes(label, index), int(rest[0]), _marks(rest[1:], reader, number),
                       number)


class _Label:
    """Recursive descent over label tokens: or > and > not > atom."""

    def __init__(self, words: list[str], reader: _LineReader, number: int):
        self.words, self.reader, self.number, self.position = words, reader, number, 0

    def parse(self) -> Formula:
        formula = self.disjunction()
        if self.position != len(self.words):
            raise self.reader.fail(self.number, f"unexpected {self.words[self.position]!r} in label")
        return formula

    def peek(self) -> str:
        return self.words[self.position] if self.position < len(self.words) else ""

    def disjunction(self) -> Formula:
        return self._chain("|", Or, self.conjunction)

    def conjunction(self) -> Formula:
        return self._chain("&", And, self.negation)

    def _chain(self, symbol: str, node, operand) -> Formula:
        formula = operand()
        while self.peek() == symbol:
            self.position += 1
            formula = node(formula, operand())
        return formula

    def negation(self) -> Formula:
        word = self.peek()
        self.position += 1
        if word == "!":
            return Not(self.negation())
        if word == "(":
            inner = self.disjunction()
            if self.peek() != ")":
                raise self.reader.fail(self.number, "unclosed '(' in label")
            self.position += 1
            return inner
        if word.isdigit():
            return Atom(word)
        if word in ("t", "f"):
            return TrueF() if word == "t" else FalseF()
        raise self.reader.fail(self.number, f"unexpected {word or 'end of label'!r} in label")


def _to_buchi(reading: _Reading, reader: _LineReader, last_line: int) -> Buchi:
    if reading.atoms is None:
        raise reader.fail(last_line, "missing 'AP:' header")
    if not reading.starts:
        raise reader.fail(last_line, "missing 'Start:' header")
    count = reading.states if reading.states is not None else len(reading.transitions)
    for state, out in reading.transitions.items():
        for t in out:
            if not (state < count and t.target < count):
                raise reader.fail(t.line, f"state {max(state, t.target)} is out of range "
                                          f"(States: {count})")
    if any(s >= count for s in reading.starts):
        raise reader.fail(last_line, f"start state is out of range (States: {count})")
    acceptance = reading.acceptance
    if acceptance not in ("1 Inf(0)", "0 t", "0 f"):
        raise reader.fail(reading.acceptance_line or last_line,
                          f"only Büchi acceptance 'Inf(0)' is supported, "
                          f"found {acceptance or 'none'!r}")
    if acceptance != "1 Inf(0)":
        every = acceptance == "0 t"
        return _assemble(reading, count, lambda state: every, lambda t: False)
    transition_based = any(t.marked for out in reading.transitions.values() for t in out)
    if not transition_based:
        return _assemble(reading, count, lambda state: state in reading.marked_states,
                         lambda t: False)
    if reading.marked_states:
        raise reader.fail(last_line, "acceptance marks on both states and transitions")
    return _assemble(reading, count, None, lambda t: t.marked)


def _assemble(reading: _Reading, count: int, state_accepts, transition_accepts) -> Buchi:
    """Build the ``Buchi``; with ``state_accepts`` None, states are (state, entered-by-mark).

    State numbering: a fresh initial state (``0``) if there are several
    starts, then the HOA states, doubled when marks sit on transitions.
    """
    def out(state: int) -> list[_Transition]:
        return reading.transitions.get(state, [])
    copies = 1 if state_accepts is not None else 2
    offset = 1 if len(reading.starts) > 1 else 0

    def number(state: int, marked: bool) -> int:
        return offset + state * copies + (1 if marked and copies == 2 else 0)

    def edges_of(state: int) -> tuple[Edge, ...]:
        return tuple(Edge(p, n, number(t.target, transition_accepts(t)))
                     for t in out(state) for p, n in t.cubes)
    edges: list[tuple[Edge, ...]] = []
    if offset:
        edges.append(tuple(e for s in reading.starts for e in edges_of(s)))
    accepting = set()
    for state in range(count):
        for marked in range(copies):
            if (state_accepts(state) if state_accepts else marked):
                accepting.add(number(state, bool(marked)))
            edges.append(edges_of(state))
    initial = 0 if offset else number(reading.starts[0], False)
    return Buchi(tuple(reading.atoms), initial, frozenset(accepting), tuple(edges))
