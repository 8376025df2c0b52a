"""What a verdict rests on that rapidmc assumed rather than read from the program (issue 19).

A check explores the program as loaded, so a verdict can rest on things no
loaded module says for sure:

* **stubs**: a module written by ``rapidmc stubs`` (it says so in its header
  comment) declares the names the program uses and no module declares, with
  empty routines and neutral values; the real ones may do and hold anything;
* **fixed controller readings**: the predefined routines that read the
  controller (``OpMode``, ``ClkRead``, ``ReadCfgData`` ...) answer fixed or
  sampled values when checking (RMC702, ``fixed_readings``);
* **PERS data no loaded task writes**: a persistent (of any type) that a
  loaded task reads and no loaded task (nor the environment) can write is
  written, if at all, outside the loaded code (another task, an encrypted
  module, a PC): the reads of its value components take the values of a finite
  domain (``load.outside_data``; where a wait reads it, only while a task waits for
  it: ``load.waited_data``), or it keeps its initial value with
  ``--fixed-outside-data``; the verdict names it and its values either way
  (``load.shared_data.data_uses`` says what each task reads and writes);
* **digital outputs no loaded code sets**: read back, they take either value
  (``load.outside_outputs``: a system output, a cross-connection, a task not
  loaded); one the loaded code sets too may end a WaitDO at any try;
* **interrupts not modelled**: an instruction ordering one that the check models with
  no effect (ISignalGI, IError, TriggInt ...: ``tried_inputs.unmodelled_interrupt_orders``)
  never interrupts the program, so its TRAP never runs;
* **the robot's start position**: the check's robot starts at its home (every coordinate
  0), a real one wherever it was left; where the code reads a position back for more than
  a move's target (``tried_inputs.start_position_reads``), the verdict says so;
* **barriers naming tasks not loaded**: a WaitSyncTask or SyncMoveOn whose task list
  names a task the check does not load takes it as arrived at once
  (``absent_partners``);
* **free inputs' values singled out from the program**: an analog or group input with no
  exact default takes the numbers the code compares it (or data computed from it) with,
  their neighbours and its configured ends (``load.stated_domains``; ``stated_domains``);
* **the robot's position left out of states**: where nothing but moves reads it
  (``model.robot_tracking``), moves leave the robot where it is; the verdicts are
  those of the tracked robot, but a counterexample shows the robot at its start
  and positions read back as that (``--track-robot`` keeps it);
* **data that only shapes moves' targets left out of states**: then (the robot not
  tracked) data whose values reach nothing but where moves go is sliced, on the
  assumption that its arithmetic stays within num's range
  (``model.reduction.move_shaping``);
* **counters that only fill bytes sent left out of states**: a num counted up by small
  steps and read only by ``PackRawBytes ... \\IntX`` into bytes only sent is sliced; code
  not loaded that writes it is taken to keep it within the packed size's range
  (``model.reduction.sent_counters``).

``assumptions(program, robot_untracked, move_shaping, sent_counters)`` lists them once;
``touched(assumption list, result)`` keeps those a counterexample executes a statement of
(the names each executed statement mentions, merged steps expanded), so that a VIOLATED
verdict names only what its counterexample rests on and HOLDS names everything.
"""
from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path
from typing import Iterable, Iterator, Optional

from .. import ast
from ..check.result import SearchResult
from ..diagnostics import SourceCache
from ..load.stubs.module_text import is_stub_module
from ..model.reduction.merging import executed_spans
from ..load.shared_data import data_uses, writes_data_by_name
from ..check.result import VIOLATED
from ..load.outside_data import UNSET_VALUE_TEXT
from ..semantics.expressions import WAIT_CHOICES
from ..semantics.library.motion import MOVE_ROUTINES
from ..semantics.library.position import ROBOT_PARTS
from ..semantics.program import ENVIRONMENT_NAMESPACE, Program
from .absent_partners import absent_partners
from .fixed_readings import fixed_readings
from .tried_inputs import start_position_reads, unmodelled_interrupt_orders

STUB, READING, OTHER_WRITER = "stub", "fixed reading", "other writer"
NO_INTERRUPT = "interrupt not modelled"
ABSENT_TASK = "task not loaded"
INPUT_DOMAIN = "input domain"
UNTRACKED = "untracked"
_IDENTIFIER = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_STRING_OR_COMMENT = re.compile(r'"(?:[^"]|"")*"|!.*$')
_HEAD_END = re.compile(r";|\b(?:THEN|DO|CASE|DEFAULT)\b", re.IGNORECASE)


