"""SPIN as an independent translator: run ``spin -f`` and read its never claim.

``spin -f 'φ'`` prints a never claim accepting exactly the words that
satisfy φ (the claim is for φ as given; checking a system needs ``!φ``).
A claim is a Promela process whose labels are states; labels starting with
``accept`` are accepting.  Options read::

    :: (guard) -> goto LABEL                      edge to LABEL
    :: atomic { (guard) -> assert(!(guard)) }     edge to an accept-all sink
    :: false                                      no edge
    skip  (at the end of the claim)               the state accepts everything
    false                                         no edge

A claim reads the first valuation in its initial state, like ``Buchi``.

Example::

    >>> claim = '''never {
    ... accept_init:
    ... T0_init:
    ...     do
    ...     :: (! ((p0))) -> goto T0_init
    ...     od;
    ... }'''
    >>> read_never_claim(claim, ("p",)).edges
    ((Edge(positive=0, negative=1, target=0),),)
"""
from __future__ import annotations

import re
import signal
import subprocess
from dataclasses import dataclass
from typing import Optional, Sequence

from ..diagnostics import AUTOMATON, error
from .buchi import Buchi, Edge
from .guards import cubes
from .printing import to_spin
from .syntax import Formula, atoms_of, parse_formula

LABEL = re.compile(r"^([A-Za-z_][A-Za-z0-9_]*):$")
GOTO = re.compile(r"^::\s*(.*?)\s*->\s*goto\s+([A-Za-z_][A-Za-z0-9_]*)$")
ASSERT = re.compile(r"^::\s*atomic\s*\{\s*(.*?)\s*->\s*assert\(.*\)\s*\}$")
DEAD_OPTION = re.compile(r"^::\s*\(*\s*(false|0)\s*\)*\s*;?$")
ACCEPT_ALL = "<accept all>"
IGNORED = {"do", "od;", "if", "fi;", "od", "fi", "}"}


def read_never_claim(text: str, atoms: Sequence[str]) -> Buchi:
    """A ``Buchi`` over ``atoms`` from a never claim whose atoms are ``p0``, ``p1`` …"""
    blocks = _blocks(text)
    names = list(blocks)
    if ACCEPT_ALL in _targets(blocks) and ACCEPT_ALL not in blocks:
        blocks[ACCEPT_ALL] = (True, "skip", [])
        names.append(ACCEPT_ALL)
    number = {label: i for i, label in enumerate(names)}
    for alias, label in _aliases(text).items():
        number[alias] = number[label]
    edges, accepting = [], set()
    for label in names:
        is_accepting, ending, options = blocks[label]
        out = []
        if ending == "skip":
            out.append(Edge(0, 0, number[label]))
            is_accepting = True
        for guard, target in options:
            if target not in number:
                raise error(AUTOMATON, f"never claim jumps to unknown label {target!r}")
            out += [Edge(p, n, number[target]) for p, n in _guard_cubes(guard, atoms)]
        edges.append(tuple(out))
        if is_accepting:
            accepting.add(number[label])
    if not names:
        raise error(AUTOMATON, "the never claim has no states")
    return Buchi(tuple(atoms), 0, frozenset(accepting), tuple(edges))


def _guard_cubes(guard: str, atoms: Sequence[str]):
    def index(name: str) -> int:
        if not re.fullmatch(r"p\d+", name) or int(name[1:]) >= len(atoms):
            raise error(AUTOMATON, f"never claim guard uses unknown proposition {name!r}")
        return int(name[1:])
    return cubes(parse_formula(guard, file="<never-claim>"), index)


def _targets(blocks) -> set[str]:
    return {target for _, _, options in blocks.values() for _, target in options}


def _aliases(text: str) -> dict[str, str]:
    """Labels written directly before another label name the same state."""
    aliases, pending = {}, []
    for line in _lines(text):
        match = LABEL.match(line)
        if match:
            pending.append(match.group(1))
            continue
        for alias in pending[1:]:
            aliases[alias] = pending[0]
        pending = []
    return aliases


def _lines(text: str) -> list[str]:
    text = re.sub(r"/\*.*?\*/", "", text, flags=re.S)
    return [line.strip() for line in text.splitlines() if line.strip()]


