"""Default value domains of free group and analog inputs, derived soundly.

A free analog (AI) or group (GI) input may hold any value of its type; the
checker needs a finite set to branch over (``--input-domain``, RMC502).
Two cases allow a default that loses no behaviour:

* **Width known.** A group input of ``n`` bits holds an integer 0..2^n-1.
  When its I/O configuration (EIO.cfg: ``-DeviceMap "0-3"``) gives ``n`` and
  ``n <= FULL_RANGE_BITS``, the default is every value: exact.
* **Only compared with numbers.** When every read of the input in the code
  is one side of a comparison (``= <> < <= > >=``) with a number literal or
  a CONST num, a TEST subject whose CASE values are such numbers, or the
  signal of ``WaitGI``/``WaitAI`` with such a (whole) number, or the override of
  ``SpeedRefresh`` (compared with its limits 0 and 100), the
  program sees only the outcomes of those comparisons.  The outcomes depend
  only on where the value lies among the numbers, so one value per place
  covers every outcome: for a group input each number, its integer
  neighbours and 0 (non-negative integers, within the width when known);
  for an analog input each number, a value between each two neighbours and
  one beyond each end.  ``GInput(s)`` / ``AInput(s)`` count as reads of
  ``s``; a signal variable reads the signals ``AliasIO`` connects it to.

* **Reaching nothing.** When every read's value goes, through ``+ - *``
  only, into an IN argument of a predefined routine modelled with no effect
  (a PLC's speed override given to ``VelSet``), no
  behaviour depends on it: one value.

* **Followed through data** (``input_flow``).  A group input's value used as
  an index of an array of known size (each element, and beyond either end, is
  a class), stored whole into num data or passed to the program's own
  routine, whose every read is again such a use; a value scaled by ``+ - *``
  into data that only moves read as their speed or zone.

Any other use (arithmetic that reaches a condition, a divisor, data a
property's atom or another task may read, an ``AliasIO`` with a computed
name) leaves the input without a default; the RMC502 error then names the
first such use.  An explicit ``--input-domain`` always wins.
"""
from __future__ import annotations

import math
from pathlib import Path
from dataclasses import dataclass
from typing import Optional, Sequence, Union

from .. import ast
from ..diagnostics import DOMAIN_ASSUMED, Diagnostic
from ..semantics.configured_signals import COMPARISONS
from ..semantics.library.motion_settings import SPEED_REFRESH_LIMITS
from ..semantics.program import Program, Signal
from ..semantics.scope import CONSTANT, SIGNAL
from ..semantics.values import to_num
from ..diagnostics.quoting import quoted
from .input_flow import InputFlow, Read, Uses
from .stated_domains import carriers, compared_constants, configured_range, roots

FULL_RANGE_BITS = 5           # a group input of at most 5 bits: every value (at most 32)
MAX_GROUP_BITS = 32           # the widest group input a controller configures
READERS = {"GINPUT": "GI", "AINPUT": "AI"}   # functions whose value is their signal's
WAITS = {"WAITGI", "WAITAI"}  # wait until the signal compares with a value as asked


@dataclass(frozen=True)
class Assumed:
    """The default domain of one input and why it covers every behaviour."""

    signal: Signal
    values: tuple                 # floats, ascending
    reason: str                   # "4-bit group input from EIO.cfg"
    # False: no exact default exists; the values are stated (``stated_domains``), and a
    # verdict covers only them
    exact: bool = True
    mentions: frozenset = frozenset()    # upper-case names whose statements read it
    read_as: frozenset = frozenset()     # upper-case names reading it: its own, signal data

    def note(self) -> Diagnostic:
        return Diagnostic(DOMAIN_ASSUMED, f"{self.signal.name}: {describe(self.values)} "
                          f"({self.reason})", self.signal.span, severity="note")

    @property
    def assumption(self) -> str:
        """The sentence beside a verdict for a stated domain (``findings.assumptions``)."""
        span = self.signal.span
        place = f" ({Path(span.file).name}:{span.line})" if span is not None else ""
        return (f"input {self.signal.name} takes only {describe(self.values)}: the verdict "
                f"covers these values, singled out from the code, not every value it may have "
                f"(RMC515 says why; --input-domain gives others){place}")


@dataclass(frozen=True)
class Refused:
    """Why an input has no default domain (a note of its RMC502 error)."""

    reason: str


Outcome = Union[Assumed, Refused]


