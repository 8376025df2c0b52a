"""Digital outputs written outside the loaded code, read like free inputs (issue 28).

An output that the loaded code reads back (``DOutput``, ``WaitDO``, an
interrupt on it) and never sets may be set by something rapidmc does not
load: the controller itself (a system output of SYSPAR/EIO.cfg's
``SYSSIG_OUT``: ``TaskExecuting`` of another task, motors on, cycle on), a
cross-connection (``EIO_CROSS -Res``), or a task of the backup checked apart
(``--task``) whose code sets it.  Keeping its first value made a communication
task that waits with ``WaitUntil DOutput(doRob_1Excuting) = 1`` for the robot
task to run wait forever.  Such an output is read as PERS data written from
outside is (``outside_data``): each read may give either value, as a free
digital input's does (``semantics.choosers.CheckConfig``), and the verdicts name
it and its writer under ``assumes:``; one a property's atom reads is kept in the
state, as a free input an atom reads is, so the atom sees what the code reads.  An
output no such writer is known for (module files without a backup, or nothing in
the backup sets it) keeps its stored value.

An output counts as set by the loaded code when any call of it (every task,
the environment model) passes it by name to anything but a reading routine
(``OUTPUT_READERS``) or a routine of the code that only reads the parameter it
binds, or names it in a string given to ``AliasIO``; an
``AliasIO`` whose signal is computed at run time may connect any output, so
then every output keeps the stored reading.  Group and analog outputs keep it
too: their values have no finite domain here (a gap the verdict's assumption
names).  ``check --fixed-outside-data`` keeps every output stored, as before.

An output the loaded code sets and a party left out sets too (``outputs_set_by_both``:
a robot task pulsing the other arm's "in position" output, checked alone) keeps the
loaded code's writes; a WaitDO on it may end at any try, taking the value it waits for
(the other party set it just before), so it is no deadlock; the verdicts say so.
"""
from __future__ import annotations

from pathlib import Path
from typing import Iterable, Optional

from .. import ast
from ..semantics.configured_signals import walk_routine
from ..semantics.library.arguments import argument_expression
from .config_file import instances

# routines that only read the signal they are given
OUTPUT_READERS = frozenset({
    "DOUTPUT", "GOUTPUT", "GOUTPUTDNUM", "AOUTPUT", "WAITDO", "WAITGO", "WAITAO",
    "ISIGNALDO", "ISIGNALGO", "ISIGNALAO", "VALIDIO", "GETSIGNALORIGIN",
    "DINPUT", "TESTDI", "GINPUTDNUM", "WAITDI", "WAITGI", "WAITAI",
    "ISIGNALDI", "ISIGNALGI", "ISIGNALAI"})


def written_signals(routines: Iterable) -> Optional[set]:
    """Upper-case names of the signals the routines' code (AST routines) may set: passed
    by name to a call other than a reading one, or named by a string given to AliasIO.
    A signal passed to a routine among ``routines`` counts only where that routine may
    set the parameter it is bound to (passes it on to such a call), so a helper such as
    ``PROC WaitHigh(VAR signaldo s) WaitDO s, 1; ENDPROC`` reads what it is given.
    None: an AliasIO names its signal at run time, so any signal may be set."""
    routines = list(routines)
    declared: dict = {}
    for routine in routines:
        declared.setdefault(routine.name.key, []).append(routine)
    # routine -> the names its code sets: the least fixed point over the calls between
    # the routines (a routine that only hands its parameter to itself sets nothing)
    sets: dict = {id(routine): set() for routine in routines}
    changed = True
    while changed:
        changed = False
        for routine in routines:
            found = _set_names(routine, declared, sets)
            if found is None:
                return None
            if found != sets[id(routine)]:
                sets[id(routine)] = found
                changed = True
    return set().union(*sets.values())


def _set_names(routine, declared: dict, sets: dict) -> Optional[set]:
    """The names ``routine``'s code passes to a call that may set them, given what each
    declared routine sets (``sets``); None where an AliasIO names a signal at run time."""
    written: set = set()
    for node in walk_routine(routine):
        if isinstance(node, ast.LateBindingCall):
            written.update(_passed_names(node.args))
        if not isinstance(node, (ast.ProcedureCall, ast.FunctionCall)):
            continue
        callees = declared.get(node.name.key)
        if callees:
            for argument in node.args:
                name = _passed_name(argument)
                if name is not None and any(_sets_parameter(callee, node.args, argument, sets)
                                            for callee in callees):
                    written.add(name)
            continue
        if node.name.key == "ALIASIO":
            source = argument_expression(node, "FromSignal", 0)
            if isinstance(source, ast.StringLiteral):
                written.add(source.value.upper())
            elif not isinstance(source, ast.NameRef):
                return None
        if node.name.key in OUTPUT_READERS:
            continue
        written.update(_passed_names(node.args))
    return written


