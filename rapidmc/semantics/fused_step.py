"""Fused steps: a routine's simple instructions as one generated Python function.

A plain state (``plain_step``) whose step runs only conditions (IF, WHILE,
compact IF), GOTOs and assignments to data named directly, over
expressions of constants, data, signals and operators, needs none of the
step machinery: no ``Machine``, no instruction objects, no closures per
operator.  ``fused_routine`` turns the routine's code into one function
that runs such a step (the instruction at the program counter, then the
merge points ``run_merged`` would join, decided with the same kinds) on
the state's own data, with the expressions' sources (``Compiled.source``)
written inline; free inputs chosen where read are chosen by ``_read`` as
``InputView`` and ``ScriptChooser`` choose them, in the same order.

The entries that give only target states (``fused_successor_states``,
for a search that projects them, ``model.RapidSystem``) leave out the
assignments in ``config.skipped_writes``: assignments of total values to
sliced data (``reduction.relevance``), whose values the projection resets
and nothing else reads.  The projected states are the same.

Anything else bails out before a transition is returned: an instruction
without a source that would run, a RAPID error (the error handling of the
general step applies), a frame in a handler or counting RETRYs.  Then
``fused_successors`` returns None and the plain driver takes the state;
the generated code only builds new values, so nothing needs undoing.
tests/test_plain_step.py compares the drivers on whole state graphs.
"""
from __future__ import annotations

import functools
from typing import Optional

from . import values
from .choosers import CheckConfig, next_script
from .errors import RapidError
from .expressions import read_signal
from .instructions import Action, Branch, ForInit, ForNext, Jump, TestDispatch
from .state import RUNNING, Frame, State, Transition

_new_tuple = tuple.__new__
LEAF_SIZE = 4                 # pcs tested one by one at the leaves of the dispatch
MAX_CODE = 4000               # longer routines are not fused (the source would be large)
ENTRY_LINES = 400             # an entry's paths go on in the dispatch loop after that many lines
NEVER_JOINS = 3               # reduction.merging's kind NEVER


class Fallback(Exception):
    """Internal: this step needs the general machinery."""


def _read(cx: list, index: int):
    """A signal's value; a free input chosen where read is chosen once per instruction
    (``cx``: signals, lazy inputs, this instruction's choices, the domain sizes of the
    transition's choices, the script, and the transition's choices as (name, value) or
    None when not wanted; as ``InputView`` and ``ScriptChooser``).  Signal data not
    bound to a signal (a negative index) raises, as ``read_signal``."""
    if index < 0:
        read_signal(None, index)
    entry = cx[1].get(index)
    if entry is None:
        return cx[0][index]
    chosen = cx[2]
    value = chosen.get(index)
    if value is None:
        name, domain = entry
        sizes = cx[3]
        script = cx[4]
        position = len(sizes)
        sizes.append(len(domain))
        value = domain[script[position]] if position < len(script) else domain[0]
        chosen[index] = value
        if cx[5] is not None:
            cx[5].append((name, value))
    return value


def _with(items: tuple, slot: int, value) -> tuple:
    return items[:slot] + (value,) + items[slot + 1:]


def _fallback():
    raise Fallback


HELPERS = {"_read": _read, "_with": _with, "_fallback": _fallback,
           "_to_num": values.to_num, "_to_dnum": values.to_dnum, "_divide": values.divide,
           "_int_div": values.int_div, "_int_mod": values.int_mod, "_concat": values.concat}


def define(lines: list, filename: str, namespace: dict) -> None:
    """Run the generated source ``lines`` (definitions) in ``namespace``.  The compiled code
    is kept per source text: the checks of one process (reduced and not, each property's
    search, a test suite's) write the same functions again, and compiling them was about
    a fiftieth of a check's time."""
    exec(_compiled("\n".join(lines) + "\n", filename), namespace)


@functools.lru_cache(maxsize=4096)
def _compiled(source: str, filename: str):
    return compile(source, filename, "exec")


