"""Atoms evaluated by one generated Python function, as the fused step runs statements.

An atom that reads only global data and signals usually compiles with a
source (``Compiled.source``: the same computation as a Python expression
over ``store`` and the signal reader's context ``cx``, see
``semantics.fused_step``).  ``fused_valuation`` writes those atoms into one
function ``valuation(state) -> bits`` that evaluates each in turn on the
state's own data: no ``Machine`` per state, no closure per operator.  As
``AtomCompiler``'s functions do, an atom whose evaluation raises a RAPID
error is false.  Atoms without a source keep their ``fn(machine)`` and are
evaluated on a ``Machine`` after the generated ones.
tests/test_fused_atoms.py compares both evaluations state by state.
"""
from __future__ import annotations

from typing import Callable, Optional

from ..semantics.errors import RapidError
from ..semantics.fused_step import HELPERS, define
from ..semantics.state import State

NO_LAZY_INPUTS: dict = {}       # every signal is read from the state itself


def fused_valuation(atoms: list[tuple[int, str, dict]],
                    others: Optional[Callable[[State], int]]) -> Callable[[State], int]:
    """``valuation(state)``: the bits (``bit``, truth ``source``, ``names``) of ``atoms``
    that hold, evaluated in order, or-ed with ``others(state)`` (the atoms without a
    source) when given."""
    names = dict(HELPERS, RapidError=RapidError, _no_lazy=NO_LAZY_INPUTS, _others=others)
    lines = ["def valuation(state):",
             "    store = state[1]",
             "    bits = 0"]
    if any("cx" in source for _, source, _ in atoms):     # an atom reads a signal
        lines.insert(2, "    cx = [state[2], _no_lazy, {}, [], [], None]")
    for bit, source, atom_names in atoms:
        names.update(atom_names)
        lines += ["    try:",
                  f"        if {source}:",
                  f"            bits |= {bit}",
                  "    except RapidError:",
                  "        pass"]
    lines.append("    return bits" if others is None else "    return bits | _others(state)")
    define(lines, "<fused atoms>", names)
    valuation = names["valuation"]
    # what the compiled core's step machine compiles (model/packed/bytecode.py)
    valuation.fused_atoms = None if others is not None else list(atoms)
    return valuation