def _passed_name(argument) -> Optional[str]:
    """The upper-case name an argument passes: a bare name (``doLamp``, ``\\Sig:=doLamp``),
    or the caller's optional parameter a conditional argument passes on (``\\Sig?Sig``)."""
    if isinstance(argument.value, ast.NameRef):
        return argument.value.name.key
    if argument.kind == ast.CONDITIONAL and argument.source is not None:
        return argument.source.key
    return None


def _passed_names(arguments) -> list:
    return [name for name in map(_passed_name, arguments) if name is not None]


def _sets_parameter(callee, arguments, argument, sets: dict) -> bool:
    """Whether ``callee`` may set the parameter ``argument`` (one of a call's
    ``arguments``) is bound to: by name (``\\Sig:=do1``), else the required parameter at
    its position among the positional arguments; one that matches no parameter may."""
    if argument.name is not None:
        matched = [p for p in callee.parameters if p.name.key == argument.name.key]
    else:
        position = next(i for i, a in enumerate(a for a in arguments if a.name is None)
                        if a is argument)
        required = [p for p in callee.parameters if not p.optional]
        matched = required[position:position + 1]
    if not matched:
        return True
    return matched[0].name.key in sets[id(callee)]


def controller_writers(eio_path: Optional[str]) -> dict:
    """Upper-case output name -> who sets it, from an EIO.cfg: system outputs (SYSSIG_OUT)
    and the results of cross-connections (EIO_CROSS)."""
    if not eio_path or not Path(eio_path).is_file():
        return {}
    text = Path(eio_path).read_bytes().decode("latin-1")
    found: dict = {}
    for _, attributes in instances(text, ("SYSSIG_OUT",)):
        name, status = attributes.get("SIGNAL"), attributes.get("STATUS") or "?"
        if name:
            of = [attributes[a] for a in ("ARG1", "ARG2") if attributes.get(a)]
            found.setdefault(name.upper(), f"the controller (system output {status}"
                             f"{' of ' + ', '.join(of) if of else ''})")
    for _, attributes in instances(text, ("EIO_CROSS",)):
        name = attributes.get("RES")
        if name:
            found.setdefault(name.upper(), "a cross-connection of the I/O configuration")
    return found


def outside_outputs(linker) -> dict:
    """Signal index -> who writes it, for each digital output some loaded code reads and
    no loaded code (nor the environment model) sets (``linker``: routines prepared)."""
    # (an output a property's atom reads too is kept in the state, as an input an atom
    # reads is: semantics.choosers.CheckConfig; the atom and the code read the same value)
    return _outputs_set_outside(linker, set_by_loaded_code=False)


def outputs_set_by_both(linker) -> dict:
    """Signal index -> who else sets it, for each digital output some loaded code waits
    for (WaitDO) and sets, and a party left out sets too (a task of the backup not loaded, the
    controller): a WaitDO on it may end at any try (``library.waits``), as a WaitUntil on
    PERS data written by both may (``outside_data``); other reads take the stored value."""
    waited = {node.args[0].value.name.key for routine in linker.routines
              if routine.ast is not None for node in walk_routine(routine.ast)
              if isinstance(node, ast.ProcedureCall) and node.name.key == "WAITDO"
              and node.args and isinstance(node.args[0].value, ast.NameRef)}
    return {index: who for index, who in
            _outputs_set_outside(linker, set_by_loaded_code=True).items()
            if linker.signals[index].key in waited}


def _outputs_set_outside(linker, set_by_loaded_code: bool) -> dict:
    from ..semantics.program import ENVIRONMENT_NAMESPACE
    trees = [routine.ast for routine in linker.routines if routine.ast is not None]
    written = written_signals(trees)
    if written is None:
        return {}
    read = named_signals(routine.ast for routine in linker.routines
                         if routine.ast is not None and routine.namespace != ENVIRONMENT_NAMESPACE)
    writers = linker.options.get("output_writers") or {}
    return {signal.index: writers[signal.key] for signal in linker.signals
            if signal.kind == "DO" and signal.key in writers and signal.key in read
            and (signal.key in written) == set_by_loaded_code}


def named_signals(routines: Iterable) -> set:
    """Upper-case names the routines' code refers to (a signal among them is read there:
    the code cannot set one but by a call, which ``written_signals`` counts)."""
    return {node.name.key for routine in routines for node in walk_routine(routine)
            if isinstance(node, ast.NameRef)}
