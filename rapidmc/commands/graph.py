"""``rapidmc graph PROG.mod... -o states.graphml|.gexf|.dot [--property NAME]``.

Writes the program's reachable state graph (with ``--property``: its
product with the automaton of the property's negation) for graph tools:
GraphML (yEd, Gephi, networkx), GEXF (Gephi) or Graphviz DOT, and prints
its size: states, edges, strongly connected components, terminal states.
Node and edge attributes are described in ``rapidmc.report.state_graph``.

Exit codes: 0 the graph is complete; 3 a bound (``--max-states``,
``--max-seconds``) stopped the search, so the file holds part of it;
2 bad input or usage.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

import networkx as nx

from ..api import environment_faults
from ..diagnostics import EXIT_OK, EXIT_UNKNOWN, USAGE, error
from ..report.state_graph import StateGraph, product_graph, state_graph
from .check import add_model_arguments, prepare_model
from ..diagnostics.quoting import quoted
from .report_file import check_report_target, write_report


def _graphml(graph: nx.MultiDiGraph) -> str:
    return "\n".join(nx.generate_graphml(graph)) + "\n"


def _gexf(graph: nx.MultiDiGraph) -> str:
    return "\n".join(nx.generate_gexf(graph)) + "\n"


def _dot(graph: nx.MultiDiGraph) -> str:
    from networkx.drawing.nx_pydot import to_pydot
    return to_pydot(graph).to_string()


WRITERS = {".graphml": _graphml, ".gexf": _gexf, ".dot": _dot, ".gv": _dot}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_model_arguments(parser)
    parser.add_argument("-o", "--output", required=True, metavar="FILE",
                        help="the file to write; its suffix picks the format: "
                             ".graphml, .gexf or .dot (.gv)")
    parser.add_argument("--property", metavar="NAME", default=None,
                        help="write the product with the automaton of this property's negation")
    parser.add_argument("--quiet", action="store_true", help="no progress line on stderr")


def execute(args: argparse.Namespace) -> int:
    writer = WRITERS.get(Path(args.output).suffix.lower())
    if writer is None:
        raise error(USAGE, f"-o {quoted(args.output)}: the suffix picks the format; use one of "
                    f"{', '.join(WRITERS)}")
    check_report_target(args.output, "graph")
    args.no_reduce = True        # the graph of the program as written: one edge per instruction
    model = prepare_model(args)
    bounds = dict(max_states=args.max_states, max_seconds=args.max_seconds)
    from ..check import Progress
    progress = Progress(sys.stderr, quiet=args.quiet)
    if args.property is not None and \
            args.property not in {prop.name for prop in model.properties}:
        raise error(USAGE, f"--property {quoted(args.property)} names no property "
                    "(give it with --ltl or --formula)")
    with environment_faults():
        if args.property is None:
            result = state_graph(model, progress=progress, **bounds)
        else:
            result = product_graph(model, args.property, progress=progress, **bounds)
    write_report(args.output, writer(result.graph), "graph")
    print(_summary(result, args.output))
    return EXIT_OK if result.complete else EXIT_UNKNOWN


def _summary(result: StateGraph, path: str) -> str:
    figures = result.summary()
    lines = [f"states: {figures['states']:,}",
             f"edges: {figures['edges']:,}",
             f"strongly connected components: {figures['components']:,} "
             f"({figures['cyclic_components']:,} with a cycle)",
             f"terminal states: {figures['terminal']:,}"]
    if not result.complete:
        lines.append(f"partial graph: {result.reason}")
    lines.append(f"written to {path}")
    return "\n".join(lines)
