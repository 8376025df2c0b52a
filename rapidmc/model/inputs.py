"""The free inputs of a check: which ones states keep, and the values each may take.

A free input that no atom reads is chosen where the program reads it and
forgotten after (``observed``); an analog or group input needs a finite set
of values, given with ``--input-domain`` or derived soundly by
``rapidmc.load.input_domains`` (RMC502 when neither is possible).
"""
from __future__ import annotations

from typing import Mapping, Optional

from .. import ast
from ..diagnostics import DOMAIN, USAGE, Diagnostic, UserError, error
from ..diagnostics.quoting import quoted
from ..load.input_domains import Assumed, default_domains
from ..semantics.configured_signals import walk_routine
from ..semantics.program import Program
from ..semantics.scope import SIGNAL
from .properties import AtomCompiler

INTERRUPT_ORDERS = {"ISIGNALDI", "ISIGNALDO", "ISIGNALAI", "ISIGNALAO", "ISIGNALGI", "ISIGNALGO"}


def observed_inputs(program: Program, atoms: AtomCompiler):
    """The free inputs whose values states must keep (None: all of them).

    Inputs that no atom reads are chosen when the program reads them.  An interrupt
    ordered on a configured signal (``ISignalDI diReset, 1, intno``) fires on a change of
    that signal, so states keep that signal's value, and only that one: the others are
    still chosen where they are read (a backup's task ordering interrupts on 4 of its 11
    inputs had 2,048 successors a step).  An atom that reads signal data bound at run time,
    or an interrupt ordered on a signal the program names through data (an AliasIO
    alias, a parameter), makes every input observed.
    """
    if atoms.observes_signal_data:
        return None
    observed = set(atoms.observed)
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node in walk_routine(routine.ast):      # every task's, handlers included
            if isinstance(node, ast.ProcedureCall) and node.name.key in INTERRUPT_ORDERS:
                signal = _configured_signal(routine, node)
                if signal is None:
                    return None
                observed.add(signal)
    return observed


def _configured_signal(routine, call: ast.ProcedureCall) -> Optional[int]:
    """The index of the configured signal an interrupt order names directly, else None."""
    first = next((arg for arg in call.args if arg.name is None), None)
    if first is None or not isinstance(first.value, ast.NameRef):
        return None
    symbol = routine.scope.lookup(first.value.name.key) if routine.scope is not None else None
    if symbol is None or symbol.kind != SIGNAL:
        return None
    return symbol.slot


def _read_inputs(program: Program, atoms: AtomCompiler) -> Optional[frozenset]:
    """Indices of the signals the program names or the properties read (None: any may
    be read).  An analog or group input of the I/O configuration that nothing reads
    needs no domain (survey round 5: a backup's EIO.cfg lists more inputs than the task
    uses)."""
    if program.named_signals is None or atoms.observes_signal_data:
        return None
    return program.named_signals | frozenset(atoms.observed)


def free_input_domains(program: Program, atoms: AtomCompiler,
                       explicit: Mapping[str, tuple] = {}) -> tuple[dict, tuple]:
    """Signal key -> values for the free analog and group inputs (``explicit`` ones as given,
    the others' defaults from input_domains), and the defaults (``Assumed``) chosen.

    ``atoms`` must have compiled the properties' atoms (it knows the signals they read).
    Raises RMC502 for an input that needs a domain and has no sound default.
    """
    domains = {name.upper(): tuple(values) for name, values in explicit.items()}
    assumed = _check_domains(program, domains, _read_inputs(program, atoms), atoms)
    domains.update({a.signal.key: a.values for a in assumed})
    return domains, assumed


def _check_domains(program: Program, domains: dict, read: Optional[frozenset],
                   atoms: AtomCompiler) -> tuple:
    """The default domains of the free inputs that need one and have no --input-domain
    (input_domains); RMC502 for those without a sound default, saying why."""
    for key in domains:
        signal = program.signal(key)
        if signal is None:
            raise error(USAGE, f"--input-domain names unknown signal {quoted(key)}")
        if signal.kind not in ("AI", "GI"):
            raise error(USAGE, f"--input-domain is for analog and group inputs; {signal.name} is "
                        f"a {signal.kind}")
    needed = [signal for signal in program.signals
              if signal.kind in ("AI", "GI") and not signal.driven and signal.key not in domains
              and (read is None or signal.index in read)]
    atom_reads = None if atoms.observes_signal_data else frozenset(atoms.observed)
    defaults = default_domains(program, needed, atom_reads)
    missing = [Diagnostic(DOMAIN, f"free {signal.kind} input '{signal.name}' needs a finite set "
                          f"of values: give --input-domain {signal.name}=v1,v2,... (or drive it "
                          "from an environment model)", signal.span,
                          notes=(f"no default: {defaults[signal.key].reason}",))
               for signal in needed if not isinstance(defaults[signal.key], Assumed)]
    if missing:                     # every input that lacks a domain at once, not one per run
        raise UserError(missing)
    return tuple(defaults[signal.key] for signal in needed)
