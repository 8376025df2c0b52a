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
from ..semantics.library.arguments import argument_expression
from ..semantics.program import Program
from ..semantics.scope import GLOBAL_DATA
from .alias_bindings import alias_bindings
from .properties import AtomCompiler

INTERRUPT_ORDERS = {"ISIGNALDI", "ISIGNALDO", "ISIGNALAI", "ISIGNALAO", "ISIGNALGI", "ISIGNALGO"}


def observed_inputs(program: Program, atoms: AtomCompiler):
    """The free inputs whose values states must keep (None: all of them).

    Inputs that no atom reads are chosen when the program reads them.  An
    interrupt ordered on a signal (``ISignalDI diReset, 1, intno``) needs that
    signal's value kept, since its edge between two states raises the
    interrupt; the other inputs stay chosen where read (a backup with eleven
    digital inputs and one ``ISignalDI`` offered 2,048 input valuations per
    step before).  An atom that reads signal data (bound at run time), an
    interrupt ordered on a routine's parameter, or on signal data that a binding
    ``alias_bindings`` cannot read gives a signal, makes every input observed (signal
    data whose AliasIO calls name their signals, or name them at run time, watches
    those: ``alias_bindings``).  A late-bound call (``%name%``) binds to user procedures only
    (``statements._LateBindingCall``), whose orders this walk sees.
    """
    if atoms.observes_signal_data:
        return None
    observed = set(atoms.observed)
    bindings: Optional[dict] = {}           # (read when an order names signal data)
    for routine in program.routines:
        if routine.ast is None:
            continue
        for node in walk_routine(routine.ast):      # every task's and model's, handlers too
            if isinstance(node, ast.ProcedureCall) and node.name.key in INTERRUPT_ORDERS:
                signal = ordered_signal(program, routine, node)
                if signal is not None:
                    observed.add(signal.index)
                    continue
                if bindings == {}:
                    bindings = alias_bindings(program)
                bound = _bound_signals(routine, node, bindings)
                if bound is None:
                    return None
                observed |= bound
    return observed


def _bound_signals(routine, call: ast.ProcedureCall, bindings: Optional[dict]):
    """The configured signals the global signal data an interrupt order names may be
    bound to by the program's AliasIO calls (``alias_bindings``), else None."""
    expr = argument_expression(call, "Signal", 0)
    if bindings is None or not isinstance(expr, ast.NameRef) or \
            getattr(routine, "scope", None) is None:
        return None
    symbol = routine.scope.lookup(expr.name.key)
    if symbol is None or symbol.kind != GLOBAL_DATA:
        return None
    return bindings.get(symbol.slot)


def ordered_signal(program: Program, routine, call: ast.ProcedureCall):
    """The configured signal an interrupt order names directly, else None (signal data,
    a parameter, a routine's own data, the task's module data, which may hide a
    configured signal of that name: known only at run time, through AliasIO)."""
    expr = argument_expression(call, "Signal", 0)
    if not isinstance(expr, ast.NameRef):
        return None
    key = expr.name.key
    own = {p.name.key for p in routine.ast.parameters} | \
        {d.name.key for d in routine.ast.data}
    if key in own or any(data.key == key and data.namespace == routine.namespace
                         for data in program.globals):
        return None
    return program.signal(key)


def _read_inputs(program: Program, atoms: AtomCompiler) -> Optional[frozenset]:
    """Indices of the signals the program names or the properties read (None: any may
    be read).  An analog or group input of the I/O configuration that nothing reads
    needs no domain (survey round 5: a backup's EIO.cfg lists more inputs than the task
    uses)."""
    if program.named_signals is None or atoms.observes_signal_data:
        return None
    return program.named_signals | frozenset(atoms.observed)


def free_input_domains(program: Program, atoms: AtomCompiler,
                       explicit: Mapping[str, tuple] = {},
                       exact_only: bool = False) -> tuple[dict, tuple]:
    """Signal key -> values for the free analog and group inputs (``explicit`` ones as given,
    the others' defaults from input_domains), and the defaults (``Assumed``) chosen.

    ``atoms`` must have compiled the properties' atoms (it knows the signals they read).
    An input with no exact default takes the values ``stated_domains`` singles out (not
    exact: the verdicts name them); with ``exact_only`` it raises RMC502 instead.
    """
    domains = {name.upper(): tuple(values) for name, values in explicit.items()}
    assumed = _check_domains(program, domains, _read_inputs(program, atoms), atoms, exact_only)
    domains.update({a.signal.key: a.values for a in assumed})
    return domains, assumed


def _check_domains(program: Program, domains: dict, read: Optional[frozenset],
                   atoms: AtomCompiler, exact_only: bool) -> tuple:
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
    atom_data = None if atoms.observed_data is None else frozenset(atoms.observed_data)
    defaults = default_domains(program, needed, atom_reads, atom_data, atoms.observes_robot,
                               exact_only, tuple(atoms.expressions), atoms.scope)
    missing = [Diagnostic(DOMAIN, f"free {signal.kind} input '{signal.name}' needs a finite set "
                          f"of values: give --input-domain {signal.name}=v1,v2,... (or drive it "
                          "from an environment model)", signal.span,
                          notes=(f"no default: {defaults[signal.key].reason}",))
               for signal in needed if not isinstance(defaults[signal.key], Assumed)]
    if missing:                     # every input that lacks a domain at once, not one per run
        raise UserError(missing)
    return tuple(defaults[signal.key] for signal in needed)