@dataclass(frozen=True)
class Assumption:
    """One thing a verdict may rest on: its kind, the name it is about, and a sentence."""

    kind: str      # STUB, READING, OTHER_WRITER, NO_INTERRUPT, UNTRACKED, ABSENT_TASK, INPUT_DOMAIN
    name: str
    text: str
    # upper-case names besides ``name`` whose statements rest on it (a counterexample
    # that executes one names it)
    mentions: frozenset = frozenset()

    @property
    def key(self) -> str:
        return self.name.upper()

    def touched_by(self, names: frozenset) -> bool:
        return self.key in names or not self.mentions.isdisjoint(names)


def assumptions(program: Program, robot_untracked: bool = False,
                move_shaping: tuple = (), sent_counters: tuple = ()) -> tuple[Assumption, ...]:
    """Every assumption the program's verdicts may rest on, in a stable order;
    ``robot_untracked``: the check leaves the robot's position out of its states
    (``CheckConfig.robot_untracked``); ``move_shaping``: (name, span) of the data sliced
    because it only shapes moves' targets (``Slicing.move_shaping``); ``sent_counters``:
    (name, span) of the counters sliced because they only fill bytes sent
    (``Slicing.sent_counters``)."""
    stub_files = _stub_files(program)
    found = list(_stubs(program, stub_files))
    found += [_reading(warning) for warning in fixed_readings(program)]
    found += list(_unwritten_persistents(program, stub_files))
    found += [Assumption(OTHER_WRITER, signal.name,
                         f"output {signal.name} is set outside the loaded code, by "
                         f"{signal.outside}; its reads take 0 or 1")
              for signal in program.signals if signal.outside]
    found += [Assumption(OTHER_WRITER, signal.name,
                         f"output {signal.name} is set by the loaded code and by "
                         f"{signal.also_set_by}; a WaitDO on it may end at any try, as if "
                         f"that party set the awaited value just before")
              for signal in program.signals if signal.also_set_by]
    found += [Assumption(READING, signal.name,
                         f"no I/O configuration is loaded: the signal AliasIO names at run "
                         f"time at {signal.named_at_run_time} is taken as configured, shown "
                         f"as <AliasIO at file:line> (give the controller's EIO.cfg, --eio, to "
                         f"check the name)", frozenset({"ALIASIO"}))
              for signal in program.signals if signal.named_at_run_time]
    found += [Assumption(NO_INTERRUPT, call.name.text,
                         f"the interrupt {call.name.text} orders at "
                         f"{Path(call.span.file).name}:{call.span.line} never comes: the check "
                         "does not model it, so the TRAP it would run does not run")
              for call in unmodelled_interrupt_orders(program)]
    found += list(_barriers_without_partners(program))
    if robot_untracked:
        found.append(UNTRACKED_ROBOT)
    if move_shaping:
        found.append(_move_shaping(move_shaping))
    found += [_sent_counter(name, span) for name, span in sent_counters]
    found += _robot_start(program)
    return tuple(found)


def stated_domains(assumed: tuple) -> tuple[Assumption, ...]:
    """The free inputs whose values were not exact but singled out from the program
    (``load.stated_domains``; ``input_domains.Assumed`` with ``exact`` False): a verdict
    covers only those values."""
    return tuple(Assumption(INPUT_DOMAIN, a.signal.name, a.assumption, a.mentions)
                 for a in assumed if not a.exact)


def _robot_start(program: Program) -> list[Assumption]:
    """The robot's start position, where the code reads a position back for more than a
    move's target (``tried_inputs.start_position_reads``): the check's robot starts at its
    home, a real one wherever it was left."""
    reads = start_position_reads(program)
    if not reads:
        return []
    first = reads[0]
    others = len(reads) - 1
    more = f" (and {others} more {'read' if others == 1 else 'reads'})" if others else ""
    return [Assumption(READING, first.name.text,
                       f"the robot starts at the check's home position (every coordinate 0); "
                       f"{first.name.text} at {_where(first.span)} reads where it is{more}",
                       frozenset(call.name.key for call in reads))]