def describe(values: Sequence[float]) -> str:
    """``values 0..15`` for a run of integers, else the values listed."""
    numbers = [int(v) if float(v).is_integer() else v for v in values]
    if len(numbers) > 2 and all(isinstance(n, int) for n in numbers) \
            and numbers == list(range(numbers[0], numbers[-1] + 1)):
        return f"values {numbers[0]}..{numbers[-1]}"
    return "values " + ", ".join(str(n) for n in numbers)


def default_domains(program: Program, signals: Sequence[Signal], atom_reads,
                    atom_data: Optional[frozenset] = None, robot_observed: bool = True,
                    exact_only: bool = False, atom_exprs: tuple = (), atom_scope=None) -> dict:
    """Signal key -> ``Assumed`` or ``Refused`` for each of ``signals`` (free AI/GI inputs).

    ``atom_reads``: indices of the signals properties read (None: any of them);
    ``atom_data``: upper-case names of the data they read (None: unknown, so an input's
    value is not followed through data); ``robot_observed``: whether they read a robot's
    position; ``exact_only``: refuse where no exact default exists (else the domain of
    ``stated_domains``, not exact, which also takes the numbers the properties' atoms
    ``atom_exprs`` compare with, read in ``atom_scope``).
    """
    if not signals:
        return {}
    widths = {s.name.upper(): s.width for s in program.options.get("configured_signals", ())
              if getattr(s, "width", None)}
    reads = ReadCollector(program, atom_data, robot_observed)
    reads.collect()
    outcomes = {}
    for signal in signals:
        outcome = _default(signal, widths.get(signal.key), reads, atom_reads)
        if isinstance(outcome, Refused) and not exact_only:
            outcome = stated(program, signal, outcome, reads, atom_exprs, atom_scope)
        outcomes[signal.key] = outcome
    return outcomes


def stated(program: Program, signal: Signal, refused: Refused, reads: "ReadCollector",
           atom_exprs: tuple = (), atom_scope=None) -> Assumed:
    """The values ``stated_domains`` singles out for an input with no exact default, and
    why there is none."""
    bound = frozenset(name for name, indices in reads.aliases.items() if signal.index in indices)
    names = carriers(program, signal, bound)
    numbers = compared_constants(program, names, number_value, atom_exprs, atom_scope)
    limits = configured_range(program, signal)
    ends = {end for end in (limits.low, limits.high) if end is not None}
    if signal.kind == "GI":
        top = limits.high if limits.high is not None else 2 ** MAX_GROUP_BITS - 1
        values = group_points(sorted(numbers | ends), int(top))
    else:
        values = analog_points(sorted(numbers | ends | {0.0}))
        values = tuple(v for v in values if (limits.low is None or v >= limits.low)
                       and (limits.high is None or v <= limits.high))
    origin = f"compared with {_listing(sorted(numbers))}" if numbers else \
        "compared with no number"
    configured = f", configured {_listing([limits.low])}..{_listing([limits.high])}" \
        if limits.low is not None and limits.high is not None else ""
    reason = (f"assumed, not exact: {refused.reason.split(';')[0]}; it or data computed from it "
              f"is {origin}{configured}")
    return Assumed(signal, values, reason, exact=False, mentions=roots(names),
                   read_as=bound | {signal.key})


def _default(signal: Signal, width: Optional[int], reads: "ReadCollector",
             atom_reads) -> Outcome:
    if signal.kind == "GI" and width is not None and width <= FULL_RANGE_BITS:
        return Assumed(signal, tuple(float(v) for v in range(2 ** width)),
                       f"{width}-bit group input from the I/O configuration")
    if atom_reads is None:
        return Refused("a property's atom reads signal data: any input's value may be observed")
    if signal.index in atom_reads:
        return Refused(f"a property's atom reads {signal.name}: its value is observed, not "
                       "only compared")
    if reads.computed_alias is not None:
        return Refused(f"AliasIO at {_where(reads.computed_alias)} names its signal at run time, "
                       f"so not every read of {signal.name} is known")
    other = reads.other_use.get(signal.index)
    if other is not None:
        return Refused(f"{other}; a default needs every read to be compared with number literals "
                       "(= <> < <= > >=, TEST ... CASE, WaitGI/WaitAI)")
    uses = reads.uses.get(signal.index)
    if uses is None:           # listed since a computed AliasIO binds other signal data
        return Assumed(signal, (0.0,), "no statement reads it: one value")
    numbers = sorted(uses.numbers)
    through = f"; followed through {', '.join(uses.through)}" if uses.through else ""
    if not numbers and uses.sinks:
        return Assumed(signal, (0.0,), "its value reaches no condition, index, divisor, atom or "
                       f"operation that can fail (only {' and '.join(uses.sinks)} here"
                       f"{through}): one value")
    if not numbers and uses.through:
        return Assumed(signal, (0.0,), f"stored into {', '.join(uses.through)}, which no "
                       "statement reads: one value")
    indexed = "".join(f", an index of a {n}-element array" for n in sorted(set(uses.indexed)))
    compared = sorted(uses.compared)
    if signal.kind == "GI":
        top = 2 ** (width or MAX_GROUP_BITS) - 1
        return Assumed(signal, group_points(numbers, top),
                       "group input only compared with " + _listing(compared) + indexed + through)
    return Assumed(signal, analog_points(numbers), "analog input only compared with "
                   + _listing(compared) + through)


