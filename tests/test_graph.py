"""``rapidmc graph``: the reachable state graph, written for graph tools and read back.

Data-driven on tests/check/: for every case the GraphML file loads back
into networkx with as many states as the complete reachability search of
``check`` stored (``no_runtime_error``'s model states), and the printed
figures are those networkx computes on the graph it read.  The sorter's
graph is read back from all three formats; ``--property`` writes the
product, whose size is that of the emptiness search that proved P1.
"""
from __future__ import annotations

import json
from pathlib import Path

import networkx as nx
import pytest
from networkx.drawing.nx_pydot import read_dot

from rapidmc.cli import main
from test_check_cases import verdict_cases

ROOT = Path(__file__).resolve().parent.parent
CASES = {case.name: case for case in verdict_cases()}
SORTER_B = ["case_studies/sorter/sorter_b.mod", "--env", "case_studies/sorter/plant.mod"]
DOOR_SAFE = ["case_studies/door/door_safe.mod", "--env", "case_studies/door/plant.mod"]
READERS = {".graphml": nx.read_graphml, ".gexf": nx.read_gexf, ".dot": read_dot}


def graph_argv(case, output: Path) -> list[str]:
    argv = ["graph", "prog.mod", *sorted(p.name for p in case.folder.glob("*.sys"))]
    if (case.folder / "env.mod").exists():
        argv += ["--env", "env.mod"]
    if (case.folder / "props.ltl").exists():
        argv += ["--ltl", "props.ltl"]
    return [*argv, *case.extra_args, "--quiet", "-o", str(output)]


def figures(text: str) -> dict[str, int]:
    """The printed summary as numbers."""
    lines = dict(line.split(": ", 1) for line in text.splitlines() if ": " in line)
    components, cyclic = lines["strongly connected components"].split(" (")
    return {"states": int(lines["states"].replace(",", "")),
            "edges": int(lines["edges"].replace(",", "")),
            "components": int(components.replace(",", "")),
            "cyclic": int(cyclic.split()[0].replace(",", "")),
            "terminal": int(lines["terminal states"].replace(",", ""))}


def computed(graph) -> dict[str, int]:
    """The same figures, computed by networkx on a graph read back from a file."""
    components = list(nx.strongly_connected_components(graph))
    return {"states": graph.number_of_nodes(), "edges": graph.number_of_edges(),
            "components": len(components),
            "cyclic": sum(1 for c in components
                          if len(c) > 1 or graph.has_edge(next(iter(c)), next(iter(c)))),
            "terminal": sum(1 for n in graph if set(graph.successors(n)) <= {n})}


@pytest.mark.parametrize("name", CASES)
def test_every_check_case_graph_loads_back_with_the_reachable_states(name, monkeypatch, capsys,
                                                                     tmp_path):
    case = CASES[name]
    monkeypatch.chdir(case.folder)
    output = tmp_path / "states.graphml"
    code = main(graph_argv(case, output))
    printed = figures(capsys.readouterr().out)
    graph = nx.read_graphml(output)
    assert printed == computed(graph)
    main([*case.argv(), "--no-reduce"])     # the graph is of the program as written
    runtime = json.loads(capsys.readouterr().out)["properties"][0]
    assert runtime["name"] == "no_runtime_error"
    if runtime["verdict"] == "HOLDS":
        assert code == 0 and graph.number_of_nodes() == runtime["stats"]["model_states"]
    if runtime["verdict"] == "UNKNOWN":
        assert code == 3                        # bounded: the file holds part of the graph


def test_every_format_reads_back_the_same_graph(monkeypatch, capsys, tmp_path):
    """The door cell (DOT files are slow to parse: the small case study)."""
    monkeypatch.chdir(ROOT)
    read = {}
    for suffix, reader in READERS.items():
        output = tmp_path / f"states{suffix}"
        assert main(["graph", *DOOR_SAFE, "--quiet", "-o", str(output)]) == 0
        capsys.readouterr()
        read[suffix] = reader(output)
    sizes = {(g.number_of_nodes(), g.number_of_edges()) for g in read.values()}
    assert len(sizes) == 1 and sizes.pop()[0] == 28             # the README's state count
    first = read[".graphml"].nodes["0"]
    assert first["location"].startswith("case_studies/door/door_safe.mod:")
    for graph in read.values():
        attributes = dict(graph.nodes["0"])
        assert {k: str(v).strip('"') for k, v in attributes.items() if k != "label"} == \
            {k: str(v) for k, v in first.items()}


def test_the_sorter_graph_has_its_reachable_states(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    output = tmp_path / "states.graphml"
    assert main(["graph", *SORTER_B, "--quiet", "-o", str(output)]) == 0
    assert figures(capsys.readouterr().out)["states"] == 466      # the case study's count
    graph = nx.read_graphml(output)
    assert graph.nodes["0"]["location"] == "case_studies/sorter/sorter_b.mod:45"
    assert graph.nodes["0"]["routine"] == "main" and graph.nodes["0"]["initial"] is True
    edge = next(iter(graph.edges(data=True)))[2]
    assert edge["source"] == "AliasIO config_cin, c_in;" and "AnyBool" in edge["inputs"]


def test_the_product_graph_is_the_graph_the_emptiness_search_explored(monkeypatch, capsys,
                                                                      tmp_path):
    monkeypatch.chdir(ROOT)
    main(["check", *SORTER_B, "--ltl", "specs/sorter.ltl", "--quiet", "--format", "json",
          "--no-reduce"])
    p1 = next(p for p in json.loads(capsys.readouterr().out)["properties"] if p["name"] == "P1")
    output = tmp_path / "product.graphml"
    assert main(["graph", *SORTER_B, "--ltl", "specs/sorter.ltl", "--property", "P1", "--quiet",
                 "-o", str(output)]) == 0
    capsys.readouterr()
    graph = nx.read_graphml(output)
    assert graph.number_of_nodes() == p1["stats"]["product_states"]
    assert {"automaton_state", "accepting"} <= set(graph.nodes["0"])


def test_a_bounded_graph_is_partial_and_exits_3(monkeypatch, capsys, tmp_path):
    monkeypatch.chdir(ROOT)
    output = tmp_path / "states.gexf"
    assert main(["graph", *SORTER_B, "--max-states", "10", "--quiet", "-o", str(output)]) == 3
    assert "partial graph: state limit 10 reached" in capsys.readouterr().out
    assert 10 <= nx.read_gexf(output).number_of_nodes() < 466


@pytest.mark.parametrize("argv, message", [
    (["-o", "states.png"], "the suffix picks the format"),
    (["-o", "states.dot", "--property", "P9"], "--property 'P9' names no property"),
])
def test_usage_errors(argv, message, monkeypatch, capsys):
    monkeypatch.chdir(ROOT)
    assert main(["graph", *SORTER_B, *argv]) == 2
    err = capsys.readouterr().err
    assert message in err and "[RMC601]" in err
