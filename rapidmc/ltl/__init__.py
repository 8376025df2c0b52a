"""LTL: formulas (Spot syntax), Büchi automata, translators, HOA.

* ``parse_formula(text, file, line, column) -> Formula``
* ``to_buchi(formula, backend=None) -> Buchi``: Spot when ``import spot``
  works, else the built-in tableau translator; ``backend="builtin"`` or
  ``"spot"`` forces one.  Atoms come in order of first appearance.
* ``patterns``: specification patterns (``response(P, S) after(Q)``) and
  their LTL translations.

Example::

    >>> automaton = to_buchi(parse_formula("G F p"), backend="builtin")
    >>> automaton.atoms, automaton.state_count
    (('p',), 2)
"""
from __future__ import annotations

from typing import Optional, Sequence

from ..diagnostics import USAGE, error
from .buchi import Buchi, Edge
from .hoa import read_hoa, write_hoa
from .printing import to_spin, to_text
from .spot_backend import spot_available, spot_translate
from .syntax import Formula, atoms_of, parse_formula
from .translate import translate

BACKENDS = ("builtin", "spot")

__all__ = ["BACKENDS", "Buchi", "Edge", "Formula", "atoms_of", "parse_formula", "read_hoa",
           "to_buchi", "to_spin", "to_text", "write_hoa"]


def to_buchi(formula: Formula, backend: Optional[str] = None,
             atoms: Optional[Sequence[str]] = None) -> Buchi:
    """A state-based Büchi automaton accepting exactly the words satisfying ``formula``."""
    atoms = tuple(atoms) if atoms is not None else atoms_of(formula)
    if backend is None:
        backend = "spot" if spot_available() else "builtin"
    if backend == "builtin":
        return translate(formula, atoms)
    if backend == "spot":
        if not spot_available():
            raise error(USAGE, "the Spot backend needs Spot's Python bindings ('import spot' "
                               "failed); use --backend builtin")
        return spot_translate(formula, atoms)
    raise error(USAGE, f"unknown LTL backend {backend!r} (choose from {', '.join(BACKENDS)})")