def _blocks(text: str) -> dict[str, tuple[bool, str, list[tuple[str, str]]]]:
    """Label -> (accepting, ending, [(guard, target label)]), in claim order."""
    lines = _lines(text)
    if not lines or not lines[0].startswith("never"):
        raise error(AUTOMATON, "not a never claim (expected 'never {')")
    blocks: dict = {}
    current: Optional[str] = None
    labels: list[str] = []
    for line in lines[1:]:
        match = LABEL.match(line)
        if match:
            labels.append(match.group(1))
            continue
        if labels:
            current = labels[0]
            blocks[current] = (any(l.startswith("accept") for l in labels), "", [])
            labels = []
        if line in IGNORED:
            continue
        if current is None:
            raise error(AUTOMATON, f"never claim statement outside a labelled state: {line!r}")
        accepting, ending, options = blocks[current]
        goto, assertion = GOTO.match(line), ASSERT.match(line)
        if goto:
            options.append((goto.group(1), goto.group(2)))
        elif assertion:
            options.append((assertion.group(1), ACCEPT_ALL))
        elif DEAD_OPTION.match(line):
            continue        # an option that can never be taken
        elif line.rstrip(";") in ("skip", "false"):
            blocks[current] = (accepting, line.rstrip(";"), options)
        else:
            raise error(AUTOMATON, f"cannot read never claim line {line!r}")
    return blocks


def spin_translate(formula: Formula, atoms: Optional[Sequence[str]] = None,
                   timeout: float = 10.0, spin: str = "spin",
                   cpu_seconds: Optional[int] = None) -> Buchi:
    """Translate with ``spin -f``; raises ``subprocess.TimeoutExpired`` on timeout.

    ``timeout`` bounds the wall time.  ``cpu_seconds`` also bounds SPIN's CPU time (``ulimit
    -t``, whole seconds): unlike the wall time, that hardly depends on how busy the machine
    is, so the same formulas run out of it on every run; running out counts as a timeout.
    """
    atoms = tuple(atoms) if atoms is not None else atoms_of(formula)
    command = [spin, "-f", to_spin(formula, atoms)]
    if cpu_seconds:
        # the shell sets the limit and becomes SPIN (safe beside threads, unlike preexec_fn)
        command = ["sh", "-c", 'ulimit -t "$0" && exec "$@"', str(cpu_seconds), *command]
    completed = subprocess.run(command, capture_output=True, text=True, timeout=timeout,
                               check=False)
    if cpu_seconds and completed.returncode in OUT_OF_CPU:
        raise subprocess.TimeoutExpired(command, cpu_seconds)
    if completed.returncode != 0 or "never" not in completed.stdout:
        raise error(AUTOMATON, f"spin failed on {to_spin(formula, atoms)!r}: "
                               f"{(completed.stderr or completed.stdout).strip()}")
    return read_never_claim(completed.stdout, atoms)


# how the kernel ends a process at its CPU limit: SIGXCPU at the soft limit, SIGKILL at the hard
OUT_OF_CPU = (-getattr(signal, "SIGXCPU", 24), -getattr(signal, "SIGKILL", 9))


@dataclass(frozen=True)
class CrossCheck:
    """The outcome of holding one translation against SPIN's for one formula."""

    formula: Formula
    agrees: Optional[bool]      # None: SPIN timed out (a skip, counted by callers)
    our_states: int
    spin_states: int
    detail: str = ""


def cross_check(formula: Formula, translate_formula, atoms: Sequence[str],
                timeout: float = 10.0, spin: str = "spin",
                cpu_seconds: Optional[int] = None) -> CrossCheck:
    """Check A(φ) × SPIN(¬φ) and SPIN(φ) × A(¬φ) are both empty.

    ``translate_formula(formula, atoms) -> Buchi`` is the translator under
    test.  Both products empty means the two translations accept the same
    words: a word in one but not the other would satisfy φ and ¬φ.
    """
    from .lasso import product_is_empty
    from .syntax import Not
    ours, ours_negated = translate_formula(formula, atoms), translate_formula(Not(formula), atoms)
    try:
        theirs = spin_translate(formula, atoms, timeout, spin, cpu_seconds)
        theirs_negated = spin_translate(Not(formula), atoms, timeout, spin, cpu_seconds)
    except subprocess.TimeoutExpired:
        return CrossCheck(formula, None, ours.state_count, 0, "spin timed out")
    problems = []
    if not product_is_empty(ours, theirs_negated):
        problems.append("ours(φ) ∩ spin(¬φ) is not empty")
    if not product_is_empty(theirs, ours_negated):
        problems.append("spin(φ) ∩ ours(¬φ) is not empty")
    return CrossCheck(formula, not problems, ours.state_count, theirs.state_count,
                      "; ".join(problems))