def group_points(numbers: Sequence[float], top: int) -> tuple:
    """Non-negative integers up to ``top``, one in each class of the comparisons with ``numbers``.

    Between two neighbouring numbers (and beyond the last) the smallest integer
    above the lower one represents its class; 0 the class below them all.
    """
    points = {0}
    for c in numbers:
        low, high = math.floor(c), math.ceil(c)
        points.update({low - 1, low, high, high + 1} if low == high else {low, high})
    return tuple(float(p) for p in sorted(points) if 0 <= p <= top)


def analog_points(numbers: Sequence[float]) -> tuple:
    """Each number, a num strictly between each two neighbours, one beyond each end."""
    if not numbers:
        return (0.0,)
    points = set(numbers)
    points.update({to_num(numbers[0] - 1), to_num(numbers[-1] + 1)})
    for low, high in zip(numbers, numbers[1:]):
        middle = to_num((low + high) / 2)
        if low < middle < high:        # neighbouring nums have no num between them
            points.add(middle)
    return tuple(sorted(points))


def _listing(numbers: Sequence[float]) -> str:
    return ", ".join(str(int(n)) if float(n).is_integer() else str(n) for n in numbers) \
        if numbers else "nothing"


def _where(span: Optional[ast.Span]) -> str:
    return f"{span.file}:{span.line}:{span.column}" if span is not None else "an unknown place"


class ReadCollector:
    """Every read of every AI/GI signal in the program's code, classified (through the data
    it is stored into: ``input_flow``)."""

    def __init__(self, program: Program, atom_data: Optional[frozenset] = None,
                 robot_observed: bool = True):
        self.program = program
        self.routines = [r for r in program.routines if r.ast is not None]
        self.flow = InputFlow(self.routines, atom_data, robot_observed, tuple(program.globals))
        self.uses: dict[int, Uses] = {}           # signal index -> what its reads amount to
        self.aliases: dict[str, set] = {}         # signal variable key -> signal indices
        self.computed_alias: Optional[ast.Span] = None

    @property
    def other_use(self) -> dict:
        """Signal index -> its first use that allows no default."""
        return {index: uses.refusal for index, uses in self.uses.items()
                if uses.refusal is not None}

    def collect(self) -> None:
        for routine in self.routines:             # AliasIO first: reads may come before
            for node, _ in ast.walk(routine.ast):
                if isinstance(node, ast.ProcedureCall) and node.name.key == "ALIASIO":
                    self._alias(node, routine.scope)
        for routine in self.routines:
            for node, parents in ast.walk(routine.ast):
                if isinstance(node, ast.NameRef) and not _inside_alias(parents):
                    for index in self._signals_named(node, routine.scope):
                        self._classify(index, Read(node, parents, routine.scope, routine))

    def _alias(self, call: ast.ProcedureCall, scope) -> None:
        values = [arg.value for arg in call.args]
        if len(values) < 2 or not isinstance(values[1], ast.NameRef):
            return
        source = values[0]
        index = None
        if isinstance(source, ast.StringLiteral):
            signal = self.program.signal(source.value.upper())
            index = signal.index if signal is not None else None
        elif isinstance(source, ast.NameRef):
            symbol = scope.lookup(source.name.key)
            index = symbol.slot if symbol is not None and symbol.kind == SIGNAL else None
        target = scope.lookup(values[1].name.key)
        binds_value_input = getattr(getattr(target, "type", None), "signal_kind", "") \
            in ("AI", "GI")    # a computed name bound to signaldi data hides no AI/GI read
        if index is None and self.computed_alias is None and binds_value_input:
            self.computed_alias = call.span
        if index is not None:
            self.aliases.setdefault(values[1].name.key, set()).add(index)

    def _signals_named(self, ref: ast.NameRef, scope) -> set:
        symbol = scope.lookup(ref.name.key)
        if symbol is None:
            return set()
        if symbol.kind == SIGNAL:
            return {symbol.slot}
        if getattr(symbol.type, "signal_kind", "") in ("AI", "GI"):
            return self.aliases.get(ref.name.key, set())
        return set()

    def _classify(self, index: int, read: Read) -> None:
        uses = self.uses.setdefault(index, Uses())
        if uses.refusal is not None:
            return
        signal = self.program.signals[index] if index < len(self.program.signals) else None
        integral = signal is not None and signal.kind == "GI"
        self.flow.raw(read, uses, integral,
                      lambda r: compared_numbers(r.node, r.parents, r.scope), set())