def _barriers_without_partners(program: Program) -> Iterator[Assumption]:
    """A WaitSyncTask or SyncMoveOn naming tasks that are not loaded: they are taken as
    arrived at once (``absent_partners``)."""
    places: dict = {}                   # (what, absent) -> the barriers' places, in order
    for barrier in absent_partners(program):
        places.setdefault((barrier.what, barrier.absent), []).append(_where(barrier.span))
    for (what, absent), where in places.items():
        who = "the tasks its list names that are not loaded" if absent is None \
            else "task " + ", ".join(absent) if len(absent) == 1 \
            else "tasks " + ", ".join(absent)
        is_are = "is" if absent is not None and len(absent) == 1 else "are"
        shown = ", ".join(where[:3]) + (f" and {len(where) - 3} more" if len(where) > 3 else "")
        yield Assumption(ABSENT_TASK, what,
                         f"{what} ({shown}) waits for {who}, which {is_are} not loaded: taken "
                         f"as arriving at once (check the tasks together to follow them)")


def touched(all_assumptions: Iterable[Assumption], result: SearchResult,
            describer=None) -> tuple[Assumption, ...]:
    """The assumptions whose name a statement of the counterexample mentions."""
    names = executed_names(result, describer)
    return tuple(a for a in all_assumptions if a.touched_by(names))


def for_verdict(all_assumptions: tuple[Assumption, ...], result: SearchResult,
                describer=None) -> tuple[str, ...]:
    """The sentences beside a verdict: what a counterexample touches, else everything."""
    chosen = touched(all_assumptions, result, describer) if result.verdict == VIOLATED \
        else all_assumptions
    return tuple(a.text for a in chosen)


def executed_names(result: SearchResult, describer=None) -> frozenset:
    """Upper-case identifiers of every statement the lasso executes or stands at (strings
    and comments left out; a compound statement up to its THEN, DO or first CASE), and
    the names of the choices it makes.  ``describer``: a ``RapidDescriber``, whose
    ``describe_stack`` says where each state stands (a wait that never ends)."""
    names: set[str] = set()
    steps = [*result.prefix, *result.cycle]
    for label in [step.label for step in steps] + [result.closing_label]:
        if not isinstance(label, tuple) or len(label) != 3:
            continue
        choices, span, _ = label
        for choice in choices or ():
            names.update(_identifiers(str(choice[0])))
        for executed in executed_spans(span):
            if executed is not None and hasattr(executed, "file"):
                names.update(_statement_names(executed.file, executed.line,
                                              executed.end_line or executed.line))
    describe_stack = getattr(describer, "describe_stack", None)
    for step in steps if describe_stack is not None else ():
        for frame in describe_stack(step.state):
            if frame.file is not None and frame.line:
                names.update(_statement_names(frame.file, frame.line, frame.line + 3))
    return frozenset(names)


def _statement_names(file: str, first: int, last: int) -> Iterator[str]:
    lines = (SourceCache.line(file, number) for number in range(first, max(first, last) + 1))
    text = " ".join(_STRING_OR_COMMENT.sub(" ", line) for line in lines if line is not None)
    return _identifiers(_HEAD_END.split(text, 1)[0])


def _identifiers(text: str) -> Iterator[str]:
    return (word.upper() for word in _IDENTIFIER.findall(text))


# --- the robot's position -----------------------------------------------------------------

UNTRACKED_ROBOT = Assumption(
    UNTRACKED, "robot position",
    "the robot's position is not tracked: nothing but moves reads it, so moves leave the "
    "robot where it is (a position read back is its start; --track-robot tracks it)",
    frozenset(MOVE_ROUTINES) | frozenset(ROBOT_PARTS))


def _move_shaping(data: tuple) -> Assumption:
    """The data left out of states because only moves' targets read it."""
    shown = ", ".join(f"{name} ({_where(span)})" for name, span in data[:3]) + \
        (f" and {len(data) - 3} more" if len(data) > 3 else "")
    one = len(data) == 1
    return Assumption(
        UNTRACKED, data[0][0],
        f"{shown} only {'shapes' if one else 'shape'} where moves go: with the robot's position "
        f"not tracked, {'it is' if one else 'they are'} left out of states, and "
        f"{'its' if one else 'their'} arithmetic is taken to stay within num's range "
        f"(ERR_NUM_LIMIT is not looked for there; --track-robot keeps "
        f"{'it' if one else 'them'})",
        frozenset(name.rsplit(".", 1)[-1].upper() for name, _ in data))