class FusedRoutine:
    """One routine's generated step functions and the pcs they can start from.

    ``run`` executes the block at any pc, then the blocks after it as long as
    they join the step, one dispatch per block.  ``entry(pc)`` is the same run
    from one start pc written out along the code's paths (made when first
    needed): the merge kinds of the blocks that can follow are known, so
    their tests and the dispatch are settled when the code is written, and
    only the choices made are tested when it runs.  A path longer than
    ``ENTRY_LINES`` lines continues in ``run`` (``quiet_run`` for the unlabelled
    entries).  Entries come in two kinds:
    ``labelled`` ones note the spans executed, the others (for a search that
    needs only the target states) do not, and skip the assignments ``skipped``."""

    __slots__ = ("run", "quiet_run", "starts", "kinds", "first_visible", "entries",
                 "labelled_entries", "_blocks", "_quiet_blocks", "_code", "_names", "_name")

    def __init__(self, runs: tuple, starts: bytes, kinds: bytes, first_visible: bytes,
                 blocks: tuple, code: list, names: dict, name: str):
        # run(pc, store, locals_, cx, kinds, seen_visible, spans), and the same without the
        # skipped assignments (for the unlabelled entries)
        self.run, self.quiet_run = runs
        self.starts = starts              # 1 where the instruction has a source
        self.kinds = kinds                # merge kinds per pc (+4: may read a signal)
        self.first_visible = first_visible  # run_merged's seen_visible for a step starting here
        # per start pc: enter(store, locals_, cx, spans), made when first needed
        self.entries: list = [None] * len(code)
        self.labelled_entries: list = [None] * len(code)
        self._blocks, self._quiet_blocks = blocks
        self._code, self._names, self._name = code, names, name

    def entry(self, pc: int, labelled: bool):
        """``enter(store, locals_, cx, spans) -> (pc, store, locals_)``: ``run`` from ``pc``
        (the spans executed noted in ``spans`` when ``labelled``)."""
        lines = ["def enter(store, locals_, cx, spans):", "    made = cx[3]"]
        blocks = self._blocks if labelled else self._quiet_blocks
        _path(lines, self, blocks, pc, bool(self.first_visible[pc]), "    ", [ENTRY_LINES])
        if not labelled:
            lines = [line for line in lines if not line.lstrip().startswith("spans.append(")]
        names = dict(self._names, _run=self.run if labelled else self.quiet_run,
                     _kinds=self.kinds)
        define(lines, f"<fused {self._name} from {pc}>", names)
        entries = self.labelled_entries if labelled else self.entries
        enter = entries[pc] = names["enter"]
        return enter


def fused_routine(routine, entry: Optional[tuple],
                  skipped: frozenset = frozenset()) -> Optional[FusedRoutine]:
    """The fused form of ``routine`` (``entry``: its merge table entry, None when its
    steps are not merged; ``skipped``: the spans of assignments its unlabelled entries
    leave out), or None when no instruction has a source."""
    code = routine.code
    blocks = [_block(pc, instruction) for pc, instruction in enumerate(code)]
    if not any(blocks) or len(code) > MAX_CODE:
        return None
    names = dict(HELPERS)
    for pc, instruction in enumerate(code):
        names[f"_s{pc}"] = instruction.span
        if blocks[pc] is not None:
            names.update(_names(instruction))
    if entry is None:
        kinds = bytes([NEVER_JOINS]) * len(code)
        first_visible = bytes([1]) * len(code)
    else:
        kinds = entry[0]
        first_visible = bytes(1 if kind & 3 in (1, 3) else 0 for kind in kinds)
    starts = bytes(1 if block is not None else 0 for block in blocks)
    run = _run_function(blocks, names, routine.name)
    quiet_blocks, quiet_run = blocks, run
    if skipped:
        quiet_blocks = [_block(pc, instruction, skipped) for pc, instruction in enumerate(code)]
        quiet_run = _run_function(quiet_blocks, names, routine.name)
    return FusedRoutine((run, quiet_run), starts, kinds, first_visible,
                        (blocks, quiet_blocks), code, names, routine.name)


def written_globals(program, skipped: frozenset) -> set[int]:
    """The global slots a fused step may write when it leaves out the assignments
    ``skipped`` (the unlabelled entries): only fused assignments write global data."""
    return {instruction.fusion[1] for routine in program.routines for instruction in routine.code
            if type(instruction) is Action and instruction.fusion is not None and
            instruction.fusion[0] == "store" and instruction.span not in skipped}


def stop_pcs(routine) -> set[int]:
    """The pcs a fused step of ``routine`` may stop at: the pcs its blocks may set (a
    constant condition sets one; the code after an endless loop is not among them)."""
    return {target for pc, instruction in enumerate(routine.code)
            if _block(pc, instruction) is not None for target in _targets(instruction)}