def compared_numbers(ref: ast.NameRef, parents: tuple, scope) -> Union[set, str]:
    """The numbers a read is compared with, or how else it is used."""
    node = ref
    if len(parents) >= 2 and isinstance(parents[-1], ast.Argument) \
            and isinstance(parents[-2], ast.FunctionCall) \
            and parents[-2].name.key in READERS and parents[-2].args[0] is parents[-1]:
        node, parents = parents[-2], parents[:-2]
    parent = parents[-1] if parents else None
    if isinstance(parent, ast.Binary) and parent.op in COMPARISONS:
        other = parent.right if parent.left is node else parent.left
        value = number_value(other, scope)
        if value is None:
            return f"compared ('{parent.op}') with something other than a number literal"
        return {value}
    if isinstance(parent, ast.Argument) and len(parents) >= 2 \
            and isinstance(parents[-2], ast.ProcedureCall) and parents[-2].name.key in WAITS:
        return _waited_for(parents[-2], parent, scope)
    if isinstance(parent, ast.Argument) and len(parents) >= 2 \
            and isinstance(parents[-2], ast.ProcedureCall) \
            and parents[-2].name.key == "SPEEDREFRESH" and scope.lookup("SPEEDREFRESH") is None:
        return set(SPEED_REFRESH_LIMITS)    # (the range it checks, raising beyond it)
    if isinstance(parent, ast.Test) and parent.subject is node:
        values = [number_value(v, scope) for case in parent.cases for v in case.values]
        if any(v is None for v in values):
            return "tested against a CASE value that is not a number literal"
        return set(values)
    return _use_of(parent)


def _waited_for(call: ast.ProcedureCall, argument: ast.Argument, scope) -> Union[set, str]:
    """``WaitGI gi, 3`` (\\NOTEQ, \\LT, \\GT): a comparison of the signal with the value."""
    positional = [arg for arg in call.args if arg.kind == ast.REQUIRED and arg.name is None]
    if len(positional) == 2 and positional[0] is argument:
        value = number_value(positional[1].value, scope)
        whole = value is not None and value == int(value) and abs(value) < 2 ** 24
        if value is not None and (whole or call.name.key == "WAITAI"):   # GI: num = dnum
            return {value}
        return f"waited for ({call.name.text}) with a value that is not a small whole number"
    return f"passed to {call.name.text} other than as its signal"


def number_value(expr, scope) -> Optional[float]:
    """The num a literal (or CONST num) denotes, as the program computes with it."""
    sign = 1
    if isinstance(expr, ast.Unary) and expr.op in ("-", "+"):
        sign, expr = (-1 if expr.op == "-" else 1), expr.operand
    if isinstance(expr, ast.NumLiteral):
        try:
            return sign * to_num(expr.value)
        except Exception:           # beyond the num range: not a comparison we can place
            return None
    if isinstance(expr, ast.NameRef):
        symbol = scope.lookup(expr.name.key)
        if symbol is not None and symbol.kind == CONSTANT and type(symbol.value) is float:
            return sign * symbol.value
    return None


def _use_of(parent) -> str:
    if isinstance(parent, ast.Assignment):
        return "assigned"
    if isinstance(parent, ast.Argument):
        return "passed as an argument"
    if isinstance(parent, ast.Binary):
        return f"an operand of '{parent.op}'"
    if isinstance(parent, ast.Index):
        return "used as an array index"
    if isinstance(parent, ast.Test):
        return "a CASE value"
    return f"used in a {type(parent).__name__} (not a comparison with a number)"


def _inside_alias(parents: tuple) -> bool:
    return any(isinstance(p, ast.ProcedureCall) and p.name.key == "ALIASIO" for p in parents)