def _sent_counter(name: str, span) -> Assumption:
    """A counter left out of states because its value only fills bytes sent."""
    return Assumption(
        UNTRACKED, name,
        f"{name} ({_where(span)}) only counts into bytes sent (PackRawBytes \\IntX, then "
        f"SocketSend): it is left out of states; the loaded code keeps it an integer within "
        f"0..2^30 (a num stops growing there), and code not loaded that writes it is taken "
        f"to keep it within the packed size's range, where PackRawBytes cannot raise",
        frozenset({name.rsplit(".", 1)[-1].upper()}))


# --- stubs ----------------------------------------------------------------------------


def _stub_files(program: Program) -> frozenset:
    """The files of the program that ``rapidmc stubs`` wrote (its marker in the header)."""
    files = {_file(routine.span) for routine in program.routines} | \
        {_file(data.span) for data in program.globals}
    return frozenset(f for f in files if f and is_stub_module(f))


def _file(span) -> Optional[str]:
    """The file of a declaration (None for the controller's own data, declared nowhere)."""
    return span.file if span is not None else None


def _stubs(program: Program, stub_files: frozenset) -> Iterator[Assumption]:
    for routine in program.routines:
        if _file(routine.span) in stub_files and routine.namespace != ENVIRONMENT_NAMESPACE:
            does = "returns a neutral value" if routine.kind == "FUNC" else "is empty"
            yield Assumption(STUB, routine.name,
                             f"stub {routine.name} {does} ({_where(routine.span)})")
    outside = getattr(program, "outside_data", None) or {}
    for data in program.globals:          # (an encrypted module's PERS: written outside)
        if _file(data.span) in stub_files and data.namespace != ENVIRONMENT_NAMESPACE and \
                data.slot not in outside:
            yield Assumption(STUB, data.name,
                             f"stub {data.name} keeps its neutral value ({_where(data.span)})")


def _where(span) -> str:
    return f"{Path(span.file).name}:{span.line}"


# --- fixed readings ---------------------------------------------------------------------


def _reading(warning) -> Assumption:
    """From an RMC702 warning: ``OpMode reads a fixed value``."""
    name = warning.message.split(" ", 1)[0]
    how = warning.message.split(" reads ", 1)[1].split(" when checking")[0]
    short = how if len(how) <= 40 else how.split(" (", 1)[0]
    return Assumption(READING, name, f"{name} reads {short} (RMC702)")


# --- persistents another task may write -------------------------------------------------


def _whole_fixed(program: Program, data) -> str:
    """What a wait reading the whole data object at once sees, when its elements have too
    many combinations to choose (``ExpressionCompiler._outside_whole``)."""
    if data.slot not in getattr(program, "whole_reads_fixed", ()):
        return ""
    return (f"; a wait or poll reading the whole of {data.name} at once reads the stored value "
            f"(more than {WAIT_CHOICES} combinations of its elements' values)")


def _index_reads(program: Program, data) -> str:
    """That the reads of outside data whose value indexes an array take only that array's
    indexes (``ExpressionCompiler._outside_index``), where some did."""
    spans = getattr(program, "outside_indexes", {}).get(data.slot)
    if not spans:
        return ""
    places = sorted({_where(span) for span in spans})
    shown = ", ".join(places[:3]) + (f" and {len(places) - 3} more" if len(places) > 3 else "")
    return (f"; where its value indexes an array, only that array's indexes (the writer "
            f"writes an index there: {shown})")


def _only_tasks(chosen) -> str:
    """That the tasks left out are taken to be the only writers, with the values their code
    writes, when that narrowed the domain (``OutsideData.written_by_tasks``)."""
    if chosen.written_by_tasks is None:
        return ""
    return (f", only by {chosen.written_by_tasks} with the values their code assigns "
            f"(no PC or HMI writes it)")


def _also_writers(chosen) -> str:
    """Who writes data the loaded code writes too: the tasks left out, with the values their
    code assigns when that narrowed the domain, else ``also_written_by`` (``a PC or ...``)."""
    if chosen.written_by_tasks is None:
        return chosen.also_written_by
    return (f"{chosen.written_by_tasks}, with the values their code assigns (no PC or HMI "
            f"writes it)")


