"""``rapidmc ltl 'FORMULA'``: print the Büchi automaton of a formula in HOA format.

A specification pattern (``response(req, ack) before(stop)``, ``ltl.patterns``) stands for
its LTL translation."""
from __future__ import annotations

import argparse

from ..diagnostics import EXIT_OK, SourceCache
from ..ltl import BACKENDS, parse_formula, to_buchi, to_text, write_hoa
from ..ltl.patterns import is_pattern, parse_pattern, pattern_formula
from ..ltl.syntax import Not


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("formula", help="LTL formula in Spot syntax, e.g. 'G(req -> F ack)', or a "
                        "specification pattern, e.g. 'response(req, ack)'")
    parser.add_argument("--backend", choices=BACKENDS, default=None,
                        help="translator (default: spot if importable, else builtin)")
    parser.add_argument("--negate", action="store_true",
                        help="translate the negation of the formula")


def execute(args: argparse.Namespace) -> int:
    SourceCache.remember("<command-line>", args.formula)
    if is_pattern(args.formula):
        formula = pattern_formula(parse_pattern(args.formula, file="<command-line>"))
    else:
        formula = parse_formula(args.formula, file="<command-line>")
    if args.negate:
        formula = Not(formula)
    automaton = to_buchi(formula, backend=args.backend)
    print(write_hoa(automaton, name=to_text(formula)))
    return EXIT_OK