def _run_function(blocks: list, names: dict, name: str):
    """``run(pc, store, locals_, cx, kinds, seen_visible, spans)``: the dispatch loop over
    ``blocks`` (see ``FusedRoutine``)."""
    lines = ["def run(pc, store, locals_, cx, kinds, seen_visible, spans):",
             "    made = cx[3]",
             "    while True:"]
    _dispatch(lines, blocks, 0, len(blocks), "        ")
    lines += ["        kind = kinds[pc]",
              "        if kind & 2:",
              "            break",
              "        if kind & 1:",
              "            if seen_visible:",
              "                break",
              "            seen_visible = True",
              "        if kind & 4 and made:",
              "            break",
              "    return pc, store, locals_"]
    namespace = dict(names)
    define(lines, f"<fused {name}>", namespace)
    return namespace["run"]


def _path(lines: list, fused: FusedRoutine, blocks: list, pc: int, seen_visible: bool,
          indent: str, budget: list) -> None:
    """The block at ``pc`` (of ``blocks``), then for each pc it may go on to, what ``run``
    does there (its tests of the merge kinds settled here: ``seen_visible`` is known)."""
    budget[0] -= len(blocks[pc])
    lines.extend(indent + line for line in blocks[pc])
    targets = _targets(fused._code[pc])
    if len(targets) == 1:
        _go_on(lines, fused, blocks, targets[0], seen_visible, indent, budget)
        return
    for number, target in enumerate(targets):
        lines.append(f"{indent}{'if' if number == 0 else 'elif'} pc == {target}:")
        _go_on(lines, fused, blocks, target, seen_visible, indent + "    ", budget)
    lines.append(f"{indent}else:")
    lines.append(f"{indent}    _fallback()")               # (no other pc is set)


def _go_on(lines: list, fused: FusedRoutine, blocks: list, pc: int, seen_visible: bool,
           indent: str, budget: list) -> None:
    """After a block, at ``pc``: stop, or run the block there (as ``run`` decides)."""
    kind = fused.kinds[pc]
    stop = f"{indent}return {pc}, store, locals_"
    if kind & 2 or kind & 1 and seen_visible:
        lines.append(stop)
        return
    seen_visible = seen_visible or bool(kind & 1)
    if kind & 4:
        lines += [f"{indent}if made:", "    " + stop]
    if blocks[pc] is None:
        lines.append(f"{indent}_fallback()")
    elif budget[0] <= 0:
        lines.append(f"{indent}return _run({pc}, store, locals_, cx, _kinds, {seen_visible}, "
                     "spans)")
    else:
        _path(lines, fused, blocks, pc, seen_visible, indent, budget)


def _targets(instruction) -> tuple:
    """The pcs the block of ``instruction`` may set, distinct, in a fixed order."""
    kind = type(instruction)
    if kind is Jump:
        found = (instruction.target,)
    elif kind is Branch and instruction.fusion is not None and instruction.fusion.is_constant:
        found = (instruction.target_true if instruction.fusion.constant else
                 instruction.target_false,)
    elif kind is Branch:
        found = (instruction.target_true, instruction.target_false)
    elif kind is Action:
        found = (instruction.next,)
    elif kind is ForInit:
        found = (instruction.next, instruction.exit)
    elif kind is ForNext:
        found = (instruction.body, instruction.exit)
    else:
        found = tuple(target for _, target in instruction.cases) + (instruction.default,)
    return tuple(dict.fromkeys(found))


def _block(pc: int, instruction, skipped: frozenset = frozenset()) -> Optional[list[str]]:
    """The statements that execute ``instruction`` (and set the next pc), or None; an
    assignment whose span is in ``skipped`` only sets the next pc."""
    kind = type(instruction)
    fusion = instruction.fusion
    lines = []
    if instruction.reads_io:
        lines.append("cx[2] = {}")               # each instruction reads inputs afresh
    if kind is Jump:
        lines.append(f"pc = {instruction.target}")
    elif kind is Branch and fusion is not None and fusion.is_constant:
        lines.append(f"pc = {_targets(instruction)[0]}")       # WHILE TRUE: one way only
    elif kind is Branch and fusion is not None:
        lines.append(f"pc = {instruction.target_true} if {fusion.source} else "
                     f"{instruction.target_false}")
    elif kind is Action and fusion is not None:
        where, slot, value = fusion
        if instruction.span in skipped:
            pass                                 # (its value is total: nothing to raise)
        elif where == "store":
            lines.append(f"store = store.set({slot}, {value.source})")
        else:
            lines.append(f"locals_ = _with(locals_, {slot}, {value.source})")
        lines.append(f"pc = {instruction.next}")
    elif kind is ForInit and fusion is not None:
        lines += _for_init(instruction, fusion)
    elif kind is ForNext:
        slot = instruction.slot
        lines += [f"_value = _to_num(locals_[{slot}] + locals_[{slot + 2}])",
                  f"_last = locals_[{slot + 1}]",
                  f"_step = locals_[{slot + 2}]",
                  f"locals_ = _with(locals_, {slot}, _value)",
                  f"pc = {instruction.body} if (_value <= _last if _step >= 0 else "
                  f"_value >= _last) else {instruction.exit}"]
    elif kind is TestDispatch and fusion is not None:
        subject, case_values = fusion
        lines.append(f"_subject = {subject.source}")
        keyword = "if"
        for values_, (_, target) in zip(case_values, instruction.cases):
            for value in values_:
                lines += [f"{keyword} ({value.source}) == _subject:", f"    pc = {target}"]
                keyword = "elif"
        lines += [f"{keyword} True:" if keyword == "if" else "else:",
                  f"    pc = {instruction.default}"]
    else:
        return None
    lines.append(f"spans.append(_s{pc})")
    return lines