def _declared_elsewhere(data) -> str:
    """Where the value of data declared here without one comes from: the declaration of
    another task of the backup (one persistent object on the controller)."""
    if data.initial_from is None:
        return ""
    return (f"; declared here without a value, it starts with the value "
            f"{data.initial_from} declares, as on the controller")


def _waited(chosen) -> str:
    """That the components of data only the outside writes that a wait reads change only
    while a task waits for them (``OutsideData.waited_paths``, ``load.waited_data``)."""
    names = " and ".join(sorted(chosen.name + "".join("." + part.lower() for part in path)
                                for path in chosen.waited_paths))
    return (f"PERS {names} changes only while a task waits for it ({chosen.waited_at}): "
            f"other reads keep the last wait's value (--outside-writes-anytime: any read "
            f"may change it; {_where(chosen.span)})")


def _value_origin(data, chosen) -> str:
    """Where the value of data written outside comes from when no loaded declaration
    gives one: another task's declaration, or a valid value in place of zeros."""
    if data.initial_from is not None:
        return _declared_elsewhere(data)
    if chosen.unset:
        return f" and declared without a value: {UNSET_VALUE_TEXT}"
    return ""


def _unwritten_persistents(program: Program, stub_files: frozenset) -> Iterator[Assumption]:
    """PERS data that some loaded task reads and none writes (``data_uses``, shared with
    the partial-order reduction and RMC731): the values its reads take when it is written
    from outside (``load.outside_data``), else that it keeps its initial value."""
    if writes_data_by_name(program.routines):
        return
    outside = getattr(program, "outside_data", None) or {}
    read, written = set(), set()
    for namespace in sorted({routine.namespace for routine in program.routines}):
        task_read, task_written = data_uses(program, namespace)
        read |= task_read
        written |= task_written
    for data in program.globals:
        chosen = outside.get(data.slot)
        if data.initial_from is not None and chosen is None and data.slot in read:
            yield Assumption(OTHER_WRITER, data.name,
                             f"PERS {data.name}, declared here without a value, starts with the "
                             f"value {data.initial_from} declares, as on the controller "
                             f"({_where(data.span)})")
        if chosen is not None and chosen.awaited_at is not None:
            yield Assumption(OTHER_WRITER, data.name,
                             f"PERS {data.name}: no write of the loaded code ends the "
                             f"{chosen.awaited_at}, so {chosen.also_written_by} writes it "
                             f"too (not the values the loaded code writes)"
                             f"{_declared_elsewhere(data)}; in waits and loop "
                             f"conditions it reads the stored value or "
                             f"{chosen.describe()}{_whole_fixed(program, data)} "
                             f"({_where(data.span)})")
            continue
        if chosen is not None and chosen.also_written_by is not None:
            yield Assumption(OTHER_WRITER, data.name,
                             f"PERS {data.name} is written by the loaded code and by "
                             f"{_also_writers(chosen)}{_declared_elsewhere(data)}; its reads "
                             f"in WaitUntil and loop conditions (and the functions they call) "
                             f"take the stored value or {chosen.describe()}, other reads the "
                             f"stored value{_whole_fixed(program, data)} ({_where(data.span)})")
            continue
        # (a barrier whose partners are not loaded has its own assumption)
        if data.storage != "PERS" or _file(data.span) is None or data.is_task_list or \
                (_file(data.span) in stub_files and data.slot not in outside) or \
                data.namespace == ENVIRONMENT_NAMESPACE or data.slot not in read or \
                data.slot in written:
            continue
        if chosen is not None:
            seen = "; the properties read the value the program's last read took" \
                if chosen.observed else ""
            yield Assumption(OTHER_WRITER, data.name,
                             f"PERS {data.name} is written outside the loaded code"
                             f"{_only_tasks(chosen)}{_value_origin(data, chosen)}; its reads take "
                             f"{chosen.describe()}{_whole_fixed(program, data)}{seen}"
                             f"{_index_reads(program, data)} ({_where(data.span)})")
            if chosen.waited_paths:
                yield Assumption(OTHER_WRITER, data.name, _waited(chosen))
        else:
            yield Assumption(OTHER_WRITER, data.name,
                             f"PERS {data.name} keeps its initial value: no loaded task writes "
                             f"it (another task or a PC may; {_where(data.span)})")
