"""``rapidmc ltl 'FORMULA'``: print the Büchi automaton of a formula in HOA format."""
from __future__ import annotations

import argparse

from ..diagnostics import EXIT_OK, SourceCache
from ..ltl import BACKENDS, parse_formula, to_buchi, to_text, write_hoa
from ..ltl.syntax import Not


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("formula", help="LTL formula in Spot syntax, e.g. 'G(req -> F ack)'")
    parser.add_argument("--backend", choices=BACKENDS, default=None,
                        help="translator (default: spot if importable, else builtin)")
    parser.add_argument("--negate", action="store_true",
                        help="translate the negation of the formula")


def execute(args: argparse.Namespace) -> int:
    SourceCache.remember("<command-line>", args.formula)
    formula = parse_formula(args.formula, file="<command-line>")
    if args.negate:
        formula = Not(formula)
    automaton = to_buchi(formula, backend=args.backend)
    print(write_hoa(automaton, name=to_text(formula)))
    return EXIT_OK