def _for_init(instruction, bounds: tuple) -> list[str]:
    """FOR entry (``ForInit.run``): FROM, TO, STEP once (STEP by direction when not
    given), the loop variable set, the interval tested."""
    slot = instruction.slot
    lines = [f"_first = {bounds[0].source}", f"_last = {bounds[1].source}"]
    if len(bounds) == 3:
        lines.append(f"_step = {bounds[2].source}")
    else:
        lines.append("_step = -1.0 if _first > _last else 1.0")
    return lines + [f"locals_ = locals_[:{slot}] + (_first, _last, _step) + "
                    f"locals_[{slot + 3}:]",
                    "_low, _high = (_first, _last) if _first <= _last else (_last, _first)",
                    f"pc = {instruction.next} if _low <= _first <= _high else "
                    f"{instruction.exit}"]


def _names(instruction) -> dict:
    """The constants the sources of ``instruction`` name."""
    fusion = instruction.fusion
    kind = type(instruction)
    if fusion is None:
        return {}
    if kind is Branch:
        compiled = [fusion]
    elif kind is Action:
        compiled = [fusion[2]]
    elif kind is ForInit:
        compiled = list(fusion)
    else:
        compiled = [fusion[0], *(value for values_ in fusion[1] for value in values_)]
    names = {}
    for item in compiled:
        names.update(item.names)
    return names


def _dispatch(lines: list, blocks: list, low: int, high: int, indent: str) -> None:
    """Run the block of ``pc`` (in ``low..high-1``), by halving the range."""
    if high - low <= LEAF_SIZE:
        keyword = "if"
        for pc in range(low, high):
            lines.append(f"{indent}{keyword} pc == {pc}:")
            body = blocks[pc] or ["_fallback()"]
            lines.extend(f"{indent}    {line}" for line in body)
            keyword = "elif"
        lines.append(f"{indent}else:")
        lines.append(f"{indent}    _fallback()")
        return
    middle = (low + high) // 2
    lines.append(f"{indent}if pc < {middle}:")
    _dispatch(lines, blocks, low, middle, indent + "    ")
    lines.append(f"{indent}else:")
    _dispatch(lines, blocks, middle, high, indent + "    ")


def _fused(program, config: CheckConfig, routine: int) -> Optional[FusedRoutine]:
    """The routine's fused form for this configuration's merge points (made when
    first needed; a copy of the config that changes ``merge_points`` makes its own)."""
    cached = config.fused
    if cached is None or cached[0] is not config.merge_points or cached[1] is not program \
            or cached[2] is not config.skipped_writes:
        cached = config.fused = (config.merge_points, program, config.skipped_writes, {})
    routines = cached[3]
    try:
        return routines[routine]
    except KeyError:
        entry = config.merge_table(program).get(routine) if config.merge_points else None
        fused = routines[routine] = fused_routine(program.routines[routine], entry,
                                                  config.skipped_writes)
        return fused


routine_fused = _fused        # (for the compiled step machine: model/packed/bytecode.py)
block_targets = _targets


def _entry(program, config: CheckConfig, frame: Frame, labelled: bool):
    """The fused entry that runs a step of ``frame`` (``FusedRoutine.entry``), or None
    when the step needs the general machinery."""
    if frame[3] or frame[5]:
        return None                              # in a handler, or counting RETRYs
    fused = _fused(program, config, frame[0])
    if fused is None:
        return None
    pc = frame[1]
    enter = (fused.labelled_entries if labelled else fused.entries)[pc]
    if enter is None:
        if not fused.starts[pc]:
            return None
        enter = fused.entry(pc, labelled)
    return enter


# the running search's time limit is checked once every 32 runs of a fused step (a run costs
# a few microseconds; ``CheckConfig.time_check``)
TIME_CHECK_MASK = 31


def fused_successors(program, state: State, config: CheckConfig) -> Optional[list[Transition]]:
    """The transitions of a plain state (``plain_step.is_plain``) through its routine's
    fused function, or None when the step needs the general machinery."""
    below, frame = state[0][:-1], state[0][-1]
    enter = _entry(program, config, frame, True)
    if enter is None:
        return None
    routine, locals_, handling = frame[0], frame[2], frame[3:]
    store, rest, io = state[1], state[2:], state[2]
    lazy = config.lazy_inputs
    result = []
    script = []
    try:
        while script is not None:
            sizes = []
            choices = []
            spans = []
            after, new_store, new_locals = enter(
                store, locals_, [io, lazy, None, sizes, script, choices], spans)
            new_frame = _new_tuple(Frame, (routine, after, new_locals) + handling)
            new_state = _new_tuple(State, (below + (new_frame,) if below else (new_frame,),
                                           new_store) + rest)
            span = spans[0] if len(spans) == 1 else tuple(spans)
            result.append(_new_tuple(Transition, (tuple(choices), span, new_state, "", False)))
            if not sizes:
                break
            script = _next_script(script, sizes)
            if not len(result) & TIME_CHECK_MASK:
                config.time_check()
    except (RapidError, Fallback):
        return None
    return result


def fused_successor_states(program, state: State, config: CheckConfig) -> Optional[list[State]]:
    """The target states of ``fused_successors``, in its order, without building the
    transitions (labels, spans) around them, the assignments ``config.skipped_writes``
    left out (the same states once projected); None when ``fused_successors`` is None."""
    frames = state[0]
    frame = frames[-1]
    # (``_entry`` written out for an entry made already: a hot path)
    cached = config.fused
    fused = cached[3].get(frame[0]) if cached is not None and \
        cached[0] is config.merge_points and cached[1] is program and \
        cached[2] is config.skipped_writes else None
    enter = fused.entries[frame[1]] if fused is not None and not frame[3] and not frame[5] \
        else None
    if enter is None:
        enter = _entry(program, config, frame, False)
        if enter is None:
            return None
    routine, locals_, handling = frame[0], frame[2], frame[3:]
    store, rest, io = state[1], state[2:], state[2]
    below = frames[:-1]
    lazy = config.lazy_inputs
    result = []
    script = []
    spans: list = []                    # (not read: an entry too long to write out notes them)
    try:
        while True:
            sizes = []
            after, new_store, new_locals = enter(store, locals_,
                                                 [io, lazy, None, sizes, script, None], spans)
            new_frame = _new_tuple(Frame, (routine, after, new_locals) + handling)
            result.append(_new_tuple(State, ((*below, new_frame) if below else (new_frame,),
                                             new_store) + rest))
            if not sizes:
                return result
            if not len(result) & TIME_CHECK_MASK:
                config.time_check()
            if len(sizes) == 1:                  # (``_next_script`` written out: a hot path)
                following = script[0] + 1 if script else 1
                if following >= sizes[0]:
                    return result
                script = [following]
            else:
                script = next_script(script, sizes)
                if script is None:
                    return result
    except (RapidError, Fallback):
        return None


def plain_successor_states(program, state: State, config: CheckConfig) -> Optional[list[State]]:
    """The target states of ``step.successors`` at a running plain state the fused step
    takes, in order, for a search that needs nothing else (labels are needed only to
    rebuild a counterexample, which asks ``step.successors``); None at any other state."""
    if state[7] != RUNNING or state[10] or config.free_inputs or \
            program.environment_react is not None:
        return None                      # (``is_plain``, its tests written out: a hot path)
    interrupts = state[4]
    if interrupts[0] or interrupts[1] or interrupts[3]:
        return None
    return fused_successor_states(program, state, config)


def _next_script(script: list, sizes: list) -> Optional[list]:
    """The choices of the next transition after ``script`` (None after the last)."""
    if len(sizes) == 1:                  # one choice (the usual): its next value
        following = script[0] + 1 if script else 1
        return [following] if following < sizes[0] else None
    return next_script(script, sizes)
